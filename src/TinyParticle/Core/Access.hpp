// WorldAccess: the narrow interface through which generators and the
// renderer reach a world's unchecked internals (slots by index, the step's
// uniform acceleration, the contact pool). World keeps its public face to
// the sketch's calls, which check their handles; it lets this class, and no
// one else, at the rest (the attorney idiom: a friend that forwards only
// what its users need). Every function is a one-line forward, inlined.
//
// The world type W is a template argument, so this header needs none of
// World's: forces and contact generators include it from below World.
#pragma once

#include <stdint.h>

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
  static const typename W::ConstraintSlot& constraint(const W& world,
                                                      uint8_t i) {
    return world.constraintAt(i);
  }

  // For gravity on every particle: adds to this step's uniform acceleration.
  template <class W>
  static void addUniformAcceleration(W& world, const typename W::Vec& a) {
    world.addUniformAcceleration(a);
  }

  // For contact generators: records a contact for this step (see
  // World::addContact), made by constraint slot `source`.
  template <class W>
  static void addContact(W& world, uint8_t a, uint8_t b,
                         const typename W::Vec& normal,
                         typename W::Scalar penetration, uint8_t source) {
    world.addContact(a, b, normal, penetration, source);
  }
};

}  // namespace tinyparticle
