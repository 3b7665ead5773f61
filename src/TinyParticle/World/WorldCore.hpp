// WorldCore<S, Dim>: the part of every World<S, Dim, ...> that does not
// depend on its capacities: the error bits and step statistics, and the
// world-side routines of the set-up and the step (placing a particle or a
// force, integrating, moving, marking statics, finishing a step). They take
// their pool as a pointer and a count, so that two World types of the same
// scalar and dimension in one sketch share them (issue 12; the routines
// over particles once per particle type: with and without the force
// accumulator, Core/Particle.hpp): the compiler
// keeps one copy of the large ones and inlines the small ones, where a call
// would cost more than it shares. World<...> (World.hpp) keeps the pools
// and the compile-time choices of which features link, and calls these. A
// routine that hides its pool's address (detail::throughPointer()) reads it
// through the pointer in every sketch: smaller than the constant addresses
// of each field when the pool has more than one slot.
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "../Contacts/Contact.hpp"
#include "../Core/Handle.hpp"
#include "../Core/Particle.hpp"
#include "../Debug/Debug.hpp"
#include "../Debug/Profile.hpp"
#include "../Math/Scaler.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "ParticleSteps.hpp"
#include "Slots.hpp"

namespace tinyparticle {
namespace detail {
// A compile-time choice as an argument, to pick an overload.
template <bool kValue>
struct Choice {};

// n, hidden from the optimizer like throughPointer() hides an address: a
// loop over a pool of a few slots then stays a loop, where the compiler
// would write it out once per slot (a step's short passes over the
// particles: about 30 bytes a slot).
inline uint8_t throughRegister(uint8_t n) {
#if defined(__GNUC__)
  asm("" : "+r"(n));
#endif
  return n;
}
// A pool of one slot keeps its constant address (and its pass no loop):
// hiding it cost the spring scene 1 % of a step.
template <class Slot>
inline Slot* poolThroughPointer(Slot* slots, uint8_t count) {
  return count > 1 ? throughPointer(slots) : slots;
}
}  // namespace detail

template <typename S, uint8_t Dim>
class WorldCore {
 protected:
  typedef tinyparticle::Vec<S, Dim> CoreVec;
  // The steps over a pool of particles of type P.
  template <class P>
  struct StepsFor {
    typedef detail::ParticleSteps<S, Dim, P::kHasAccumulator> Type;
  };

  constexpr WorldCore()
      : mError(0), mContactCount(0), mIterationCap(0), mStats() {}

  // The first free slot of the pool takes a particle (in use, colliding,
  // static when inverseMass is 0); kParticlesFull when there is none.
  template <class ParticleType>
  ParticleId placeParticle(ParticleType* slots, uint8_t count,
                           const CoreVec& position, S inverseMass, S radius) {
    slots = detail::throughPointer(slots);
    for (uint8_t i = 0; i < count; ++i) {
      ParticleType& p = slots[i];
      if (p.inUse()) continue;
      // Every field but the generation (the handles' count goes on),
      // each written once: a whole new particle would be zeroed first.
      p.position = position;
      p.velocity = CoreVec();
      p.inverseMass = inverseMass;
      p.radius = radius;
      p.damping = 0;
      p.flags = detail::isZero(inverseMass)
                    ? uint8_t(ParticleType::kInUse | ParticleType::kCollides |
                              ParticleType::kStatic)
                    : uint8_t(ParticleType::kInUse | ParticleType::kCollides);
      p.clearAccumulated();
      return ParticleId(i, p.generation);
    }
    mError |= WorldError::kParticlesFull;
    TINYPARTICLE_DEBUG_PRINT("particle pool full");
    return ParticleId();
  }

  // Whether a handle names a live particle of the pool; else kStaleHandle
  // is raised (World::check()).
  template <class ParticleType>
  bool checkParticle(const ParticleType* slots, uint8_t count,
                     ParticleId id) {
    if (id.index < count) {
      const ParticleType& p = slots[id.index];
      if (p.inUse() && p.generation == id.generation) return true;
    }
    return staleParticle();
  }

  // Empties a particle, force or constraint slot; its generation moves on,
  // so the handles to it become stale.
  template <class Slot>
  static void freeSlot(Slot& slot) {
    const uint8_t generation = uint8_t(slot.generation + 1);
    slot = Slot();
    slot.generation = generation;
  }

  // A handle that names no live particle (World::check()): kStaleHandle,
  // false.
  bool staleParticle() {
    mError |= WorldError::kStaleHandle;
    TINYPARTICLE_DEBUG_PRINT("stale or invalid particle id");
    return false;
  }

  typedef tinyparticle::ForceSlot<S, Dim> CoreForceSlot;

  // The first free force slot takes a generator of the given kind and
  // runner (its parameters are the caller's to copy: their class is known
  // there); null and kForcesFull when there is none.
  CoreForceSlot* newForce(CoreForceSlot* slots, uint8_t count, ForceId& id,
                          uint8_t a, uint8_t b, uint8_t kind,
                          typename CoreForceSlot::Apply apply) {
    for (uint8_t i = 0; i < count; ++i) {
      CoreForceSlot& f = slots[i];
      if (f.inUse()) continue;
      f.apply = apply;
      f.a = a;
      f.b = b;
      f.kind = kind;
      id = ForceId(i, f.generation);
      return &f;
    }
    mError |= WorldError::kForcesFull;
    TINYPARTICLE_DEBUG_PRINT("force pool full");
    return nullptr;
  }

