// The box of balls: N balls of radius 0.03 m and mass 0.1 kg in a 1 m box
// (its walls are planes), under gravity, colliding with each other and the
// walls with restitution 0.8. They start on a grid with velocities of up to
// 1 m/s from a fixed-seed generator, so every run is the same. Sleeping is
// the caller's choice (World::enableSleeping(), about 700 B of flash on a
// Nano): with it, once the balls have settled into a pile, a step costs
// little until something disturbs them; the benchmark's balls rows sleep,
// the BouncingBalls example does not.
//
//   BallsWorld<Q16_16, 2, 16> world;  // N particles, no force slot, the box +
//   buildBouncingBalls(world, 16);    // collisions, 32 contacts
//   world.enableSleeping();           // (optional)
#pragma once

#include <stdint.h>

#include "../Core/Handle.hpp"
#include "../World/World.hpp"
#include "Random.hpp"

namespace tinyparticle {

template <typename S, uint8_t Dim, uint8_t kBalls, uint8_t kContacts = 32>
using BallsWorld = World<S, Dim, kBalls, 0, 2, kContacts>;

namespace detail {
// The box, the balls on their grid with their velocities; gravity or not.
template <class W>
uint8_t buildBallBox(W& world, uint8_t count, uint16_t seed,
                     typename W::Scalar restitution, bool gravity) {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  V low, high;
  for (uint8_t k = 0; k < W::kDimensions; ++k) high[k] = S(1);
  world.addBox(low, high, restitution);
  if (gravity) world.addGravity();
  world.addCollisions(restitution);

  // The smallest grid with at least `count` places per layer.
  uint8_t side = 1;
  while (side * side < count) ++side;
  // (The compact reciprocal: the same value as S(1) / x, without linking
  // the fast divide into a sketch that may not need it; of a positive x.)
  const S spacing = detail::compactReciprocalOfPositive(S(int(side + 1)));
  SceneRandom random(seed);
  // Each velocity component is a multiple of 1/128 of 0.7 m/s (0.57 in 3D),
  // so the speed stays below 1 m/s.
  const S unit(W::kDimensions == 2 ? 0.7 / 128 : 0.57 / 128);
  uint8_t added = 0;
  // Places 1 .. side along x, row by row (counted, not divided: the
  // division routine would be linked for this alone).
  uint8_t column = 0, row = 1;
  for (uint8_t i = 0; i < count; ++i) {
    if (++column > side) {
      column = 1;
      ++row;
    }
    V position;
    position.x = spacing * S(int(column));
    position.y = spacing * S(int(row));
    if (W::kDimensions == 3) position[2] = S(0.5);
    const ParticleId id = world.addParticle(position, S(0.1), S(0.03));
    if (!id.isValid()) break;
    typename W::Vec& velocity = world.particleAt(id.index).velocity;
    for (uint8_t k = 0; k < W::kDimensions; ++k) {
      velocity[k] = unit * S(int(random.symmetric(128)));
    }
    ++added;
  }
  return added;
}
}  // namespace detail

// Adds the walls, gravity, collisions and `count` balls (sleeping stays as
// it was: see the top); returns the number of balls added.
template <class W>
uint8_t buildBouncingBalls(W& world, uint8_t count, uint16_t seed = 2024) {
  return detail::buildBallBox(world, count, seed, typename W::Scalar(0.8),
                             true);
}

// The elastic box: the same balls, walls and start, with restitution 1 and
// no gravity, and no sleeping: nothing comes to rest, and the kinetic
// energy stays what it was (the collisions' and the walls' exchanges are
// exact up to rounding). Returns the number of balls added.
template <class W>
uint8_t buildElasticBox(W& world, uint8_t count, uint16_t seed = 2024) {
  return detail::buildBallBox(world, count, seed, typename W::Scalar(1), false);
}

}  // namespace tinyparticle
