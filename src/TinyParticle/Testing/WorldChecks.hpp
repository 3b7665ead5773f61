// Test support: the world's pools and handles (exhaustion, stale handles,
// removal cascades, bad arguments), for any scalar.
//
// Used by extras/test/WorldTest (Q16.16) and extras/test/WorldFloatTest (Float): the two
// scalars together no longer fit in the Nano's 30 KB of flash, so one sketch
// per scalar runs the same checks from here. Not included by TinyParticle.h:
// include <TinyParticle/Testing/WorldChecks.hpp> after it. Nothing here steps
// a world (stepping is tested by the physics sketches), which keeps the
// sketches small.
#pragma once

#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

// Each function builds its own world and returns a bit mask of the checks
// that held; a test compares the mask with all bits set, so a failure names
// the check that broke.
template <typename S>
struct WorldChecks {
  // One world type for every check: each World type instantiates the engine
  // again, and flash is 32 KB.
  typedef World<S, 2, 3, 4, 3, 4> W;

  // Fills every pool one past its capacity. Returns a bit mask of what
  // behaved: 1 particles, 2 forces (the world's gravity takes no slot: it
  // is still added to a full pool), 4 constraints (all: 7).
  static int exhaustPools() {
    W w;
    typename W::Vec origin;
    int ok = 0;
    ParticleId a = w.addParticle(origin, S(1));
    ParticleId b = w.addParticle(origin, S(1));
    ParticleId c = w.addParticle(origin, S(1));
    ParticleId d = w.addParticle(origin, S(1));
    if (a.isValid() && b.isValid() && c.isValid() && !d.isValid() &&
        w.particle(d) == nullptr && (w.error() & WorldError::kParticlesFull)) {
      ok |= 1;
    }
    ForceId f;
    for (uint8_t i = 0; i < 4; ++i) f = w.addGravity(a);
    ForceId extra = w.addGravity(b);
    const bool full = (w.error() & WorldError::kForcesFull) != 0;
    w.clearError();
    ForceId world = w.addGravity();
    if (f.isValid() && !extra.isValid() && w.force(extra) == nullptr &&
        full && world.isValid() && w.error() == 0 &&
        w.uniformAcceleration() == W::standardGravity()) {
      ok |= 2;
    }
    ConstraintId k;
    for (uint8_t i = 0; i < 3; ++i) k = w.addRod(a, b, S(1));
    ConstraintId more = w.addCollisions(S(1));
    if (k.isValid() && !more.isValid() && w.constraint(more) == nullptr &&
        (w.error() & WorldError::kConstraintsFull)) {
      ok |= 4;
    }
    return ok;
  }

  // Removes and re-adds particles, forces and constraints (all bits: 63).
  static int staleHandles() {
    W w;
    typename W::Vec origin;
    uint8_t ok = 0;
    ParticleId a = w.addParticle(origin, S(1));
    ParticleId b = w.addParticle(origin, S(1));
    if (w.removeParticle(a) && w.particle(a) == nullptr) ok |= 1;
    w.clearError();
    if (!w.removeParticle(a) && (w.error() & WorldError::kStaleHandle)) ok |= 2;
    ParticleId again = w.addParticle(origin, S(2));  // reuses a's slot
    if (again.index == a.index && again != a && w.particle(a) == nullptr &&
        w.particle(again) != nullptr && w.particle(b) != nullptr) {
      ok |= 4;
    }
    ForceId f = w.addGravity(b);
    w.removeForce(f);
    ForceId g = w.addGravity(b);
    if (w.force(f) == nullptr && w.force(g) != nullptr) ok |= 8;
    ConstraintId k = w.addCollisions(S(1));
    w.removeConstraint(k);
    ConstraintId m = w.addCollisions(S(1));
    if (w.constraint(k) == nullptr && w.constraint(m) != nullptr) ok |= 16;
    // A stale particle handle is refused by every function that takes one.
    w.clearError();
    if (!w.addSpring(a, again, S(1), S(1)).isValid() &&
        !w.addRod(again, a, S(1)).isValid() && !w.applyForce(a, origin) &&
        (w.error() & WorldError::kStaleHandle)) {
      ok |= 32;
    }
    return ok;
  }

  // Removing a particle removes what refers to it, and only that (all: 15).
  static int removalCascade() {
    W w;
    typename W::Vec p, push;
    ParticleId a = w.addParticle(p, S(1));
    p.x = S(1);
    ParticleId b = w.addParticle(p, S(1));
    p.x = S(2);
    ParticleId c = w.addParticle(p, S(1));
    ForceId spring = w.addSpring(a, b, S(10), S(1));
    ForceId custom = w.addCustomForce(a, &push);
    ForceId gravity = w.addGravity();
    ForceId cSpring = w.addSpring(c, p, S(1), S(0));
    ConstraintId rod = w.addRod(b, c, S(1));
    typename W::Vec up;
    up.y = S(1);
    ConstraintId floor = w.addPlane(up, S(-5), S(0.5));
    uint8_t ok = 0;
    if (w.removeParticle(b)) ok |= 1;
    if (w.force(spring) == nullptr && w.constraint(rod) == nullptr) ok |= 2;
    if (w.force(custom) != nullptr && gravity.isValid() &&
        w.uniformAcceleration() == W::standardGravity() &&
        w.force(cSpring) != nullptr && w.constraint(floor) != nullptr) {
      ok |= 4;
    }
    if (w.particle(a) != nullptr && w.particle(c) != nullptr) ok |= 8;
    return ok;
  }

  // A massless particle and a plane without a normal are refused with
  // kBadArgument, and clearError() clears the flag (all: 7).
  static int badArguments() {
    W w;
    typename W::Vec origin;
    uint8_t ok = 0;
    if (!w.addParticle(origin, S(0)).isValid() &&
        (w.error() & WorldError::kBadArgument)) {
      ok |= 1;
    }
    w.clearError();
    if (w.error() == 0) ok |= 2;
    if (!w.addPlane(origin, S(0), S(1)).isValid() &&
        (w.error() & WorldError::kBadArgument)) {
      ok |= 4;
    }
    return ok;
  }
};

}  // namespace testing
}  // namespace tinyparticle
