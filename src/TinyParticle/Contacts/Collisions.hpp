// Particle-particle collisions between spheres, as a contact generator: a
// scene that never calls World::addCollisions() links none of this code and
// pays nothing per step.
//
// Sort and sweep along x. Each colliding particle's extent along x starts at
// low = x - r (less the contact margin); the particles are sorted by it, and
// each one is paired only with those after it whose extent starts before
// its own ends: the inner loop stops at the first one that does not, so a
// step costs about one compare per particle plus one per pair that overlaps
// along x, instead of one per pair. The order is kept from one step to the
// next (particles move little in a step), so the insertion sort that
// restores it costs about one compare per particle. The pairs that pass are
// tested on the other axes (|d| > r1 + r2 rejects) in the same loop, then
// squared, and only touching pairs pay a square root and a division.
// Touching counts, and so does a gap below World::contactMargin(), as for
// planes: a resting ball must still lose the closing velocity that gravity
// gives it in each step.
//
// The speed limit (tunnelling). Contacts are found from the positions after
// each step's move, so two balls that cross each other within one step are
// never seen. While every moving particle goes at most the smallest radius
// in a step along the axes together ((|vx| + |vy| + |vz|) dt <= r_min, a
// bound on the length of its move), two particles close by at most the sum
// of their radii per step: their centres cannot pass each other between two
// looks, so a collision is found, and resolved on the right side. (What a
// step can still miss: a glancing touch, shallower than 13 % of the radii's
// sum, of two particles that are apart again by the step's end.) Beyond
// that speed a pair may pass through each other unseen, and the step raises
// WorldError::kTunnelling. Planes need no limit: they are half-spaces, and
// whatever has crossed one is behind it and is pushed back. (r = 3 cm at
// dt = 1/256 s: 7.7 m/s; halving dt doubles it.)
//
// Memory: the sort order lives in a static array of one byte per particle
// slot (plus one), linked only with this generator. Worlds of one type share
// it; any starting order gives the same contacts, a shared one is only less
// sorted. The sweep list is on the stack (5 bytes per colliding particle in
// Q16.16 and float).
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "../Math/Fixed.hpp"
#include "../Math/Scaler.hpp"
#include "../Math/Vec.hpp"
#include "../World/Handle.hpp"

namespace tinyparticle {
namespace detail {

// |vx| + |vy| (+ |vz|), for the speed limit: in any scalar, a sum that
// cannot overflow (Sum) and its value as the scalar (toScalar).
template <typename S>
struct AxisSpeed {
  typedef S Sum;
  static S of(const Vec<S, 2>& v) { return fabs(v.x) + fabs(v.y); }
  static S of(const Vec<S, 3>& v) {
    return fabs(v.x) + fabs(v.y) + fabs(v.z);
  }
  static S toScalar(S sum) { return sum; }
};

// Fixed point: the magnitudes of the raw values, unsigned; a sum past the
// unsigned range is held at its top (3D: three magnitudes of up to 2^31).
template <uint8_t I, uint8_t F>
struct AxisSpeed<Fixed<I, F> > {
  typedef Fixed<I, F> T;
  typedef typename T::URaw Sum;
  static Sum of(const Vec<T, 2>& v) {
    return plus(T::magnitude(v.x.raw()), T::magnitude(v.y.raw()));
  }
  static Sum of(const Vec<T, 3>& v) {
    return plus(plus(T::magnitude(v.x.raw()), T::magnitude(v.y.raw())),
                T::magnitude(v.z.raw()));
  }
  static T toScalar(Sum sum) {
    return sum > Sum(T::kRawMax) ? T::largest()
                                 : T::fromRaw(typename T::Raw(sum));
  }

 private:
  static Sum plus(Sum a, Sum b) {
    const Sum sum = Sum(a + b);
    return sum < a ? Sum(~Sum(0)) : sum;
  }
};

}  // namespace detail

template <class W>
struct CollisionConstraint {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef typename W::ParticleType P;

  static void generate(W& world, typename W::ConstraintSlot&, uint8_t source) {
    const uint8_t both = P::kInUse | P::kCollides;
    // At least one entry: ISO C++ has no zero-size arrays.
    static const uint8_t kSize =
        W::kParticleCapacity > 0 ? W::kParticleCapacity : 1;
    uint8_t* order = sortOrder();

    // The colliding particles in last step's order, by their centre's x,
    // each inserted at its place (insertion sort: a nearly sorted list
    // costs one compare per particle). The centre, not the start of the
    // extent: the loop then does no arithmetic, and the sweep allows for
    // the largest radius instead.
    Entry entries[kSize];
    Entry* end = entries;
    for (uint8_t k = 0; k < W::kParticleCapacity; ++k) {
      const uint8_t i = order[k];
      const P& p = world.particleAt(i);
      if ((p.flags & both) != both) continue;
      const S x = p.position.x;
      Entry* e = end++;
      while (e != entries && x < e[-1].x) {
        *e = e[-1];
        --e;
      }
      e->x = x;
      e->index = i;
    }
    const uint8_t count = uint8_t(end - entries);
    // Keep the new order for the next step: the colliding particles
    // sorted, then the others (any order will do for them).
    if (count > 0) {
      uint8_t* o = order;
      for (const Entry* e = entries; e != end; ++e) *o++ = e->index;
      if (count < W::kParticleCapacity) {
        for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
          if ((world.particleAt(i).flags & both) != both) *o++ = i;
        }
      }
    }
    const S largest = survey(world);
    sweep(world, entries, count, largest + W::contactMargin(), source);
  }

