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

#include "../Math/Vec.hpp"
#include "../World/Handle.hpp"

namespace tinyparticle {

template <typename S, uint8_t Dim>
struct PlaneParams {
  Vec<S, Dim> normal;  // unit length, pointing into the allowed side
  S offset;            // m: the plane is dot(normal, x) = offset
};

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
    const V normal = slot.params.plane.normal;
    const S offset = slot.params.plane.offset;
    uint8_t axis = 0;
    while (axis + 1 < W::kDimensions && normal[axis] == S()) ++axis;
    const bool positive = normal[axis] > S();
    // With the normal +e: penetration = offset - (x - r), a contact from
    // -margin on, i.e. while x - r <= offset + margin. With -e (offset holds
    // minus the bound): penetration = offset + (x + r), while
    // x + r >= -(offset + margin).
    const S limit = offset + W::contactMargin();
    const S negativeLimit = -limit;
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const typename W::ParticleType& p = world.particleAt(i);
      if (!isTarget(p)) continue;
      const S coordinate = p.position[axis];
      if (positive) {
        const S side = coordinate - p.radius;
        if (side <= limit) {
          world.addContact(i, kNoIndex, normal, offset - side, source);
        }
      } else {
        const S side = coordinate + p.radius;
        if (side >= negativeLimit) {
          world.addContact(i, kNoIndex, normal, offset + side, source);
        }
      }
    }
  }

 private:
  static bool isTarget(const typename W::ParticleType& p) {
    typedef typename W::ParticleType P;
    return (p.flags & (P::kInUse | P::kCollides | P::kStatic)) ==
           (P::kInUse | P::kCollides);
  }
};

}  // namespace tinyparticle
