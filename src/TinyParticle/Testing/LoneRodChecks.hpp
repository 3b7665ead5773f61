// Test support: lone rods (Contacts/RodSolver.hpp, solveLone()) against
// the chains' solve of the same rod, for any scalar and dimension.
//
// A rod of 0.15 m from the origin to a 0.1 kg end, gravity on. Alone, it
// takes the lone rods' solve; with a free chain of two rods (three
// particles) besides, every rod of the world goes through the chains'
// solve. The two runs of each case are compared.
// Not included by TinyParticle.h: include it after <TinyParticle.h>.
#pragma once

#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

// How the rod is built: which end moves, what holds the other.
enum LoneHolder : uint8_t { kLoneEndIsA, kLoneEndIsB, kLoneAnchored };

// The world: the rod's two ends and the chain's three particles, gravity,
// three rods.
template <typename S, uint8_t Dim>
struct LoneRodChecks {
  typedef World<S, Dim, 5, 1, 3, 1> W;
  typedef typename W::Vec V;
  static const uint8_t kSamples = 8;

  // The largest distance (m) between the end's positions in the lone and
  // the chains' solve, sampled kSamples times over `steps` steps of dt
  // from `start` with velocity v0; 1 if a world did not take the solve it
  // should, or raised an error.
  static float difference(W& w, LoneHolder holder, const V& start,
                          const V& v0, S dt, uint16_t steps) {
    V lone[kSamples], chain[kSamples];
    if (!run(w, holder, false, start, v0, dt, steps, lone)) return 1;
    if (run(w, holder, true, start, v0, dt, steps, chain)) return 1;
    float worst = 0;
    for (uint8_t i = 0; i < kSamples; ++i) {
      const float d = (lone[i] - chain[i]).magnitude().toFloat();
      if (d > worst) worst = d;
    }
    return worst;
  }

  // The two solves compute the same step equations and differ by rounding
  // (and the lone solve mends half of a length error at a time): a unit of
  // 2^-16 m a step at most, over `steps` steps. (At a fast turn the lone
  // solve takes two terms of the chains' closed form: the rest is below a
  // unit a step up to 0.2 rad a step, Contacts/RodSolver.hpp.)
  static float bound(uint16_t steps) { return steps * (1.0f / 65536); }

 private:
  // One run; `chains` adds the free chain. Whether the world took the lone
  // rods' solve (and raised no error).
  static bool run(W& w, LoneHolder holder, bool chains, const V& start,
                  const V& v0, S dt, uint16_t steps, V* samples) {
    w.clear();
    const ParticleId end = w.addParticle(start, S(0.1));
    if (holder == kLoneAnchored) {
      w.addRod(end, V(), S(0.15));
    } else {
      const ParticleId pivot = w.addFixedParticle(V());
      if (holder == kLoneEndIsA) {
        w.addRod(end, pivot, S(0.15));
      } else {
        w.addRod(pivot, end, S(0.15));
      }
    }
    if (chains) {
      V a, b, c;
      a.x = S(1);
      b.x = S(1.1);
      c.x = S(1.2);
      const ParticleId pa = w.addParticle(a, S(0.1));
      const ParticleId pb = w.addParticle(b, S(0.1));
      w.addRod(pa, pb, S(0.1));
      w.addRod(pb, w.addParticle(c, S(0.1)), S(0.1));
    }
    w.addGravity();
    w.particle(end)->velocity = v0;
    const uint16_t every = steps / kSamples;
    for (uint16_t k = 1; k <= steps; ++k) {
      w.step(dt);
      if (k % every == 0) samples[k / every - 1] = w.particle(end)->position;
    }
    return (WorldAccess::rodState(w) & W::kRodsLone) != 0 && w.error() == 0;
  }
};

}  // namespace testing
}  // namespace tinyparticle
