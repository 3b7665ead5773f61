// WorldAccess: the narrow interface through which generators and the
// renderer reach a world's unchecked internals (slots by index, the world's
// gravity, the contact pool). World keeps its public face to
// the sketch's calls, which check their handles; it lets this class, and no
// one else, at the rest (the attorney idiom: a friend that forwards only
// what its users need). Every function is a one-line forward, inlined.
//
// The world type W is a template argument, so this header needs none of
// World's: forces and contact generators include it from below World.
#pragma once

#include <stdint.h>

#include "../Math/Scaler.hpp"

namespace tinyparticle {

class WorldAccess {
 public:
  // Slots by index, without checks: index < capacity.
  template <class W>
  static typename W::ParticleType& particle(W& world, uint8_t i) {
    return world.particleAt(i);
  }
  template <class W>
  static const typename W::ParticleType& particle(const W& world, uint8_t i) {
    return world.particleAt(i);
  }
  template <class W>
  static const typename W::ForceSlot& force(const W& world, uint8_t i) {
    return world.forceAt(i);
  }
  template <class W>
  static typename W::ConstraintSlot& constraint(W& world, uint8_t i) {
    return world.constraintAt(i);
  }
  template <class W>
  static const typename W::ConstraintSlot& constraint(const W& world,
                                                      uint8_t i) {
    return world.constraintAt(i);
  }
  template <class W>
  static typename W::ContactType& contact(W& world, uint8_t i) {
    return world.contactAt(i);
  }
  template <class W>
  static const typename W::ContactType& contact(const W& world, uint8_t i) {
    return world.contactAt(i);
  }
  template <class W>
  static bool isRod(const W& world, const typename W::ConstraintSlot& c) {
    return world.isRod(c);
  }
  template <class W>
  static bool isCollision(const W& world, uint8_t constraintIndex) {
    return world.isCollision(constraintIndex);
  }
  template <class W>
  static typename W::Scalar restitutionOf(const W& world,
                                          uint8_t constraintIndex) {
    return world.restitutionOf(constraintIndex);
  }
  template <class W>
  static void raiseError(W& world, uint16_t bits) {
    world.raiseError(bits);
  }

  // The step in progress: its dt as a multiplier, and the acceleration a
  // particle gets in it along a contact normal (World::accelerationAlong).
  template <class W>
  static const Scaler<typename W::Scalar>& stepScaler(const W& world) {
    return world.stepScaler();
  }
  template <class W>
  static typename W::Scalar accelerationAlong(
      const W& world, const typename W::ParticleType& p,
      const typename W::ContactType::Normal& direction) {
    return world.accelerationAlong(p, direction);
  }

  // For the rod solvers: their state bits (World::kRods...), dt's inverse,
  // and the positions' move, which the step leaves to them.
  template <class W>
  static uint8_t rodState(const W& world) {
    return world.rodState();
  }
  template <class W>
  static void setRodState(W& world, uint8_t state) {
    world.setRodState(state);
  }
  template <class W>
  static typename W::Scalar inverseDt(W& world, typename W::Scalar dt) {
    return world.inverseDt(dt);
  }
  template <class W>
  static void movePositions(W& world,
                            const Scaler<typename W::Scalar>& byDt) {
    world.movePositions(byDt);
  }
  // The same with the step's own Scaler (World::movePositionsOfStep()).
  template <class W>
  static void movePositionsOfStep(W& world,
                                  const Scaler<typename W::Scalar>& byDt) {
    world.movePositionsOfStep(byDt);
  }

  // For sleeping (World/Sleep.hpp): the steps in a row at rest, and
  // whether some particles sleep.
  template <class W>
  static uint8_t restCount(const W& world) {
    return world.restCount();
  }
  template <class W>
  static bool hasSleepers(const W& world) {
    return world.hasSleepers();
  }
  template <class W>
  static void setRest(W& world, uint8_t count, bool sleepers) {
    world.setRest(count, sleepers);
  }
  // For the resolver: a contact has pushed a sleeper; all wake.
  template <class W>
  static void wakeInContacts(W& world) {
    world.wakeInContacts();
  }

  // For contact generators: records a contact for this step (see
  // World::addContact), made by constraint slot `source`; recordContact()
  // when the generator has computed the separating velocity.
  template <class W>
  static void addContact(W& world, uint8_t a, uint8_t b,
                         const typename W::Vec& normal,
                         typename W::Scalar penetration, uint8_t source) {
    world.addContact(a, b, normal, penetration, source);
  }
  template <class W>
  static void recordContact(W& world, uint8_t a, uint8_t b,
                            const typename W::Vec& normal,
                            typename W::Scalar penetration,
                            typename W::Scalar separating, uint8_t source) {
    world.recordContact(a, b, normal, penetration, separating, source);
  }
  // The same with the normal in the contacts' stored form (Contact::Normal).
  template <class W>
  static void addStored(W& world, uint8_t a, uint8_t b,
                        const typename W::ContactType::Normal& normal,
                        typename W::Scalar penetration,
                        typename W::Scalar separating, uint8_t source) {
    world.addStored(a, b, normal, penetration, separating, source);
  }
  // For the resolver's pool policy (Resolver::slotFor()).
  template <class W>
  static void takeContactSlot(W& world) {
    world.takeContactSlot();
  }
  template <class W>
  static void dropContact(W& world) {
    world.dropContact();
  }
};

}  // namespace tinyparticle
