// Rods and cables: contact generators that hold two particles (or a particle
// and a fixed anchor) at a distance.
//
// A rod keeps the distance equal to its length: it makes one contact every
// step, pushing the ends apart when too close and pulling them together when
// too far (restitution 0), so a rod attached to a fixed point keeps its
// length to the resolver's rounding. A cable only pulls, and only once
// stretched to its length; it may bounce back with a restitution.
//
// Cost per link and step: one square root and one division.
#pragma once

#include <stdint.h>

#include "../Math/Vec.hpp"
#include "../World/Handle.hpp"

namespace tinyparticle {

template <typename S, uint8_t Dim>
struct LinkParams {
  Vec<S, Dim> anchor;  // anchored links only (b == kAnchorIndex)
  S length;            // rod length, or the cable's maximum length, m
};

template <class W, bool kAnchored, bool kRod>
struct LinkConstraint {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;

  static void generate(W& world, typename W::ConstraintSlot& slot,
                       uint8_t source) {
    typename W::ParticleType& a = world.particleAt(slot.a);
    V delta = a.position;
    if (kAnchored) {
      if (a.isStatic()) return;
      delta -= slot.params.link.anchor;
    } else {
      const typename W::ParticleType& b = world.particleAt(slot.b);
      if (a.isStatic() && b.isStatic()) return;
      delta -= b.position;
    }
    S lengthSquared = delta.magnitudeSquared();
    if (lengthSquared == S()) return;  // ends together: no direction
    S length = sqrt(lengthSquared);
    const S target = slot.params.link.length;
    if (!kRod && length < target) return;  // slack cable
    // The normal pushes a: away from b while too close, towards b while
    // too far (or exactly right: then the contact only removes the closing
    // velocity along the link).
    S inverse = S(1) / length;
    S penetration = length - target;
    if (penetration >= S()) {
      inverse = -inverse;
    } else {
      penetration = -penetration;
    }
    world.addContact(slot.a, kAnchored ? kNoIndex : slot.b, delta * inverse,
                     penetration, source);
  }
};

}  // namespace tinyparticle
