// Half-space planes (floors and walls): every colliding particle must keep
// dot(normal, position) - radius >= offset. A plane is a contact generator
// over all particles, so its cost grows with the particle count: a plane
// whose normal is along an axis takes the fast path, which reads one
// coordinate instead of taking a dot product, and a box's walls share one
// pass (generateBox()).
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
  // saves flash.)
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
    // x + r >= -(offset + margin). The scan only tests and notes the
    // particles within reach; their contacts are made after it, out of
    // line. With no call in it, the scan keeps its values in registers (a
    // call inside spilled the particle pointer: it cost twice as much).
    const S limit = offset + W::contactMargin();
    const S negativeLimit = -limit;
    uint8_t near[ParticleSlots<W>::value];
    uint8_t count = 0;
    const P* p = &WorldAccess::particle(world, 0);
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
      if (!isTarget(*p)) continue;
      const S at = p->position.*along;
      if (positive ? !(at - p->radius > limit)
                   : !(at + p->radius < negativeLimit)) {
        near[count++] = i;
      }
    }
    const Wall wall = {normal, along, offset, source, positive};
    for (uint8_t k = 0; k < count; ++k) touch(world, wall, near[k]);
  }

  // The 2 Dim walls of a box in one pass over the particles: each one's
  // coordinates and radius are read once for all walls (four planes cost
  // four passes). The pass only tests and notes which walls each particle
  // is within reach of; the contacts are made after it, wall by wall in
  // the order of separate axis planes (x low, x high, y low, ...), so that
  // a box makes the same contacts in the same order as its planes would.
  template <class W>
  static void generateBox(W& world, typename W::ConstraintSlot& slot,
                          uint8_t source) {
    typedef Vec<S, Dim> V;
    typedef Particle<S, Dim> P;
    const BoxParams<S, Dim>& box = InSlot::of<BoxParams<S, Dim> >(slot);
    const S margin = W::contactMargin();
    uint8_t near[ParticleSlots<W>::value];
    // walls: bit 2k for the low wall of axis k, 2k + 1 for its high wall.
    uint8_t walls[ParticleSlots<W>::value];
    uint8_t count = 0, touched = 0;
    // The limits for the centre of a particle of radius r: within reach
    // while x - r <= low + margin, i.e. x <= (low + margin) + r, and so
    // on; worked out again only when the radius changes (in most scenes
    // every particle has the same one).
    V low, high;
    bool first = true;
    S radius = S();
    const P* p = &WorldAccess::particle(world, 0);
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
      if (!isTarget(*p)) continue;
      if (first || !(p->radius == radius)) {
        first = false;
        radius = p->radius;
        for (uint8_t k = 0; k < W::kDimensions; ++k) {
          low[k] = (box.low[k] + margin) + radius;
          high[k] = (box.high[k] - margin) - radius;
        }
      }
      uint8_t bits = 0;
      if (!(p->position.x > low.x)) bits |= 1;
      if (!(p->position.x < high.x)) bits |= 2;
      if (!(p->position.y > low.y)) bits |= 4;
      if (!(p->position.y < high.y)) bits |= 8;
      if (W::kDimensions == 3) {
        if (!(p->position[2] > low[2])) bits |= 16;
        if (!(p->position[2] < high[2])) bits |= 32;
      }
      if (bits != 0) {
        near[count] = i;
        walls[count] = bits;
        touched |= bits;
        ++count;
      }
    }
    if (touched != 0) {
      touchWalls(world, box, near, walls, count, touched, source);
    }
  }

  // generateBox()'s contacts, wall by wall, for the `count` particles near
  // a wall (near: their slots; walls: their bits). (Out of line: the scan's
  // frame stays small.)
  template <class W>
  TINYPARTICLE_NOINLINE static void touchWalls(
      W& world, const BoxParams<S, Dim>& box, const uint8_t* near,
      const uint8_t* walls, uint8_t count, uint8_t touched, uint8_t source) {
    typedef Vec<S, Dim> V;
    for (uint8_t side = 0; side < 2 * W::kDimensions; ++side) {
      const uint8_t bit = uint8_t(1u << side);
      if ((touched & bit) == 0) continue;  // no particle near this wall
      const uint8_t axis = uint8_t(side >> 1);
      Wall wall;
      wall.positive = (side & 1) == 0;
      wall.along = detail::AxisMember<V>::of(axis);
      wall.normal = V();
      wall.normal.*wall.along = wall.positive ? S(1) : S(-1);
      // As an axis plane's: offset = low, or minus high.
      wall.offset = wall.positive ? box.low.*wall.along
                                  : -(box.high.*wall.along);
      wall.source = source;
      for (uint8_t k = 0; k < count; ++k) {
        if ((walls[k] & bit) == 0) continue;
        touch(world, wall, near[k]);
      }
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
  // argument, not five: the call costs less): its normal (+e or -e), that
  // axis's member, the offset, the constraint slot, and the normal's sign.
  struct Wall {
    Vec<S, Dim> normal;
    S Vec<S, Dim>::*along;
    S offset;
    uint8_t source;
    bool positive;
  };

  // Particle i within the margin of the wall (its offset: see
  // generateAxis(), the bound, or minus it for a negative normal). Its
  // penetration, separating velocity and acceleration along the normal are
  // that coordinate of its position (less or plus its radius), velocity and
  // acceleration, with the normal's sign (exactly what the dot products
  // give); the sign does not matter for the acceleration, only whether it
  // is zero (WorldAccess::isIdle<W>()).
  template <class W>
  TINYPARTICLE_NOINLINE static void touch(W& world, const Wall& wall,
                                          uint8_t i) {
    S Vec<S, Dim>::*const along = wall.along;
    const bool positive = wall.positive;
    const S offset = wall.offset;
    const Particle<S, Dim>& p = WorldAccess::particle(world, i);
    const S side = positive ? p.position.*along - p.radius
                            : p.position.*along + p.radius;
    const S penetration = positive ? offset - side : offset + side;
    const S velocity = p.velocity.*along;
    const S separating = positive ? velocity : -velocity;
    const S acceleration =
        p.acceleration.*along + WorldAccess::uniformComponent(world, along);
    if (WorldAccess::isIdle<W>(penetration, separating, acceleration, S())) {
      return;
    }
    WorldAccess::recordContact(world, i, kNoIndex, wall.normal, penetration,
                               separating, wall.source);
  }

  static bool isTarget(const Particle<S, Dim>& p) {
    typedef Particle<S, Dim> P;
    return (p.flags & (P::kInUse | P::kCollides | P::kStatic | P::kAsleep)) ==
           (P::kInUse | P::kCollides);
  }
};

}  // namespace tinyparticle
