// The step's work on the particle pool alone (World.hpp): integrating,
// moving, and the float checks. It is templated on the scalar and the
// dimension only and takes the pool as a pointer and a count, so that a
// sketch with several World types links one copy of it (issue 12: each
// World<S, Dim, ...> type otherwise instantiates its own).
#pragma once

#include <stdint.h>
#include <string.h>

#include "../Configuration.hpp"
#include "../Core/Handle.hpp"
#include "../Core/Particle.hpp"
#include "../Debug/Debug.hpp"
#include "../Math/Scaler.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"

namespace tinyparticle {
namespace detail {

// n, hidden from the optimizer like throughPointer() hides an address: a
// loop over a pool of a few slots then stays a loop, where the compiler
// would write it out once per slot (a step's short passes over the
// particles: about 30 bytes a slot).
inline uint8_t throughRegister(uint8_t n) {
#if defined(__GNUC__)
  asm("" : "+r"(n));
#endif
  return n;
}
// What a non-finite component x saturates to: +-largest() for an
// infinity, 0 for a NaN.
template <typename S>
inline S finiteLimit(S x) {
  return x > S() ? S::largest() : (x < S() ? S::lowest() : S());
}
// Float: from the bits, with no float compare (a library call on AVR). An
// infinity's bits less one are the largest finite float of its sign.
inline Float finiteLimit(Float x) {
  const uint32_t bits = floatBits(x);
  if ((bits & 0x007FFFFFul) != 0) return Float();  // NaN
  const uint32_t limit = bits - 1;
  float f;
  memcpy(&f, &limit, sizeof(f));
  return Float(f);
}

// x += d, for the step's many adds to a particle's velocity and position.
// Float: inlined (the add is a call already, and the float spring has no
// cycles to spare). Fixed point: out of line, a leaf that saves no
// register: a saturating add written out is about 30 bytes a site (the
// loads, the add, the saturation's call, the stores), a call about 10, for
// about 12 cycles.
// (d first: it comes in r22..r25, where the add wants x, and moves to
// registers that need no saving.)
template <typename S>
struct AddTo {
  TINYPARTICLE_ALWAYS_INLINE static void add(S d, S& x) { x += d; }
};
template <uint8_t I, uint8_t F>
struct AddTo<Fixed<I, F> > {
  TINYPARTICLE_NOINLINE static void add(Fixed<I, F> d, Fixed<I, F>& x) {
    x = d + x;
  }
};

template <typename A, typename B>
struct IsSameScalar {
  static const bool value = false;
};
template <typename A>
struct IsSameScalar<A, A> {
  static const bool value = true;
};

// kAccumulates: the pool's particles keep a force accumulator (a world
// with force slots); without one, the accumulator's terms fold away.
template <typename S, uint8_t Dim, bool kAccumulates = true>
struct ParticleSteps {
  typedef Particle<S, Dim, kAccumulates> P;
  typedef Vec<S, Dim> V;

  // In use and movable: what the integrator steps.
  static bool isMoving(const P& p) {
    return (p.flags & (P::kInUse | P::kStatic | P::kAsleep)) == P::kInUse;
  }

  // v += a dt + uniformStep (the uniform acceleration's share, computed
  // once by the world), damping, then x += v dt when `andMove` (not with
  // rods: their solver moves the particles, movePositions()). Error bits go
  // to `error` (the world's). kMoveHere: the move written out here, for a
  // world without constraints (there integrate() is the only place that
  // moves, and a call per particle cost a spring in Float 1 %); else the
  // out-of-line move() that movePositions() shares.
  template <bool kMoveHere>
  static void integrate(P* particles, uint8_t count, const V& uniformStep,
                        const Scaler<S>& byDt, bool andMove, uint16_t& error) {
    S dampingUnit = S();
    bool haveDampingUnit = false;
    for (uint8_t i = 0; i < count; ++i) {
      P& p = particles[i];
      if (!isMoving(p)) continue;
      // One axis at a time, written out: a loop over the axes would select
      // the component at every access.
      accelerateIn<kMoveHere>(p.velocity.x, p.accumulated().x, uniformStep.x,
                              byDt);
      accelerateIn<kMoveHere>(p.velocity.y, p.accumulated().y, uniformStep.y,
                              byDt);
      if (Dim == 3) {
        accelerateIn<kMoveHere>(p.velocity[2], p.accumulated()[2],
                                uniformStep[2], byDt);
      }
      // (Linked only by a sketch that damps: Core/Particle.hpp.)
      const typename Damping<S, Dim>::Apply damp = Damping<S, Dim>::sApply;
      if (p.damping != 0 && damp != nullptr) {
        if (!haveDampingUnit) {
          dampingUnit = byDt.factor() * S(1.0 / 256);
          haveDampingUnit = true;
        }
        damp(p, dampingUnit);
      }
      // A float state that left the finite numbers (a diverging scene) is
      // flagged, and the particle stops (see nonFinite()): two bit tests
      // for the velocity, two for the position. Nothing at all for fixed
      // point, whose values are always finite.
      if (isNonFinite(p.velocity)) {
        nonFinite(p, error);
        continue;
      }
      if (!andMove) continue;
      if (kMoveHere) {
        moveWrittenOut(p, byDt, error);
      } else {
        move(p, byDt, error);
      }
    }
  }

