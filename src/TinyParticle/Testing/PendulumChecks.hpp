// Test support: the pendulum scene's period and rod length, for any scalar.
//
// Used by extras/test/PendulumTest (Q16.16) and extras/test/PendulumFloatTest (Float):
// the two scalars together come within a few bytes of the Nano's 30 KB of
// flash with the real AUnit, so one sketch per scalar runs the same scene
// from here and asserts on what it measures.
// Not included by TinyParticle.h: include
// <TinyParticle/Testing/PendulumChecks.hpp> after it.
#pragma once

#include <math.h>
#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

template <typename S>
struct PendulumChecks {
  typedef PendulumWorld<S, 2> W;

  // T = 2 pi sqrt(L / g) (1 + theta0^2 / 16) for L = 1 m, theta0 = 0.2 rad:
  // 2.01108 s.
  static float expectedPeriod() {
    return 2 * 3.14159265f * ::sqrtf(1.0f / 9.81f) * (1 + 0.2f * 0.2f / 16);
  }

  // Period of L = 1 m, theta0 = 0.2 rad at dt = 1/1024 s (exact in both
  // scalars, so time is the step count times dt). Measured between the
  // first and the third downward zero crossing of x, each found by linear
  // interpolation between the two steps around it. -1 if the bob did not
  // cross three times in 5 s.
  static float period() {
    W w;
    PendulumScene scene = buildPendulum(w, S(1), S(0.2), S(1));
    const float dt = 1.0f / 1024;
    float previous = w.particle(scene.bob)->position.x.toFloat();
    float first = -1, last = -1;
    uint8_t crossings = 0;
    for (uint16_t i = 1; i <= 5 * 1024 && crossings < 3; ++i) {
      w.step(S(1.0 / 1024));
      float x = w.particle(scene.bob)->position.x.toFloat();
      if (previous > 0 && x <= 0) {
        float t = i * dt - dt * x / (x - previous);
        if (crossings == 0) first = t;
        last = t;
        ++crossings;
      }
      previous = x;
    }
    return crossings == 3 ? (last - first) / 2 : -1;
  }

  // The largest |length - L| over a 10 s swing from theta0 = 0.5 rad at
  // dt = 1/256 s; `swung` tells whether the bob crossed to the other side.
  static float lengthError(bool* swung) {
    W w;
    PendulumScene scene = buildPendulum(w, S(1), S(0.5), S(1));
    float worst = 0;
    *swung = false;
    for (uint16_t i = 0; i < 10 * 256; ++i) {
      w.step(S(1.0 / 256));
      const typename W::Vec& p = w.particle(scene.bob)->position;
      float x = p.x.toFloat(), y = p.y.toFloat();
      float error = ::fabsf(::sqrtf(x * x + y * y) - 1.0f);
      if (error > worst) worst = error;
      if (x < -0.4f) *swung = true;
    }
    return worst;
  }
};

}  // namespace testing
}  // namespace tinyparticle
