// Gravity on one particle (World::addGravity(id, multiplier)): a force slot
// that adds a constant acceleration to that particle's accumulator. It never
// needs a mass or a division. Gravity on every particle is no generator: it
// is the world's (World::addGravity()), which adds g dt, computed once per
// step, to every velocity while it integrates.
#pragma once

#include <stdint.h>

#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "../Core/Generator.hpp"
#include "../Core/Particle.hpp"

namespace tinyparticle {

// A generator class (Core/Generator.hpp) with a runner of its own (runOn()).
template <typename S, uint8_t Dim>
struct GravityForce {
  static const uint8_t kShape = SlotShape::kNone;
  Vec<S, Dim> acceleration;  // g times the multiplier, m/s^2

  static GravityForce make(const Vec<S, Dim>& acceleration) {
    GravityForce gravity;
    gravity.acceleration = acceleration;
    return gravity;
  }

  // An immovable particle gets nothing: its accumulator must stay zero for
  // the resolver's resting-contact test (the runner skips it). Zero
  // components (gravity is usually along y only) are skipped: a compare is
  // cheaper than an add.
  void apply(Particle<S, Dim>& p, S) const {
    for (uint8_t k = 0; k < Dim; ++k) {
      if (!detail::isZero(acceleration[k])) p.acceleration[k] += acceleration[k];
    }
  }

  // Its runner: the acceleration into the particle's accumulator (an
  // immovable particle gets none).
  template <class W>
  static void runOn(W& world, typename W::ForceSlot& slot, S dt) {
    Particle<S, Dim>& p = WorldAccess::particle(world, slot.a);
    if (!p.isStatic()) InSlot::of<GravityForce>(slot).apply(p, dt);
  }
};

}  // namespace tinyparticle
