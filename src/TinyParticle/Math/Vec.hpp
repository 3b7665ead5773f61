// Vec<S, N>: a 2D or 3D vector over any scalar S (Fixed or Float).
// Vec2<S> has x and y; Vec3<S> adds z. dot() and cross() are free functions;
// cross of two Vec2 is the scalar z of the 3D cross product.
//
// magnitude() and normalize() go through detail::VecMath<S>: the plain
// formulas for Float and other scalars, and for Fixed a version that scales
// the vector by a power of two first, so that
// - the squared sum never overflows, however long the vector (a magnitude
//   that does not fit saturates and raises MathError::kOverflow);
// - short vectors keep their precision: any nonzero vector, down to one
//   step of the format, normalizes to unit length within a few steps;
// - no MathError is raised by the intermediate steps.
#pragma once

#include <stdint.h>

#include "Fixed.hpp"
#include "FixedMath.hpp"

namespace tinyparticle {

namespace detail {

// The plain formulas: for Float, and any scalar with sqrt() and a division.
template <typename S>
struct VecMath {
  static S magnitude(S x, S y) { return sqrt(x * x + y * y); }
  static S magnitude(S x, S y, S z) { return sqrt(x * x + y * y + z * z); }
  static S normalize(S& x, S& y, bool = true) {
    S length = magnitude(x, y);
    if (length == S()) return rescued2(x, y);
    x = x / length;
    y = y / length;
    return length;
  }
  static S normalize(S& x, S& y, S& z, bool = true) {
    S length = magnitude(x, y, z);
    if (length == S()) return rescued(x, y, z);
    x = x / length;
    y = y / length;
    z = z / length;
    return length;
  }

 private:
  // A nonzero vector whose squares all underflowed to zero (floats below
  // about 1e-19): normalize a copy scaled by 2^64; its length is then too
  // small to tell from 0, which is what is returned.
  static S rescued(S& x, S& y, S& z) {
    const S zero = S();
    if (x == zero && y == zero && z == zero) return zero;
    const S scale(18446744073709551616.0);
    S sx = x * scale, sy = y * scale, sz = z * scale;
    S length = magnitude(sx, sy, sz);
    if (length == zero) return zero;  // the scalar has no such range
    x = sx / length;
    y = sy / length;
    z = sz / length;
    return zero;
  }
  static S rescued2(S& x, S& y) {
    S z = S();
    return rescued(x, y, z);
  }
};

// Fixed: scale the components by a power of two first. The largest
// magnitude m is brought up to at least 2^F (the length is then at least 1,
// so its relative error is a few 2^-F) and down below 2^W,
// W = (bits + F - 3) / 2, where a sum of three squares cannot overflow
// (Q16_16: m < 2^22, i.e. |x| < 64). A vector already in [2^F, 2^W) is used
// as it is; shorter ones are shifted up just enough, longer ones down.
template <uint8_t I, uint8_t F>
struct VecMath<Fixed<I, F> > {
  typedef Fixed<I, F> T;
  typedef typename T::Raw Raw;
  typedef typename T::URaw URaw;
  static const uint8_t kTop = (I + F + F - 3) / 2;  // W

  static T magnitude(T x, T y) {
    T c[2] = {x, y};
    return magnitudeOf(c);
  }
  static T magnitude(T x, T y, T z) {
    T c[3] = {x, y, z};
    return magnitudeOf(c);
  }
  // Returns the length the vector had when `wantLength`, else 0: the
  // length of a unit-normalizable vector may not fit (and would raise
  // kOverflow), the unit vector always does.
  static T normalize(T& x, T& y, bool wantLength = true) {
    T c[2] = {x, y};
    T length = normalizeIn(c, wantLength);
    x = c[0];
    y = c[1];
    return length;
  }
  static T normalize(T& x, T& y, T& z, bool wantLength = true) {
    T c[3] = {x, y, z};
    T length = normalizeIn(c, wantLength);
    x = c[0];
    y = c[1];
    z = c[2];
    return length;
  }

 private:
  template <uint8_t N>
  static T magnitudeOf(T (&c)[N]) {
    const int8_t shift = shiftFor(c);
    if (shift == 0) return lengthOf(c);
    if (shift == kZero) return T();
    for (uint8_t i = 0; i < N; ++i) c[i] = scaled(c[i], shift);
    return unscaled(lengthOf(c), shift);
  }

