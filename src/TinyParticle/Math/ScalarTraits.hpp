// What a scalar must provide, in one place: ScalarTraits<S> says whether S
// is a scalar and holds what the engine needs to know of it beyond its
// interface (the margins below which a contact touches and a speed is
// zero, whether it is coarse near zero); IsScalar<S> is World's first check
// (a static_assert with one message), which also asks for the interface.
//
// The interface (extras/doc/design.md, "The scalar interface"): S() is zero;
// explicit constexpr S(int, long, double...); + - * / and compares between
// two S; toFloat(), toInt(); S::largest(), S::lowest(), S::epsilon(); free
// fabs, fmin, fmax, sqrt, sin, cos, atan2. IsScalar checks these exist.
//
// Faster paths per family of scalars live beside the code that uses them,
// each with a plain version that any scalar gets: Fixed specialises
// detail::VecMath (Vec.hpp: lengths without overflow), NormalComponent
// (Contacts/Contact.hpp: no multiply by 0 or +-1), Scaler (Scaler.hpp:
// * dt as a shift), TurnsOf (Turns.hpp, and Float.hpp for Float) and the
// sign tests from the bits (Zero.hpp; Float too). A new scalar needs none
// of them: a specialisation of ScalarTraits (from ComputedScalarTraits)
// and the interface, as the benchmarks' host-only Double shows.
#pragma once

#include <stdint.h>

#include "Fixed.hpp"
#include "Float.hpp"

namespace tinyparticle {

// Any other type: not a scalar (float, double, int...).
template <typename S>
struct ScalarTraits {
  static const bool kIsScalar = false;
};

// The traits of a scalar of one's own, computed from its interface: the
// margins are 1/8192 m/s (0.12 mm/s) and 1/32768 m (31 um), or four units
// of the scalar where those would round to nothing; not coarse near zero.
template <typename S>
struct ComputedScalarTraits {
  static const bool kIsScalar = true;
  // Speeds and depths below these count as zero (the resolver, the planes
  // and collisions make contacts from within depthMargin()).
  static S speedMargin() { return fmax(S(1.0 / 8192), S::epsilon() * S(4)); }
  static S depthMargin() { return fmax(S(1.0 / 32768), S::epsilon() * S(4)); }
  // Whether the scalar is coarse near zero (fixed point: steps of one unit),
  // and then the smallest factor that a correction may scale by: 8 units,
  // rounded to within about 6 %. (A factor of one or two units would be off
  // by half of itself, every step the same way.)
  static const bool kCoarse = false;
  static S smallestFactor() { return S(); }
};

// Fixed point: constants folded at compile time; Q24.8's margins are four
// units (its 1/8192 would round to 0).
template <uint8_t I, uint8_t F>
struct ScalarTraits<Fixed<I, F> > {
  typedef Fixed<I, F> T;
  static const bool kIsScalar = true;
  static constexpr typename T::Raw atLeastFour(typename T::Raw raw) {
    return raw > 4 ? raw : 4;
  }
  static constexpr T speedMargin() {
    return T::fromRaw(atLeastFour(T(1.0 / 8192).raw()));
  }
  static constexpr T depthMargin() {
    return T::fromRaw(atLeastFour(T(1.0 / 32768).raw()));
  }
  static const bool kCoarse = true;
  static constexpr T smallestFactor() { return T::fromRaw(8); }
};

template <>
struct ScalarTraits<Float> {
  static const bool kIsScalar = true;
  static constexpr Float speedMargin() { return Float(1.0 / 8192); }
  static constexpr Float depthMargin() { return Float(1.0 / 32768); }
  static const bool kCoarse = false;
  static constexpr Float smallestFactor() { return Float(); }
};

namespace detail {

// Whether S has the interface above (an expression that names each part;
// a type without one of them is not a scalar).
template <typename S>
struct HasScalarInterface {
  template <typename T>
  static char probe(decltype(
      T() + T(), T() - T(), T() * T(), T() / T(), -T(), T() < T(),
      T() == T(), T(1), T(1.0), T().toFloat(), T().toInt(), T::largest(),
      T::lowest(), T::epsilon(), fabs(T()), fmin(T(), T()), fmax(T(), T()),
      sqrt(T()), sin(T()), cos(T()), atan2(T(), T()), 0)*);
  template <typename T>
  static long probe(...);
  static const bool value = sizeof(probe<S>(nullptr)) == 1;
};

}  // namespace detail

// True for Fixed<IntBits, FracBits> (Q16_16, Q24_8, Q8_8...), Float and a
// type whose ScalarTraits say so, when it has the interface.
template <typename S>
struct IsScalar {
  static const bool value =
      ScalarTraits<S>::kIsScalar && detail::HasScalarInterface<S>::value;
};

}  // namespace tinyparticle

// One message for every check, so the first error reads the same wherever
// the wrong scalar is met.
#define TINYPARTICLE_SCALAR_MESSAGE                                         \
  "the scalar must be Q16_16, Q24_8, Q8_8 (any Fixed<IntBits, FracBits>) " \
  "or Float, not float, double or an integer"