 private:
  struct Entry {
    S x;
    uint8_t index;
  };

  // One look at the colliding particles: the largest radius (returned, for
  // the sweep), and the speed limit (top of this file): whether the
  // fastest moving one goes farther in this step, counting the axes
  // together, than the smallest moving one's radius (then
  // WorldError::kTunnelling). Out of line, with a pointer walk: in the sort
  // loop it cost three times as much (spilled registers). The speeds are
  // summed as AxisSpeed's magnitudes: for fixed point the raw bits,
  // unsigned, with no saturating arithmetic in the loop.
  TINYPARTICLE_NOINLINE static S survey(W& world) {
    typedef detail::AxisSpeed<S> Speed;
    const uint8_t both = P::kInUse | P::kCollides;
    typename Speed::Sum fastest = typename Speed::Sum();
    S smallest = S::largest(), largest = S();
    const P* p = &world.particleAt(0);
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
      if ((p->flags & both) != both) continue;
      if (p->radius > largest) largest = p->radius;
      if (p->isResting()) continue;  // immovable or asleep
      const typename Speed::Sum speed = Speed::of(p->velocity);
      if (speed > fastest) fastest = speed;
      if (p->radius < smallest) smallest = p->radius;
    }
    if (world.stepScaler()(Speed::toScalar(fastest)) > smallest) {
      world.raiseError(WorldError::kTunnelling);
    }
    return largest;
  }

  // The pairs of the sorted list; spread is the largest radius plus the
  // contact margin. Out of line, so that its frame is small: behind the
  // list's frame, every spilled value would cost more to reach.
  TINYPARTICLE_NOINLINE static void sweep(W& world, const Entry* entries,
                                          uint8_t count, S spread,
                                          uint8_t source) {
    const S margin = W::contactMargin();
    for (uint8_t m = 0; m + 1 < count; ++m) {
      const uint8_t i = entries[m].index;
      const P& p = world.particleAt(i);
      const S reach = p.radius + margin;
      // Every later entry's centre is at or after this one's; those whose
      // centre is farther than this radius plus the largest one (and the
      // margin), and all after them, are apart along x.
      const S high = entries[m].x + (p.radius + spread);
      for (uint8_t n = m + 1; n < count && !(high < entries[n].x); ++n) {
        const uint8_t j = entries[n].index;
        const P& q = world.particleAt(j);
        // Apart along an axis: |d| > r1 + r2 + margin. Tested here,
        // before a call: most pairs that overlap along x end here.
        const S outer = reach + q.radius;
        if (fabs(p.position.y - q.position.y) > outer) continue;
        if (W::kDimensions == 3 &&
            fabs(p.position[2] - q.position[2]) > outer) {
          continue;
        }
        // The lower slot index is a, as a sweep in slot order would have it.
        if (i < j) {
          pair(world, i, j, outer, source);
        } else {
          pair(world, j, i, outer, source);
        }
      }
    }
  }

  // The order of the particle slots by their centre's x,
  // as of the last step: a permutation of 0 .. capacity - 1.
  static uint8_t* sortOrder() {
    static const uint8_t kSize =
        W::kParticleCapacity > 0 ? W::kParticleCapacity : 1;
    static uint8_t order[kSize];
    static bool ready = false;
    if (!ready) {
      for (uint8_t i = 0; i < kSize; ++i) order[i] = i;
      ready = true;
    }
    return order;
  }

  // Particles i < j whose boxes overlap: outer = r1 + r2 + margin.
  static void pair(W& world, uint8_t i, uint8_t j, S outer, uint8_t source) {
    const P& a = world.particleAt(i);
    const P& b = world.particleAt(j);
    if (a.isResting() && b.isResting()) return;  // immovable or asleep
    const S reach = a.radius + b.radius;
    const V delta = a.position - b.position;
    const S distanceSquared = delta.magnitudeSquared();
    if (distanceSquared > outer * outer) return;
    // The normal from the difference itself, not from distanceSquared: for
    // small balls in fixed point that square is a few units of the scalar
    // (r = 1 cm in Q16.16: 26 units at contact), and a normal from it would
    // be off by a few percent, a bounce gaining or losing as much energy.
    // Vec's normalisation scales the difference up first (Math/Vec.hpp), so
    // the normal is unit length to a few units of the scalar.
    V normal = delta;
    const S distance = normal.magnitudeAndNormalize();
    S penetration = reach - distance;
    if (distance == S()) {
      normal = V();
      normal.y = S(1);  // centres coincide: any direction will do
    }
    world.addContact(i, j, normal, penetration, source);
  }
};

}  // namespace tinyparticle
