// Which types the engine takes as its scalar: the checks that give a clear
// first error for a wrong one (World's static_assert), kept in one place.
#pragma once

#include <stdint.h>

#include "Fixed.hpp"
#include "Float.hpp"

namespace tinyparticle {

// IsScalar<S>::value: true for Fixed<IntBits, FracBits> (Q16_16, Q24_8,
// Q8_8...) and Float, the types with the interface the engine is written
// against; false for everything else (float, double, int...). A type of
// one's own with that interface (extras/doc/design.md, "The scalar
// interface") is let in by a specialization with value = true, as the
// benchmarks' host-only Double does.
template <typename S>
struct IsScalar {
  static const bool value = false;
};
template <uint8_t IntBits, uint8_t FracBits>
struct IsScalar<Fixed<IntBits, FracBits> > {
  static const bool value = true;
};
template <>
struct IsScalar<Float> {
  static const bool value = true;
};

}  // namespace tinyparticle

// One message for every check, so the first error reads the same wherever
// the wrong scalar is met.
#define TINYPARTICLE_SCALAR_MESSAGE                                         \
  "the scalar must be Q16_16, Q24_8, Q8_8 (any Fixed<IntBits, FracBits>) " \
  "or Float, not float, double or an integer"
