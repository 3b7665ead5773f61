// Drag: a force against the velocity, k1 * |v| + k2 * |v|^2 in magnitude
// (k1 in N s/m, k2 in N s^2/m^2). One square root per particle and step.
// A falling particle of mass m reaches the terminal speed v where
// k1 v + k2 v^2 = m g.
#pragma once

#include <stdint.h>

#include "../Core/Generator.hpp"
#include "../Core/Particle.hpp"

namespace tinyparticle {

// A generator class (Core/Generator.hpp): its parameters and its force on
// one particle; the world runs it for one particle or for each.
template <typename S, uint8_t Dim>
struct DragForce {
  static const uint8_t kShape = SlotShape::kNone;
  S k1;  // N s/m
  S k2;  // N s^2/m^2

  static DragForce make(S k1, S k2) {
    DragForce drag;
    drag.k1 = k1;
    drag.k2 = k2;
    return drag;
  }

  void apply(Particle<S, Dim>& p, S) const {
    S speedSquared = p.velocity.magnitudeSquared();
    if (speedSquared == S()) return;
    // F = -v * (k1 + k2 |v|), so |F| = k1 |v| + k2 |v|^2.
    S coefficient = k1;
    if (k2 != S()) coefficient += k2 * sqrt(speedSquared);
    p.acceleration.addScaled(p.velocity, -(coefficient * p.inverseMass));
  }
};

}  // namespace tinyparticle
