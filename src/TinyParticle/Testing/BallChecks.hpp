// Test support: the box of balls scene (Scenes/BouncingBalls.hpp), as the
// examples and the benchmarks build it, for any scalar, in 2D or 3D: how far
// the balls get beyond the walls, and how the energy changes.
//
// Used by extras/test/BallsTest (2D, both scalars), extras/test/Balls3DTest (3D, Q16.16)
// and extras/test/Balls3DFloatTest (3D, Float), which assert on what it measures.
// Not included by TinyParticle.h: include
// <TinyParticle/Testing/BallChecks.hpp> after it.
#pragma once

#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

template <typename S, uint8_t Dim>
struct BallChecks {
  // 8 balls and 16 contacts keep the world small enough for the Nano's
  // stack; the scene is the same as the 16-ball one.
  typedef BallsWorld<S, Dim, 8, 16> W;

  // Kinetic plus potential energy of the 0.1 kg balls (J).
  static float energy(const W& w) {
    float e = 0;
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const typename W::ParticleType& p = w.particleAt(i);
      e += 0.1f * (p.velocity.magnitudeSquared().toFloat() / 2 +
                   9.81f * p.position.y.toFloat());
    }
    return e;
  }

  // Runs 3 s at dt = 1/256. Returns how far any ball got beyond the walls
  // (its surface past a wall, m); `gain` gets the largest energy rise over
  // the start (J) and `loss` the energy lost by the end.
  static float run(float* gain, float* loss) {
    W w;
    buildBouncingBalls(w, 8);
    w.enableSleeping();  // as the benchmark runs it
    const float start = energy(w);
    float outside = 0;
    *gain = 0;
    for (uint16_t n = 0; n < 3 * 256; ++n) {
      w.step(S(1.0 / 256));
      for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
        const typename W::ParticleType& p = w.particleAt(i);
        for (uint8_t k = 0; k < Dim; ++k) {
          float x = p.position[k].toFloat();
          if (0.03f - x > outside) outside = 0.03f - x;
          if (x - 0.97f > outside) outside = x - 0.97f;
        }
      }
      float e = energy(w);
      if (e - start > *gain) *gain = e - start;
    }
    *loss = start - energy(w);
    return outside;
  }
};

}  // namespace testing
}  // namespace tinyparticle
