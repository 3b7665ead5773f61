// Particle: a point mass with a radius, the only body the engine simulates.
//
// A public plain struct: sketches read and write its fields directly through
// the pointer that World::particle() returns. 2D Q16.16 takes 36 bytes:
// position, velocity and the acceleration accumulator (8 each), inverse mass
// and radius (4 each), damping (2), flags and generation (1 each).
//
// Particle<S, Dim> is the particle of a world with force slots, and the one
// that force generators see. A world without force slots has nothing to
// fill an accumulator with: its particles are Particle<S, Dim, false>
// (World::ParticleType), 8 bytes smaller in 2D Q16.16, with the same fields
// and functions but the accumulator (accumulated() reads zero there).
#pragma once

#include <stdint.h>

#include "../Math/Vec.hpp"

namespace tinyparticle {

namespace detail {
template <typename S, uint8_t Dim>
struct Damping;

// Every field and function of a particle but the accumulator.
template <typename S, uint8_t Dim>
struct ParticleBase {
  typedef Vec<S, Dim> VecType;

  enum : uint8_t {
    kInUse = 1,     // the slot holds a live particle
    kCollides = 2,  // takes part in planes and particle collisions
    // Set by the world at the start of each step when inverseMass is 0, so
    // that the step's many immovability tests are a bit test, not a scalar
    // compare (a float compare costs about 45 cycles on AVR).
    kStatic = 4,
    // Asleep (World::enableSleeping()): not stepped, not tested against
    // planes or other resting particles, until something wakes it.
    kAsleep = 8,
  };

  VecType position;
  VecType velocity;
  // 1 / mass; 0 makes the particle immovable (nothing ever moves it).
  S inverseMass;
  // For collisions and planes; also the size the renderer draws.
  S radius;
  // Linear damping rate in units of 1/256 per second: each step the velocity
  // loses the fraction damping / 256 * dt (one multiply; skipped when 0).
  // Set it with setDampingRate() (in 1/s), which also switches on the
  // step's damping code (detail::Damping): a sketch that never calls it
  // links none, and a value written here directly is then ignored.
  uint16_t damping;
  uint8_t flags;
  // Bumped when the slot is freed, so that old handles are recognised.
  uint8_t generation;

  constexpr ParticleBase()
      : position(), velocity(), inverseMass(), radius(), damping(0), flags(0),
        generation(0) {}

  bool inUse() const { return (flags & kInUse) != 0; }
  bool collides() const { return (flags & kCollides) != 0; }
  bool isImmovable() const { return inverseMass == S(); }
  // isImmovable() as of the start of the current step (see kStatic).
  bool isStatic() const { return (flags & kStatic) != 0; }
  bool isAsleep() const { return (flags & kAsleep) != 0; }
  // Immovable or asleep: two such particles need no contact.
  bool isResting() const { return (flags & (kStatic | kAsleep)) != 0; }

  // Mass in kg; an immovable particle reports S::largest().
  S mass() const {
    return isImmovable() ? S::largest() : detail::compactReciprocal(inverseMass);
  }

  void setCollides(bool on) {
    flags = on ? uint8_t(flags | kCollides) : uint8_t(flags & ~kCollides);
  }

  // Sets the damping rate in 1/s (0 to 255.99). Velocity then decays like
  // exp(-rate * t) for small rate * dt.
  void setDampingRate(S rate) {
    // (No S(65535): it does not fit every format, and a conversion out of
    // range raises MathError::kOverflow.)
    S scaled = rate * S(256);
    const int32_t n = scaled.toInt();
    damping = scaled <= S() ? uint16_t(0)
            : n >= 65535 || scaled == S::largest() ? uint16_t(65535)
            : uint16_t(n);
    if (damping != 0) detail::Damping<S, Dim>::on();
  }
  S dampingRate() const { return S(long(damping)) * S(1.0 / 256); }
};

}  // namespace detail

template <typename S, uint8_t Dim, bool kAccumulates = true>
struct Particle : detail::ParticleBase<S, Dim> {
  typedef Vec<S, Dim> VecType;
  static const bool kHasAccumulator = true;

  // Acceleration accumulated by force generators (force * inverseMass)
  // during a step; cleared at the end of the step, so a force applied
  // between steps acts in the next one.
  VecType acceleration;

  constexpr Particle() : detail::ParticleBase<S, Dim>(), acceleration() {}

  // The accumulator, for code that serves both kinds of particle.
  const VecType& accumulated() const { return acceleration; }
  void clearAccumulated() { acceleration = VecType(); }

  // Adds a force for the current step (as acceleration: force * 1/mass).
  void addForce(const VecType& force) {
    acceleration.addScaled(force, this->inverseMass);
  }
};

// The particle of a world without force slots: no accumulator, so its
// acceleration is the world's gravity alone.
template <typename S, uint8_t Dim>
struct Particle<S, Dim, false> : detail::ParticleBase<S, Dim> {
  typedef Vec<S, Dim> VecType;
  static const bool kHasAccumulator = false;

  constexpr Particle() : detail::ParticleBase<S, Dim>() {}

  // A constant zero: the step's and the contacts' reads of it fold away.
  VecType accumulated() const { return VecType(); }
  void clearAccumulated() {}

  // (A template, so that the assert fires only where it is called.)
  template <bool kCalled = true>
  void addForce(const VecType&) {
    static_assert(!kCalled,
                  "this World has no force slot, so its particles keep no "
                  "force accumulator: World<S, Dim, particles, forces, "
                  "constraints, contacts> needs forces > 0 for applyForce() "
                  "and addForce()");
  }
};

namespace detail {

// The damping of one particle's velocity in a step (World::integrate()),
// called through a pointer that the first setDampingRate() of a nonzero
// rate sets: a sketch that never damps links neither this nor its
// multiplies (250 bytes of the lever scene's step). `unit` is dt / 256.
template <typename S, uint8_t Dim>
struct Damping {
  typedef void (*Apply)(ParticleBase<S, Dim>& p, S unit);
  static Apply sApply;  // null until a particle is damped

  static void on() { sApply = &apply; }
  static void apply(ParticleBase<S, Dim>& p, S unit) {
    S loss = S(long(p.damping)) * unit;
    if (loss >= S(1)) {
      p.velocity = Vec<S, Dim>();
    } else {
      p.velocity.addScaled(p.velocity, -loss);
    }
  }
};
template <typename S, uint8_t Dim>
typename Damping<S, Dim>::Apply Damping<S, Dim>::sApply = nullptr;

}  // namespace detail
}  // namespace tinyparticle
