// Test support: collisions and contacts with restitution, for any scalar: an
// elastic head-on collision, and a ball dropped on the floor (its rebound,
// then whether it rests).
//
// Used by extras/test/CollisionTest (Q16.16) and extras/test/CollisionFloatTest (Float):
// the two scalars together no longer fit in the Nano's 30 KB of flash, so one
// sketch per scalar runs the same scenes from here and asserts on what they
// measure. Not included by TinyParticle.h: include
// <TinyParticle/Testing/CollisionChecks.hpp> after it.
#pragma once

#include <math.h>
#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

template <typename S>
struct CollisionChecks {
  // One world type per scalar (each type instantiates the engine again).
  typedef World<S, 2, 2, 1, 1, 2> W;
  typedef typename W::Vec V;

  // Two 1 kg balls (radius 0.05 m) meet head-on at +1 and -0.5 m/s with
  // restitution 1 and no gravity. Reports their velocities along x after
  // 1 s, and the sum of their speeds across the line of impact.
  static void headOn(float* v1, float* v2, float* sideways) {
    W w;
    V left(0.2, 0.5), right(0.8, 0.5);
    ParticleId a = w.addParticle(left, S(1), S(0.05));
    ParticleId b = w.addParticle(right, S(1), S(0.05));
    w.particle(a)->velocity.x = S(1);
    w.particle(b)->velocity.x = S(-0.5);
    w.addCollisions(S(1));
    for (uint16_t i = 0; i < 256; ++i) w.step(S(1.0 / 256));
    *v1 = w.particle(a)->velocity.x.toFloat();
    *v2 = w.particle(b)->velocity.x.toFloat();
    // ::fabs: the C function on floats (tinyparticle::fabs takes scalars).
    *sideways = ::fabs(w.particle(a)->velocity.y.toFloat()) +
                ::fabs(w.particle(b)->velocity.y.toFloat());
  }

  // A ball whose bottom starts 1 m above a floor with restitution 0.5,
  // dt = 1/1024 s. Returns the highest bottom height between the first and
  // the second impact; over the last 2 s of 10 s, reports the lowest bottom
  // height, the highest one and the largest speed.
  static float drop(float* lowest, float* highest, float* fastest) {
    W w;
    const float radius = 0.05f;
    V start(0.0, 1.05);
    ParticleId ball = w.addParticle(start, S(1), S(radius));
    w.addGravity();
    V up(0.0, 1.0);
    w.addPlane(up, S(0), S(0.5));
    float rebound = 0;
    uint8_t impacts = 0;
    bool falling = true;
    *lowest = 10;
    *highest = -10;
    *fastest = 0;
    for (uint16_t i = 0; i < 10 * 1024; ++i) {
      w.step(S(1.0 / 1024));
      const typename W::ParticleType* p = w.particle(ball);
      float bottom = p->position.y.toFloat() - radius;
      float v = p->velocity.y.toFloat();
      if (falling && v > 0) {
        ++impacts;  // the velocity turned upwards: an impact
        falling = false;
      } else if (!falling && v < 0) {
        falling = true;
      }
      if (impacts == 1 && bottom > rebound) rebound = bottom;
      if (i >= 8 * 1024) {
        if (bottom < *lowest) *lowest = bottom;
        if (bottom > *highest) *highest = bottom;
        if (::fabs(v) > *fastest) *fastest = ::fabs(v);
      }
    }
    return rebound;
  }
};

}  // namespace testing
}  // namespace tinyparticle
