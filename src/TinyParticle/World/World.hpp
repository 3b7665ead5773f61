// World: the particle world, with every pool allocated statically.
//
//   World<S, Dim, kParticles, kForces, kConstraints, kContacts>
//
// S is the scalar (Q16_16, Q24_8, Float...), Dim is 2 or 3, and the four
// capacities size the pools. Nothing is allocated at run time. What a scene
// does not use costs nothing: a pool of capacity 0 takes no RAM and its step
// code disappears at compile time; a generator type that is never added is
// never instantiated, so its code is not linked.
//
// Gravity on every particle is a setting of the world (addGravity()), not a
// force slot: every world keeps it, also one with no force slot. A world
// without force slots also keeps no force accumulator in its particles
// (ParticleType is Particle<S, Dim, false>, Core/Particle.hpp).
//
// A step (step(dt)):
//  1. force generators add acceleration to their particles' accumulators;
//  2. semi-implicit Euler: v += a dt (plus the world's g dt, computed once),
//     damping (one multiply, skipped when 0), x += v dt, for every particle
//     that is in use and movable. When dt is a power of two (1/256 s...),
//     the multiplies by dt are rounding shifts (Math/Scaler.hpp). For a
//     float scalar the new velocity and position are checked here, the
//     one place that touches them all: one that is inf or NaN stops the
//     particle and raises WorldError::kNonFinite (see World/ParticleSteps.hpp);
//  3. contact generators (rods, cables, planes, collisions) fill the contact
//     pool;
//  4. the resolver (Contacts/Resolver.hpp) resolves them; for a float
//     scalar what the rods and contacts leave is checked as in 2, so that
//     after a step every particle is finite or kNonFinite is set;
//  5. the accumulators are cleared, so forces applied between steps act in
//     the next step.
//
// A dt <= 0 (or NaN) is refused: nothing moves, kBadArgument is raised.
// clear() empties a world in place.
//
// Conventions: SI units; y points up and gravity is (0, -9.81[, 0]) m/s^2.
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "../Contacts/Collisions.hpp"
#include "../Contacts/Contact.hpp"
#include "../Contacts/Link.hpp"
#include "../Contacts/LoneRod.hpp"
#include "../Contacts/Plane.hpp"
#include "../Contacts/Resolver.hpp"
#include "../Contacts/RodSolver.hpp"
#include "../Debug/Debug.hpp"
#include "../Debug/Profile.hpp"
#include "../Math/ScalarTraits.hpp"
#include "../Math/Scaler.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "../Core/Handle.hpp"
#include "../Core/Particle.hpp"
#include "ParticleSteps.hpp"
#include "RodState.hpp"
#include "Sleep.hpp"
#include "Slots.hpp"
#include "UniformAcceleration.hpp"
#include "WorldCore.hpp"

