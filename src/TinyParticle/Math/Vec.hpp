// Vec<S, N>: a 2D or 3D vector over any scalar S (Fixed or Float).
// Vec2<S> has x and y; Vec3<S> adds z. dot() and cross() are free functions;
// cross of two Vec2 is the scalar z of the 3D cross product.
#pragma once

#include <stdint.h>

namespace tinyparticle {

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
  S magnitudeSquared() const { return x * x + y * y; }
  S magnitude() const { return sqrt(magnitudeSquared()); }
  bool isZero() const { return x == S() && y == S(); }

  // Scales this vector to unit length. A zero vector stays zero and the
  // call returns false; otherwise it returns true.
  bool normalize() {
    S length = magnitude();
    if (length == S()) return false;
    x = x / length;
    y = y / length;
    return true;
  }
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
  S magnitude() const { return sqrt(magnitudeSquared()); }
  bool isZero() const { return x == S() && y == S() && z == S(); }

  bool normalize() {
    S length = magnitude();
    if (length == S()) return false;
    x = x / length;
    y = y / length;
    z = z / length;
    return true;
  }
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

}  // namespace tinyparticle
