// Buoyancy against a horizontal water surface (y = surface; gravity points
// down along -y). A particle counts as a body of the given volume and of
// half-height maxDepth: fully under water when its centre is maxDepth below
// the surface, out of the water when maxDepth above it, and in between the
// lifting force grows linearly with the submerged fraction. The full force is
// density * volume * g (Archimedes).
//
// At rest, a floating body of mass m is submerged by the fraction
// m / (density * volume).
#pragma once

#include <stdint.h>

#include "../World/Handle.hpp"

namespace tinyparticle {

template <typename S>
struct BuoyancyParams {
  S surface;        // y of the water surface, m
  S maxDepth;       // half-height of the body, m
  S invTwiceDepth;  // 1 / (2 maxDepth), precomputed
  S fullForce;      // density * volume * g, N
};

template <class W>
struct BuoyancyForce {
  typedef typename W::Scalar S;

  static void apply(W& world, typename W::ForceSlot& slot, S) {
    const BuoyancyParams<S> water = slot.params.buoyancy;
    if (slot.a != kAllIndex) {
      add(world.particleAt(slot.a), water);
      return;
    }
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      typename W::ParticleType& p = world.particleAt(i);
      if (p.inUse()) add(p, water);
    }
  }

 private:
  static void add(typename W::ParticleType& p, const BuoyancyParams<S>& w) {
    if (p.isStatic()) return;
    // How far the bottom of the body is below the surface, in [0, 2 d].
    S depth = w.surface + w.maxDepth - p.position.y;
    if (depth <= S()) return;  // above the water
    S force = w.fullForce;
    if (depth < w.maxDepth + w.maxDepth) force = force * (depth * w.invTwiceDepth);
    p.acceleration.y += force * p.inverseMass;
  }
};

}  // namespace tinyparticle
