// Double: a host-only scalar with the library's scalar interface
// (extras/doc/design.md), over a plain double. The scene benchmark runs the
// very same engine templates with it on the PC, and takes that run as the
// reference the Nano's Q16.16, Q24.8 and float runs are compared with.
//
// Not for sketches: it is never built for the Nano (double is float there).
// Division by zero and sqrt of a negative number raise the same MathError
// bits as the other scalars and return the same defined values.
#pragma once

#include <float.h>
#include <math.h>
#include <stdint.h>

#include <TinyParticle.hpp>

namespace tinyparticle {

class Double {
 public:
  constexpr Double() : mValue(0.0) {}
  constexpr explicit Double(int v) : mValue(v) {}
  constexpr explicit Double(long v) : mValue(double(v)) {}
  constexpr explicit Double(long long v) : mValue(double(v)) {}
  constexpr explicit Double(unsigned v) : mValue(v) {}
  constexpr explicit Double(unsigned long v) : mValue(double(v)) {}
  constexpr explicit Double(double v) : mValue(v) {}

  // Named toFloat() like the other scalars; here it keeps full precision.
  constexpr double toFloat() const { return mValue; }
  constexpr double toDouble() const { return mValue; }
  // Rounds toward zero; saturates outside int32_t's range; NaN gives 0.
  constexpr int32_t toInt() const {
    return mValue != mValue ? 0
         : mValue >= 2147483648.0 ? INT32_MAX
         : mValue <= -2147483648.0 ? INT32_MIN
         : int32_t(mValue);
  }

  static constexpr Double largest() { return Double(DBL_MAX); }
  static constexpr Double lowest() { return Double(-DBL_MAX); }
  static constexpr Double epsilon() { return Double(DBL_MIN); }
  static constexpr Double pi() { return Double(3.14159265358979323846); }

  Double operator+(Double b) const { return Double(mValue + b.mValue); }
  Double operator-(Double b) const { return Double(mValue - b.mValue); }
  Double operator*(Double b) const { return Double(mValue * b.mValue); }
  Double operator/(Double b) const {
    if (b.mValue == 0.0) {
      detail::raiseMathError(MathError::kDivideByZero);
      return mValue > 0.0 ? largest() : (mValue < 0.0 ? lowest() : Double());
    }
    return Double(mValue / b.mValue);
  }
  Double operator-() const { return Double(-mValue); }
  Double& operator+=(Double b) { return *this = *this + b; }
  Double& operator-=(Double b) { return *this = *this - b; }
  Double& operator*=(Double b) { return *this = *this * b; }
  Double& operator/=(Double b) { return *this = *this / b; }

  constexpr bool operator==(Double b) const { return mValue == b.mValue; }
  constexpr bool operator!=(Double b) const { return mValue != b.mValue; }
  constexpr bool operator<(Double b) const { return mValue < b.mValue; }
  constexpr bool operator<=(Double b) const { return mValue <= b.mValue; }
  constexpr bool operator>(Double b) const { return mValue > b.mValue; }
  constexpr bool operator>=(Double b) const { return mValue >= b.mValue; }

 private:
  double mValue;
};

// A scalar for World (Math/ScalarTraits.hpp): its margins computed.
template <>
struct ScalarTraits<Double> : ComputedScalarTraits<Double> {};

inline Double fabs(Double x) { return Double(::fabs(x.toDouble())); }
inline Double fmin(Double a, Double b) { return b < a ? b : a; }
inline Double fmax(Double a, Double b) { return a < b ? b : a; }
inline Double clamp(Double x, Double lo, Double hi) {
  return x < lo ? lo : (hi < x ? hi : x);
}
inline Double sqrt(Double x) {
  if (x < Double()) {
    detail::raiseMathError(MathError::kNegativeSqrt);
    return Double();
  }
  return Double(::sqrt(x.toDouble()));
}
inline Double atan2(Double y, Double x) {
  return Double(::atan2(y.toDouble(), x.toDouble()));
}
inline Double sin(Double x) { return Double(::sin(x.toDouble())); }
inline Double cos(Double x) { return Double(::cos(x.toDouble())); }

}  // namespace tinyparticle