  template <uint8_t N>
  static T normalizeIn(T (&c)[N], bool wantLength) {
    const int8_t shift = shiftFor(c);
    if (shift == kZero) return T();
    if (shift != 0) {
      for (uint8_t i = 0; i < N; ++i) c[i] = scaled(c[i], shift);
    }
    const T length = lengthOf(c);  // >= 1 here
    for (uint8_t i = 0; i < N; ++i) {
      if (c[i] != T()) c[i] = c[i] / length;
    }
    if (!wantLength) return T();
    return shift == 0 ? length : unscaled(length, shift);
  }

  static const int8_t kZero = -128;  // shiftFor's answer for a zero vector

  // 0 when the largest magnitude m is in [2^F, 2^W); else the shift that
  // brings it there: > 0 to the left, < 0 to the right; kZero for m == 0.
  template <uint8_t N>
  static int8_t shiftFor(const T (&c)[N]) {
    URaw m = 0;
    for (uint8_t i = 0; i < N; ++i) {
      const URaw mi = T::magnitude(c[i].raw());
      if (mi > m) m = mi;
    }
    if (m == 0) return kZero;
    const URaw top = URaw(URaw(1) << kTop);
    const URaw one = URaw(URaw(1) << F);
    int8_t shift = 0;
    while (m >= top) {
      m = URaw(m >> 1);
      --shift;
    }
    while (m < one) {
      m = URaw(m << 1);
      ++shift;
    }
    return shift;
  }

  // x * 2^shift; a right shift rounds (ties away from zero). Never
  // overflows: the largest component lands below 2^W.
  static T scaled(T x, int8_t shift) {
    const bool negative = x.raw() < 0;
    URaw m = T::magnitude(x.raw());
    if (shift > 0) {
      m = URaw(m << shift);
    } else {
      const uint8_t right = uint8_t(-shift);
      m = URaw((m >> right) + ((m >> (right - 1)) & 1u));
    }
    return T::fromRaw(negative ? T::toSigned(URaw(URaw(0) - m)) : Raw(m));
  }

  // length * 2^-shift, rounded or saturated.
  static T unscaled(T length, int8_t shift) {
    URaw m = URaw(length.raw());  // >= 0
    if (shift > 0) {
      const uint8_t right = uint8_t(shift);
      m = URaw((m >> right) + ((m >> (right - 1)) & 1u));
      return T::fromRaw(Raw(m));
    }
    const uint8_t left = uint8_t(-shift);
    if (m > (URaw(T::kRawMax) >> left)) {
      return T::fromRaw(T::overflow(false));
    }
    return T::fromRaw(Raw(m << left));
  }

  // The square root of the sum of squares of components below 2^W:
  // nothing overflows.
  static T lengthOf(const T (&c)[2]) { return sqrt(c[0] * c[0] + c[1] * c[1]); }
  static T lengthOf(const T (&c)[3]) {
    return sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  }
};

}  // namespace detail

template <typename S, uint8_t N>
struct Vec;

template <typename S>
struct Vec<S, 2> {
  static const uint8_t kDimensions = 2;
  S x, y;

  constexpr Vec() : x(), y() {}
  constexpr Vec(S x_, S y_) : x(x_), y(y_) {}
  // From numbers, e.g. Vec2<Q16_16>(0.15, 0): folded at compile time.
  constexpr Vec(double x_, double y_) : x(x_), y(y_) {}

  S& operator[](uint8_t i) { return i == 0 ? x : y; }
  constexpr S operator[](uint8_t i) const { return i == 0 ? x : y; }

  Vec operator+(const Vec& b) const { return Vec(x + b.x, y + b.y); }
  Vec operator-(const Vec& b) const { return Vec(x - b.x, y - b.y); }
  Vec operator-() const { return Vec(-x, -y); }
  Vec operator*(S s) const { return Vec(x * s, y * s); }
  Vec& operator+=(const Vec& b) { x += b.x; y += b.y; return *this; }
  Vec& operator-=(const Vec& b) { x -= b.x; y -= b.y; return *this; }
  Vec& operator*=(S s) { x *= s; y *= s; return *this; }
  bool operator==(const Vec& b) const { return x == b.x && y == b.y; }
  bool operator!=(const Vec& b) const { return !(*this == b); }

  // this += v * s
  void addScaled(const Vec& v, S s) { x += v.x * s; y += v.y * s; }
  Vec componentProduct(const Vec& b) const { return Vec(x * b.x, y * b.y); }
  // x^2 + y^2 with the scalar's own saturation: for a fixed-point vector
  // longer than sqrt(max()) it saturates (and raises kOverflow); use it to
  // compare lengths of short vectors, magnitude() otherwise.
  S magnitudeSquared() const { return x * x + y * y; }
  S magnitude() const { return detail::VecMath<S>::magnitude(x, y); }
  bool isZero() const { return x == S() && y == S(); }

