// Test and benchmark support: a sketch's own generators against the
// built-in ones they copy (World::addForce against World::addDrag,
// World::addConstraint against World::addPlane), for any scalar.
//
// UserDrag and UserPlane are written as a sketch would write them, outside
// the library: the same operations in the same order as Forces/Drag.hpp and
// Contacts/Plane.hpp, run through the same runners (Core/Generator.hpp), so
// the worlds must agree bit for bit in fixed point and float alike. The
// GeneratorBenchmark times and sizes these same two classes.
// Not included by TinyParticle.h: include it after <TinyParticle.h>.
#pragma once

#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

// Drag k1 |v| + k2 |v|^2 against the velocity, as Forces/Drag.hpp.
template <class W>
struct UserDrag {
  typedef typename W::Scalar S;
  S k1, k2;

  void apply(typename W::ParticleType& p, S) {
    S speedSquared = p.velocity.magnitudeSquared();
    if (speedSquared == S()) return;
    S coefficient = k1;
    if (k2 != S()) coefficient += k2 * sqrt(speedSquared);
    p.acceleration.addScaled(p.velocity, -(coefficient * p.inverseMass));
  }
};

// A half-space dot(normal, x) - r >= offset, as Contacts/Plane.hpp.
template <class W>
struct UserPlane {
  typedef typename W::Scalar S;
  typename W::Vec normal;  // unit
  S offset;

  bool contact(const typename W::ParticleType& p, typename W::Vec& unit,
               S& penetration) {
    penetration = offset + p.radius - dot(normal, p.position);
    if (!(penetration >= -W::contactMargin())) return false;
    unit = normal;
    return true;
  }
};

// Same position and velocity, to the last bit.
template <class P>
bool sameMotion(const P& a, const P& b) {
  return a.position.x == b.position.x && a.position.y == b.position.y &&
         a.velocity.x == b.velocity.x && a.velocity.y == b.velocity.y;
}

// A ball of 0.05 m dropped from (0.1, 0.5) onto a floor tilted by 0.3 rad
// (normal (-sin, cos)), bouncing with restitution 0.5 and rolling down it,
// for 2 s at 1/256 s: the built-in plane (any normal) against the sketch's,
// added for every particle or (forOne) for the ball alone. Returns the
// first step at which the two worlds differ, 0 when none does; `touched`:
// the ball did reach the floor. W is 2D, with a constraint and a contact
// slot and gravity.
template <class W>
uint16_t tiltedPlaneAgainstBuiltIn(bool forOne, bool& touched) {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  W builtIn, user;
  const V start(0.1, 0.5);
  ParticleId a = builtIn.addParticle(start, S(1), S(0.05));
  ParticleId b = user.addParticle(start, S(1), S(0.05));
  builtIn.addGravity();
  user.addGravity();
  V normal(-0.29552, 0.95534);
  builtIn.addPlane(normal, S(0), S(0.5));
  normal.normalize();  // as addPlane() does
  UserPlane<W> plane = {normal, S(0)};
  const ConstraintId added = forOne ? user.addConstraint(plane, b, S(0.5))
                                    : user.addConstraint(plane, S(0.5));
  if (!added.isValid()) return 0xFFFF;
  touched = false;
  for (uint16_t n = 1; n <= 512; ++n) {
    builtIn.step(S(1.0 / 256));
    user.step(S(1.0 / 256));
    if (!sameMotion(*builtIn.particle(a), *user.particle(b))) return n;
    if (user.contactCount() > 0) touched = true;
  }
  return 0;
}

}  // namespace testing
}  // namespace tinyparticle
