// Contact: one violated (or touching) constraint found during a step, for the
// resolver. Contact generators write them into the world's contact pool.
//
// Two particles a and b (b = kNoIndex for scenery such as a plane or an
// anchor). The normal points from b towards a: the direction in which a is
// pushed. In a fixed-point world of 32-bit scalars the unit normal is kept
// in 16-bit components (CompactNormal below): 2D Q16.16 takes 15 bytes (17
// in 3D) instead of 19 (23); float keeps its float normal.
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "../Math/Fixed.hpp"
#include "../Math/Vec.hpp"

namespace tinyparticle {

namespace detail {

// Products with the components of a contact normal. The normals of axis
// planes (floors and walls, the most common contacts) have components 0 and
// +-1, which need no multiply: x * 0 = 0, x * 1 = x and x * -1 = -x exactly
// (saturation included), so for fixed point a few compares of the raw value
// spare a multiply (about 70 cycles on AVR) and give the same result. A zero
// x (no relative velocity, no acceleration across) is spared the same way.
// Float and any other scalar multiply: on AVR the tests cost about what
// they save over a normal in general position (a rod's, a collision's).
template <typename S>
struct NormalComponent {
  static S times(S x, S c) { return x * c; }
};

template <uint8_t I, uint8_t F>
struct NormalComponent<Fixed<I, F> > {
  typedef Fixed<I, F> T;
  // (Out of line: it is used in many places.)
  TINYPARTICLE_NOINLINE static T times(T x, T c) {
    const typename T::Raw raw = c.raw();
    if (raw == 0 || x.raw() == 0) return T();
    if (raw == T::kRawOne) return x;
    if (raw == -T::kRawOne) return -x;
    return x * c;
  }
};

// dot(v, normal), the components of the normal taken as above.
template <typename S>
inline S alongNormal(const Vec<S, 2>& v, const Vec<S, 2>& normal) {
  return NormalComponent<S>::times(v.x, normal.x) +
         NormalComponent<S>::times(v.y, normal.y);
}
template <typename S>
inline S alongNormal(const Vec<S, 3>& v, const Vec<S, 3>& normal) {
  return NormalComponent<S>::times(v.x, normal.x) +
         NormalComponent<S>::times(v.y, normal.y) +
         NormalComponent<S>::times(v.z, normal.z);
}

// dot(u + v, normal), without the vector u + v.
template <typename S>
inline S sumAlongNormal(const Vec<S, 2>& u, const Vec<S, 2>& v,
                        const Vec<S, 2>& normal) {
  return NormalComponent<S>::times(u.x + v.x, normal.x) +
         NormalComponent<S>::times(u.y + v.y, normal.y);
}
template <typename S>
inline S sumAlongNormal(const Vec<S, 3>& u, const Vec<S, 3>& v,
                        const Vec<S, 3>& normal) {
  return NormalComponent<S>::times(u.x + v.x, normal.x) +
         NormalComponent<S>::times(u.y + v.y, normal.y) +
         NormalComponent<S>::times(u.z + v.z, normal.z);
}

// velocity += normal * dv, move = normal * dx, position += move, likewise,
// component by component (a vector returned by value costs copies on AVR).
template <typename S>
inline void pushAlongNormal(Vec<S, 2>& velocity, Vec<S, 2>& position,
                            Vec<S, 2>& move, const Vec<S, 2>& normal, S dv,
                            S dx) {
  velocity.x += NormalComponent<S>::times(dv, normal.x);
  velocity.y += NormalComponent<S>::times(dv, normal.y);
  move.x = NormalComponent<S>::times(dx, normal.x);
  move.y = NormalComponent<S>::times(dx, normal.y);
  position.x += move.x;
  position.y += move.y;
}
template <typename S>
inline void pushAlongNormal(Vec<S, 3>& velocity, Vec<S, 3>& position,
                            Vec<S, 3>& move, const Vec<S, 3>& normal, S dv,
                            S dx) {
  velocity.x += NormalComponent<S>::times(dv, normal.x);
  velocity.y += NormalComponent<S>::times(dv, normal.y);
  velocity.z += NormalComponent<S>::times(dv, normal.z);
  move.x = NormalComponent<S>::times(dx, normal.x);
  move.y = NormalComponent<S>::times(dx, normal.y);
  move.z = NormalComponent<S>::times(dx, normal.z);
  position.x += move.x;
  position.y += move.y;
  position.z += move.z;
}

// A contact's unit normal in 16-bit components, for a 32-bit fixed-point
// scalar T: each component holds min(F, 14) fraction bits (Q1.14 for
// Q16.16; Q24.8's normal is kept exactly), so +-1 is exact (axis planes keep
// their fast path) and a component of a unit vector fits with room. A
// component is rounded to the nearest unit (ties away from zero, so no sign
// is favoured); truncation would shorten every normal a little and lose
// energy at each bounce. Error, for Q16.16: each component within 2^-15 of
// the Q16.16 one, so |n| within sqrt(Dim) 2^-15 < 2^-14 of the input's
// length. A component beyond 16 bits (outside (-2, 2) for Q16.16: not a
// unit normal) saturates.
template <typename T>
struct CompactComponent {
  typedef typename T::Raw Raw;
  typedef typename T::URaw URaw;
  static const uint8_t kFracBits = T::kFracBits < 14 ? T::kFracBits : 14;
  static const uint8_t kDropBits = T::kFracBits - kFracBits;
  static const int16_t kOne = int16_t(1) << kFracBits;
  // Decoding multiplies (a negative component is not shifted).
  static const Raw kScale = Raw(1) << kDropBits;
  static const URaw kHalf = kDropBits == 0 ? 0 : URaw(1) << (kDropBits - 1);

