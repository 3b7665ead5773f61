// Custom force: each step adds the force held in a vector that the sketch
// owns and updates (for example from sensors), read through a pointer. This
// is how the HapticLever puts the user's push into the simulation.
#pragma once

#include <stdint.h>

#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"

namespace tinyparticle {

template <typename S, uint8_t Dim>
struct CustomForceParams {
  const Vec<S, Dim>* force;  // N; must outlive the generator
};

template <class W>
struct CustomForce {
  typedef typename W::Scalar S;

  static void apply(W& world, typename W::ForceSlot& slot, S) {
    const typename W::Vec& force = *slot.params.custom.force;
    if (detail::isZeroVector(force)) return;
    typename W::ParticleType& p = world.particleAt(slot.a);
    p.acceleration.addScaled(force, p.inverseMass);
  }
};

}  // namespace tinyparticle
