// Gravity: adds a constant acceleration to one particle or to all of them.
// It never needs a mass or a division: the acceleration goes straight into
// the accumulator. One slot serves every particle of the world, and then it
// touches no particle at all: it hands the acceleration to the world, which
// adds (g dt, computed once per step) to every velocity while it integrates,
// and counts it wherever the resolver looks at a particle's acceleration.
#pragma once

#include <stdint.h>

#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "../World/Handle.hpp"

namespace tinyparticle {

template <typename S, uint8_t Dim>
struct GravityParams {
  Vec<S, Dim> acceleration;  // g times the multiplier, m/s^2
};

template <class W>
struct GravityForce {
  typedef typename W::Scalar S;

  static void apply(W& world, typename W::ForceSlot& slot, S) {
    const typename W::Vec& g = slot.params.gravity.acceleration;
    if (slot.a != kAllIndex) {
      add(world.particleAt(slot.a), g);
    } else {
      world.addUniformAcceleration(g);
    }
  }

 private:
  // An immovable particle gets nothing: its accumulator must stay zero for
  // the resolver's resting-contact test. Zero components (gravity is
  // usually along y only) are skipped: a compare is cheaper than an add.
  static void add(typename W::ParticleType& p, const typename W::Vec& g) {
    if (p.isStatic()) return;
    for (uint8_t k = 0; k < W::kDimensions; ++k) {
      if (!detail::isZero(g[k])) p.acceleration[k] += g[k];
    }
  }
};

}  // namespace tinyparticle
