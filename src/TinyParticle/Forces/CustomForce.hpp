// Custom force: each step adds the force held in a vector that the sketch
// owns and updates (for example from sensors), read through a pointer. This
// is how the HapticLever puts the user's push into the simulation.
#pragma once

#include <stdint.h>

#include "../Core/Generator.hpp"
#include "../Core/Particle.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"

namespace tinyparticle {

// A generator class (Core/Generator.hpp) with a runner of its own (run()):
// a force that is zero (the usual case: nobody pushes) is left before the
// particle is looked up.
template <typename S, uint8_t Dim>
struct CustomForce {
  static const uint8_t kShape = SlotShape::kNone;
  const Vec<S, Dim>* force;  // N; must outlive the generator

  static CustomForce make(const Vec<S, Dim>* force) {
    CustomForce custom;
    custom.force = force;
    return custom;
  }

  template <class W>
  static void run(W& world, typename W::ForceSlot& slot, S) {
    const Vec<S, Dim>& push = *InSlot::of<CustomForce>(slot).force;
    if (detail::isZeroVector(push)) return;
    Particle<S, Dim>& p = WorldAccess::particle(world, slot.a);
    p.acceleration.addScaled(push, p.inverseMass);
  }
};

}  // namespace tinyparticle