  // Places a built-in force generator of class G (its parameters in the
  // slot) with its runner; a and b as in the slot.
  template <class G>
  ForceId placeForce(CoreForceSlot* slots, uint8_t count, uint8_t a,
                     uint8_t b, const G& generator,
                     typename CoreForceSlot::Apply apply) {
    ForceId id;
    CoreForceSlot* f =
        newForce(slots, count, id, a, b,
                 KindOf<G, typename CoreForceSlot::Params>::value, apply);
    if (f != nullptr) f->params.template as<G>() = generator;
    return id;
  }

  // The step's first part: a dt that is not positive (0, negative, NaN) is
  // refused (kBadArgument, false: nothing moves); else the statics are
  // marked.
  template <class ParticleType>
  bool beginStep(ParticleType* particles, uint8_t count, S dt) {
    if (!detail::isPositive(dt)) {
      mError |= WorldError::kBadArgument;
      return false;
    }
    TINYPARTICLE_PROFILE_BEGIN(kProfileStep);
    markStatic(particles, count);
    return true;
  }

  // The step's force generators, each once (they add to the particles'
  // accumulators). Only a world with force slots has any, and only its
  // particles have accumulators.
  static void runForces(Particle<S, Dim>* particles, uint8_t count,
                        CoreForceSlot* slots, uint8_t forceCount, S dt) {
    TINYPARTICLE_PROFILE_BEGIN(kProfileForces);
    ForceStep<S, Dim> forces = {particles, count};
    for (uint8_t i = 0; i < forceCount; ++i) {
      CoreForceSlot& f = slots[i];
      if (f.apply != nullptr) f.apply(forces, f, dt);
    }
    TINYPARTICLE_PROFILE_END(kProfileForces);
  }

  // The step's first pass: a particle is static while its inverse mass is
  // 0 (a sketch may change the mass between steps).
  template <class ParticleType>
  static void markStatic(ParticleType* slots, uint8_t count) {
    slots = detail::poolThroughPointer(slots, count);
    for (uint8_t i = 0; i < count; ++i) {
      ParticleType& p = slots[i];
      p.flags = detail::isZero(p.inverseMass)
                    ? uint8_t(p.flags | ParticleType::kStatic)
                    : uint8_t(p.flags & ~ParticleType::kStatic);
    }
  }

  // v += (a + uniform) dt, damping, and x += v dt unless `andMove` is
  // false (rods: their solver moves the particles, movePositions(), and
  // only half of the uniform kick comes now, the rest after the move:
  // kick, drift, kick, the step of RATTLE, whose energy error is second
  // order in dt). kMoveHere as in ParticleSteps::integrate().
  template <bool kMoveHere, class ParticleType>
  void integrateParticles(ParticleType* slots, uint8_t count,
                          const CoreVec& uniform, const Scaler<S>& byDt,
                          bool andMove) {
    slots = detail::throughPointer(slots);
    CoreVec uniformStep;
    for (uint8_t k = 0; k < Dim; ++k) {
      if (detail::isZero(uniform[k])) continue;
      const S whole = byDt(uniform[k]);
      uniformStep[k] = andMove ? whole : detail::half(whole);
    }
    StepsFor<ParticleType>::Type::template integrate<kMoveHere>(
        slots, count, uniformStep, byDt, andMove, mError);
  }

  // For the rod solver: x += v dt for every movable particle, then the
  // rest of the uniform acceleration's kick (integrateParticles() gave the
  // first half).
  template <class ParticleType>
  void moveParticles(ParticleType* slots, uint8_t count,
                     const CoreVec& uniform, const Scaler<S>& byDt) {
    CoreVec rest;
    rest.x = restOfKick(uniform.x, byDt);
    rest.y = restOfKick(uniform.y, byDt);
    if (Dim == 3) rest[2] = restOfKick(uniform[2], byDt);
    StepsFor<ParticleType>::Type::movePositions(slots, count, rest, byDt,
                                                mError);
  }

  // One axis of it: the kick a dt less its first half. Out of line, once
  // per axis and step: a loop over the axes picks the component by its
  // index at every access.
  TINYPARTICLE_NOINLINE static S restOfKick(S acceleration,
                                            const Scaler<S>& byDt) {
    if (detail::isZero(acceleration)) return S();
    const S whole = byDt(acceleration);
    return whole - detail::half(whole);
  }

  // The step's last pass: with constraints (`checkFinite`), what the rods
  // and contacts left is checked (float only, ParticleSteps::checkFinite());
  // then the accumulators are cleared, so that forces applied between
  // steps act in the next one.
  template <class ParticleType>
  void finishStep(ParticleType* slots, uint8_t count, bool checkFinite) {
    slots = detail::throughPointer(slots);
    if (checkFinite) {
      StepsFor<ParticleType>::Type::checkFinite(slots, count, mError);
    }
    if (!ParticleType::kHasAccumulator) return;
    if (count > 1) count = detail::throughRegister(count);
    for (uint8_t i = 0; i < count; ++i) slots[i].clearAccumulated();
  }

  // The 16-bit field first: no padding byte between the fields.
  uint16_t mError;
  uint8_t mContactCount;
  uint8_t mIterationCap;
  StepStats mStats;
};

}  // namespace tinyparticle
