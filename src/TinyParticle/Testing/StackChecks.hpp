// Test support: a resting stack of balls on the floor, for any scalar.
//
// Used by extras/test/StackTest (Q16.16) and extras/test/StackFloatTest (Float): the two
// scalars together no longer fit in the Nano's 30 KB of flash, so one sketch
// per scalar runs the same scene from here and asserts on what it measures.
// Not included by TinyParticle.h: include
// <TinyParticle/Testing/StackChecks.hpp> after it.
#pragma once

#include <math.h>
#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

template <typename S>
struct StackChecks {
  typedef World<S, 2, 3, 1, 2, 3> W;
  typedef typename W::Vec V;

  // Three balls of radius 0.1 m stacked on a floor under gravity, released
  // 1 mm apart, restitution 0.3; `cap` is the resolver's iteration cap (0:
  // the default). Over the last second of 3 s, returns the largest height
  // error of a ball centre against its ideal place (0.1, 0.3, 0.5 m); `jitter`
  // gets the largest height range of a ball and `fastest` the largest speed.
  static float stack(uint8_t cap, float* jitter, float* fastest) {
    W w;
    V up(0.0, 1.0);
    w.addPlane(up, S(0), S(0.3));
    w.addCollisions(S(0.3));
    w.addGravity();
    w.setIterationCap(cap);
    for (uint8_t i = 0; i < 3; ++i) {
      V where(0.0, 0.101 + 0.201 * i);
      w.addParticle(where, S(1), S(0.1));
    }
    float worst = 0, low[3], high[3];
    *fastest = 0;
    for (uint16_t step = 0; step < 3 * 256; ++step) {
      w.step(S(1.0 / 256));
      if (step < 2 * 256) continue;
      for (uint8_t i = 0; i < 3; ++i) {
        const typename W::ParticleType& p = w.particleAt(i);
        float y = p.position.y.toFloat();
        // ::fabs: the C function on floats (tinyparticle::fabs takes scalars).
        float error = ::fabs(y - (0.1f + 0.2f * i));
        if (error > worst) worst = error;
        if (step == 2 * 256 || y < low[i]) low[i] = y;
        if (step == 2 * 256 || y > high[i]) high[i] = y;
        float speed = p.velocity.magnitude().toFloat();
        if (speed > *fastest) *fastest = speed;
      }
    }
    *jitter = 0;
    for (uint8_t i = 0; i < 3; ++i) {
      if (high[i] - low[i] > *jitter) *jitter = high[i] - low[i];
    }
    return worst;
  }
};

}  // namespace testing
}  // namespace tinyparticle
