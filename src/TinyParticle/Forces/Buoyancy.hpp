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
#include "../Math/Fixed.hpp"
#include "../Math/Scaler.hpp"

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
  // density * volume * 9.81 and 1 / (2 maxDepth) are computed once, the
  // same bits on every platform: in float for a float scalar, in fixed
  // point for a fixed one (a fixed-point sketch links no float routine for
  // them; see setUp()).
  static bool make(BuoyancyForce& out, S surface, S maxDepth, S volume,
                   S density) {
    if (maxDepth <= S()) return false;
    out.surface = surface;
    out.maxDepth = maxDepth;
    setUp(out, maxDepth, volume, density);
    return true;
  }

  // Float (and any other scalar): in float.
  template <typename T>
  static void setUp(BuoyancyForce& out, T maxDepth, T volume, T density) {
    out.invTwiceDepth = T(0.5f / maxDepth.toFloat());
    out.fullForce = T(density.toFloat() * volume.toFloat() * 9.81f);
  }
  // Fixed point: 1 / (2 maxDepth) within one step (the compact reciprocal,
  // halved), and the full force within a few steps: density * 9.81 first,
  // whose rounding then shrinks with the (usually small) volume, unless
  // that product could leave the range (|density| above a tenth of the
  // largest value), then density * volume first.
  template <uint8_t I, uint8_t F>
  static void setUp(BuoyancyForce& out, Fixed<I, F> maxDepth,
                    Fixed<I, F> volume, Fixed<I, F> density) {
    typedef Fixed<I, F> T;
    out.invTwiceDepth = detail::half(detail::compactReciprocal(maxDepth));
    const T g(9.81);
    const T limit = T::fromRaw(T::kRawMax / 10);
    out.fullForce = density <= limit && -limit <= density
                        ? (density * g) * volume
                        : (density * volume) * g;
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
