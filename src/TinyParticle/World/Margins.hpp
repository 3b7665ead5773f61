// The small margins below which the engine treats a contact as touching and
// a speed as zero: 1/8192 m/s (0.12 mm/s) and 1/32768 m (31 um), or four
// units of the scalar where those would round to nothing (Q24.8); and the
// smallest factor a correction trusts. Constants for Fixed and Float, folded
// at compile time.
#pragma once

#include <stdint.h>

#include "../Math/Fixed.hpp"
#include "../Math/Float.hpp"

namespace tinyparticle {
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
