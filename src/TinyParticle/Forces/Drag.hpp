// Drag: a force against the velocity, k1 * |v| + k2 * |v|^2 in magnitude
// (k1 in N s/m, k2 in N s^2/m^2). One square root per particle and step.
// A falling particle of mass m reaches the terminal speed v where
// k1 v + k2 v^2 = m g.
#pragma once

#include <stdint.h>

#include "../World/Handle.hpp"

namespace tinyparticle {

template <typename S>
struct DragParams {
  S k1;
  S k2;
};

template <class W>
struct DragForce {
  typedef typename W::Scalar S;

  static void apply(W& world, typename W::ForceSlot& slot, S) {
    const DragParams<S> drag = slot.params.drag;
    if (slot.a != kAllIndex) {
      add(world.particleAt(slot.a), drag);
      return;
    }
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      typename W::ParticleType& p = world.particleAt(i);
      if (p.inUse()) add(p, drag);
    }
  }

 private:
  static void add(typename W::ParticleType& p, const DragParams<S>& drag) {
    if (p.isStatic()) return;
    S speedSquared = p.velocity.magnitudeSquared();
    if (speedSquared == S()) return;
    // F = -v * (k1 + k2 |v|), so |F| = k1 |v| + k2 |v|^2.
    S coefficient = drag.k1;
    if (drag.k2 != S()) coefficient += drag.k2 * sqrt(speedSquared);
    p.acceleration.addScaled(p.velocity, -(coefficient * p.inverseMass));
  }
};

}  // namespace tinyparticle
