// Newton's cradle: five balls (radius 0.05 m, 0.1 kg) hang on rods of
// 0.5 m from posts 0.1 m apart (x = 0.3 ... 0.7 m, y = 0.8 m), just
// touching, under gravity; collisions with restitution 1. The first ball
// starts raised to 60 degrees (0.25 m up), at rest. It swings down and stops
// at the others; the last one swings out to the same height, the middle
// ones stay put. Each impact is a chain of exchanges between equal masses,
// one contact after the other, which the resolver makes exactly (the
// contact normal along x, the masses equal: halves, no division).
//
//   CradleWorld<Q16_16> world;  // 5 balls, gravity, 5 rods + collisions
//   buildCradle(world);
#pragma once

#include <stdint.h>

#include "../Core/Handle.hpp"
#include "../World/World.hpp"

namespace tinyparticle {

template <typename S>
using CradleWorld = World<S, 2, 5, 0, 6, 8>;

// Adds the balls (slots 0 to 4, from the raised one), their rods, gravity
// and collisions; returns the number of balls added.
template <class W>
uint8_t buildCradle(W& world) {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  const S length(0.5), radius(0.05), mass(0.1);
  world.addGravity();
  uint8_t added = 0;
  for (uint8_t k = 0; k < 5; ++k) {
    V post;
    post.x = S(0.3) + S(0.1) * S(int(k));
    post.y = S(0.8);
    V ball = post;
    ball.y -= length;
    if (k == 0) {  // 60 degrees out: sin 60 = 0.866..., cos 60 = 0.5
      ball.x -= length * S(0.8660254037844386);
      ball.y = post.y - length * S(0.5);
    }
    ParticleId id = world.addParticle(ball, mass, radius);
    if (!world.addRod(id, post, length).isValid()) break;
    ++added;
  }
  world.addCollisions(S(1));
  return added;
}

}  // namespace tinyparticle
