// Particle-particle collisions between spheres, as a contact generator: a
// scene that never calls World::addCollisions() links none of this code and
// pays nothing per step.
//
// Brute force over all pairs of colliding particles, with an early reject
// that costs two compares and no arithmetic: each particle's extent along x
// (x - r, x + r, with the contact margin) is computed once per step, on the
// stack (9 bytes per particle in Q16.16), and a pair whose extents do not
// overlap is dropped at once. The pairs that pass are tested on the other
// axes (|d| > r1 + r2 rejects), then squared, and only touching pairs pay a
// square root and a division.
// Touching counts, and so does a gap below World::contactMargin(), as for
// planes: a resting ball must still lose the closing velocity that gravity
// gives it in each step.
#pragma once

#include <stdint.h>

#include "../Math/Vec.hpp"
#include "../World/Handle.hpp"

namespace tinyparticle {

template <class W>
struct CollisionConstraint {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef typename W::ParticleType P;

  static void generate(W& world, typename W::ConstraintSlot&, uint8_t source) {
    const uint8_t both = P::kInUse | P::kCollides;
    const S margin = W::contactMargin();
    // The colliding particles and their extents along x. (At least one
    // entry: ISO C++ has no zero-size arrays.)
    static const uint8_t kSize =
        W::kParticleCapacity > 0 ? W::kParticleCapacity : 1;
    uint8_t index[kSize];
    S low[kSize];
    S high[kSize];
    uint8_t count = 0;
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const P& p = world.particleAt(i);
      if ((p.flags & both) != both) continue;
      index[count] = i;
      const S reach = p.radius + margin;
      low[count] = p.position.x - reach;
      high[count] = p.position.x + reach;
      ++count;
    }
    for (uint8_t m = 0; m + 1 < count; ++m) {
      const S lowM = low[m], highM = high[m];
      for (uint8_t n = m + 1; n < count; ++n) {
        if (high[n] < lowM || highM < low[n]) continue;  // apart along x
        pair(world, index[m], index[n], source);
      }
    }
  }

 private:
  static void pair(W& world, uint8_t i, uint8_t j, uint8_t source) {
    const P& a = world.particleAt(i);
    const P& b = world.particleAt(j);
    if (a.isStatic() && b.isStatic()) return;
    const S reach = a.radius + b.radius;
    const S outer = reach + W::contactMargin();
    V delta = a.position - b.position;
    for (uint8_t k = 1; k < W::kDimensions; ++k) {
      if (fabs(delta[k]) > outer) return;  // apart along another axis
    }
    S distanceSquared = delta.magnitudeSquared();
    if (distanceSquared > outer * outer) return;
    V normal;
    S penetration = reach;
    if (distanceSquared == S()) {
      normal.y = S(1);  // centres coincide: any direction will do
    } else {
      S distance = sqrt(distanceSquared);
      normal = delta * (S(1) / distance);
      penetration = reach - distance;
    }
    world.addContact(i, j, normal, penetration, source);
  }
};

}  // namespace tinyparticle
