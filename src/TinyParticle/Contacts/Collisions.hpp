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
#include "../Math/Scaler.hpp"
#include "../Math/Vec.hpp"
#include "../Core/Handle.hpp"
#include "../Core/Access.hpp"

namespace tinyparticle {

template <class W>
struct CollisionConstraint {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef typename W::ParticleType P;

  static void generate(W& world, typename W::ConstraintSlot&, uint8_t source) {
    const uint8_t both = P::kInUse | P::kCollides;
    const S margin = W::contactMargin();
    // At least one entry: ISO C++ has no zero-size arrays.
    static const uint8_t kSize =
        W::kParticleCapacity > 0 ? W::kParticleCapacity : 1;
    uint8_t* order = sortOrder();

    // The colliding particles in last step's order, with the start of
    // their extent along x, each inserted at its place (insertion sort: a
    // nearly sorted list costs one compare per particle).
    Entry entries[kSize];
    Entry* end = entries;
    for (uint8_t k = 0; k < W::kParticleCapacity; ++k) {
      const uint8_t i = order[k];
      const P& p = world.particleAt(i);
      if ((p.flags & both) != both) continue;
      const S low = p.position.x - (p.radius + margin);
      Entry* e = end++;
      while (e != entries && low < e[-1].low) {
        *e = e[-1];
        --e;
      }
      e->low = low;
      e->index = i;
    }
    const uint8_t count = uint8_t(end - entries);
    if (isTooFast(world)) {
      WorldAccess::raiseError(world, WorldError::kTunnelling);
    }
    // Keep the new order for the next step: the colliding particles
    // sorted, then the others (any order will do for them).
    if (count > 0) {
      uint8_t* o = order;
      for (const Entry* e = entries; e != end; ++e) *o++ = e->index;
      for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
        if ((world.particleAt(i).flags & both) != both) *o++ = i;
      }
    }
    sweep(world, entries, count, margin, source);
  }

 private:
  struct Entry {
    S low;
    uint8_t index;
  };


  // The speed limit (top of this file): whether the fastest moving
  // colliding particle goes farther in this step, counting the axes
  // together, than the smallest one's radius. Out of line, with a pointer
  // walk: in the sort loop it cost three times as much (spilled registers).
  TINYPARTICLE_NOINLINE static bool isTooFast(W& world) {
    const uint8_t mask = P::kInUse | P::kCollides | P::kStatic | P::kAsleep;
    const uint8_t moving = P::kInUse | P::kCollides;
    S fastest = S(), smallest = S::largest();
    const P* p = &world.particleAt(0);
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
      if ((p->flags & mask) != moving) continue;
      S speed = fabs(p->velocity.x) + fabs(p->velocity.y);
      if (W::kDimensions == 3) speed += fabs(p->velocity[2]);
      if (speed > fastest) fastest = speed;
      if (p->radius < smallest) smallest = p->radius;
    }
    return WorldAccess::stepScaler(world)(fastest) > smallest;
  }

  // The pairs of the sorted list. Out of line, so that its frame is small:
  // behind the list's frame, every spilled value would cost more to reach.
  TINYPARTICLE_NOINLINE static void sweep(W& world, const Entry* entries,
                                          uint8_t count, S margin,
                                          uint8_t source) {
    for (uint8_t m = 0; m + 1 < count; ++m) {
      const uint8_t i = entries[m].index;
      const P& p = world.particleAt(i);
      const S reach = p.radius + margin;
      const S high = p.position.x + reach;
      // Every later entry starts at or after this one; those that start
      // past its end, and all after them, are apart along x.
      for (uint8_t n = m + 1; n < count && !(high < entries[n].low); ++n) {
        const uint8_t j = entries[n].index;
        const P& q = world.particleAt(j);
        // Apart along another axis: |d| > r1 + r2 + margin. Tested here,
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

  // The order of the particle slots by the start of their extent along x,
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
    WorldAccess::addContact(world, i, j, normal, penetration, source);
  }
};

}  // namespace tinyparticle
