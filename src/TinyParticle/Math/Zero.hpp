// detail::isZero(x), isNegative(x), isPositive(x): x == 0, x < 0, x > 0 for
// any scalar, by the cheapest test; isNonFinite(x or vector) below. A float compare is a library call on
// AVR (about 50 cycles, against 130 for a multiply); a look at the bits
// takes a few. The engine skips multiplies by zero components (gravity
// along one axis, a particle at rest), which pays only with a cheap test,
// and asks for signs in its per-step paths.
#pragma once

#include <stdint.h>
#include <string.h>

#include "Fixed.hpp"
#include "Float.hpp"
#include "Vec.hpp"

namespace tinyparticle {
namespace detail {

template <typename S>
inline bool isZero(S x) {
  return x == S();
}
template <typename S>
inline bool isNegative(S x) {
  return x < S();
}
template <typename S>
inline bool isPositive(S x) {
  return S() < x;
}

template <uint8_t I, uint8_t F>
inline bool isZero(Fixed<I, F> x) {
  return x.raw() == 0;
}
template <uint8_t I, uint8_t F>
inline bool isNegative(Fixed<I, F> x) {
  return x.raw() < 0;
}
template <uint8_t I, uint8_t F>
inline bool isPositive(Fixed<I, F> x) {
  return x.raw() > 0;
}

// The bits of a float: the sign on top, then the magnitude, which orders
// as an integer; above 0x7F800000 (infinity) it is a NaN, which is neither
// zero, nor negative, nor positive, as with the compares.
inline uint32_t floatBits(Float x) {
  const float f = x.toFloat();
  uint32_t bits;
  memcpy(&bits, &f, sizeof(bits));
  return bits;
}
inline bool isZero(Float x) {  // +0 and -0
  return (floatBits(x) & 0x7FFFFFFFul) == 0;
}
inline bool isNegative(Float x) {
  const uint32_t bits = floatBits(x);
  const uint32_t magnitude = bits & 0x7FFFFFFFul;
  return (bits & 0x80000000ul) != 0 && magnitude != 0 &&
         magnitude <= 0x7F800000ul;
}
inline bool isPositive(Float x) {
  const uint32_t bits = floatBits(x);
  return (bits & 0x80000000ul) == 0 && bits != 0 && bits <= 0x7F800000ul;
}

// Compares of values known not to be negative (magnitudes, squares and
// products of them, and +0, never -0): a < b, a > b, and a == b for positive
// a and b that are not NaN. A Float compares by its bits, which order as
// unsigned integers: a few instructions, and no float compare linked. NaN
// sits above infinity: NaN < b is false as with the compare, NaN > b is
// true where the compare says false (a step that met a NaN is flagged by
// its finite checks either way).
template <typename S>
inline bool isBelowNonNegative(S a, S b) {
  return a < b;
}
template <typename S>
inline bool isAboveNonNegative(S a, S b) {
  return a > b;
}
template <typename S>
inline bool isEqualPositive(S a, S b) {
  return a == b;
}
inline bool isBelowNonNegative(Float a, Float b) {
  return floatBits(a) < floatBits(b);
}
inline bool isAboveNonNegative(Float a, Float b) {
  return floatBits(a) > floatBits(b);
}
inline bool isEqualPositive(Float a, Float b) {
  return floatBits(a) == floatBits(b);
}

// isNonFinite(v): a component of v is infinite or NaN. Only a float can
// be: for fixed point it is false at compile time, so the checks that use
// it cost nothing there. For a float it is a test of the exponent's bits
// (all ones), a few cycles a component.
template <typename S>
inline bool isNonFinite(S x) {
  return !(x - x == S());  // inf - inf and NaN - NaN are NaN
}
template <uint8_t I, uint8_t F>
constexpr bool isNonFinite(Fixed<I, F>) {
  return false;
}
inline bool isNonFinite(Float x) {
  // The exponent, all ones, from the high half alone: shifted left past
  // the sign, it fills the top byte (half the bytes of a 32-bit test).
  const uint16_t high = uint16_t(floatBits(x) >> 16);
  return uint16_t(high << 1) >= 0xFF00u;
}
template <typename S>
inline bool isNonFinite(const Vec<S, 2>& v) {
  return isNonFinite(v.x) | isNonFinite(v.y);
}
template <typename S>
inline bool isNonFinite(const Vec<S, 3>& v) {
  return isNonFinite(v.x) | isNonFinite(v.y) | isNonFinite(v.z);
}

// d -= v, skipping zero components (a pivot at the origin): for float a
// subtraction is a library call, the test a few cycles.
template <typename S>
inline void subtractNonZero(Vec<S, 2>& d, const Vec<S, 2>& v) {
  if (!isZero(v.x)) d.x -= v.x;
  if (!isZero(v.y)) d.y -= v.y;
}
template <typename S>
inline void subtractNonZero(Vec<S, 3>& d, const Vec<S, 3>& v) {
  if (!isZero(v.x)) d.x -= v.x;
  if (!isZero(v.y)) d.y -= v.y;
  if (!isZero(v.z)) d.z -= v.z;
}

// Fixed: a subtraction costs what the test does; the plain one is smaller.
template <uint8_t I, uint8_t F>
inline void subtractNonZero(Vec<Fixed<I, F>, 2>& d,
                            const Vec<Fixed<I, F>, 2>& v) {
  d -= v;
}
template <uint8_t I, uint8_t F>
inline void subtractNonZero(Vec<Fixed<I, F>, 3>& d,
                            const Vec<Fixed<I, F>, 3>& v) {
  d -= v;
}

template <typename S>
inline bool isZeroVector(const Vec<S, 2>& v) {
  return isZero(v.x) && isZero(v.y);
}
template <typename S>
inline bool isZeroVector(const Vec<S, 3>& v) {
  return isZero(v.x) && isZero(v.y) && isZero(v.z);
}

}  // namespace detail
}  // namespace tinyparticle
