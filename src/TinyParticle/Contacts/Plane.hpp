// Half-space planes (floors and walls): every colliding particle must keep
// dot(normal, position) - radius >= offset. A plane is a contact generator
// over all particles, so its cost grows with the particle count: a plane
// whose normal is along an axis takes the fast path, which reads one
// coordinate instead of taking a dot product, and a box's two walls along
// an axis share one pass (generateBox()).
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
#include "Resolver.hpp"

namespace tinyparticle {

// A box's walls (World::addBox): low <= x <= high, in one constraint slot
// (PlaneConstraint::generateBox()). A generator class of its own, so that
// the slot's kind tells a box from a plane.
template <typename S, uint8_t Dim>
struct BoxParams {
  static const uint8_t kShape = SlotShape::kNone;
  // The walls' offsets as axis planes' (low, and minus high, for x, then
  // y...), worked out once by World::addBox(): the step reads one per wall.
  S offsets[2 * Dim];
};

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
  bool contact(const detail::ParticleBase<S, Dim>& p, Vec<S, Dim>& unit,
               S& penetration) const {
    penetration = offset + p.radius - dot(normal, p.position);
    if (!(penetration >= -ScalarTraits<S>::depthMargin())) return false;
    unit = normal;
    return true;
  }

  // A normal of +1 or -1 along one axis: one coordinate instead of a dot
  // product per particle. (One function for all axes, found from the
  // normal, costs a compare per plane and step and saves flash.)
  template <class W>
  static void generateAxis(W& world, typename W::ConstraintSlot& slot,
                           uint8_t source) {
    const PlaneConstraint& plane = InSlot::of<PlaneConstraint>(slot);
    uint8_t axis = 0;
    while (axis + 1 < Dim && plane.normal[axis] == S()) ++axis;
    touchWall(world, axis, plane.normal[axis] > S(), plane.offset, source);
  }

  // The 2 Dim walls of a box, each as its axis plane would be: the same
  // contacts in the same order (x low, x high, y low, ...), from the same
  // routine, one pass over the particles per wall. (One pass per axis,
  // noting the particles near either wall in two lists, took about 250 B
  // more flash for 5 % fewer cycles per step in the elastic box in Q16.16,
  // 1 % in float.)
  template <class W>
  static void generateBox(W& world, typename W::ConstraintSlot& slot,
                          uint8_t source) {
    const BoxParams<S, Dim>& box = InSlot::of<BoxParams<S, Dim> >(slot);
    for (uint8_t wall = 0; wall < 2 * Dim; ++wall) {
      touchWall(world, uint8_t(wall >> 1), (wall & 1) == 0,
                box.offsets[wall], source);
    }
  }

 private:
  // The particles' count as an array size, at least one entry: ISO C++ has
  // no zero-size arrays.
  template <class W>
  struct ParticleSlots {
    static const uint8_t value =
        W::kParticleCapacity > 0 ? W::kParticleCapacity : 1;
  };

  // The contacts of the axis plane x[axis] >= offset (positive: normal +e)
  // or -x[axis] >= offset (normal -e; offset is minus the bound). A first
  // pass only tests the colliding particles that are neither immovable nor
  // asleep, one subtraction each, and lists those within
  // World::contactMargin() of the plane: x - r <= offset + margin, or
  // -x - r <= offset + margin. (With no call in it, the scan keeps its
  // values in registers: making each contact inside it took 158 B less
  // flash, 9 % more cycles per step for the elastic box in Q16.16 and 15 %
  // for two float balls, over the 3 % that issue 12 allows.) Then each
  // listed particle's penetration and separating velocity along the
  // normal are that coordinate of its position (less its radius) and of
  // its velocity, with the normal's sign (exactly what the dot products
  // give): penetration = offset - (x - r) for +e, offset - (-x - r) for
  // -e; the world leaves out an idle contact (World::addStored()). (Out of
  // line: one copy for every wall.)
  template <class W>
  TINYPARTICLE_NOINLINE static void touchWall(W& world, uint8_t axis,
                                              bool positive, S offset,
                                              uint8_t source) {
    typedef Vec<S, Dim> V;
    typedef typename W::ParticleType P;
    typedef typename W::ContactType::Normal N;
    // The coordinate as a member pointer: one load at a fixed offset per
    // particle, where v[axis] would select the component every time.
    S V::*const along = detail::AxisMember<V>::of(axis);
    const S limit = offset + W::contactMargin();
    uint8_t near[ParticleSlots<W>::value];
    uint8_t count = 0;
    const P* p = &WorldAccess::particle(world, 0);
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
      if (!isTarget(*p)) continue;
      S at = p->position.*along;
      if (!positive) at = -at;
      if (!(at - p->radius > limit)) near[count++] = i;
    }
    if (count == 0) return;
    const N normal =
        detail::axisNormal(axis, positive, static_cast<const N*>(nullptr));
    for (uint8_t k = 0; k < count; ++k) {
      const P& q = WorldAccess::particle(world, near[k]);
      S at = q.position.*along;
      S separating = q.velocity.*along;
      if (!positive) {
        at = -at;
        separating = -separating;
      }
      WorldAccess::addStored(world, near[k], kNoIndex, normal,
                             offset - (at - q.radius), separating, source);
    }
  }

  static bool isTarget(const detail::ParticleBase<S, Dim>& p) {
    typedef detail::ParticleBase<S, Dim> P;
    return (p.flags & (P::kInUse | P::kCollides | P::kStatic | P::kAsleep)) ==
           (P::kInUse | P::kCollides);
  }
};

}  // namespace tinyparticle