  // Scales this vector to unit length. A zero vector stays zero and the
  // call returns false; otherwise it returns true.
  bool normalize() {
    if (isZero()) return false;
    detail::VecMath<S>::normalize(x, y, false);
    return true;
  }

  // normalize() that also returns the length the vector had (0 for a zero
  // vector, which stays zero): one square root for both. A length that
  // does not fit saturates and raises kOverflow; the vector is still
  // normalized.
  S magnitudeAndNormalize() { return detail::VecMath<S>::normalize(x, y); }
};

template <typename S>
struct Vec<S, 3> {
  static const uint8_t kDimensions = 3;
  S x, y, z;

  constexpr Vec() : x(), y(), z() {}
  constexpr Vec(S x_, S y_, S z_) : x(x_), y(y_), z(z_) {}
  constexpr Vec(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

  S& operator[](uint8_t i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr S operator[](uint8_t i) const {
    return i == 0 ? x : (i == 1 ? y : z);
  }

  Vec operator+(const Vec& b) const { return Vec(x + b.x, y + b.y, z + b.z); }
  Vec operator-(const Vec& b) const { return Vec(x - b.x, y - b.y, z - b.z); }
  Vec operator-() const { return Vec(-x, -y, -z); }
  Vec operator*(S s) const { return Vec(x * s, y * s, z * s); }
  Vec& operator+=(const Vec& b) { x += b.x; y += b.y; z += b.z; return *this; }
  Vec& operator-=(const Vec& b) { x -= b.x; y -= b.y; z -= b.z; return *this; }
  Vec& operator*=(S s) { x *= s; y *= s; z *= s; return *this; }
  bool operator==(const Vec& b) const {
    return x == b.x && y == b.y && z == b.z;
  }
  bool operator!=(const Vec& b) const { return !(*this == b); }

  void addScaled(const Vec& v, S s) {
    x += v.x * s;
    y += v.y * s;
    z += v.z * s;
  }
  Vec componentProduct(const Vec& b) const {
    return Vec(x * b.x, y * b.y, z * b.z);
  }
  S magnitudeSquared() const { return x * x + y * y + z * z; }
  S magnitude() const { return detail::VecMath<S>::magnitude(x, y, z); }
  bool isZero() const { return x == S() && y == S() && z == S(); }

  bool normalize() {
    if (isZero()) return false;
    detail::VecMath<S>::normalize(x, y, z, false);
    return true;
  }
  S magnitudeAndNormalize() { return detail::VecMath<S>::normalize(x, y, z); }
};

template <typename S>
using Vec2 = Vec<S, 2>;
template <typename S>
using Vec3 = Vec<S, 3>;

template <typename S, uint8_t N>
inline Vec<S, N> operator*(S s, const Vec<S, N>& v) {
  return v * s;
}

template <typename S>
inline S dot(const Vec<S, 2>& a, const Vec<S, 2>& b) {
  return a.x * b.x + a.y * b.y;
}
template <typename S>
inline S dot(const Vec<S, 3>& a, const Vec<S, 3>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <typename S>
inline S cross(const Vec<S, 2>& a, const Vec<S, 2>& b) {
  return a.x * b.y - a.y * b.x;
}
template <typename S>
inline Vec<S, 3> cross(const Vec<S, 3>& a, const Vec<S, 3>& b) {
  return Vec<S, 3>(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                   a.x * b.y - a.y * b.x);
}

namespace detail {

// Out-of-line vector kernels, for code that runs once per rod and step (the
// rods' solves). On AVR an inlined product of two fixed-point or float
// scalars costs 20 to 28 bytes of argument moves and a call; a kernel
// called through two pointers replaces two or three of them by one call,
// for some cycles more (removeAlong() in the lever's velocity solve: 116 B
// less, 148 cycles a step more). The hot loops elsewhere keep the inlined
// operators.
template <typename S, uint8_t N>
TINYPARTICLE_NOINLINE S dotOutOfLine(const Vec<S, N>& a, const Vec<S, N>& b) {
  return dot(a, b);
}
// v -= u (v . u): v without its part along the unit vector u.
template <typename S, uint8_t N>
TINYPARTICLE_NOINLINE void removeAlong(Vec<S, N>& v, const Vec<S, N>& u) {
  v.addScaled(u, -dotOutOfLine(v, u));
}

// Room for a value that a call writes whole before anything reads it
// (a noinline routine's out-argument): Vec's constructor zeroes it, 16 B
// of stores per 2D vector that the optimizer cannot drop across the call.
// `value` is written (by plain, trivial assignment) before it is read.
template <typename T>
union Unset {
  Unset() {}
  T value;
};

}  // namespace detail

}  // namespace tinyparticle
