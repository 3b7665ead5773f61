// Test support: particles with inverse mass 0 under gravity, collisions, a
// rod and applied forces, for any scalar.
//
// Used by extras/test/ImmovableTest (Q16.16) and extras/test/ImmovableFloatTest (Float):
// one sketch per scalar leaves the Nano flash to spare with the real AUnit.
// Not included by TinyParticle.h: include
// <TinyParticle/Testing/ImmovableChecks.hpp> after it.
#pragma once

#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

template <typename S>
struct ImmovableChecks {
  typedef World<S, 2, 3, 1, 2, 4> W;
  typedef typename W::Vec V;

  // An immovable particle under gravity, hit by a ball, held by a rod to
  // another particle and pushed by applyForce. Returns 1 if it never moved,
  // plus 2 if the ball did bounce off it.
  static int immovable() {
    W w;
    V where(0.5, 0.5), above(0.5, 0.9), aside(0.9, 0.5);
    ParticleId fixed = w.addFixedParticle(where, S(0.05));
    ParticleId ball = w.addParticle(above, S(1), S(0.05));
    ParticleId swing = w.addParticle(aside, S(2), S(0.01));
    w.particle(fixed)->velocity.x = S(1);  // ignored: it never moves
    w.addGravity();
    w.addCollisions(S(1));
    w.addRod(swing, fixed, S(0.4));
    bool bounced = false;
    for (uint16_t i = 0; i < 512; ++i) {
      V shove(3.0, -4.0);
      w.applyForce(fixed, shove);
      w.step(S(1.0 / 256));
      if (w.particle(ball)->velocity.y > S(0.5)) bounced = true;
      if (w.particle(fixed)->position != where) return 0;
    }
    return bounced ? 3 : 1;
  }
};

}  // namespace testing
}  // namespace tinyparticle
