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

// A generator class (Core/Generator.hpp), run for one particle.
template <typename S, uint8_t Dim>
struct CustomForce {
  static const uint8_t kShape = SlotShape::kNone;
  const Vec<S, Dim>* force;  // N; must outlive the generator

  static CustomForce make(const Vec<S, Dim>* force) {
    CustomForce custom;
    custom.force = force;
    return custom;
  }

  void apply(Particle<S, Dim>& p, S) const {
    if (detail::isZeroVector(*force)) return;
    p.acceleration.addScaled(*force, p.inverseMass);
  }
};

}  // namespace tinyparticle