  static T decode(int16_t c) { return T::fromRaw(Raw(c) * kScale); }
  // Round to nearest on the magnitude, then the sign back: no shift of a
  // negative number, and the same error for n and -n. (Out of line: every
  // generator's contacts come through here.)
  TINYPARTICLE_NOINLINE static int16_t encode(T x) {
    const Raw raw = x.raw();
    const bool negative = raw < 0;
    // (In unsigned arithmetic: -kRawMin would overflow.)
    const URaw magnitude = negative ? URaw(0) - URaw(raw) : URaw(raw);
    URaw rounded = (magnitude + kHalf) >> kDropBits;
    if (rounded > URaw(INT16_MAX)) rounded = INT16_MAX;
    const int16_t m = int16_t(rounded);
    return negative ? int16_t(-m) : m;
  }
  // x * the component c, sparing the multiply for a component 0 or +1
  // (here with 16-bit compares). A -1 (a ceiling's, a right wall's: rarer
  // than the floor's +1) and a zero x are multiplied: exact too, and 52 B
  // less than a saturating negation and a test of x here. (Out of line: it
  // is used in many places.)
  TINYPARTICLE_NOINLINE static T times(T x, int16_t c) {
    if (c == 0) return T();
    if (c == kOne) return x;
    return x * decode(c);
  }
};

template <typename T, uint8_t Dim>
struct CompactNormal;

template <typename T>
struct CompactNormal<T, 2> {
  typedef CompactComponent<T> Component;
  int16_t x, y;
  constexpr CompactNormal() : x(0), y(0) {}
  CompactNormal& operator=(const Vec<T, 2>& unit) {
    x = Component::encode(unit.x);
    y = Component::encode(unit.y);
    return *this;
  }
  T operator[](uint8_t i) const {
    return Component::decode(i == 0 ? x : y);
  }
  Vec<T, 2> decoded() const {
    return Vec<T, 2>(Component::decode(x), Component::decode(y));
  }
  // The unit normal +e (positive) or -e along an axis, encoded directly.
  static CompactNormal alongAxis(uint8_t axis, bool positive) {
    CompactNormal n;
    (axis == 0 ? n.x : n.y) = positive ? Component::kOne : -Component::kOne;
    return n;
  }
};

template <typename T>
struct CompactNormal<T, 3> {
  typedef CompactComponent<T> Component;
  int16_t x, y, z;
  constexpr CompactNormal() : x(0), y(0), z(0) {}
  CompactNormal& operator=(const Vec<T, 3>& unit) {
    x = Component::encode(unit.x);
    y = Component::encode(unit.y);
    z = Component::encode(unit.z);
    return *this;
  }
  T operator[](uint8_t i) const {
    return Component::decode(i == 0 ? x : (i == 1 ? y : z));
  }
  Vec<T, 3> decoded() const {
    return Vec<T, 3>(Component::decode(x), Component::decode(y),
                     Component::decode(z));
  }
  static CompactNormal alongAxis(uint8_t axis, bool positive) {
    CompactNormal n;
    (axis == 0 ? n.x : (axis == 1 ? n.y : n.z)) =
        positive ? Component::kOne : -Component::kOne;
    return n;
  }
};

// How a contact of scalar S keeps its normal: a Vec, or a CompactNormal for
// a 32-bit fixed point (a 16-bit one gains nothing).
template <typename S, uint8_t Dim>
struct ContactNormalOf {
  typedef Vec<S, Dim> Type;
};
template <typename T, uint8_t Dim, bool Wide>
struct FixedContactNormal {
  typedef Vec<T, Dim> Type;
};
template <typename T, uint8_t Dim>
struct FixedContactNormal<T, Dim, true> {
  typedef CompactNormal<T, Dim> Type;
};
template <uint8_t I, uint8_t F, uint8_t Dim>
struct ContactNormalOf<Fixed<I, F>, Dim>
    : FixedContactNormal<Fixed<I, F>, Dim, I + F == 32> {};

// alongNormal(), sumAlongNormal() and pushAlongNormal() for a compact
// normal.
template <typename T>
inline T alongNormal(const Vec<T, 2>& v, const CompactNormal<T, 2>& normal) {
  typedef CompactComponent<T> C;
  return C::times(v.x, normal.x) + C::times(v.y, normal.y);
}
template <typename T>
inline T alongNormal(const Vec<T, 3>& v, const CompactNormal<T, 3>& normal) {
  typedef CompactComponent<T> C;
  return C::times(v.x, normal.x) + C::times(v.y, normal.y) +
         C::times(v.z, normal.z);
}
template <typename T>
inline T sumAlongNormal(const Vec<T, 2>& u, const Vec<T, 2>& v,
                        const CompactNormal<T, 2>& normal) {
  typedef CompactComponent<T> C;
  return C::times(u.x + v.x, normal.x) + C::times(u.y + v.y, normal.y);
}
template <typename T>
inline T sumAlongNormal(const Vec<T, 3>& u, const Vec<T, 3>& v,
                        const CompactNormal<T, 3>& normal) {
  typedef CompactComponent<T> C;
  return C::times(u.x + v.x, normal.x) + C::times(u.y + v.y, normal.y) +
         C::times(u.z + v.z, normal.z);
}
// (2D: a loop over the axes, each picked by member pointers: one copy of
// the products and adds, 18 B less than the two written out.)
template <typename T>
inline void pushAlongNormal(Vec<T, 2>& velocity, Vec<T, 2>& position,
                            Vec<T, 2>& move, const CompactNormal<T, 2>& normal,
                            T dv, T dx) {
  typedef CompactComponent<T> C;
  typedef Vec<T, 2> V;
  for (uint8_t k = 0; k < 2; ++k) {
    T V::*const axis = k == 0 ? &V::x : &V::y;
    const int16_t c = k == 0 ? normal.x : normal.y;
    velocity.*axis += C::times(dv, c);
    const T moved = C::times(dx, c);
    move.*axis = moved;
    position.*axis += moved;
  }
}
template <typename T>
inline void pushAlongNormal(Vec<T, 3>& velocity, Vec<T, 3>& position,
                            Vec<T, 3>& move, const CompactNormal<T, 3>& normal,
                            T dv, T dx) {
  typedef CompactComponent<T> C;
  velocity.x += C::times(dv, normal.x);
  velocity.y += C::times(dv, normal.y);
  velocity.z += C::times(dv, normal.z);
  move.x = C::times(dx, normal.x);
  move.y = C::times(dx, normal.y);
  move.z = C::times(dx, normal.z);
  position.x += move.x;
  position.y += move.y;
  position.z += move.z;
}

// A Vec normal in a contact's stored form (Contact::Normal: the second
// argument only picks it): the same Vec, or its compact form.
template <typename S, uint8_t Dim>
inline const Vec<S, Dim>& storedNormal(const Vec<S, Dim>& normal,
                                       const Vec<S, Dim>*) {
  return normal;
}
template <typename T, uint8_t Dim>
inline CompactNormal<T, Dim> storedNormal(const Vec<T, Dim>& normal,
                                          const CompactNormal<T, Dim>*) {
  CompactNormal<T, Dim> stored;
  stored = normal;
  return stored;
}

// The stored form of the unit normal +e or -e along an axis (an axis
// plane's): no encoding at run time.
template <typename S, uint8_t Dim>
inline Vec<S, Dim> axisNormal(uint8_t axis, bool positive,
                              const Vec<S, Dim>*) {
  Vec<S, Dim> unit;
  unit[axis] = positive ? S(1) : S(-1);
  return unit;
}
template <typename T, uint8_t Dim>
inline CompactNormal<T, Dim> axisNormal(uint8_t axis, bool positive,
                                        const CompactNormal<T, Dim>*) {
  return CompactNormal<T, Dim>::alongAxis(axis, positive);
}

}  // namespace detail

template <typename S, uint8_t Dim>
struct Contact {
  typedef typename detail::ContactNormalOf<S, Dim>::Type Normal;
  // Unit length, from b towards a: a Vec<S, Dim>, or its 16-bit form in a
  // 32-bit fixed-point world (detail::CompactNormal: assign a Vec, read
  // components with [] or the whole with decoded()).
  Normal normal;
  S penetration;           // > 0 while overlapping or stretched
  S separatingVelocity;    // dot(va - vb, normal), < 0 while closing
  uint8_t a;
  uint8_t b;
  uint8_t source;          // the constraint slot that made it (restitution)

  constexpr Contact()
      : normal(), penetration(), separatingVelocity(), a(0), b(0), source(0) {}
};

// What the last step did with contacts; World::stats() returns it.
struct StepStats {
  uint8_t contacts;    // contacts generated (at most the pool capacity)
  uint8_t dropped;     // contacts that did not fit (the least severe go)
  uint8_t iterations;  // resolver iterations used
  // The most contacts one step has asked for (kept + dropped, at most 255)
  // since the world was made or cleared: a contact pool at least this large
  // would have dropped none.
  uint8_t peakContacts;
  constexpr StepStats()
      : contacts(0), dropped(0), iterations(0), peakContacts(0) {}
};

}  // namespace tinyparticle
