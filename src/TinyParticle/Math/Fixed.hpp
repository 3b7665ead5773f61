// Fixed<IntBits, FracBits>: a binary fixed-point number.
//
// The storage follows from the format: 16 bits in all -> int16_t,
// 32 bits in all -> int32_t. IntBits counts the sign bit.
//
// Rules every operation keeps:
// - + - * / round to nearest (ties away from zero) and saturate: a result
//   that does not fit becomes max() or lowest() and raises
//   MathError::kOverflow. There is no signed overflow and no shift of a
//   negative value anywhere, so there is no undefined behaviour.
// - x / 0 returns max() or lowest() with x's sign (0 / 0 returns 0) and
//   raises MathError::kDivideByZero.
// - Construction from an integer or a decimal literal is constexpr, so
//   Q16_16(0.15) costs nothing at run time. Out-of-range values saturate.
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "MathErrors.hpp"

namespace tinyparticle {

namespace detail {

template <uint8_t TotalBits>
struct FixedStorage;

template <>
struct FixedStorage<16> {
  typedef int16_t Raw;
  typedef uint16_t URaw;
  typedef uint32_t UWide;  // holds a product of two magnitudes
  static const Raw kMax = INT16_MAX;
};

template <>
struct FixedStorage<32> {
  typedef int32_t Raw;
  typedef uint32_t URaw;
  typedef uint64_t UWide;
  static const Raw kMax = INT32_MAX;
};

}  // namespace detail

template <uint8_t IntBits, uint8_t FracBits>
class Fixed {
  static_assert(IntBits + FracBits == 16 || IntBits + FracBits == 32,
                "Fixed needs 16 or 32 bits in all");
  static_assert(IntBits >= 2 && FracBits >= 1,
                "Fixed needs a sign bit, an integer bit and a fraction bit");
  typedef detail::FixedStorage<IntBits + FracBits> Storage;

 public:
  typedef typename Storage::Raw Raw;
  typedef typename Storage::URaw URaw;
  typedef typename Storage::UWide UWide;

  static const uint8_t kIntBits = IntBits;
  static const uint8_t kFracBits = FracBits;
  static const Raw kRawMax = Storage::kMax;
  static const Raw kRawMin = -Storage::kMax - 1;
  static const Raw kRawOne = Raw(1) << FracBits;

  constexpr Fixed() : mRaw(0) {}
  constexpr explicit Fixed(int v) : mRaw(fromSigned(v)) {}
  constexpr explicit Fixed(long v) : mRaw(fromSigned(v)) {}
  constexpr explicit Fixed(long long v) : mRaw(fromSigned(v)) {}
  constexpr explicit Fixed(unsigned v) : mRaw(fromUnsigned(v)) {}
  constexpr explicit Fixed(unsigned long v) : mRaw(fromUnsigned(v)) {}
  constexpr explicit Fixed(double v) : mRaw(fromDouble(v)) {}

  // The value whose representation is `raw`, i.e. raw / 2^FracBits.
  static constexpr Fixed fromRaw(Raw raw) { return Fixed(raw, RawTag()); }
  constexpr Raw raw() const { return mRaw; }

  constexpr float toFloat() const { return float(mRaw) * (1.0f / kScale); }
  // Rounds toward zero, like a cast from float to int.
  constexpr int32_t toInt() const { return int32_t(mRaw / kRawOne); }

  static constexpr Fixed max() { return fromRaw(kRawMax); }
  static constexpr Fixed lowest() { return fromRaw(kRawMin); }
  static constexpr Fixed epsilon() { return fromRaw(1); }
  static constexpr Fixed pi() { return Fixed(3.14159265358979323846); }

  Fixed operator+(Fixed b) const { return fromRaw(add(mRaw, b.mRaw)); }
  Fixed operator-(Fixed b) const { return fromRaw(subtract(mRaw, b.mRaw)); }
  Fixed operator*(Fixed b) const { return fromRaw(multiply(mRaw, b.mRaw)); }
  Fixed operator/(Fixed b) const { return fromRaw(divide(mRaw, b.mRaw)); }
  Fixed operator-() const { return fromRaw(subtract(0, mRaw)); }
  Fixed& operator+=(Fixed b) { return *this = *this + b; }
  Fixed& operator-=(Fixed b) { return *this = *this - b; }
  Fixed& operator*=(Fixed b) { return *this = *this * b; }
  Fixed& operator/=(Fixed b) { return *this = *this / b; }

  constexpr bool operator==(Fixed b) const { return mRaw == b.mRaw; }
  constexpr bool operator!=(Fixed b) const { return mRaw != b.mRaw; }
  constexpr bool operator<(Fixed b) const { return mRaw < b.mRaw; }
  constexpr bool operator<=(Fixed b) const { return mRaw <= b.mRaw; }
  constexpr bool operator>(Fixed b) const { return mRaw > b.mRaw; }
  constexpr bool operator>=(Fixed b) const { return mRaw >= b.mRaw; }