  // For the rod solver: x += v dt for every movable particle, then `rest`,
  // the rest of the uniform acceleration's kick (integrate() gave the
  // first half).
  static void movePositions(P* particles, uint8_t count, const V& rest,
                            const Scaler<S>& byDt, uint16_t& error) {
    for (uint8_t i = 0; i < count; ++i) {
      P& p = particles[i];
      if (!isMoving(p)) continue;
      if (!move(p, byDt, error)) continue;
      accelerateIn<false>(p.velocity.x, S(), rest.x, byDt);
      accelerateIn<false>(p.velocity.y, S(), rest.y, byDt);
      if (Dim == 3) accelerateIn<false>(p.velocity[2], S(), rest[2], byDt);
    }
  }

  // x += v dt; false (and the particle stopped, see nonFinitePosition())
  // when the new position is not finite (float only). Out of line: the
  // step moves particles in two places (integrate() and, with rods,
  // movePositions()), and the sleepers' catch-up in a third.
  TINYPARTICLE_NOINLINE static bool move(P& p, const Scaler<S>& byDt,
                                         uint16_t& error) {
    return moveWrittenOut(p, byDt, error);
  }
  TINYPARTICLE_ALWAYS_INLINE static bool moveWrittenOut(P& p,
                                                        const Scaler<S>& byDt,
                                                        uint16_t& error) {
    moveAxis(p.position.x, p.velocity.x, byDt);
    moveAxis(p.position.y, p.velocity.y, byDt);
    if (Dim == 3) moveAxis(p.position[2], p.velocity[2], byDt);
    if (!isNonFinite(p.position)) return true;
    nonFinitePosition(p, error);
    return false;
  }

  // What the rods and contacts leave is checked too, so that the state a
  // step leaves is finite or flagged: contacts fed extreme input (a
  // restitution far above 1, found by extras/fuzz) can take a float
  // velocity or position beyond range after integrate() checked it. The
  // particle is treated as there (nonFinitePosition(), nonFinite()). For
  // fixed point the test is a constant false and the loop disappears.
  static void checkFinite(P* particles, uint8_t count, uint16_t& error) {
    for (uint8_t i = 0; i < count; ++i) {
      P& p = particles[i];
      if (!isMoving(p)) continue;
      if (isNonFinite(p.position)) {
        nonFinitePosition(p, error);
      } else if (isNonFinite(p.velocity)) {
        nonFinite(p, error);
      }
    }
  }

  // A particle whose new velocity is not finite (float only) keeps the
  // position it had (finite: it was checked when it moved) and stops: its
  // velocity becomes zero, and WorldError::kNonFinite is raised. Out of
  // line: rare.
  TINYPARTICLE_NOINLINE static void nonFinite(P& p, uint16_t& error) {
    p.velocity = V();
    error |= WorldError::kNonFinite;
    TINYPARTICLE_DEBUG_PRINT("non-finite state: particle stopped");
  }
  // A position that left the range while moving (a finite but huge
  // velocity, or a position set to inf or NaN from outside): each such
  // component saturates at S::largest() or S::lowest() (a NaN becomes 0),
  // as fixed point would, and the particle stops as above. (Going back to
  // the position before the move would need a copy of it for every
  // particle and step: +300 cycles each on the Nano, measured.)
  TINYPARTICLE_NOINLINE static void nonFinitePosition(P& p, uint16_t& error) {
    saturateNonFinite(p.position.x);
    saturateNonFinite(p.position.y);
    if (Dim == 3) saturateNonFinite(p.position[2]);
    nonFinite(p, error);
  }
  // One component, out of line: a call is smaller than a copy per axis.
  // (A loop over the axes through Vec's operator[] was 12 bytes more.)
  TINYPARTICLE_NOINLINE static void saturateNonFinite(S& x) {
    if (isNonFinite(x)) x = finiteLimit(x);
  }

  // One axis of a step: v += a dt + (uniform a) dt, then x += v dt. Zeros
  // are skipped: an accumulator is usually empty (gravity is uniform) and
  // resting particles have no velocity, and a compare costs far less than
  // a multiply (or a shift) and an add. Inlined: a call would cost more
  // in saved registers than the work.
  TINYPARTICLE_ALWAYS_INLINE static void accelerate(S& velocity,
                                                    S acceleration,
                                                    S uniformStep,
                                                    const Scaler<S>& byDt) {
    if (!isZero(acceleration)) AddTo<S>::add(byDt(acceleration), velocity);
    if (!isZero(uniformStep)) AddTo<S>::add(uniformStep, velocity);
  }
  // accelerate() for integrate<kMoveHere>(): written out in a world
  // without constraints (the float spring has no cycles to spare); else,
  // for Float, out of line: its two adds written out were about 90 bytes
  // an axis, and a world with rods spends its cycles on them.
  template <bool kWrittenOut>
  TINYPARTICLE_ALWAYS_INLINE static void accelerateIn(S& velocity,
                                                      S acceleration,
                                                      S uniformStep,
                                                      const Scaler<S>& byDt) {
    if (kWrittenOut || !kFloatScalar) {
      accelerate(velocity, acceleration, uniformStep, byDt);
    } else {
      accelerateOutOfLine(velocity, acceleration, uniformStep, byDt);
    }
  }
  static const bool kFloatScalar = IsSameScalar<S, Float>::value;
  TINYPARTICLE_NOINLINE static void accelerateOutOfLine(
      S& velocity, S acceleration, S uniformStep, const Scaler<S>& byDt) {
    accelerate(velocity, acceleration, uniformStep, byDt);
  }
  TINYPARTICLE_ALWAYS_INLINE static void moveAxis(S& position, S velocity,
                                                  const Scaler<S>& byDt) {
    if (!isZero(velocity)) AddTo<S>::add(byDt(velocity), position);
  }
};

}  // namespace detail
}  // namespace tinyparticle
