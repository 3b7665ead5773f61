// Test support: a pendulum's energy through a long swing, and a push along
// its rod, for any scalar.
//
// Used by extras/test/RodEnergyTest (Q16.16) and extras/test/RodEnergyFloatTest (Float):
// one sketch per scalar leaves the Nano flash to spare with the real AUnit.
// Not included by TinyParticle.h: include
// <TinyParticle/Testing/RodEnergyChecks.hpp> after it.
#pragma once

#include <math.h>
#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

template <typename S>
struct RodEnergyChecks {
  typedef PendulumWorld<S, 2> W;


  // Energy per unit mass, with the height counted from the pivot:
  // v^2 / 2 + g y.
  static float energy(const typename W::ParticleType& bob) {
    float vx = bob.velocity.x.toFloat(), vy = bob.velocity.y.toFloat();
    return (vx * vx + vy * vy) / 2 + 9.81f * bob.position.y.toFloat();
  }

  // L = 1 m, theta0 = 0.5 rad, dt = 1/256 s, for 10 s (almost 5 periods).
  // Returns the largest |E(t) - E(0)| over the swing, divided by the energy
  // that the swing exchanges, g L (1 - cos theta0) (what the bob would
  // have at the bottom); `swung` tells whether it still reaches the other
  // side at the end.
  static float energyError(bool* swung) {
    W w;
    PendulumScene scene = buildPendulum(w, S(1), S(0.5), S(1));
    const typename W::ParticleType& bob = *w.particle(scene.bob);
    const float start = energy(bob);
    const float swing = 9.81f * 0.12241744f;  // 1 - cos 0.5
    float worst = 0;
    *swung = false;
    for (uint16_t i = 0; i < 10 * 256; ++i) {
      w.step(S(1.0 / 256));
      float error = ::fabsf(energy(bob) - start);
      if (error > worst) worst = error;
      if (i >= 9 * 256 && bob.position.x.toFloat() < -0.45f) *swung = true;
    }
    return worst / swing;
  }

  // The bob hangs at rest, and is pushed straight away from the pivot at
  // 1 m/s (gravity on). Returns the largest |length - L| over 1 s; `speed`
  // gets the largest speed from the second step on, and `back` the
  // velocity towards the pivot after the first step (a bounce would be
  // +1 m/s).
  static float radialPush(float* speed, float* back) {
    W w;
    PendulumScene scene = buildPendulum(w, S(1), S(0), S(1));
    typename W::ParticleType& bob = *w.particle(scene.bob);
    bob.velocity.y = S(-1);
    float worst = 0;
    *speed = 0;
    for (uint16_t i = 0; i < 256; ++i) {
      w.step(S(1.0 / 256));
      float x = bob.position.x.toFloat(), y = bob.position.y.toFloat();
      float error = ::fabsf(::sqrtf(x * x + y * y) - 1.0f);
      if (error > worst) worst = error;
      float vx = bob.velocity.x.toFloat(), vy = bob.velocity.y.toFloat();
      if (i == 0) *back = vy;
      if (i > 0 && ::sqrtf(vx * vx + vy * vy) > *speed) {
        *speed = ::sqrtf(vx * vx + vy * vy);
      }
    }
    return worst;
  }
};

}  // namespace testing
}  // namespace tinyparticle
