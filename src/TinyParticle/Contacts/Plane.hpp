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
#include "../World/Handle.hpp"

namespace tinyparticle {

template <typename S, uint8_t Dim>
struct PlaneParams {
  Vec<S, Dim> normal;  // unit length, pointing into the allowed side
  S offset;            // m: the plane is dot(normal, x) = offset
};

// A box's walls (World::addBox): low <= x <= high.
template <typename S, uint8_t Dim>
struct BoxParams {
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

template <class W>
struct PlaneConstraint {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;

  // Any normal.
  static void generate(W& world, typename W::ConstraintSlot& slot,
                       uint8_t source) {
    const V normal = slot.params.plane.normal;
    const S offset = slot.params.plane.offset;
    const S margin = -W::contactMargin();
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const typename W::ParticleType& p = world.particleAt(i);
      if (!isTarget(p)) continue;
      S penetration = offset + p.radius - dot(normal, p.position);
      if (penetration >= margin) {
        world.addContact(i, kNoIndex, normal, penetration, source);
      }
    }
  }

  // A normal of +1 or -1 along one axis: one coordinate instead of a dot
  // product, and one addition per particle to test it. (One function for
  // all axes, found from the normal, costs a compare per plane and step and
  // saves flash.)
  static void generateAxis(W& world, typename W::ConstraintSlot& slot,
                           uint8_t source) {
    const V& normal = slot.params.plane.normal;
    const S offset = slot.params.plane.offset;
    uint8_t axis = 0;
    while (axis + 1 < W::kDimensions && normal[axis] == S()) ++axis;
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
    uint8_t near[kSize];
    uint8_t count = 0;
    const P* p = &world.particleAt(0);
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
      if (!isTarget(*p)) continue;
      const S at = p->position.*along;
      if (positive ? !(at - p->radius > limit)
                   : !(at + p->radius < negativeLimit)) {
        near[count++] = i;
      }
    }
    for (uint8_t k = 0; k < count; ++k) {
      const uint8_t i = near[k];
      const P& q = world.particleAt(i);
      const S side = positive ? q.position.*along - q.radius
                              : q.position.*along + q.radius;
      touch(world, normal, along, positive, i,
            positive ? offset - side : offset + side, source);
    }
  }

  // The 2 Dim walls of a box in one pass over the particles: each one's
  // coordinates and radius are read once for all walls (four planes cost
  // four passes). The pass only tests and notes which walls each particle
  // is within reach of; the contacts are made after it, wall by wall in
  // the order of separate axis planes (x low, x high, y low, ...), so that
  // a box makes the same contacts in the same order as its planes would.
  static void generateBox(W& world, typename W::ConstraintSlot& slot,
                          uint8_t source) {
    const BoxParams<S, W::kDimensions>& box = slot.params.box;
    const S margin = W::contactMargin();
    V lowLimit, highLimit;  // within reach: x - r <= low + margin, ...
    for (uint8_t k = 0; k < W::kDimensions; ++k) {
      lowLimit[k] = box.low[k] + margin;
      highLimit[k] = box.high[k] - margin;
    }
    uint8_t near[kSize];
    uint8_t walls[kSize];  // bit 2k: the low wall of axis k; 2k + 1: high
    uint8_t count = 0, touched = 0;
    const P* p = &world.particleAt(0);
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
      if (!isTarget(*p)) continue;
      const S r = p->radius;
      uint8_t bits = 0;
      if (!(p->position.x - r > lowLimit.x)) bits |= 1;
      if (!(p->position.x + r < highLimit.x)) bits |= 2;
      if (!(p->position.y - r > lowLimit.y)) bits |= 4;
      if (!(p->position.y + r < highLimit.y)) bits |= 8;
      if (W::kDimensions == 3) {
        if (!(p->position[2] - r > lowLimit[2])) bits |= 16;
        if (!(p->position[2] + r < highLimit[2])) bits |= 32;
      }
      if (bits != 0) {
        near[count] = i;
        walls[count] = bits;
        touched |= bits;
        ++count;
      }
    }
    for (uint8_t wall = 0; wall < 2 * W::kDimensions; ++wall) {
      const uint8_t bit = uint8_t(1u << wall);
      if ((touched & bit) == 0) continue;  // no particle near this wall
      const uint8_t axis = uint8_t(wall >> 1);
      const bool positive = (wall & 1) == 0;
      S V::*const along = detail::AxisMember<V>::of(axis);
      V normal;
      normal.*along = positive ? S(1) : S(-1);
      // As an axis plane's: offset = low, or minus high.
      const S offset = positive ? box.low.*along : -(box.high.*along);
      for (uint8_t k = 0; k < count; ++k) {
        if ((walls[k] & bit) == 0) continue;
        const P& q = world.particleAt(near[k]);
        const S side = positive ? q.position.*along - q.radius
                                : q.position.*along + q.radius;
        touch(world, normal, along, positive, near[k],
              positive ? offset - side : offset + side, source);
      }
    }
  }

 private:
  typedef typename W::ParticleType P;
  // At least one entry: ISO C++ has no zero-size arrays.
  static const uint8_t kSize =
      W::kParticleCapacity > 0 ? W::kParticleCapacity : 1;

  // A particle within the margin of an axis plane: the separating velocity
  // and the acceleration along the normal are that coordinate of the
  // velocity and of the acceleration, with the normal's sign (exactly what
  // the dot products give); the sign does not matter for the acceleration,
  // only whether it is zero (W::isIdle()).
  TINYPARTICLE_NOINLINE static void touch(W& world, const V& normal,
                                          S V::*along, bool positive,
                                          uint8_t i, S penetration,
                                          uint8_t source) {
    const typename W::ParticleType& p = world.particleAt(i);
    const S velocity = p.velocity.*along;
    const S separating = positive ? velocity : -velocity;
    const S acceleration =
        p.acceleration.*along + world.uniformComponent(along);
    if (W::isIdle(penetration, separating, acceleration, S())) return;
    world.recordContact(i, kNoIndex, normal, penetration, separating, source);
  }

  static bool isTarget(const typename W::ParticleType& p) {
    typedef typename W::ParticleType P;
    return (p.flags & (P::kInUse | P::kCollides | P::kStatic | P::kAsleep)) ==
           (P::kInUse | P::kCollides);
  }
};

}  // namespace tinyparticle
