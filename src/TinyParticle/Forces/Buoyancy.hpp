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

#include "../Core/Generator.hpp"
#include "../Core/Particle.hpp"

namespace tinyparticle {

// A generator class (Core/Generator.hpp), run for one particle or for each.
template <typename S, uint8_t Dim>
struct BuoyancyForce {
  static const uint8_t kShape = SlotShape::kNone;
  S surface;        // y of the water surface, m
  S maxDepth;       // half-height of the body, m
  S invTwiceDepth;  // 1 / (2 maxDepth), precomputed
  S fullForce;      // density * volume * g, N

  // False (nothing set) for a maxDepth that is not positive. The full force
  // density * volume * 9.81 is computed once, in float on every platform,
  // so that the bits are the same everywhere.
  static bool make(BuoyancyForce& out, S surface, S maxDepth, S volume,
                   S density) {
    if (maxDepth <= S()) return false;
    out.surface = surface;
    out.maxDepth = maxDepth;
    out.invTwiceDepth = S(0.5f / maxDepth.toFloat());
    out.fullForce = S(density.toFloat() * volume.toFloat() * 9.81f);
    return true;
  }

  void apply(Particle<S, Dim>& p, S) const {
    // How far the bottom of the body is below the surface, in [0, 2 d].
    S depth = surface + maxDepth - p.position.y;
    if (depth <= S()) return;  // above the water
    S force = fullForce;
    if (depth < maxDepth + maxDepth) force = force * (depth * invTwiceDepth);
    p.acceleration.y += force * p.inverseMass;
  }
};

}  // namespace tinyparticle