  // The raw operations, portable C++. They are the reference for any
  // faster platform code and are tested against exact arithmetic.
  static Raw add(Raw a, Raw b) {
    Raw sum = toSigned(URaw(URaw(a) + URaw(b)));
    // Overflow only when a and b share a sign that the sum lacks.
    if (((a ^ sum) & (b ^ sum)) < 0) return overflow(a < 0);
    return sum;
  }

  static Raw subtract(Raw a, Raw b) {
    Raw difference = toSigned(URaw(URaw(a) - URaw(b)));
    if (((a ^ b) & (a ^ difference)) < 0) return overflow(a < 0);
    return difference;
  }

  static Raw multiply(Raw a, Raw b) {
    UWide product = UWide(magnitude(a)) * magnitude(b);
    UWide rounded = (product + (UWide(1) << (FracBits - 1))) >> FracBits;
    return fromMagnitude(rounded, (a < 0) != (b < 0));
  }

  static Raw divide(Raw a, Raw b) {
    if (b == 0) {
      detail::raiseMathError(MathError::kDivideByZero);
      return a > 0 ? kRawMax : (a < 0 ? kRawMin : 0);
    }
    UWide numerator = UWide(magnitude(a)) << FracBits;
    UWide divisor = magnitude(b);
    UWide quotient = (numerator + divisor / 2) / divisor;
    return fromMagnitude(quotient, (a < 0) != (b < 0));
  }

  // |raw| as an unsigned number; exact for kRawMin too.
  static constexpr URaw magnitude(Raw raw) {
    return raw < 0 ? URaw(URaw(0) - URaw(raw)) : URaw(raw);
  }

  // The value with magnitude `m` and the given sign, saturated.
  static Raw fromMagnitude(UWide m, bool negative) {
    if (negative) {
      if (m > UWide(kRawMax) + 1) return overflow(true);
      return toSigned(URaw(URaw(0) - URaw(m)));
    }
    if (m > UWide(kRawMax)) return overflow(false);
    return Raw(m);
  }

 private:
  struct RawTag {};
  constexpr Fixed(Raw raw, RawTag) : mRaw(raw) {}

  static constexpr double kScale = double(uint32_t(1) << FracBits);
  // long is 32 bits on AVR, so these compares stay cheap there.
  static constexpr long kIntMax = long(kRawMax >> FracBits);
  static constexpr long kIntMin = -kIntMax - 1;

  // Two's-complement reinterpretation without implementation-defined casts.
  static constexpr Raw toSigned(URaw u) {
    return u <= URaw(kRawMax) ? Raw(u) : Raw(-Raw(URaw(~u)) - 1);
  }

  static Raw overflow(bool negative) {
    detail::raiseMathError(MathError::kOverflow);
    return negative ? kRawMin : kRawMax;
  }

  // In range, v * 2^FracBits fits Raw, so the product cannot overflow.
  template <typename T>
  static constexpr Raw fromSigned(T v) {
    return v > kIntMax ? kRawMax
                       : (v < kIntMin ? kRawMin : Raw(Raw(v) * kRawOne));
  }
  template <typename T>
  static constexpr Raw fromUnsigned(T v) {
    return v > (unsigned long)kIntMax ? kRawMax : Raw(Raw(v) * kRawOne);
  }
  static constexpr Raw fromDouble(double v) {
    return v != v ? Raw(0)  // NaN
         : v * kScale + 0.5 >= double(kRawMax) + 1.0 ? kRawMax
         : v * kScale - 0.5 <= double(kRawMin) - 1.0 ? kRawMin
         : Raw(v >= 0 ? v * kScale + 0.5 : v * kScale - 0.5);
  }

  Raw mRaw;
};

template <uint8_t I, uint8_t F>
constexpr double Fixed<I, F>::kScale;

// The formats the library names. Q16_16 is the default fixed type.
typedef Fixed<16, 16> Q16_16;
typedef Fixed<24, 8> Q24_8;
typedef Fixed<8, 8> Q8_8;

// abs, min and max are macros in Arduino.h, so these take the C library's
// floating-point names, which are functions there.
template <uint8_t I, uint8_t F>
inline Fixed<I, F> fabs(Fixed<I, F> x) {
  return x < Fixed<I, F>() ? -x : x;
}
template <uint8_t I, uint8_t F>
inline Fixed<I, F> fmin(Fixed<I, F> a, Fixed<I, F> b) {
  return b < a ? b : a;
}
template <uint8_t I, uint8_t F>
inline Fixed<I, F> fmax(Fixed<I, F> a, Fixed<I, F> b) {
  return a < b ? b : a;
}

template <uint8_t I, uint8_t F>
inline Fixed<I, F> clamp(Fixed<I, F> x, Fixed<I, F> lo, Fixed<I, F> hi) {
  return x < lo ? lo : (hi < x ? hi : x);
}

}  // namespace tinyparticle
