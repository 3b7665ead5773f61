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
      // Every field but the generation (the handles' count goes on): its
      // bytes zeroed (see freeSlot()) by a loop written out here, smaller
      // than the stores of the zero fields (a call of clearBytesBut() took
      // 28 bytes more: the arguments wait in saved registers across it),
      // then the rest.
      static_assert(sizeof(ParticleType) < 256,
                    "a particle's bytes are counted in 8 bits");
      uint8_t* const bytes = reinterpret_cast<uint8_t*>(&p);
      const uint8_t kept = uint8_t(&p.generation - bytes);
      for (uint8_t k = 0; k < sizeof(ParticleType); ++k) {
        if (k != kept) bytes[k] = 0;
      }
      p.position = position;
      p.inverseMass = inverseMass;
      p.radius = radius;
      p.flags = detail::isZero(inverseMass)
                    ? uint8_t(ParticleType::kInUse | ParticleType::kCollides |
                              ParticleType::kStatic)
                    : uint8_t(ParticleType::kInUse | ParticleType::kCollides);
      return ParticleId(i, p.generation);
    }
    mError |= WorldError::kParticlesFull;
    TINYPARTICLE_DEBUG_PRINT("particle pool full");
    return ParticleId();
  }

  // The particle a handle names, if it is live; else null. Out of line:
  // every add*() checks its handles, and a sketch looks its particles up
  // in its loop (World::particle()); written out, each took about 40 bytes.
  template <class ParticleType>
  TINYPARTICLE_NOINLINE static ParticleType* liveParticle(
      ParticleType* slots, uint8_t count, ParticleId id) {
    if (id.index < count) {
      ParticleType& p = slots[id.index];
      if (p.inUse() && p.generation == id.generation) return &p;
    }
    return nullptr;
  }

  // Whether a handle names a live particle of the pool; else kStaleHandle
  // is raised (World::check()).
  template <class ParticleType>
  bool checkParticle(ParticleType* slots, uint8_t count, ParticleId id) {
    if (liveParticle(slots, count, id) != nullptr) return true;
    return staleParticle();
  }

  // Empties a particle, force or constraint slot; its generation moves on,
  // so the handles to it become stale.
  // (All bytes zero is every slot's empty state: null pointers, zero
  // scalars, no flags; a scalar's zero is all zero bytes, as Fixed's,
  // Float's and any IEEE float's. One routine for every slot type: a
  // constraint slot's type names its World, and the copy per type cost 30
  // bytes.)
  template <class Slot>
  static void freeSlot(Slot& slot) {
    clearBut(slot);
    ++slot.generation;
  }
  // Every byte of the slot zero but its generation.
  template <class Slot>
  static void clearBut(Slot& slot) {
    static_assert(sizeof(Slot) < 256, "a slot's bytes are counted in 8 bits");
    uint8_t* const bytes = reinterpret_cast<uint8_t*>(&slot);
    clearBytesBut(bytes, sizeof(Slot), uint8_t(&slot.generation - bytes));
  }
  TINYPARTICLE_NOINLINE static void clearBytesBut(uint8_t* bytes,
                                                  uint8_t size,
                                                  uint8_t kept) {
    for (uint8_t i = 0; i < size; ++i) {
      if (i != kept) bytes[i] = 0;
    }
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
    // (Through a hidden pointer: a short store per field, here and in the
    // caller's copy of the parameters.)
    slots = detail::throughPointer(slots);
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
    if (count > 1) count = detail::throughRegister(count);
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
  // order in dt). kMoveHere as in ParticleSteps::integrate(). `restKick`
  // receives the rest of the kick for moveParticles() (zero when the
  // whole kick came now; not written when kMoveHere).
  template <bool kMoveHere, class ParticleType>
  void integrateParticles(ParticleType* slots, uint8_t count,
                          const CoreVec& uniform, const Scaler<S>& byDt,
                          bool andMove, CoreVec& restKick) {
    slots = detail::throughPointer(slots);
    CoreVec uniformStep;
    if (kMoveHere) {
      // No rods: always the whole kick, and no halves linked.
      for (uint8_t k = 0; k < Dim; ++k) {
        if (!detail::isZero(uniform[k])) uniformStep[k] = byDt(uniform[k]);
      }
    } else {
      uniformStep.x = kickPart(uniform.x, byDt, andMove, restKick.x);
      uniformStep.y = kickPart(uniform.y, byDt, andMove, restKick.y);
      if (Dim == 3) {
        uniformStep[2] = kickPart(uniform[2], byDt, andMove, restKick[2]);
      }
    }
    StepsFor<ParticleType>::Type::template integrate<kMoveHere>(
        slots, count, uniformStep, byDt, andMove, mError);
  }

  // For the rod solver: x += v dt for every movable particle, then
  // `restKick`, the rest of the uniform acceleration's kick
  // (integrateParticles() gave the first half and worked out the rest).
  template <class ParticleType>
  void moveParticles(ParticleType* slots, uint8_t count,
                     const CoreVec& restKick, const Scaler<S>& byDt) {
    StepsFor<ParticleType>::Type::movePositions(slots, count, restKick, byDt,
                                                mError);
  }
  // The same for a step of another dt than integrateParticles()'s (the
  // rods' solver takes a hard step as two of dt / 2): the rest of that
  // dt's kick, worked out here.
  template <class ParticleType>
  void moveParticlesBy(ParticleType* slots, uint8_t count,
                       const CoreVec& uniform, const Scaler<S>& byDt) {
    CoreVec rest;
    kickPart(uniform.x, byDt, false, rest.x);
    kickPart(uniform.y, byDt, false, rest.y);
    if (Dim == 3) kickPart(uniform[2], byDt, false, rest[2]);
    moveParticles(slots, count, rest, byDt);
  }

  // One axis of the uniform acceleration's kick a dt: the whole kick
  // (`whole`, rest 0) or its first half, the rest (the whole less the
  // first half) into `rest`. Both halves in one call, once per axis and
  // step: the rest worked out again after the move cost two more calls a
  // step (the lever Q24.8 was 3.5 % slower than f83da34 with them). Out of
  // line: a loop over the axes picks the component by its index at every
  // access.
  // (The component by reference: its address is two instructions where
  // its value took four loads at every call.)
  TINYPARTICLE_NOINLINE static S kickPart(const S& component,
                                          const Scaler<S>& byDt, bool whole,
                                          S& rest) {
    const S acceleration = component;
    S first = S();
    S all = S();
    if (!detail::isZero(acceleration)) {
      all = byDt(acceleration);
      first = whole ? all : detail::half(all);
    }
    rest = all - first;
    return first;
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
