// Sleeping (World::enableSleeping()): particles at rest cost (almost)
// nothing until something touches them.
//
// The world is one island: it falls asleep as a whole and wakes as a whole.
// Before each step moves anything, every movable particle is looked at once.
// When each one's speed along every axis has stayed within
// World::sleepSpeed() (1/64 m/s), or so low that the step moves it by
// nothing at all, with no force on it, for kRestSteps steps in a row, they
// all fall asleep: their velocities become exactly zero. (The second case
// is coarse fixed point: in Q24.8 at dt = 1/256 s a velocity below 0.5 m/s
// moves a particle by less than half a unit, 1/256 m, so it stays where it
// is. Without it such a particle kept its velocity and its place forever,
// and a Q24.8 pile never slept.) A
// velocity or a force given to a sleeper since (by the sketch, or a force
// generator) wakes them all.
// A sleeping particle is not integrated and makes no contact with planes or
// with other resting particles (asleep or immovable). When all sleep, a step
// is this look and nothing else: no contacts are made.
//
// Waking: a contact between a sleeper and an awake particle that is closing
// or penetrating beyond the margins wakes them all, once the step's contacts
// are made or when the resolver is about to push a sleeper
// (Sleeping::wakeIfReached()). A pile whose support is
// knocked away then never hangs in the air, and a disturbed pile reacts as
// it would have without sleeping: the woken particles get the motion of
// the step they missed, and the step makes its contacts again with
// everyone awake. A particle added to a sleeping world is awake; the world
// sleeps again once it too is at rest. The price of one island: a pile
// sleeps only when everything is still, and wakes whole.
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "../Math/Scaler.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "../Core/Access.hpp"

namespace tinyparticle {
namespace detail {

// What the world keeps for sleeping: the look (Sleeping<World>::settle, set
// by enableSleeping(), so a world that never sleeps links none of it), and
// its state. Only a world with constraint slots has it (contacts need
// them); without them it is an empty base class and takes no RAM.
template <typename Settle, bool kHasConstraints>
struct SleepState {
  constexpr SleepState() : mSettle(nullptr), mBits(0) {}
  Settle settler() const { return mSettle; }
  void setSettler(Settle settle) { mSettle = settle; }
  bool woke() const { return (mBits & kWoke) != 0; }
  void setWoke(bool on) { setBit(kWoke, on); }
  bool inContacts() const { return (mBits & kInContacts) != 0; }
  void setInContacts(bool on) { setBit(kInContacts, on); }
  uint8_t restCount() const { return uint8_t(mBits & kCount); }
  bool hasSleepers() const { return (mBits & kSleepers) != 0; }
  void setRest(uint8_t count, bool sleepers) {
    mBits = uint8_t((mBits & (kWoke | kInContacts)) | (count & kCount) |
                    (sleepers ? kSleepers : 0));
  }

 private:
  // One byte: the steps in a row at rest, whether particles sleep, whether
  // a sleeper woke during this step's contacts, and whether the step is
  // making or resolving contacts.
  static const uint8_t kCount = 0x1F;
  static const uint8_t kWoke = 0x20;
  static const uint8_t kInContacts = 0x40;
  static const uint8_t kSleepers = 0x80;
  void setBit(uint8_t bit, bool on) {
    mBits = on ? uint8_t(mBits | bit) : uint8_t(mBits & ~bit);
  }
  Settle mSettle;
  uint8_t mBits;
};

template <typename Settle>
struct SleepState<Settle, false> {
  constexpr SleepState() {}
  Settle settler() const { return nullptr; }
  void setSettler(Settle) {}
  bool woke() const { return false; }
  void setWoke(bool) {}
  bool inContacts() const { return false; }
  void setInContacts(bool) {}
  uint8_t restCount() const { return 0; }
  bool hasSleepers() const { return false; }
  void setRest(uint8_t, bool) {}
};

}  // namespace detail

template <class W>
struct Sleeping {
  typedef typename W::Scalar S;
  typedef typename W::ParticleType P;

