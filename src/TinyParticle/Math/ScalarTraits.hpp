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


// The small margins below which the engine treats a contact as touching and
// a speed as zero: 1/8192 m/s (0.12 mm/s) and 1/32768 m (31 um), or four
// units of the scalar where those would round to nothing (Q24.8); and the
// smallest factor a correction trusts. Constants for Fixed and Float, folded
// at compile time.
namespace detail {

// Any other scalar: computed.
template <typename S>
struct Margins {
  static S speed() { return fmax(S(1.0 / 8192), S::epsilon() * S(4)); }
  static S depth() { return fmax(S(1.0 / 32768), S::epsilon() * S(4)); }
  // Whether the scalar is coarse near zero (fixed point: steps of one unit),
  // and then the smallest factor that a correction may scale by: 8 units,
  // rounded to within about 6 %. (A factor of one or two units would be off
  // by half of itself, every step the same way.)
  static const bool kCoarse = false;
  static S smallestFactor() { return S(); }
};

template <uint8_t I, uint8_t F>
struct Margins<Fixed<I, F> > {
  typedef Fixed<I, F> T;
  static constexpr typename T::Raw atLeastFour(typename T::Raw raw) {
    return raw > 4 ? raw : 4;
  }
  static constexpr T speed() { return T::fromRaw(atLeastFour(T(1.0 / 8192).raw())); }
  static constexpr T depth() { return T::fromRaw(atLeastFour(T(1.0 / 32768).raw())); }
  static const bool kCoarse = true;
  static constexpr T smallestFactor() { return T::fromRaw(8); }
};

template <>
struct Margins<Float> {
  static constexpr Float speed() { return Float(1.0 / 8192); }
  static constexpr Float depth() { return Float(1.0 / 32768); }
  static const bool kCoarse = false;
  static constexpr Float smallestFactor() { return Float(); }
};

}  // namespace detail
}  // namespace tinyparticle

// One message for every check, so the first error reads the same wherever
// the wrong scalar is met.
#define TINYPARTICLE_SCALAR_MESSAGE                                         \
  "the scalar must be Q16_16, Q24_8, Q8_8 (any Fixed<IntBits, FracBits>) " \
  "or Float, not float, double or an integer"