namespace tinyparticle {

template <typename S, uint8_t Dim, uint8_t kParticles, uint8_t kForces = 0,
          uint8_t kConstraints = 0, uint8_t kContacts = 0>
class World
    : private detail::Pool<Particle<S, Dim, (kForces > 0)>, kParticles>,
      private detail::Pool<ForceSlot<S, Dim>, kForces>,
      private detail::Pool<
          ConstraintSlot<
              S, Dim,
              World<S, Dim, kParticles, kForces, kConstraints, kContacts> >,
          kConstraints>,
      private detail::Pool<Contact<S, Dim>, kContacts>,
      private detail::UniformAcceleration<Vec<S, Dim> >,
      private detail::StepScaler<Scaler<S>, Vec<S, Dim>, (kConstraints > 0)>,
      private detail::RodState<
          void (*)(World<S, Dim, kParticles, kForces, kConstraints, kContacts>&,
                   const Scaler<S>&, S),
          S, (kConstraints > 0)>,
      private detail::SleepState<
          bool (*)(World<S, Dim, kParticles, kForces, kConstraints, kContacts>&,
                   const Scaler<S>*),
          (kConstraints > 0)>,
      // Last, so that its fields come after the pools, as members would.
      private WorldCore<S, Dim> {
  static_assert(IsScalar<S>::value, TINYPARTICLE_SCALAR_MESSAGE);
  static_assert(Dim == 2 || Dim == 3, "World is 2D or 3D");
  static_assert(kParticles < kAnchorIndex && kForces < kAnchorIndex &&
                    kConstraints < kAnchorIndex && kContacts < kAnchorIndex,
                "a pool holds at most 252 objects");

 public:
  typedef S Scalar;
  typedef tinyparticle::Vec<S, Dim> Vec;
  // Particle<S, Dim> with force slots; without, the same but the force
  // accumulator (Core/Particle.hpp).
  typedef Particle<S, Dim, (kForces > 0)> ParticleType;
  typedef Contact<S, Dim> ContactType;
  typedef tinyparticle::ForceSlot<S, Dim> ForceSlot;
  typedef tinyparticle::ConstraintSlot<S, Dim, World> ConstraintSlot;
  typedef LinkParams<S, Dim> LinkParamsType;

  static const uint8_t kDimensions = Dim;
  static const uint8_t kParticleCapacity = kParticles;
  static const uint8_t kForceCapacity = kForces;
  static const uint8_t kConstraintCapacity = kConstraints;
  static const uint8_t kContactCapacity = kContacts;

 private:
  typedef detail::Pool<ParticleType, kParticles> ParticlePool;
  typedef detail::Pool<ForceSlot, kForces> ForcePool;
  typedef detail::Pool<ConstraintSlot, kConstraints> ConstraintPool;
  typedef detail::Pool<ContactType, kContacts> ContactPool;
  typedef detail::UniformAcceleration<Vec> UniformStore;
  typedef detail::StepScaler<Scaler<S>, Vec, (kConstraints > 0)>
      StepScalerStore;
  typedef void (*RodSolve)(World&, const Scaler<S>&, S);
  typedef detail::RodState<RodSolve, S, (kConstraints > 0)> RodStore;
  typedef detail::SleepState<bool (*)(World&, const Scaler<S>*),
                             (kConstraints > 0)>
      SleepStore;
  typedef GravityForce<S, Dim> GravityType;
  // What the force runners take in place of the world (World/Slots.hpp).
  typedef ForceStep<S, Dim> Forces;
  // The step's work on the particles, shared by every World<S, Dim, ...>:
  // the routines of WorldCore, and the algorithms they run.
  typedef WorldCore<S, Dim> Core;
  typedef detail::ParticleSteps<S, Dim, (kForces > 0)> Steps;
  using Core::mError;
  using Core::mContactCount;
  using Core::mIterationCap;
  using Core::mStats;
  // Generators and the renderer reach the slots and the step's uniform
  // acceleration through it (Core/Access.hpp).
  friend class WorldAccess;

 public:
  constexpr World() {}

  // The standard gravity of every scene: 9.81 m/s^2 along -y.
  static Vec standardGravity() {
    Vec g;
    g.y = S(-9.81);
    return g;
  }

  // ---- Particles --------------------------------------------------------

  // A particle of the given mass (kg, > 0) and radius (m). It collides
  // (with planes and, if enabled, with other particles); see setCollides().
  // Returns an invalid id and sets WorldError::kParticlesFull when the pool
  // is full (kBadArgument for a mass <= 0 or NaN).
  ParticleId addParticle(const Vec& position, S mass, S radius = S()) {
    if (!detail::isPositive(mass)) {
      mError |= WorldError::kBadArgument;
      return ParticleId();
    }
    // Set-up: the compact reciprocal, so that a scene whose step never
    // divides links no fast divide (Math/Fixed.hpp).
    return addWithInverseMass(position, detail::compactReciprocal(mass),
                              radius);
  }

  // An immovable particle (inverse mass 0): pivots and anchors.
  ParticleId addFixedParticle(const Vec& position, S radius = S()) {
    return addWithInverseMass(position, S(), radius);
  }

  ParticleId addWithInverseMass(const Vec& position, S inverseMass, S radius) {
    static_assert(kParticles > 0,
                  "this World has no particle slot: World<S, Dim, particles, "
                  "forces, constraints, contacts> needs particles > 0");
    return Core::placeParticle(&particleAt(0), kParticles, position,
                               inverseMass, radius);
  }

  // The particle, or null if the id is invalid or stale.
  ParticleType* particle(ParticleId id) {
    if (kParticles == 0) return nullptr;
    return Core::liveParticle(&particleAt(0), kParticles, id);
  }
  const ParticleType* particle(ParticleId id) const {
    return const_cast<World*>(this)->particle(id);
  }

  // Removes the particle and every force generator and constraint that
  // refers to it by index (generators for all particles stay). Returns
  // false (and sets kStaleHandle) for an invalid or stale id.
  bool removeParticle(ParticleId id) {
    if (!check(id)) return false;
    for (uint8_t i = 0; i < kForces; ++i) {
      ForceSlot& f = forceAt(i);
      if (f.inUse() && (f.a == id.index || f.b == id.index)) freeSlot(f);
    }
    for (uint8_t i = 0; i < kConstraints; ++i) {
      ConstraintSlot& c = constraintAt(i);
      if (c.inUse() && (c.a == id.index || c.b == id.index)) {
        freeSlot(c);
      }
    }
    freeSlot(particleAt(id.index));
    RodStore::addRodBits(kRodsChanged);
    return true;
  }

  // Adds a force (N) for the next step: acceleration += force / mass.
  bool applyForce(ParticleId id, const Vec& force) {
    static_assert(kForces > 0,
                  "this World has no force slot, so its particles keep no "
                  "force accumulator: World<S, Dim, particles, forces, "
                  "constraints, contacts> needs forces > 0 for applyForce()");
    ParticleType* p = particle(id);
    if (p == nullptr) {
      mError |= WorldError::kStaleHandle;
      return false;
    }
    p->addForce(force);
    return true;
  }

  uint8_t particleCount() const {
    uint8_t n = 0;
    for (uint8_t i = 0; i < kParticles; ++i) {
      if (particleAt(i).inUse()) ++n;
    }
    return n;
  }

  // The handle of the particle in slot `index` (invalid if the slot is free).
  ParticleId idOf(uint8_t index) const {
    if (index >= kParticles || !particleAt(index).inUse()) return ParticleId();
    return ParticleId(index, particleAt(index).generation);
  }

  // ---- Force generators -------------------------------------------------
  // Each returns an invalid id and sets an error bit when the pool is full
  // (kForcesFull) or a particle id is stale (kStaleHandle).

  // Gravity for every particle: standard gravity, or any acceleration. It
  // is the world's, and takes no force slot (a world with none has it
  // too): every movable particle gets it each step, until removeForce()
  // of the id returned here switches it off. A second call adds to it.
  // The id is always valid (kGravityIndex); removing it removes all of
  // the world's gravity.
  ForceId addGravity() { return addGravity(standardGravity()); }
  ForceId addGravity(const Vec& acceleration) {
    UniformStore::addUniform(acceleration);
    return ForceId(kGravityIndex, 0);
  }
  // The force index of the world's gravity: never a slot (a pool holds at
  // most 252), below kAnchorIndex so that the id is valid.
  static const uint8_t kGravityIndex = 0xFC;
  // Gravity for one particle, standard gravity times `multiplier`.
  ForceId addGravity(ParticleId target, S multiplier = S(1)) {
    if (!check(target)) return ForceId();
    return placeForce(target.index, kNoIndex,
                      GravityType::make(standardGravity() * multiplier),
                      &GravityType::template runOn<Forces>);
  }

  // Drag k1 |v| + k2 |v|^2 against the velocity, on every particle or one.
  ForceId addDrag(S k1, S k2) {
    return placeForceOnEach(DragForce<S, Dim>::make(k1, k2));
  }
  ForceId addDrag(ParticleId target, S k1, S k2) {
    if (!check(target)) return ForceId();
    return placeForceOn(target.index, kNoIndex,
                        DragForce<S, Dim>::make(k1, k2));
  }

  // A spring of stiffness k (N/m) and rest length (m) between two particles.
  ForceId addSpring(ParticleId a, ParticleId b, S k, S restLength) {
    return placePairForce(a, b, SpringForce<S, Dim>::make(k, restLength));
  }
  // A spring from a particle to a fixed point.
  ForceId addSpring(ParticleId a, const Vec& anchor, S k, S restLength) {
    if (!check(a)) return ForceId();
    return placeForceOn(a.index, kAnchorIndex,
                        AnchoredSpringForce<S, Dim>::make(anchor, k, restLength));
  }
  // A bungee: a spring that only pulls, and only beyond its rest length.
  ForceId addBungee(ParticleId a, ParticleId b, S k, S restLength) {
    return placePairForce(a, b,
                          SpringForce<S, Dim, true>::make(k, restLength));
  }
  ForceId addBungee(ParticleId a, const Vec& anchor, S k, S restLength) {
    if (!check(a)) return ForceId();
    return placeForceOn(
        a.index, kAnchorIndex,
        AnchoredSpringForce<S, Dim, true>::make(anchor, k, restLength));
  }

  // Buoyancy under a water surface at height `surface` (m, along y), for
  // bodies of half-height maxDepth (m, > 0) and the given volume (m^3), in a
  // liquid of the given density (kg/m^3; water 1000). For every particle or
  // one. The full force density * volume * 9.81 is computed once: in fixed
  // point for a fixed scalar, in float for Float (Forces/Buoyancy.hpp).
  ForceId addBuoyancy(S surface, S maxDepth, S volume, S density) {
    BuoyancyForce<S, Dim> buoyancy;
    if (!BuoyancyForce<S, Dim>::make(buoyancy, surface, maxDepth, volume,
                                     density)) {
      return refused();
    }
    return placeForceOnEach(buoyancy);
  }
  ForceId addBuoyancy(ParticleId target, S surface, S maxDepth, S volume,
                      S density) {
    if (!check(target)) return ForceId();
    BuoyancyForce<S, Dim> buoyancy;
    if (!BuoyancyForce<S, Dim>::make(buoyancy, surface, maxDepth, volume,
                                     density)) {
      return refused();
    }
    return placeForceOn(target.index, kNoIndex, buoyancy);
  }

  // A stiff spring (Forces/StiffSpring.hpp) from a particle to an anchor:
  // stiffness k (N/m, >= 0) and damping (N s/m, >= 0) with the particle's
  // present mass, exact for steps of `dt` (> 0). Its two gains are computed
  // once, in float on every platform. Refused (kBadArgument, invalid id)
  // when an argument is out of range, when k or damping did not fit the
  // scalar (it arrives saturated: S::largest()), or when a gain would not
  // fit it (in Q16.16, k/m beyond about 32000 at dt = 1/256 s).
  ForceId addStiffSpring(ParticleId target, const Vec& anchor, S k, S damping,
                         S dt) {
    if (!check(target)) return ForceId();
    StiffSpringForce<S, Dim> spring;
    if (!StiffSpringForce<S, Dim>::make(
            spring, anchor, k, damping, dt,
            particleAt(target.index).inverseMass)) {
      TINYPARTICLE_DEBUG_PRINT("stiff spring does not fit the scalar");
      return refused();
    }
    return placeForceOn(target.index, kAnchorIndex, spring);
  }

  // A force (N) read each step from a vector the sketch owns.
  ForceId addCustomForce(ParticleId target, const Vec* force) {
    if (!check(target)) return ForceId();
    if (force == nullptr) {
      mError |= WorldError::kBadArgument;
      return ForceId();
    }
    return placeForce(target.index, kNoIndex, CustomForce<S, Dim>::make(force),
                      &CustomForce<S, Dim>::template run<Forces>);
  }

  // A force generator of the sketch's own (extras/doc/design.md, "Adding a
  // generator"): an object of any class with
  //   void apply(ParticleType& p, Scalar dt)
  // that adds to p.acceleration (p.addForce(f)), called each step for every
  // movable particle, or for one; or, added for a pair, with
  //   void apply(ParticleType& a, ParticleType& b, Scalar dt).
  // The object stays in the sketch and must outlive the generator; the
  // sketch may change its fields at any time. Errors as for the others.
  template <class G>
  ForceId addForce(G& generator) {
    return placeSketchForce<EachForceRunner<Forces, G, InSketch> >(
        kAllIndex, kNoIndex, &generator);
  }
  template <class G>
  ForceId addForce(G& generator, ParticleId target) {
    if (!check(target)) return ForceId();
    return placeSketchForce<ForceRunner<Forces, G, InSketch> >(
        target.index, kNoIndex, &generator);
  }
  template <class G>
  ForceId addForce(G& generator, ParticleId a, ParticleId b) {
    if (!checkPair(a, b)) return ForceId();
    return placeSketchForce<PairForceRunner<Forces, G, InSketch> >(
        a.index, b.index, &generator);
  }

  // The slot, to tell whether the handle is live; null if stale.
  ForceSlot* force(ForceId id) {
    return id.index < kForces ? liveSlot(forceAt(id.index), id) : nullptr;
  }
  // The parameters of a built-in generator of class C (SpringForce<S, Dim>,
  // StiffSpringForce<S, Dim>...), to read or change them; null if the
  // handle is stale or the slot holds another class.
  template <class C>
  C* forceParams(ForceId id) {
    return paramsIn<C>(force(id));
  }

  // Removes a force generator; the world's gravity for its id (false and
  // kStaleHandle when the world has none).
  bool removeForce(ForceId id) {
    if (id == ForceId(kGravityIndex, 0)) return removeGravity();
    return removeSlot(force(id));
  }

  // ---- Constraints (contact generators) ----------------------------------
  // Each returns an invalid id and sets an error bit when the pool is full
  // (kConstraintsFull) or a particle id is stale (kStaleHandle).

  // A rod: the two particles stay `length` (m, > 0) apart. Rods are solved
  // together, exactly, by Contacts/RodSolver.hpp; they take no contacts.
  // A length that is not positive is refused (kBadArgument) before a
  // slot is taken.
  ConstraintId addRod(ParticleId a, ParticleId b, S length) {
    if (!(length > S())) return refusedRod();
    if (!checkPair(a, b)) return ConstraintId();
    return rodAdded(placeRod(a.index, b.index, Vec(), length));
  }
  ConstraintId addRod(ParticleId a, const Vec& anchor, S length) {
    if (!(length > S())) return refusedRod();
    if (!check(a)) return ConstraintId();
    return anchoredRodAdded(placeRod(a.index, kAnchorIndex, anchor, length));
  }
  // A cable: at most `length` (m) apart; it bounces with `restitution`.
  ConstraintId addCable(ParticleId a, ParticleId b, S length, S restitution) {
    requireContacts();
    return addLink(a, b, length, restitution,
                   &CableConstraint<World, false>::generate);
  }
  ConstraintId addCable(ParticleId a, const Vec& anchor, S length,
                        S restitution) {
    requireContacts();
    return addAnchoredLink(a, anchor, length, restitution,
                           &CableConstraint<World, true>::generate);
  }

  // Changes a rod's or a cable's length (m, > 0). False if the id is not
  // one (kStaleHandle) or the length is not positive (kBadArgument).
  bool setLength(ConstraintId id, S length) {
    LinkParamsType* link = constraintParams<LinkParamsType>(id);
    if (link == nullptr) {
      mError |= WorldError::kStaleHandle;
      return false;
    }
    if (!(length > S())) {
      mError |= WorldError::kBadArgument;
      return false;
    }
    link->length = length;
    link->inverseLength = detail::compactReciprocal(length);
    return true;
  }

  // A half-space: every colliding particle keeps
  // dot(normal, position) - radius >= offset. The normal need not be unit
  // length (it is normalised here); along an axis it takes a fast path.
  ConstraintId addPlane(const Vec& normal, S offset, S restitution) {
    requireContacts();
    Vec unit = normal;
    if (!unit.normalize()) {
      mError |= WorldError::kBadArgument;
      return ConstraintId();
    }
    for (uint8_t k = 0; k < Dim; ++k) {
      if (unit[k] == S(1)) return addAxisPlane(k, true, offset, restitution);
      if (unit[k] == S(-1)) {
        return addAxisPlane(k, false, -offset, restitution);
      }
    }
    return placeConstraint(
        kAllIndex, kNoIndex, restitution,
        PlaneConstraint<S, Dim>::make(unit, offset),
        &EachContactRunner<World, PlaneConstraint<S, Dim>, InSlot>::generate);
  }

  // The walls of the box low <= x <= high (2 Dim axis-aligned planes, facing
  // inwards), in one constraint slot: one pass over the particles for all
  // walls. False if the pool has no free slot.
  bool addBox(const Vec& low, const Vec& high, S restitution) {
    requireContacts();
    const ConstraintId id = newScenery(
        restitution, KindOf<BoxParams<S, Dim>, ConstraintParams>::value,
        &PlaneConstraint<S, Dim>::template generateBox<World>);
    if (!id.isValid()) return false;
    BoxParams<S, Dim>& box =
        constraintAt(id.index).params.template as<BoxParams<S, Dim> >();
    // (Axis by axis, unrolled: a loop over Vec's operator[] cost more.)
    box.offsets[0] = low.x;
    box.offsets[1] = -high.x;
    box.offsets[2] = low.y;
    box.offsets[3] = -high.y;
    if (Dim == 3) {
      box.offsets[2 * Dim - 2] = low[Dim - 1];
      box.offsets[2 * Dim - 1] = -high[Dim - 1];
    }
    return true;
  }

  // Collisions between all pairs of colliding particles.
  ConstraintId addCollisions(S restitution) {
    requireContacts();
    return newScenery(restitution,
                      KindOf<CollisionParams, ConstraintParams>::value,
                      &CollisionConstraint<World>::generate);
  }
  // The same, and pairs that pass through each other within a step are
  // found at any speed (swept contacts, Contacts/Collisions.hpp); costs more
  // per step. Use one of the two.
  ConstraintId addSweptCollisions(S restitution) {
    requireContacts();
    return newScenery(restitution,
                      KindOf<CollisionParams, ConstraintParams>::value,
                      &CollisionConstraint<World>::generateSwept);
  }

  // A contact generator of the sketch's own (extras/doc/design.md, "Adding
  // a generator"): an object of any class with
  //   bool contact(const ParticleType& p, Vec& normal, Scalar& penetration)
  // called each step for every colliding, movable, awake particle, or for
  // one; or, added for a pair, with
  //   bool contact(const ParticleType& a, const ParticleType& b,
  //                Vec& normal, Scalar& penetration).
  // It returns true to make a contact: the unit normal pushes p (or a) out,
  // the penetration (m) is positive while the constraint is violated; the
  // resolver then bounces it with `restitution`. The object stays in the
  // sketch and must outlive the generator. Errors as for the others.
  template <class G>
  ConstraintId addConstraint(G& generator, S restitution) {
    requireContacts();
    return placeSketchConstraint<EachContactRunner<World, G, InSketch> >(
        kAllIndex, kNoIndex, restitution, &generator);
  }
  template <class G>
  ConstraintId addConstraint(G& generator, ParticleId target, S restitution) {
    requireContacts();
    if (!check(target)) return ConstraintId();
    return placeSketchConstraint<ContactRunner<World, G, InSketch> >(
        target.index, kNoIndex, restitution, &generator);
  }
  template <class G>
  ConstraintId addConstraint(G& generator, ParticleId a, ParticleId b,
                             S restitution) {
    requireContacts();
    if (!checkPair(a, b)) return ConstraintId();
    return placeSketchConstraint<PairContactRunner<World, G, InSketch> >(
        a.index, b.index, restitution, &generator);
  }

  // The slot, to tell whether the handle is live; null if stale.
  ConstraintSlot* constraint(ConstraintId id) {
    return id.index < kConstraints ? liveSlot(constraintAt(id.index), id)
                                   : nullptr;
  }
  // The parameters of a built-in constraint of class C (LinkParamsType for
  // rods and cables...); null if the handle is stale or the slot holds
  // another class.
  template <class C>
  C* constraintParams(ConstraintId id) {
    return paramsIn<C>(constraint(id));
  }

  bool removeConstraint(ConstraintId id) {
    RodStore::addRodBits(kRodsChanged);
    return removeSlot(constraint(id));
  }

  // ---- Stepping -----------------------------------------------------------

  // Advances the world by dt seconds (see the top of this file). A dt that
  // is not positive (0, negative, NaN) is refused: nothing moves, and
  // WorldError::kBadArgument is raised.
  void step(S dt) {
    // dt, statics, forces: WorldCore's, shared by the world types of this
    // S and Dim.
    if (!Core::beginStep(&particleAt(0), kParticles, dt)) return;
    runForces(dt, detail::Choice<(kForces > 0)>());
    // dt looked at once: a multiply by it may be a shift (Math/Scaler.hpp).
    const Scaler<S> byDt(dt);
    // Sleeping (World/Sleep.hpp): when everything sleeps, nothing moves.
    if (SleepStore::settler() != nullptr &&
        SleepStore::settler()(*this, &byDt)) {
      mContactCount = 0;
      mStats = StepStats();
      TINYPARTICLE_PROFILE_END(kProfileStep);
      return;
    }
    StepScalerStore::setStepScaler(&byDt);
    // With rods, the positions move after the rods' velocity solve, so that
    // each moves once, rounded once (the solver calls movePositions()).
    const RodSolve solveRods = RodStore::rodSolver();
    integrate(byDt, solveRods == nullptr);
    if (kConstraints != 0) {
      if (solveRods != nullptr) {
        TINYPARTICLE_PROFILE_BEGIN(kProfileRods);
        solveRods(*this, byDt, dt);
        TINYPARTICLE_PROFILE_END(kProfileRods);
      }
    }
    // Without contact slots the only constraints are rods (cables, planes
    // and collisions need contacts): no contacts to make, no resolver.
    if (kConstraints != 0 && kContacts != 0) {
      TINYPARTICLE_PROFILE_BEGIN(kProfileContacts);
      SleepStore::setInContacts(true);
      generateContacts();
      // A contact woke the sleepers: their contacts again, all awake.
      if (SleepStore::woke()) generateContacts();
      mStats.contacts = mContactCount;
      const uint16_t asked = uint16_t(mContactCount + mStats.dropped);
      if (asked > mStats.peakContacts) {
        mStats.peakContacts = asked > 255 ? uint8_t(255) : uint8_t(asked);
      }
      TINYPARTICLE_PROFILE_END(kProfileContacts);
      TINYPARTICLE_PROFILE_BEGIN(kProfileResolve);
      uint16_t cap = mIterationCap;
      if (cap == 0) cap = uint16_t(2u * mContactCount);
      if (cap > 255) cap = 255;
      mStats.iterations =
          Resolver<World>::resolve(*this, byDt, uint8_t(cap));
      SleepStore::setInContacts(false);
      TINYPARTICLE_PROFILE_END(kProfileResolve);
    }
    Core::finishStep(&particleAt(0), kParticles, kConstraints != 0);
    StepScalerStore::setStepScaler(nullptr);  // byDt ends with the step
    TINYPARTICLE_PROFILE_END(kProfileStep);
  }

  // `substeps` steps of dt each (so time advances by substeps * dt).
  void step(S dt, uint8_t substeps) {
    for (uint8_t i = 0; i < substeps; ++i) step(dt);
  }

  // Empties the world in place: no particles, forces, constraints or
  // contacts; the error bits, the statistics, the iteration cap and the
  // rods' state as in a new world. Unlike `world = World()` it builds no
  // World temporary (on a 2 KB stack that may not fit), and every slot in
  // use has its generation moved on, so that every handle from before the
  // clear is stale, also once its slot is reused.
  void clear() {
    for (uint8_t i = 0; i < kParticles; ++i) {
      if (particleAt(i).inUse()) freeSlot(particleAt(i));
    }
    for (uint8_t i = 0; i < kForces; ++i) {
      if (forceAt(i).inUse()) freeSlot(forceAt(i));
    }
    for (uint8_t i = 0; i < kConstraints; ++i) {
      if (constraintAt(i).inUse()) freeSlot(constraintAt(i));
    }
    UniformStore::clearUniform();
    RodStore::setRodBits(0);
    RodStore::setRodSolver(nullptr);
    mContactCount = 0;
    mError = 0;
    mIterationCap = 0;
    mStats = StepStats();
    SleepStore::setSettler(nullptr);
    SleepStore::setWoke(false);
    SleepStore::setRest(0, false);
  }

  // Sleeping (World/Sleep.hpp), off by default: once every particle has
  // moved slower than sleepSpeed() along every axis for 32 steps, all stop
  // and cost almost nothing until something touches them; then all wake.
  // A sketch that moves a sleeping particle by hand (its position) calls
  // wakeAll(). Its code is linked only into sketches that call this.
  void enableSleeping(bool on = true) {
    if (!on) wakeAll();
    SleepStore::setSettler(on ? &Sleeping<World>::hook : nullptr);
  }
  bool isSleepingEnabled() const { return SleepStore::settler() != nullptr; }

 private:
  // For Sleeping<World> (through WorldAccess): the steps in a row that
  // everything was at rest, and whether some particles sleep (none once
  // all are awake).
  uint8_t restCount() const { return SleepStore::restCount(); }
  bool hasSleepers() const { return SleepStore::hasSleepers(); }
  void setRest(uint8_t count, bool sleepers) {
    SleepStore::setRest(count, sleepers);
  }

 public:
  void wakeAll() {
    SleepStore::setRest(0, false);
    for (uint8_t i = 0; i < kParticles; ++i) {
      ParticleType& p = particleAt(i);
      if (!p.isAsleep()) continue;
      p.flags &= uint8_t(~ParticleType::kAsleep);
      SleepStore::setWoke(true);
      // Woken by a contact: it gets the motion of this step that it
      // missed, as if it had been awake.
      if (SleepStore::inContacts()) catchUp(p);
    }
  }
  // The speed (1/64 m/s, along each axis) below which a particle counts as
  // at rest for sleeping: four units of Q24.8 and Q8.8, the coarsest
  // scalars, and well below what gravity adds in a step at 1/256 s.
  static S sleepSpeed() { return S(1.0 / 64); }

  // The resolver's iteration cap per step; 0 (the default) means twice the
  // number of contacts of that step.
  void setIterationCap(uint8_t cap) { mIterationCap = cap; }

  const StepStats& stats() const { return mStats; }
  uint8_t contactCount() const { return mContactCount; }

  // WorldError bits, sticky until clearError().
  uint16_t error() const { return mError; }
  void clearError() { mError = 0; }

  // A particle by slot index, without checks: index < capacity (for loops
  // over the pool; handles go through particle(id)).
  ParticleType& particleAt(uint8_t i) { return ParticlePool::at(i); }
  const ParticleType& particleAt(uint8_t i) const {
    return ParticlePool::at(i);
  }

 private:
  // ---- For generators, solvers and the renderer (Core/Access.hpp) --------
  // Unchecked; WorldAccess is their one way in.
  void raiseError(uint16_t bits) { mError |= bits; }
  ConstraintSlot& constraintAt(uint8_t i) { return ConstraintPool::at(i); }
  const ConstraintSlot& constraintAt(uint8_t i) const {
    return ConstraintPool::at(i);
  }
  ContactType& contactAt(uint8_t i) { return ContactPool::at(i); }
  const ContactType& contactAt(uint8_t i) const { return ContactPool::at(i); }

 public:
  // Contacts are made a little before surfaces touch: planes and collisions
  // report a contact while the gap is at most this (31 um, or four units of
  // a coarse scalar), so that rounding cannot leave a resting particle a
  // hair above its support, free to fall and hop for a step. The resolver
  // treats depths and speeds below the same margins as resolved.
  static S contactMargin() { return ScalarTraits<S>::depthMargin(); }
  static S speedMargin() { return ScalarTraits<S>::speedMargin(); }

  // The acceleration that every movable particle gets in each step besides
  // its accumulator: the world's gravity (addGravity()), m/s^2.
  Vec uniformAcceleration() const { return UniformStore::uniform(); }
 private:

  // dot(acceleration of p in this step, direction): its accumulator plus
  // the uniform acceleration; 0 for an immovable particle. The direction is
  // a contact normal in its stored form (ContactType::Normal), so that one
  // product routine serves all contact arithmetic. (Contact normals along
  // an axis take no multiply: Contacts/Contact.hpp.)
  S accelerationAlong(const ParticleType& p,
                      const typename ContactType::Normal& direction) const {
    if (p.isStatic()) return S();
    if (kForces == 0) {
      return detail::alongNormal(UniformStore::uniform(), direction);
    }
    return detail::sumAlongNormal(p.accumulated(), UniformStore::uniform(),
                                  direction);
  }

  // For the lone rods' solve: x += v dt for every movable particle, then
  // the rest of the uniform acceleration's kick (integrate() gave the
  // first half and kept the rest). The step leaves both to the solver
  // when the world has rods. byDt is the step's (stepScaler()).
  void movePositionsOfStep(const Scaler<S>& byDt) {
    Core::moveParticles(&particleAt(0), kParticles,
                        StepScalerStore::restKick(), byDt);
  }
  // The same for the chains' solve, which may take the step as two of
  // dt / 2 (byDt is then its own): the rest of that dt's kick, worked out
  // again. (The lone rods' solve, the lever's, skips these two calls a
  // step: the lever Q24.8 was 3.5 % slower than f83da34 with them.)
  void movePositions(const Scaler<S>& byDt) {
    Core::moveParticlesBy(&particleAt(0), kParticles,
                          UniformStore::uniform(), byDt);
  }

  // During a step, for contact generators: multiplies by the step's dt.
  const Scaler<S>& stepScaler() const {
    return StepScalerStore::stepScaler();
  }

  S restitutionOf(uint8_t constraintIndex) const {
    return constraintAt(constraintIndex).restitution;
  }

  // For the rod solver: whether a constraint slot holds a rod, and the
  // solver's state (kRodsChanged: rods were added or removed since the
  // chains were found; kRodsCoupled: chains meet, so passes repeat;
  // kRodsLone: every rod is alone).
 public:
  static const uint8_t kRodsChanged = 1;
  static const uint8_t kRodsCoupled = 2;
  static const uint8_t kRodsLone = 4;

 private:
  bool isRod(const ConstraintSlot& c) const {
    return c.generate == &RodSolver<World>::generate;
  }
  uint8_t rodState() const { return RodStore::rodBits(); }
  S inverseDt(S dt) { return RodStore::inverseOf(dt); }
  void setRodState(uint8_t state) { RodStore::setRodBits(state); }

  // True if that constraint is the particle collisions (contacts between two
  // particles from a generator that acts on all of them).
  bool isCollision(uint8_t constraintIndex) const {
    return constraintAt(constraintIndex).template holds<CollisionParams>();
  }

  // Records a contact for this step, unless it is idle (see addStored()).
  // When the pool is full the least severe contact (largest separating
  // velocity) gives way to a more severe one; either way one contact is
  // dropped, counted in stats().dropped, and WorldError::kContactsDropped
  // is set.
  void addContact(uint8_t a, uint8_t b, const Vec& unit, S penetration,
                  uint8_t source) {
    // (In the stored form from here on: converted once.)
    const typename ContactType::Normal& normal = detail::storedNormal(
        unit, static_cast<const typename ContactType::Normal*>(nullptr));
    addStored(a, b, normal, penetration,
              Resolver<World>::separatingVelocityStored(*this, a, b, normal),
              source);
  }

  // addContact() for a generator that has computed the separating velocity
  // dot(va - vb, normal) itself, more cheaply (an axis plane, a cable).
  void recordContact(uint8_t a, uint8_t b, const Vec& unit, S penetration,
                     S separating, uint8_t source) {
    addStored(a, b,
              detail::storedNormal(unit, static_cast<const typename
                                   ContactType::Normal*>(nullptr)),
              penetration, separating, source);
  }
  // recordContact() with the normal in its stored form (ContactType::Normal).
  // A contact that can be left out is: touching (or within the margin), not
  // closing, and no acceleration along the normal (each particle's, see
  // accelerationAlong(), computed only when the rest holds). Only a push
  // from another contact could make it close this step, and the next step
  // would catch that. Such contacts are common (balls side by side on the
  // floor) and leaving them out spares the pool and the resolver's passes.
  // (A ball resting on another one is kept: the floor stops the lower one,
  // and then they close.) (Out of line: the generators share it, and its
  // rare full-pool path would fill their loops' registers.)
  TINYPARTICLE_NOINLINE void addStored(
      uint8_t a, uint8_t b, const typename ContactType::Normal& normal,
      S penetration, S separating, uint8_t source) {
    if (!detail::isPositive(penetration) && !detail::isNegative(separating) &&
        detail::isZero(accelerationAlong(particleAt(a), normal)) &&
        (b == kNoIndex ||
         detail::isZero(accelerationAlong(particleAt(b), normal)))) {
      return;
    }
    // Which slot it takes is the resolver's policy (Resolver::slotFor()).
    const uint8_t slot = Resolver<World>::slotFor(*this, separating);
    if (slot == kNoIndex) return;
    ContactType& c = contactAt(slot);
    c.normal = normal;
    c.penetration = penetration;
    c.separatingVelocity = separating;
    c.a = a;
    c.b = b;
    c.source = source;
  }
  // For Resolver::slotFor(): a contact takes the next free slot, or one
  // is dropped (counted in stats().dropped, kContactsDropped raised).
  void takeContactSlot() { ++mContactCount; }
  void dropContact() {
    mError |= WorldError::kContactsDropped;
    if (mStats.dropped == 0) TINYPARTICLE_DEBUG_PRINT("contact pool full");
    if (mStats.dropped != 255) ++mStats.dropped;
  }

 private:
  // Cables, planes and collisions work through contacts: a world without a
  // contact slot would drop every one of them (rods take none).
  static void requireContacts() {
    static_assert(kContacts > 0,
                  "this World has no contact slot: World<S, Dim, particles, "
                  "forces, constraints, contacts> needs contacts > 0 for "
                  "cables, planes and collisions (rods need none)");
  }

  // The slot if it is in use and of the handle's generation, else null: the
  // test behind the force and constraint handles (particles: WorldCore::
  // liveParticle()).
  template <typename Slot, typename Id>
  static Slot* liveSlot(Slot& slot, Id id) {
    return slot.inUse() && slot.generation == id.generation ? &slot : nullptr;
  }

  // Frees a force or constraint slot found by handle; a null one (stale or
  // invalid handle) is recorded instead.
  template <typename Slot>
  bool removeSlot(Slot* slot) {
    if (slot == nullptr) {
      mError |= WorldError::kStaleHandle;
      return false;
    }
    freeSlot(*slot);
    return true;
  }

  // Whether the handle names a live particle; else records a stale or
  // invalid handle.
  // (A world without particle slots says so at compile time, so that what
  // follows a successful check is seen to be dead code there.)
  bool check(ParticleId id) {
    if (kParticles == 0) return Core::staleParticle();
    return Core::checkParticle(&particleAt(0), kParticles, id);
  }

  // v += a dt (and, without rods, x += v dt) for every movable particle:
  // WorldCore's routine, shared by the world types of this S and Dim.
  // (The rest of the uniform kick, for movePositions(), kept by the world.)
  void integrate(const Scaler<S>& byDt, bool andMove) {
    TINYPARTICLE_PROFILE_BEGIN(kProfileIntegrate);
    Core::template integrateParticles<kConstraints == 0>(
        &particleAt(0), kParticles, UniformStore::uniform(), byDt, andMove,
        StepScalerStore::restKick());
    TINYPARTICLE_PROFILE_END(kProfileIntegrate);
  }

  static bool isMoving(const ParticleType& p) { return Steps::isMoving(p); }
  // x += v dt (see ParticleSteps::move()).
  bool moveParticle(ParticleType& p, const Scaler<S>& byDt) {
    return Steps::move(p, byDt, mError);
  }

  // For WorldAccess (force slots: the renderer; the uniform acceleration:
  // gravity on every particle).
  ForceSlot& forceAt(uint8_t i) { return ForcePool::at(i); }
  const ForceSlot& forceAt(uint8_t i) const { return ForcePool::at(i); }

  // Empties a slot (WorldCore::freeSlot(): one copy per slot type).
  template <class Slot>
  static void freeSlot(Slot& slot) {
    Core::freeSlot(slot);
  }

  ConstraintSlot* newConstraint(ConstraintId& id, uint8_t a, uint8_t b,
                                S restitution) {
    static_assert(kConstraints > 0,
                  "this World has no constraint slot: World<S, Dim, "
                  "particles, forces, constraints, contacts> needs "
                  "constraints > 0 for rods, cables, planes and collisions");
    // (Through a pointer the compiler cannot see through: the slot's
    // fields, written here and by the caller, take a short store each
    // where a constant address took four bytes.)
    ConstraintSlot* const slots = detail::throughPointer(&constraintAt(0));
    for (uint8_t i = 0; i < kConstraints; ++i) {
      ConstraintSlot& c = slots[i];
      if (c.inUse()) continue;
      c.a = a;
      c.b = b;
      c.restitution = restitution;
      id = ConstraintId(i, c.generation);
      return &c;
    }
    mError |= WorldError::kConstraintsFull;
    TINYPARTICLE_DEBUG_PRINT("constraint pool full");
    return nullptr;
  }

  // Places a built-in generator of class G (its parameters in the slot)
  // with its runner; a and b as in the slot.
  template <class G>
  ForceId placeForce(uint8_t a, uint8_t b, const G& generator,
                     typename ForceSlot::Apply apply) {
    static_assert(kForces > 0,
                  "this World has no force slot: World<S, Dim, particles, "
                  "forces, constraints, contacts> needs forces > 0 for "
                  "drag, springs, buoyancy, custom forces and gravity on "
                  "one particle (the world's gravity takes no slot)");
    return Core::placeForce(&forceAt(0), kForces, a, b, generator, apply);
  }
  // ... run for particle a by the ForceRunner (b: kNoIndex, or
  // kAnchorIndex for an anchorable class with its anchor).
  template <class G>
  ForceId placeForceOn(uint8_t a, uint8_t b, const G& generator) {
    return placeForce(a, b, generator,
                      &ForceRunner<Forces, G, InSlot>::apply);
  }
  // ... run for every movable particle by the EachForceRunner.
  template <class G>
  ForceId placeForceOnEach(const G& generator) {
    return placeForce(kAllIndex, kNoIndex, generator,
                      &EachForceRunner<Forces, G, InSlot>::apply);
  }
  // ... run for the pair a, b by the PairForceRunner.
  template <class G>
  ForceId placePairForce(ParticleId a, ParticleId b, const G& generator) {
    if (!checkPair(a, b)) return ForceId();
    return placeForce(a.index, b.index, generator,
                      &PairForceRunner<Forces, G, InSlot>::apply);
  }
  // A sketch's generator: the slot holds a pointer to it.
  template <class Runner, class G>
  ForceId placeSketchForce(uint8_t a, uint8_t b, G* generator) {
    SketchGenerator sketch;
    sketch.object = generator;
    return placeForce(a, b, sketch, &Runner::apply);
  }

  typedef typename ConstraintSlot::Params ConstraintParams;
  // A slot for a generator over every particle (the box, collisions), its
  // kind and runner set (the caller writes any parameters); an invalid id
  // and kConstraintsFull when the pool is full. (Out of line: a scene of
  // balls adds two, and the inlined slot search cost about 45 B each.)
  TINYPARTICLE_NOINLINE ConstraintId newScenery(
      S restitution, uint8_t kind,
      typename ConstraintSlot::Generate generate) {
    ConstraintId id;
    ConstraintSlot* c = newConstraint(id, kAllIndex, kNoIndex, restitution);
    if (c != nullptr) {
      c->kind = kind;
      c->generate = generate;
    }
    return id;
  }

  template <class G>
  ConstraintId placeConstraint(uint8_t a, uint8_t b, S restitution,
                               const G& generator,
                               typename ConstraintSlot::Generate generate) {
    ConstraintId id;
    ConstraintSlot* c = newConstraint(id, a, b, restitution);
    if (c == nullptr) return id;
    c->params.template as<G>() = generator;
    c->kind = KindOf<G, typename ConstraintSlot::Params>::value;
    c->generate = generate;
    return id;
  }
  template <class Runner, class G>
  ConstraintId placeSketchConstraint(uint8_t a, uint8_t b, S restitution,
                                     G* generator) {
    SketchGenerator sketch;
    sketch.object = generator;
    return placeConstraint(a, b, restitution, sketch, &Runner::generate);
  }

  // A slot's parameters of class C; null for no slot or another class.
  template <class C, class Slot>
  static C* paramsIn(Slot* slot) {
    return slot != nullptr && slot->template holds<C>()
               ? &slot->params.template as<C>()
               : nullptr;
  }

  // Both live, and two different particles.
  bool checkPair(ParticleId a, ParticleId b) {
    if (!check(a) || !check(b)) return false;
    if (a == b) {
      mError |= WorldError::kBadArgument;
      return false;
    }
    return true;
  }

  // A generator whose parameters are out of range: an invalid id.
  ForceId refused() {
    mError |= WorldError::kBadArgument;
    return ForceId();
  }

  // A rod between two particles just added (or an invalid id): its
  // length's inverse and its first direction, and the solver's turn on.
  // Rods between particles may form chains: the chains' solve, unless the
  // world has one constraint slot (one rod: lone, Contacts/LoneRod.hpp).
  ConstraintId rodAdded(ConstraintId id) {
    if (!startRod(id)) return ConstraintId();
    RodStore::setRodSolver(
        kConstraints == 1
            ? &LoneRods<World>::template solve<LoneEnds::kTwoMovable>
            : &RodSolver<World>::solve);
    return id;
  }
  // The same for a rod from a particle to an anchor. A world whose rods all
  // hang from anchors solves them as lone rods, without linking the chains'
  // solve; there a particle takes one rod (another one on it is refused
  // with kBadArgument), until a rod between two particles brings the
  // chains' solve, which solves any rods.
  ConstraintId anchoredRodAdded(ConstraintId id) {
    if (!startRod(id)) return ConstraintId();
    const RodSolve lone =
        &LoneRods<World>::template solve<LoneEnds::kAnchored>;
    const RodSolve current = RodStore::rodSolver();
    // (In a world of one slot the rod is alone: known at compile time, so
    // that no slot freeing is linked for a refusal that cannot happen.)
    if (current == nullptr) {
      RodStore::setRodSolver(lone);
    } else if (kConstraints > 1 && current == lone &&
               !LoneRods<World>::isAlone(*this, id.index)) {
      freeSlot(constraintAt(id.index));
      mError |= WorldError::kBadArgument;
      return ConstraintId();
    }
    return id;
  }
  // A rod's slot, written in place: its anchor and length here, the rest
  // (1 / length, direction, chain links) by startRod(). (Through a local
  // LinkParams, as the cables take, the set-up zeroed and copied it.)
  ConstraintId placeRod(uint8_t a, uint8_t b, const Vec& anchor, S length) {
    ConstraintId id;
    ConstraintSlot* c = newConstraint(id, a, b, S());
    if (c == nullptr) return id;
    LinkParamsType& link = c->params.template as<LinkParamsType>();
    link.anchor = anchor;
    link.length = length;
    c->kind = KindOf<LinkParamsType, typename ConstraintSlot::Params>::value;
    c->generate = &RodSolver<World>::generate;
    return id;
  }
  // (The length is positive: addRod() checked it. A valid id is the slot
  // just taken: no look-up.)
  bool startRod(ConstraintId id) {
    if (!id.isValid()) return false;
    RodSolver<World>::start(*this, constraintAt(id.index));
    RodStore::addRodBits(kRodsChanged);
    return true;
  }
  ConstraintId refusedRod() {
    mError |= WorldError::kBadArgument;
    return ConstraintId();
  }

  ConstraintId addLink(ParticleId a, ParticleId b, S length, S restitution,
                       typename ConstraintSlot::Generate generate) {
    if (!checkPair(a, b)) return ConstraintId();
    LinkParamsType link = LinkParamsType();
    link.length = length;
    return placeConstraint(a.index, b.index, restitution, link, generate);
  }

  ConstraintId addAnchoredLink(ParticleId a, const Vec& anchor, S length,
                               S restitution,
                               typename ConstraintSlot::Generate generate) {
    if (!check(a)) return ConstraintId();
    LinkParamsType link = LinkParamsType();
    link.anchor = anchor;
    link.length = length;
    return placeConstraint(a.index, kAnchorIndex, restitution, link,
                           generate);
  }

  // The plane x[axis] >= offset (positive) or x[axis] <= offset (negative).
  ConstraintId addAxisPlane(uint8_t axis, bool positive, S offset,
                            S restitution) {
    return placeConstraint(
        kAllIndex, kNoIndex, restitution,
        PlaneConstraint<S, Dim>::alongAxis(axis, positive, offset),
        &PlaneConstraint<S, Dim>::template generateAxis<World>);
  }

  // The step's contacts: every generator once, from an empty pool.
  void generateContacts() {
    SleepStore::setWoke(false);
    mContactCount = 0;
    mStats.dropped = 0;
    for (uint8_t i = 0; i < kConstraints; ++i) {
      ConstraintSlot& c = constraintAt(i);
      if (c.generate != nullptr) c.generate(*this, c, i);
    }
    wakeInContacts();  // (sets woke() when it wakes the sleepers)
  }

  // The integration of this step for a particle woken after it (it was
  // asleep: no accumulated force, no velocity). The gravity's kick,
  // v += g dt, as one vector: a zero component adds zero exactly.
  void catchUp(ParticleType& p) {
    const Scaler<S>& byDt = StepScalerStore::stepScaler();
    const Vec& uniform = UniformStore::uniform();
    Vec kick;
    kick.x = byDt(uniform.x);
    kick.y = byDt(uniform.y);
    if (Dim == 3) kick[2] = byDt(uniform[2]);
    p.velocity += kick;
    moveParticle(p, byDt);
  }

  // The step's force generators (WorldCore::runForces()); a world without
  // force slots has none, and particles without accumulators.
  void runForces(S dt, detail::Choice<true>) {
    Core::runForces(&particleAt(0), kParticles, &forceAt(0), kForces, dt);
  }
  void runForces(S, detail::Choice<false>) {}

  // removeForce() of the gravity's id: the world's gravity off.
  bool removeGravity() {
    if (detail::isZeroVector(UniformStore::uniform())) {
      mError |= WorldError::kStaleHandle;
      return false;
    }
    UniformStore::clearUniform();
    return true;
  }

  // A contact of the pool that has a sleeper and is closing or penetrating
  // wakes everyone: after the generators, and when the resolver is about to
  // push a sleeper. Through the sleep hook (Sleeping::hook()): a world that
  // never sleeps links no waking.
  void wakeInContacts() {
    if (SleepStore::settler() != nullptr) SleepStore::settler()(*this, nullptr);
  }
};

}  // namespace tinyparticle
