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
  Vec<S, Dim> low;
  Vec<S, Dim> high;
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
  // product, and one addition per particle to test it. (One function for
  // all axes, found from the normal, costs a compare per plane and step and
  // saves flash.)
  template <class W>
  static void generateAxis(W& world, typename W::ConstraintSlot& slot,
                           uint8_t source) {
    const PlaneConstraint& plane = InSlot::of<PlaneConstraint>(slot);
    uint8_t axis = 0;
    while (axis + 1 < Dim && plane.normal[axis] == S()) ++axis;
    const bool positive = plane.normal[axis] > S();
    touchAxis(world, axis, positive ? kLowWall : kHighWall, plane.offset,
              plane.offset, source);
  }

  // The 2 Dim walls of a box, each as its axis plane would be: the same
  // contacts in the same order (x low, x high, y low, ...), from the same
  // routine, in one pass over the particles per axis. (One pass for all
  // walls, each particle noting the walls it is near, then the contacts
  // wall by wall, took 190 B more flash for 3 % fewer cycles per step
  // with 16 balls in Q16.16, 5-10 % in float; a pass per wall took 160 B
  // less for 3 % more.)
  template <class W>
  static void generateBox(W& world, typename W::ConstraintSlot& slot,
                          uint8_t source) {
    const BoxParams<S, Dim>& box = InSlot::of<BoxParams<S, Dim> >(slot);
    for (uint8_t axis = 0; axis < Dim; ++axis) {
      // As axis planes' offsets: low, and minus high.
      touchAxis(world, axis, kLowWall | kHighWall, box.low[axis],
                -box.high[axis], source);
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

  // An axis plane, or one wall of a box, as touch() takes it (one
  // argument, not five: the call costs less): its normal (+e or -e, in the
  // contacts' stored form N), that axis's member, the offset, the
  // constraint slot, and the normal's sign.
  template <class N>
  struct Wall {
    N normal;
    S Vec<S, Dim>::*along;
    S offset;
    uint8_t source;
    bool positive;
  };

  // The walls of one axis that touchAxis() makes contacts for.
  static const uint8_t kLowWall = 1;   // x[axis] >= low: normal +e
  static const uint8_t kHighWall = 2;  // x[axis] <= high: normal -e

  // The contacts of the walls x[axis] >= low and x[axis] <= high, as
  // `walls` says, each given as an axis plane's offset (low, and minus
  // high); the low wall's first. With the normal +e: penetration =
  // low - (x - r), a contact from -margin on, i.e. while x - r <= low +
  // margin. With -e (offset = -high): penetration = offset + (x + r),
  // while x + r >= -(offset + margin). The scan only tests and notes the
  // particles within reach; their contacts are made after it, out of
  // line. With no call in it, the scan keeps its values in registers (a
  // call inside spilled the particle pointer: it cost twice as much).
  template <class W>
  static void touchAxis(W& world, uint8_t axis, uint8_t walls, S low,
                        S highOffset, uint8_t source) {
    typedef Vec<S, Dim> V;
    typedef typename W::ParticleType P;
    // The coordinate as a member pointer: one load at a fixed offset per
    // particle, where v[axis] would select the component every time.
    S V::*const along = detail::AxisMember<V>::of(axis);
    const S lowLimit = low + W::contactMargin();
    const S highLimit = -(highOffset + W::contactMargin());
    uint8_t nearLow[ParticleSlots<W>::value];
    uint8_t nearHigh[ParticleSlots<W>::value];
    uint8_t lowCount = 0, highCount = 0;
    const P* p = &WorldAccess::particle(world, 0);
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
      if (!isTarget(*p)) continue;
      const S at = p->position.*along;
      if ((walls & kLowWall) != 0 && !(at - p->radius > lowLimit)) {
        nearLow[lowCount++] = i;
      }
      if ((walls & kHighWall) != 0 && !(at + p->radius < highLimit)) {
        nearHigh[highCount++] = i;
      }
    }
    typedef typename W::ContactType::Normal N;
    Wall<N> wall;
    wall.along = along;
    wall.source = source;
    V unit;
    if (lowCount != 0) {
      unit.*along = S(1);
      wall.normal = detail::storedNormal(unit, static_cast<const N*>(nullptr));
      wall.offset = low;
      wall.positive = true;
      for (uint8_t k = 0; k < lowCount; ++k) touch(world, wall, nearLow[k]);
    }
    if (highCount != 0) {
      unit.*along = S(-1);
      wall.normal = detail::storedNormal(unit, static_cast<const N*>(nullptr));
      wall.offset = highOffset;
      wall.positive = false;
      for (uint8_t k = 0; k < highCount; ++k) touch(world, wall, nearHigh[k]);
    }
  }

  // Particle i within the margin of the wall (its offset: see
  // touchAxis(), the bound, or minus it for a negative normal). Its
  // penetration and separating velocity along the normal are that
  // coordinate of its position (less or plus its radius) and velocity, with
  // the normal's sign (exactly what the dot products give); the world
  // leaves out an idle contact (World::addStored()).
  template <class W>
  TINYPARTICLE_NOINLINE static void touch(
      W& world, const Wall<typename W::ContactType::Normal>& wall,
      uint8_t i) {
    S Vec<S, Dim>::*const along = wall.along;
    const typename W::ParticleType& p = WorldAccess::particle(world, i);
    // Along the normal: the coordinate and velocity, negated for -e (the
    // offset holds minus the bound), so that both walls take one formula:
    // penetration = offset - (x - r) for +e, offset + (x + r) for -e.
    S at = p.position.*along;
    S separating = p.velocity.*along;
    if (!wall.positive) {
      at = -at;
      separating = -separating;
    }
    WorldAccess::addStored(world, i, kNoIndex, wall.normal,
                           wall.offset - (at - p.radius), separating,
                           wall.source);
  }

  static bool isTarget(const detail::ParticleBase<S, Dim>& p) {
    typedef detail::ParticleBase<S, Dim> P;
    return (p.flags & (P::kInUse | P::kCollides | P::kStatic | P::kAsleep)) ==
           (P::kInUse | P::kCollides);
  }
};

}  // namespace tinyparticle
