// Contact: one violated (or touching) constraint found during a step, for the
// resolver. Contact generators write them into the world's contact pool.
//
// Two particles a and b (b = kNoIndex for scenery such as a plane or an
// anchor). The normal points from b towards a: the direction in which a is
// pushed. 2D Q16.16 takes 19 bytes (23 in 3D).
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

}  // namespace detail

template <typename S, uint8_t Dim>
struct Contact {
  Vec<S, Dim> normal;      // unit length, from b towards a
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
