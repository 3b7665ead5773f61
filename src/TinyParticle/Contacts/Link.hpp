// Cables: a contact generator that keeps two particles (or a particle and a
// fixed anchor) at most a length apart. A cable only pulls, and only once
// stretched to its length; it may bounce back with a restitution. (Rods,
// which hold a length both ways, are solved together by RodSolver.hpp; they
// share LinkParams.)
//
// Keeping the energy of a swing on a taut cable. Semi-implicit Euler moves
// the end along the old tangent, and the contact then removes the velocity
// along the new direction of the link. That velocity has two parts: what
// forces built along the link in this step (b = g_r dt for gravity, which
// the cable's tension cancels, as it should) and what the turn of the link
// by theta = |v| dt / L explains, about |v| theta. Taking all of it away
// along the new direction also shortens the tangential speed, by about
// |v| theta^2 / 2 + b theta per step (a pendulum on a link, L = 1 m,
// theta0 = 0.5, dt = 1/256 s, lost a third of its energy in 10 s, even in
// double precision). So while a cable is closing, the generator first
// scales the part of the relative velocity across the link by k, with
//   k^2 = 1 + (dt / L) (2 v_r - |v|^2 dt / L),   k ~ 1 + q (v_r - |v|^2 q / 2),
// where v_r is the stretching speed and q = dt / L: after the resolver has
// taken the speed along the link away, the tangential speed is what it
// would be had the velocity turned with the link. A genuine pull along the
// link (no tangential speed) gains nothing. The square root is expanded:
// the dropped terms are O(dt^4) per step. In fixed point, a factor k - 1
// below eight units of the format is not applied
// (ScalarTraits::smallestFactor()): rounded, it would be off by half of itself
// every step in the same direction, and add energy; there the cable keeps
// the plain, slightly lossy behaviour.
//
// Cost per cable and step: one square root and one division; while
// closing, a few multiplies more (dt / L is a shift when dt is a power of
// two).
#pragma once

#include <stdint.h>

#include "../Math/Scaler.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "../Core/Generator.hpp"
#include "../Math/ScalarTraits.hpp"
#include "Resolver.hpp"
#include "../Core/Access.hpp"

namespace tinyparticle {

// The parameters of rods and cables (a kind of World/Slots.hpp).
template <typename S, uint8_t Dim>
struct LinkParams {
  static const uint8_t kShape = SlotShape::kAnchorable;
  Vec<S, Dim> anchor;  // anchored links only (b == kAnchorIndex)
  S length;            // rod length, or the cable's maximum length, m
  // Rods only (Contacts/RodSolver.hpp):
  S inverseLength;        // 1 / length
  Vec<S, Dim> direction;  // unit, from b to a, at the end of the last step
  uint8_t next;           // the next rod of its chain, or kNoIndex
  uint8_t prev;           // the rod before it, or kNoIndex
};

template <class W, bool kAnchored>
struct CableConstraint {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef typename W::ParticleType P;

  typedef LinkParams<S, W::kDimensions> Link;

  static void generate(W& world, typename W::ConstraintSlot& slot,
                       uint8_t source) {
    const Link& link = InSlot::of<Link>(slot);
    P& a = world.particleAt(slot.a);
    P* b = nullptr;
    V delta = a.position;
    if (kAnchored) {
      if (a.isStatic()) return;
      detail::subtractNonZero(delta, link.anchor);
    } else {
      b = &world.particleAt(slot.b);
      if (a.isStatic() && b->isStatic()) return;
      detail::subtractNonZero(delta, b->position);
    }
    S lengthSquared = delta.magnitudeSquared();
    if (detail::isZero(lengthSquared)) return;  // ends together: no direction
    S length = sqrt(lengthSquared);
    const S target = link.length;
    if (length < target) return;  // slack
    // The normal pushes a: away from b while too close, towards b while
    // too far (or exactly right: then the contact only removes the closing
    // velocity along the link).
    const S inverse = S(1) / length;
    S penetration = length - target;
    const bool stretched = !detail::isNegative(penetration);
    if (!stretched) penetration = -penetration;
    const V normal = delta * (stretched ? -inverse : inverse);
    const uint8_t other = kAnchored ? kNoIndex : slot.b;
    S separating =
        Resolver<W>::separatingVelocity(world, slot.a, other, normal);
    if (!detail::isNegative(separating)) {
      WorldAccess::addContact(world, slot.a, other, normal, penetration,
                              source);
      return;
    }
    // Closing: keep the tangential speed that the turn of the link takes
    // (see the top of this file): the part of the relative velocity across
    // the link grows by h, h = q (v_r - |v|^2 q / 2), v_r = -separating the
    // stretching speed. Only the part across grows, so that the bounce sees
    // the speed along the link as it was.
    P* movingB = (b != nullptr && !b->isStatic()) ? b : nullptr;
    V relative;
    const V* v = &a.velocity;  // to a fixed point: a's own velocity
    if (movingB != nullptr) {
      relative =
          a.isStatic() ? -movingB->velocity : a.velocity - movingB->velocity;
      v = &relative;
    }
    const S q = WorldAccess::stepScaler(world)(inverse);  // dt / L
    const S h = q * (-separating - detail::half(v->magnitudeSquared() * q));
    if (ScalarTraits<S>::kCoarse &&
        fabs(h) < ScalarTraits<S>::smallestFactor()) {
      // Too small for the scalar (Q16.16 at dt = 1/1024 s, Q24.8): rounded,
      // it would add energy at every step; the link takes a little instead.
    } else {
      V change = *v * h;
      change -= normal * (h * separating);
      if (movingB == nullptr) {
        a.velocity += change;
      } else {
        push(a, *movingB, change);
      }
    }
    WorldAccess::recordContact(world, slot.a, other, normal, penetration,
                               separating, source);
  }

 private:
  // A change of the relative velocity between two ends (b moves), shared
  // in the ratio of their inverse masses, as an impulse is.
  static void push(P& a, P& b, const V& change) {
    if (a.isStatic()) {
      b.velocity -= change;
      return;
    }
    const S shareA = a.inverseMass == b.inverseMass
                         ? S(0.5)
                         : a.inverseMass / (a.inverseMass + b.inverseMass);
    const V changeA = change * shareA;
    a.velocity += changeA;
    b.velocity -= change - changeA;
  }
};

}  // namespace tinyparticle
