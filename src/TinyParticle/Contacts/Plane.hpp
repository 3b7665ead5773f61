// Half-space planes (floors and walls): every colliding particle must keep
// dot(normal, position) - radius >= offset. A plane is a contact generator
// over all particles, so its cost grows with the particle count: a plane
// whose normal is along an axis takes the fast path, which reads one
// coordinate instead of taking a dot product.
//
// A particle touching the plane, or within World::contactMargin() of it,
// makes a contact too: in fixed point a slow particle may not move in a
// step (v dt rounds to 0), and it must still lose the closing velocity that
// gravity gives it, or it would gather speed over several steps and hop.
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "../Math/Vec.hpp"
#include "../Core/Generator.hpp"
#include "../Core/Particle.hpp"
#include "../Math/ScalarTraits.hpp"
#include "../Core/Access.hpp"

namespace tinyparticle {

namespace detail {

// The member of a vector that holds coordinate `axis`.
template <class V>
struct AxisMember;
template <typename S>
struct AxisMember<Vec<S, 2> > {
  typedef Vec<S, 2> V;
  static S V::*of(uint8_t axis) { return axis == 0 ? &V::x : &V::y; }
};
template <typename S>
struct AxisMember<Vec<S, 3> > {
  typedef Vec<S, 3> V;
  static S V::*of(uint8_t axis) {
    return axis == 0 ? &V::x : (axis == 1 ? &V::y : &V::z);
  }
};

}  // namespace detail

// A generator class (Core/Generator.hpp). A plane of any normal is run by
// the ContactRunner, as a sketch's contact generator would be; a plane
// along an axis by generateAxis(), its fast path.
template <typename S, uint8_t Dim>
struct PlaneConstraint {
  static const uint8_t kShape = SlotShape::kNone;
  Vec<S, Dim> normal;  // unit length, pointing into the allowed side
  S offset;            // m: the plane is dot(normal, x) = offset

  // The plane dot(unit, x) = offset; unit must be of length 1.
  static PlaneConstraint make(const Vec<S, Dim>& unit, S offset) {
    PlaneConstraint plane;
    plane.normal = unit;
    plane.offset = offset;
    return plane;
  }
  // The plane x[axis] >= offset (positive) or x[axis] <= offset (negative).
  static PlaneConstraint alongAxis(uint8_t axis, bool positive, S offset) {
    PlaneConstraint plane;
    plane.normal[axis] = positive ? S(1) : S(-1);
    plane.offset = positive ? offset : -offset;
    return plane;
  }

  // Any normal: a contact from within the contact margin on.
  bool contact(const Particle<S, Dim>& p, Vec<S, Dim>& unit,
               S& penetration) const {
    penetration = offset + p.radius - dot(normal, p.position);
    if (!(penetration >= -ScalarTraits<S>::depthMargin())) return false;
    unit = normal;
    return true;
  }

  // A normal of +1 or -1 along one axis: one coordinate instead of a dot
  // product, and one addition per particle to test it. (One function for
  // all axes, found from the normal, costs a compare per plane and step and
  // saves flash. Tried: one pass over the particles for a whole box; it was
  // no faster on AVR, the walls' data no longer fit in registers.)
  template <class W>
  static void generateAxis(W& world, typename W::ConstraintSlot& slot,
                           uint8_t source) {
    typedef Vec<S, Dim> V;
    typedef Particle<S, Dim> P;
    const PlaneConstraint& plane = InSlot::of<PlaneConstraint>(slot);
    const V& normal = plane.normal;
    const S offset = plane.offset;
    uint8_t axis = 0;
    while (axis + 1 < Dim && normal[axis] == S()) ++axis;
    const bool positive = normal[axis] > S();
    // The coordinate as a member pointer: one load at a fixed offset per
    // particle, where v[axis] would select the component every time.
    S V::*const along = detail::AxisMember<V>::of(axis);
    // With the normal +e: penetration = offset - (x - r), a contact from
    // -margin on, i.e. while x - r <= offset + margin. With -e (offset holds
    // minus the bound): penetration = offset + (x + r), while
    // x + r >= -(offset + margin). The loops only test; the rare contact is
    // made out of line, so that the loops keep their values in registers.
    const S limit = offset + W::contactMargin();
    P* p = &WorldAccess::particle(world, 0);
    if (positive) {
      for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
        if (!isTarget(*p)) continue;
        const S side = p->position.*along - p->radius;
        if (!(side > limit)) {
          touch(world, normal, along, true, i, offset - side, source);
        }
      }
    } else {
      const S negativeLimit = -limit;
      for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
        if (!isTarget(*p)) continue;
        const S side = p->position.*along + p->radius;
        if (!(side < negativeLimit)) {
          touch(world, normal, along, false, i, offset + side, source);
        }
      }
    }
  }

 private:
  // A particle within the margin of an axis plane: the separating velocity
  // and the acceleration along the normal are that coordinate of the
  // velocity and of the acceleration, with the normal's sign (exactly what
  // the dot products give); the sign does not matter for the acceleration,
  // only whether it is zero (WorldAccess::isIdle<W>()).
  template <class W>
  TINYPARTICLE_NOINLINE static void touch(W& world, const Vec<S, Dim>& normal,
                                          S Vec<S, Dim>::*along,
                                          bool positive, uint8_t i,
                                          S penetration, uint8_t source) {
    const Particle<S, Dim>& p = WorldAccess::particle(world, i);
    const S velocity = p.velocity.*along;
    const S separating = positive ? velocity : -velocity;
    const S acceleration =
        p.acceleration.*along + WorldAccess::uniformComponent(world, along);
    if (WorldAccess::isIdle<W>(penetration, separating, acceleration, S())) return;
    WorldAccess::recordContact(world, i, kNoIndex, normal, penetration,
                               separating, source);
  }

  static bool isTarget(const Particle<S, Dim>& p) {
    typedef Particle<S, Dim> P;
    return (p.flags & (P::kInUse | P::kCollides | P::kStatic | P::kAsleep)) ==
           (P::kInUse | P::kCollides);
  }
};

}  // namespace tinyparticle
