// Sleeping (World::enableSleeping()): particles at rest cost (almost)
// nothing until something touches them.
//
// Before each step moves anything, every movable particle is looked at once:
//  - awake: if its speed along every axis stayed within World::sleepSpeed()
//    (1/128 m/s) and no force acted on it, its rest count goes up; after
//    kRestSteps such steps in a row it falls asleep: its velocity becomes
//    exactly zero. Any faster step starts the count again;
//  - asleep: a velocity or a force given to it since (by the sketch, or a
//    force generator) wakes it.
// A sleeping particle is not integrated and makes no contact with planes or
// with other resting particles (asleep or immovable), so a settled pile
// costs one test per particle in each generator and nothing in the
// resolver.
//
// Waking: a contact between a sleeper and an awake particle that is closing
// or penetrating beyond the margins (World::recordContact) wakes it, and so
// does the resolver pushing it. Any wake wakes every sleeper: the world is
// one island. A pile whose support is knocked away then never hangs in the
// air, and a disturbed pile reacts as it would have without sleeping (the
// step that wakes it makes its contacts again, with everyone awake). The
// price: one disturbance wakes all piles of the scene, which fall asleep
// again kRestSteps steps after they are still.
#pragma once

#include <stdint.h>

#include "../Math/Zero.hpp"

namespace tinyparticle {

template <class W>
struct Sleeping {
  typedef typename W::Scalar S;
  typedef typename W::ParticleType P;

  // The steps at rest before a particle falls asleep (at most 15: the count
  // lives in four bits of its flags).
  static const uint8_t kRestSteps = 15;

  static void settle(W& world) {
    const S limit = W::sleepSpeed();
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      P& p = world.particleAt(i);
      if ((p.flags & (P::kInUse | P::kStatic)) != P::kInUse) continue;
      const bool pushed = !isNull(p.acceleration);
      if (p.isAsleep()) {
        if (pushed || !isNull(p.velocity)) world.wakeAll();
        continue;
      }
      if (pushed || !isSlow(p.velocity, limit)) {
        p.flags &= uint8_t(~P::kRestCount);
      } else if ((p.flags & P::kRestCount) >= kRestSteps * P::kRestStep) {
        p.flags |= P::kAsleep;
        p.velocity = typename W::Vec();
      } else {
        p.flags = uint8_t(p.flags + P::kRestStep);
      }
    }
  }

 private:
  static bool isNull(const Vec<S, 2>& v) {
    return detail::isZero(v.x) && detail::isZero(v.y);
  }
  static bool isNull(const Vec<S, 3>& v) {
    return detail::isZero(v.x) && detail::isZero(v.y) && detail::isZero(v.z);
  }
  static bool isSlow(const Vec<S, 2>& v, S limit) {
    return !(fabs(v.x) > limit) && !(fabs(v.y) > limit);
  }
  static bool isSlow(const Vec<S, 3>& v, S limit) {
    return !(fabs(v.x) > limit) && !(fabs(v.y) > limit) &&
           !(fabs(v.z) > limit);
  }
};

}  // namespace tinyparticle
