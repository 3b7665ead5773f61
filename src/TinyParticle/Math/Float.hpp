// Float: a float with the same interface as Fixed, so that the engine is
// written once as a template over its scalar. It is a thin layer over the
// compiler's float (avr-libc's emulation on AVR).
//
// Differences from plain float, kept so that both scalars behave alike:
// - x / 0 returns max() or lowest() with x's sign (0 / 0 returns 0) and
//   raises MathError::kDivideByZero, instead of producing inf or NaN.
// - sqrt(x < 0) returns 0 and raises MathError::kNegativeSqrt.
// Other overflow follows IEEE 754 (inf) and raises nothing.
#pragma once

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "MathErrors.hpp"
#include "Turns.hpp"

// (As Fixed.hpp defines it; the same definition, whichever comes first.)
#ifndef TINYPARTICLE_ALWAYS_INLINE
#if defined(__GNUC__)
#define TINYPARTICLE_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define TINYPARTICLE_ALWAYS_INLINE inline
#endif
#endif

namespace tinyparticle {

class Float {
 public:
  constexpr Float() : mValue(0.0f) {}
  constexpr explicit Float(int v) : mValue(float(v)) {}
  constexpr explicit Float(long v) : mValue(float(v)) {}
  constexpr explicit Float(long long v) : mValue(float(v)) {}
  constexpr explicit Float(unsigned v) : mValue(float(v)) {}
  constexpr explicit Float(unsigned long v) : mValue(float(v)) {}
  constexpr explicit Float(unsigned long long v) : mValue(float(v)) {}
  constexpr explicit Float(double v) : mValue(float(v)) {}

  constexpr float toFloat() const { return mValue; }
  // Rounds toward zero; saturates outside int32_t's range; NaN gives 0.
  constexpr int32_t toInt() const {
    return mValue != mValue ? 0
         : mValue >= 2147483648.0f ? INT32_MAX
         : mValue <= -2147483648.0f ? INT32_MIN
         : int32_t(mValue);
  }

  // The largest finite value. (Not max(): Arduino.h defines max(a, b) as a
  // macro.)
  static constexpr Float largest() { return Float(FLT_MAX); }
  static constexpr Float lowest() { return Float(-FLT_MAX); }
  // The smallest positive normal float.
  static constexpr Float epsilon() { return Float(FLT_MIN); }
  static constexpr Float pi() { return Float(3.14159265358979323846); }

  Float operator+(Float b) const { return Float(mValue + b.mValue); }
  Float operator-(Float b) const { return Float(mValue - b.mValue); }
  Float operator*(Float b) const { return Float(mValue * b.mValue); }
  Float operator/(Float b) const {
    if (b.isZeroBits()) {
      detail::raiseMathError(MathError::kDivideByZero);
      return signedLargest();
    }
    return Float(mValue / b.mValue);
  }
  Float operator-() const { return Float(-mValue); }
  Float& operator+=(Float b) { return *this = *this + b; }
  Float& operator-=(Float b) { return *this = *this - b; }
  Float& operator*=(Float b) { return *this = *this * b; }
  Float& operator/=(Float b) { return *this = *this / b; }

  constexpr bool operator==(Float b) const { return mValue == b.mValue; }
  constexpr bool operator!=(Float b) const { return mValue != b.mValue; }
  constexpr bool operator<(Float b) const { return mValue < b.mValue; }
  constexpr bool operator<=(Float b) const { return mValue <= b.mValue; }
  constexpr bool operator>(Float b) const { return mValue > b.mValue; }
  constexpr bool operator>=(Float b) const { return mValue >= b.mValue; }

 private:
  // x == 0 (either sign) from the bits: a float compare is a library call
  // on AVR (about 50 cycles), this is a few.
  bool isZeroBits() const {
    uint32_t bits;
    memcpy(&bits, &mValue, sizeof(bits));
    return (bits & 0x7FFFFFFFul) == 0;
  }
  // x / 0: largest() with x's sign, 0 for 0 and NaN. From the bits, as
  // isZeroBits(): float compares here linked the library's compare
  // routines (about 90 bytes) into sketches that compare no float.
  // (Always inlined: else the link kept an unused copy, 62 bytes, where a
  // divide had been folded away.)
  TINYPARTICLE_ALWAYS_INLINE Float signedLargest() const {
    uint32_t bits;
    memcpy(&bits, &mValue, sizeof(bits));
    const uint32_t magnitude = bits & 0x7FFFFFFFul;
    if (magnitude == 0 || magnitude > 0x7F800000ul) return Float();
    return (bits & 0x80000000ul) != 0 ? lowest() : largest();
  }
  friend Float sqrt(Float x);

  float mValue;
};

inline Float fabs(Float x) { return Float(::fabsf(x.toFloat())); }
inline Float fmin(Float a, Float b) { return b < a ? b : a; }
inline Float fmax(Float a, Float b) { return a < b ? b : a; }
inline Float clamp(Float x, Float lo, Float hi) {
  return x < lo ? lo : (hi < x ? hi : x);
}

inline Float sqrt(Float x) {
  // x < 0 from the bits (see isZeroBits): the sign set, and neither a zero
  // nor a NaN.
  uint32_t bits;
  memcpy(&bits, &x.mValue, sizeof(bits));
  const uint32_t magnitude = bits & 0x7FFFFFFFul;
  if ((bits & 0x80000000ul) != 0 && magnitude != 0 &&
      magnitude <= 0x7F800000ul) {
    detail::raiseMathError(MathError::kNegativeSqrt);
    return Float();
  }
  return Float(::sqrtf(x.toFloat()));
}
// The angle of (x, y) in radians, in [-pi, pi]; atan2(0, 0) is 0.
inline Float atan2(Float y, Float x) {
  return Float(::atan2f(y.toFloat(), x.toFloat()));
}
inline Float sin(Float x) { return Float(::sinf(x.toFloat())); }
inline Float cos(Float x) { return Float(::cosf(x.toFloat())); }

// Binary angles (Turns.hpp): sinTurns<Float>(a), cosTurns<Float>(a).
namespace detail {
template <>
struct TurnsOf<Float> {
  // As a signed turn fraction, so that sinf reduces a small argument.
  static float angleOf(uint16_t turns) {
    int32_t s = turns < 32768u ? int32_t(turns) : int32_t(turns) - 65536;
    return float(s) * float(6.283185307179586 / 65536.0);
  }
  static Float sinTurns(uint16_t turns) { return Float(::sinf(angleOf(turns))); }
  static Float cosTurns(uint16_t turns) { return Float(::cosf(angleOf(turns))); }
};
}  // namespace detail

// The binary angle nearest to `radians`, wrapped into one turn.
// Non-finite input gives 0.
inline uint16_t radiansToTurns(Float angle) {
  float t = angle.toFloat() * float(65536.0 / 6.283185307179586);
  if (!(::fabsf(t) < 1.0e30f)) return 0;
  t -= 65536.0f * ::floorf(t * (1.0f / 65536.0f));  // now in [0, 65536]
  return uint16_t(uint32_t(t + 0.5f) & 0xffffu);
}

}  // namespace tinyparticle
