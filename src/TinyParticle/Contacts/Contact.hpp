// Contact: one violated (or touching) constraint found during a step, for the
// resolver. Contact generators write them into the world's contact pool.
//
// Two particles a and b (b = kNoIndex for scenery such as a plane or an
// anchor). The normal points from b towards a: the direction in which a is
// pushed. 2D Q16.16 takes 19 bytes (23 in 3D).
#pragma once

#include <stdint.h>

#include "../Math/Vec.hpp"

namespace tinyparticle {

template <typename S, uint8_t Dim>
struct Contact {
  Vec<S, Dim> normal;      // unit length, from b towards a
  S penetration;           // > 0 while overlapping or stretched
  S separatingVelocity;    // dot(va - vb, normal), < 0 while closing
  uint8_t a;
  uint8_t b;
  uint8_t source;          // the constraint slot that made it (restitution)

  constexpr Contact()
      : normal(), penetration(), separatingVelocity(), a(0), b(0), source(0) {}
};

// What the last step did with contacts; World::stats() returns it.
struct StepStats {
  uint8_t contacts;    // contacts generated (at most the pool capacity)
  uint8_t dropped;     // contacts that did not fit (the least severe go)
  uint8_t iterations;  // resolver iterations used
  constexpr StepStats() : contacts(0), dropped(0), iterations(0) {}
};

}  // namespace tinyparticle
