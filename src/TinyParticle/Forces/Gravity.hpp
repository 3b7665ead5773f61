// Gravity: adds a constant acceleration to one particle or to all of them.
// It never needs a mass or a division: the acceleration goes straight into
// the accumulator. One slot serves every particle of the world, and then it
// touches no particle at all: it hands the acceleration to the world, which
// adds (g dt, computed once per step) to every velocity while it integrates,
// and counts it wherever the resolver looks at a particle's acceleration.
#pragma once

#include <stdint.h>

#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "../Core/Generator.hpp"
#include "../Core/Particle.hpp"

namespace tinyparticle {

// A generator class (Core/Generator.hpp) with a runner of its own (run()):
// for every particle it touches none.
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

  // Two runners, so that a sketch links only the one it uses: gravity on
  // every particle (runUniform(), World::addGravity()) hands the
  // acceleration to the world; gravity on one particle (runOn()) adds it to
  // that particle's accumulator.
  template <class W>
  static void runUniform(W& world, typename W::ForceSlot& slot, S) {
    WorldAccess::addUniformAcceleration(
        world, InSlot::of<GravityForce>(slot).acceleration);
  }
  template <class W>
  static void runOn(W& world, typename W::ForceSlot& slot, S dt) {
    Particle<S, Dim>& p = WorldAccess::particle(world, slot.a);
    if (!p.isStatic()) InSlot::of<GravityForce>(slot).apply(p, dt);
  }
};

}  // namespace tinyparticle