  // The steps in a row that every particle must be at rest before all fall
  // asleep.
  static const uint8_t kRestSteps = 31;

  // The world's sleep hook, which World::enableSleeping() stores, so that
  // a world that never sleeps links none of this, waking included: with
  // the step's Scaler, the look before the step (settle()); with none,
  // during the step's contacts, the look at them (wakeIfReached()).
  static bool hook(W& world, const Scaler<S>* byDt) {
    if (byDt == nullptr) {
      wakeIfReached(world);
      return false;
    }
    return settle(world, *byDt);
  }

  // When a contact of the pool has a sleeper and is closing or penetrating
  // beyond the margins (World::speedMargin(), contactMargin(): what the
  // resolver would act on), all wake (World::wakeAll(): with the motion of
  // the step they missed). Looked at once the generators are done, and
  // again when the resolver is about to push a sleeper (a contact that its
  // pushes made active). A contact that a full pool dropped wakes no one.
  static void wakeIfReached(W& world) {
    if (!WorldAccess::hasSleepers(world)) return;
    const S closing = -W::speedMargin();
    const S deep = W::contactMargin();
    for (uint8_t i = 0; i < world.contactCount(); ++i) {
      const typename W::ContactType& c = WorldAccess::contact(world, i);
      const bool asleep =
          world.particleAt(c.a).isAsleep() ||
          (c.b < W::kParticleCapacity && world.particleAt(c.b).isAsleep());
      if (asleep && (c.penetration > deep || c.separatingVelocity < closing)) {
        world.wakeAll();
        return;
      }
    }
  }

  // Returns true when every movable particle sleeps: the step (byDt
  // multiplies by its dt) has nothing to do.
  static bool settle(W& world, const Scaler<S>& byDt) {
    const S limit = W::sleepSpeed();
    // Without sleepers the first particle that moves ends the look (in a
    // busy scene, usually the first one); sleepers are all looked at, for
    // a disturbance.
    const bool sleepers = WorldAccess::hasSleepers(world);
    bool still = true, awake = false;
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      P& p = world.particleAt(i);
      if ((p.flags & (P::kInUse | P::kStatic)) != P::kInUse) continue;
      const bool pushed = !detail::isZeroVector(p.accumulated());
      if (p.isAsleep()) {
        if (pushed || !detail::isZeroVector(p.velocity)) {
          world.wakeAll();  // no sleepers left
          return false;
        }
        continue;
      }
      awake = true;
      if (pushed ||
          !(isSlow(p.velocity, limit) || isStuck(p.velocity, byDt))) {
        still = false;
        if (!sleepers) break;
      }
    }
    if (!awake) return sleepers;
    const uint8_t count = WorldAccess::restCount(world);
    if (!still) {
      WorldAccess::setRest(world, 0, sleepers);
    } else if (count < kRestSteps) {
      WorldAccess::setRest(world, uint8_t(count + 1), sleepers);
    } else {
      WorldAccess::setRest(world, 0, true);  // a particle added later counts from zero
      for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
        P& p = world.particleAt(i);
        if ((p.flags & (P::kInUse | P::kStatic)) != P::kInUse) continue;
        p.flags |= P::kAsleep;
        p.velocity = typename W::Vec();
      }
    }
    return false;
  }

 private:
  // Moved by nothing in a step: v dt rounds to zero on every axis, as the
  // integrator rounds it (World::move(), with the same Scaler). Out of
  // line: asked only of a particle faster than the sleep speed, it leaves
  // the look's loop its registers.
  TINYPARTICLE_NOINLINE static bool isStuck(const Vec<S, 2>& v,
                                            const Scaler<S>& byDt) {
    return detail::isZero(byDt(v.x)) && detail::isZero(byDt(v.y));
  }
  TINYPARTICLE_NOINLINE static bool isStuck(const Vec<S, 3>& v,
                                            const Scaler<S>& byDt) {
    return detail::isZero(byDt(v.x)) && detail::isZero(byDt(v.y)) &&
           detail::isZero(byDt(v.z));
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
