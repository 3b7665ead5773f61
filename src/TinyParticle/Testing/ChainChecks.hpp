// Test support: rigid links (Contacts/RodSolver.hpp) for any scalar.
//
// The whip chain of issue 9 (Scenes/Chain.hpp, buildChain): a fixed pivot
// at (0, 0), N beads of 0.05 kg at (0.125 i, 0), rods of 0.125 m between
// neighbours (the first to the pivot), gravity on all, released from rest.
// Energies are in units of the fall energy E_fall = m g 0.125 N (N + 1) / 2,
// what the chain gives up falling from level to hanging.
// Not included by TinyParticle.h: include it after <TinyParticle.h>.
#pragma once

#include <math.h>
#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

struct ChainResult {
  float linkError;    // largest |length / L - 1| over the run
  float energyError;  // largest |E(t) - E(0)| / E_fall
  uint16_t error;     // world.error() at the end
};

// One world type for every length up to kMaxBeads (on the Nano each world
// type is a copy of the engine's code; 16 beads need more RAM than the
// Nano's: host tests only).
template <typename S, uint8_t kBeads = 8>
struct ChainChecks {
  static const uint8_t kMaxBeads = kBeads;
  typedef ChainWorld<S, 2, kMaxBeads> W;

  static float lengthOf(const W& w, uint8_t a, uint8_t b) {
    const float dx = w.particleAt(a).position.x.toFloat() -
                     w.particleAt(b).position.x.toFloat();
    const float dy = w.particleAt(a).position.y.toFloat() -
                     w.particleAt(b).position.y.toFloat();
    return ::sqrtf(dx * dx + dy * dy);
  }

  static float energy(const W& w, uint8_t n) {
    float e = 0;
    for (uint8_t i = 1; i <= n; ++i) {
      const typename W::ParticleType& p = w.particleAt(i);
      const float vx = p.velocity.x.toFloat(), vy = p.velocity.y.toFloat();
      e += 0.05f * ((vx * vx + vy * vy) / 2 + 9.81f * p.position.y.toFloat());
    }
    return e;
  }

  // N beads (at most kMaxBeads), `steps` steps of 1/rate s.
  static ChainResult run(uint8_t N, uint16_t rate, uint16_t steps) {
    static W w;  // (static: a world on the Nano's stack is too large)
    w.clear();  // in place: w = W() would build a second world on the stack
    buildChain(w, N);  // Scenes/Chain.hpp, in this one world type
    const float fall = 0.05f * 9.81f * 0.125f * N * (N + 1) / 2;
    const float start = energy(w, N);
    ChainResult r = {0, 0, 0};
    const S dt = S(1) / S(long(rate));
    for (uint16_t k = 0; k < steps; ++k) {
      w.step(dt);
      const float e = ::fabsf(energy(w, N) - start) / fall;
      if (e > r.energyError) r.energyError = e;
      for (uint8_t i = 1; i <= N; ++i) {
        const float l = ::fabsf(lengthOf(w, i, i - 1) / 0.125f - 1);
        if (l > r.linkError) r.linkError = l;
      }
    }
    r.error = w.error();
    return r;
  }
};

}  // namespace testing
}  // namespace tinyparticle
