// Test support: the stability suite of issue 13, for any scalar.
//
// Each case runs a hard scene for a long time and returns the worst value of
// what it measures; the test sketches (extras/test/Stability*SuiteTest) assert it
// against a bound derived from physics or from the integrator's known error,
// stated with the case, and print one machine-readable line per check:
//
//   STABILITY <platform> <case> <scalar> <bound> <measured>
//
// (platform: host or nano). extras/stability/collect gathers those lines
// from the host and simavr runs into extras/stability/results.csv and the
// table in extras/stability/README.md.
// Not included by TinyParticle.h: include
// <TinyParticle/Testing/StabilityCases.hpp> after it.
#pragma once

#include <math.h>
#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

inline const char* scalarName(Q16_16) { return "Q16.16"; }
inline const char* scalarName(Q24_8) { return "Q24.8"; }
inline const char* scalarName(Float) { return "Float"; }
// For a check that involves no scalar (the real-time loop's clock).
struct NoScalar {};
inline const char* scalarName(NoScalar) { return "-"; }

// The step of the scalar around `magnitude`: one unit of the last place for
// fixed point, float's spacing there for Float.
template <uint8_t I, uint8_t F>
inline float unitAt(Fixed<I, F>, float) {
  return Fixed<I, F>::epsilon().toFloat();
}
inline float unitAt(Float, float magnitude) {
  return magnitude * 1.1920929e-7f;  // 2^-23
}

// Fixed point saturates at its edges (and raises kOverflow); a float
// reaching FLT_MAX is only rounding (it overflows to inf: kNonFinite).
template <uint8_t I, uint8_t F>
inline bool saturates(Fixed<I, F>) {
  return true;
}
inline bool saturates(Float) { return false; }

// The shortest vector component the cases use: one unit of the last place
// for fixed point; for Float 2^-60, whose square is still a normal float
// (magnitude() squares: below about 1e-19 m, FLT_MIN's square root, a
// float vector's magnitude underflows to 0; normalize() still works).
template <uint8_t I, uint8_t F>
inline Fixed<I, F> tinyUnit(Fixed<I, F>) {
  return Fixed<I, F>::epsilon();
}
inline Float tinyUnit(Float) { return Float(8.6736174e-19); }  // 2^-60

// x as d.dddddde[-]N (7 significant digits: a float's), so that tiny
// bounds and values keep their digits ("0" for zero).
inline void printScientific(float x) {
  if (x == 0) {
    Serial.print('0');
    return;
  }
  if (x < 0) {
    Serial.print('-');
    x = -x;
  }
  // By tens, not log10f() and powf(): a sketch of rod cases has no flash
  // for them. (Each step may round the last digit: these are for reading.)
  int exponent = 0;
  while (x >= 9.9999995f) {  // (what would print as 10.000000)
    x /= 10;
    ++exponent;
  }
  while (x < 0.99999995f) {
    x *= 10;
    --exponent;
  }
  Serial.print(x, 6);
  Serial.print('e');
  Serial.print(exponent);
}

// Prints the line and returns whether measured <= bound (NaN fails).
template <typename S>
bool stabilityLine(const __FlashStringHelper* name, float bound,
                   float measured) {
  Serial.print(F("STABILITY "));
#if defined(EPOXY_DUINO)
  Serial.print(F("host "));
#else
  Serial.print(F("nano "));
#endif
  Serial.print(name);
  Serial.print(' ');
  Serial.print(scalarName(S()));
  Serial.print(' ');
  printScientific(bound);
  Serial.print(' ');
  printScientific(measured);
  Serial.println();
  return measured <= bound;
}

template <typename S>
struct StabilityCases {
  typedef Vec<S, 2> V;
  // Three world types serve every case, so that a sketch pays for each
  // copy of the engine once (on the Nano the rod cases and the others need
  // a sketch each). Each is one static world, emptied in place (a world on
  // the Nano's stack is too large).
  typedef World<S, 2, 9, 1, 8, 1> RodWorld;      // pendulum, chain, rods
  typedef World<S, 2, 4, 1, 2, 3> ContactWorld;  // walls, balls, stacks
  typedef World<S, 2, 2, 1> ForceWorld;          // springs, free fall
  static RodWorld& rodWorld() {
    static RodWorld w;
    w.clear();
    return w;
  }
  static ContactWorld& contactWorld() {
    static ContactWorld w;
    w.clear();
    return w;
  }
  static ForceWorld& forceWorld() {
    static ForceWorld w;
    w.clear();
    return w;
  }

  static float speedOf(const Particle<S, 2>& p) {
    const float x = p.velocity.x.toFloat(), y = p.velocity.y.toFloat();
    return ::sqrtf(x * x + y * y);
  }
  static float distance(const Particle<S, 2>& a, const Particle<S, 2>& b) {
    const float x = a.position.x.toFloat() - b.position.x.toFloat();
    const float y = a.position.y.toFloat() - b.position.y.toFloat();
    return ::sqrtf(x * x + y * y);
  }
  static bool isFinite(const Particle<S, 2>& p) {
    const float v[4] = {p.position.x.toFloat(), p.position.y.toFloat(),
                        p.velocity.x.toFloat(), p.velocity.y.toFloat()};
    for (uint8_t k = 0; k < 4; ++k) {
      if (!(::fabsf(v[k]) <= 3.4028235e38f)) return false;
    }
    return true;
  }

  // ---- The undamped pendulum --------------------------------------------
  // L = 1 m, theta0 = 0.5 rad, 1 kg, dt = 1/256 s, `steps` steps. Returns
  // the largest |E(t) - E(0)| over the swing's energy g L (1 - cos theta0);
  // `lengthError` gets the largest |length - L| (m).
  static float pendulum(uint32_t steps, float* lengthError) {
    RodWorld& w = rodWorld();
    PendulumScene scene = buildPendulum(w, S(1), S(0.5), S(1));
    const Particle<S, 2>& bob = *w.particle(scene.bob);
    const float swing = 9.81f * 0.12241744f;  // 1 - cos 0.5
    const float start = energyOf(bob);
    float worst = 0;
    *lengthError = 0;
    for (uint32_t n = 0; n < steps; ++n) {
      w.step(S(1.0 / 256));
      const float e = ::fabsf(energyOf(bob) - start);
      if (e > worst) worst = e;
      const float x = bob.position.x.toFloat(), y = bob.position.y.toFloat();
      const float l = ::fabsf(::sqrtf(x * x + y * y) - 1.0f);
      if (l > *lengthError) *lengthError = l;
    }
    return worst / swing;
  }
  static float energyOf(const Particle<S, 2>& bob) {
    const float s = speedOf(bob);
    return s * s / 2 + 9.81f * bob.position.y.toFloat();
  }

  // ---- A stiff spring at and beyond the stable step ----------------------
  // 1 kg on a spring of k = (h / dt)^2 N/m to the origin (rest length 0,
  // no gravity), dt = 1/64 s, released at rest 0.1 m out: omega dt = h.
  // Returns the largest |x| / 0.1 over `steps` steps; `flaggedAt` gets the
  // first step after which the world or the math flags say the state left
  // the scalar's range (kNonFinite, kOverflow), 0 if never.
  static float spring(float h, uint16_t steps, uint16_t* flaggedAt) {
    ForceWorld& w = forceWorld();
    const float k = h * h * 64.0f * 64.0f;
    ParticleId p = w.addParticle(V(0.1, 0.0), S(1));
    w.addSpring(p, V(), S(k), S(0));
    clearMathErrors();
    float worst = 0;
    *flaggedAt = 0;
    for (uint16_t n = 1; n <= steps; ++n) {
      w.step(S(1.0 / 64));
      const float x = ::fabsf(w.particle(p)->position.x.toFloat()) / 0.1f;
      if (x > worst) worst = x;
      const bool flagged = (w.error() & WorldError::kNonFinite) != 0 ||
                           (mathErrors() & MathError::kOverflow) != 0;
      if (flagged && *flaggedAt == 0) *flaggedAt = n;
    }
    clearMathErrors();
    return worst;
  }

  // ---- High speed against a wall ------------------------------------------
  // A ball of radius 0.05 m between two walls 1 m apart (restitution 1, no
  // gravity), at `speed` m/s: it crosses the box in a few steps and bounces
  // at most steps. Over 1 s returns the largest relative change of its
  // speed; `depth` gets the deepest it was found behind a wall after a
  // step (m), `escaped` whether it was ever outside the box.
  static float wall(float speed, float* depth, bool* escaped) {
    ContactWorld& w = contactWorld();
    ParticleId p = w.addParticle(V(0.5, 0.0), S(1), S(0.05));
    w.particle(p)->velocity = V(S(speed), S());
    w.addPlane(V(1.0, 0.0), S(0), S(1));
    w.addPlane(V(-1.0, 0.0), S(-1), S(1));
    float worst = 0;
    *depth = 0;
    *escaped = false;
    for (uint16_t n = 0; n < 256; ++n) {
      w.step(S(1.0 / 256));
      const Particle<S, 2>& q = *w.particle(p);
      const float x = q.position.x.toFloat();
      const float behind = x - 0.05f < 0 ? 0.05f - x
                           : x + 0.05f > 1 ? x + 0.05f - 1 : 0.0f;
      if (behind > *depth) *depth = behind;
      if (x < 0 || x > 1) *escaped = true;
      const float change = ::fabsf(speedOf(q) / speed - 1);
      if (change > worst) worst = change;
    }
    return worst;
  }

  // ---- High speed against a ball -------------------------------------------
  // Two balls of 1 kg and radius 0.05 m, head on, restitution 1, no gravity:
  // the moving one at `speed` must hand all of it to the one at rest.
  // Collisions are tested at the end of each step, so a ball moving more
  // than a diameter per step (2 r / dt = 25.6 m/s at 256 Hz) can pass
  // through; below that it cannot. After 0.25 s returns the largest of
  // |v_struck / speed - 1| and |v_striker| / speed.
  static float ballHit(float speed) {
    ContactWorld& w = contactWorld();
    ParticleId a = w.addParticle(V(0.0, 0.0), S(1), S(0.05));
    ParticleId b = w.addParticle(V(0.5, 0.0), S(1), S(0.05));
    w.particle(a)->velocity = V(S(speed), S());
    w.addCollisions(S(1));
    for (uint8_t n = 0; n < 64; ++n) w.step(S(1.0 / 256));
    const float struck = ::fabsf(w.particle(b)->velocity.x.toFloat() / speed - 1);
    const float striker = speedOf(*w.particle(a)) / speed;
    return struck > striker ? struck : striker;
  }

  // ---- Mass ratio 1:1000 in a collision -----------------------------------
  // 1 kg at 1 m/s strikes 1 g at rest, restitution 1: the light ball
  // leaves at 2 M / (M + m) = 1.998 m/s, the heavy one keeps
  // (M - m) / (M + m) = 0.998 m/s. Returns the larger relative error.
  static float massRatioCollision() {
    ContactWorld& w = contactWorld();
    ParticleId heavy = w.addParticle(V(0.0, 0.0), S(1), S(0.05));
    ParticleId light = w.addParticle(V(0.2, 0.0), S(0.001), S(0.05));
    w.particle(heavy)->velocity = V(1.0, 0.0);
    w.addCollisions(S(1));
    for (uint8_t n = 0; n < 64; ++n) w.step(S(1.0 / 256));
    const float vl = w.particle(light)->velocity.x.toFloat();
    const float vh = w.particle(heavy)->velocity.x.toFloat();
    const float el = ::fabsf(vl / (2.0f / 1.001f) - 1);
    const float eh = ::fabsf(vh / (0.999f / 1.001f) - 1);
    return el > eh ? el : eh;
  }

  // ---- Mass ratio 1:1000 on a rod -----------------------------------------
  // 1 kg and 1000 kg on a 0.5 m rod, no gravity, the light end spinning at
  // 2 m/s, for 10 s. Returns the largest |length / L - 1|; `energy` gets
  // the largest relative change of the kinetic energy.
  static float massRatioRod(float* energy) {
    RodWorld& w = rodWorld();
    ParticleId light = w.addParticle(V(0.5, 0.0), S(1));
    ParticleId heavy = w.addParticle(V(0.0, 0.0), S(1000));
    w.addRod(light, heavy, S(0.5));
    w.particle(light)->velocity = V(0.0, 2.0);
    float worst = 0;
    *energy = 0;
    for (uint16_t n = 0; n < 2560; ++n) {
      w.step(S(1.0 / 256));
      const float v = speedOf(*w.particle(light));
      const float u = speedOf(*w.particle(heavy));
      const float e = ::fabsf((v * v + 1000 * u * u) / 4.0f - 1);
      if (e > *energy) *energy = e;
      const float l = ::fabsf(distance(*w.particle(light), *w.particle(heavy)) / 0.5f - 1);
      if (l > worst) worst = l;
    }
    return worst;
  }

  // ---- A resting stack for 60 s -------------------------------------------
  // Three balls of radius 0.1 m and 1 kg stacked on the floor, released
  // 1 mm apart, restitution 0.3, gravity. Returns the largest speed after
  // the first 2 s (m/s); `overlap` gets the deepest overlap, ball on ball
  // or ball in floor, after 2 s (m).
  static float stack(float* overlap) {
    ContactWorld& w = contactWorld();
    w.addPlane(V(0.0, 1.0), S(0), S(0.3));
    w.addCollisions(S(0.3));
    w.addGravity();
    for (uint8_t i = 0; i < 3; ++i) {
      w.addParticle(V(S(0), S(0.101) + S(0.201) * S(int(i))), S(1), S(0.1));
    }
    float fastest = 0;
    *overlap = 0;
    for (uint16_t n = 0; n < 60 * 256; ++n) {
      w.step(S(1.0 / 256));
      if (n < 2 * 256) continue;
      for (uint8_t i = 0; i < 3; ++i) {
        const Particle<S, 2>& p = w.particleAt(i);
        const float s = speedOf(p);
        if (s > fastest) fastest = s;
        const float floorDepth = 0.1f - p.position.y.toFloat();
        if (floorDepth > *overlap) *overlap = floorDepth;
        if (i > 0) {
          const float d = 0.2f - distance(p, w.particleAt(i - 1));
          if (d > *overlap) *overlap = d;
        }
      }
    }
    return fastest;
  }

  // ---- Coincident particles -------------------------------------------------
  // Two balls of radius 0.05 m at the same point (no gravity, restitution
  // 0.5): no direction separates them, yet they must come apart, finite.
  // Returns the overlap left after 1 s (m); `finite` whether both stayed
  // finite throughout.
  static float coincident(bool* finite) {
    ContactWorld& w = contactWorld();
    ParticleId a = w.addParticle(V(0.3, 0.3), S(1), S(0.05));
    ParticleId b = w.addParticle(V(0.3, 0.3), S(1), S(0.05));
    w.addCollisions(S(0.5));
    *finite = true;
    for (uint16_t n = 0; n < 256; ++n) {
      w.step(S(1.0 / 256));
      if (!isFinite(*w.particle(a)) || !isFinite(*w.particle(b))) *finite = false;
    }
    const float gap = distance(*w.particle(a), *w.particle(b));
    return gap < 0.1f ? 0.1f - gap : 0.0f;
  }

  // ---- Zero-length and tiny vectors, a rod of zero length ----------------
  // Returns how many of these came out wrong: the zero vector does not
  // normalize; tinyUnit() along an axis has that magnitude and normalizes
  // to that axis; a rod of length 0 and a plane of zero normal are refused
  // (kBadArgument, invalid id); a rod between two particles at the same
  // point is taken and pushes them apart to its length within 1 mm.
  static uint8_t tinyVectors() {
    uint8_t wrong = 0;
    V zero;
    if (zero.normalize()) ++wrong;
    V tiny(tinyUnit(S()), S());
    if (!(tiny.magnitude() == tinyUnit(S()))) ++wrong;
    if (!tiny.normalize() || !(tiny.x == S(1)) || !(tiny.y == S())) ++wrong;
    RodWorld& w = rodWorld();
    ParticleId a = w.addParticle(V(0.2, 0.2), S(1));
    ParticleId b = w.addParticle(V(0.2, 0.2), S(1));
    if (w.addRod(a, b, S()).isValid() || w.error() != WorldError::kBadArgument) ++wrong;
    w.clearError();
    if (w.addPlane(V(), S(), S()).isValid() || w.error() != WorldError::kBadArgument) ++wrong;
    w.clearError();
    if (!w.addRod(a, b, S(0.1)).isValid()) ++wrong;
    for (uint8_t n = 0; n < 64; ++n) w.step(S(1.0 / 256));
    const float l = distance(*w.particle(a), *w.particle(b));
    if (!(::fabsf(l - 0.1f) <= 0.001f)) ++wrong;
    if (!isFinite(*w.particle(a)) || !isFinite(*w.particle(b))) ++wrong;
    return wrong;
  }

  // ---- The range edge ------------------------------------------------------
  // A particle near the largest position, moving outwards fast, and one
  // near the largest speed, accelerated further by gravity. Returns how
  // many steps left a value that wrapped around (changed sign) or left the
  // range unflagged (fixed point: kOverflow; Float: kNonFinite).
  static uint16_t rangeEdge() {
    ForceWorld& w = forceWorld();
    const S top = S::largest();
    const S speed = top * S(0.25);  // 1/4 of the range per second
    // Three steps short of the edge, less one unit: the third step would
    // end one unit beyond it (not exactly on it, which would be no
    // overflow).
    const S start = top - speed * S(3.0 / 256) + S::epsilon();
    ParticleId p = w.addParticle(V(start, S()), S(1));
    ParticleId q = w.addParticle(V(), S(1));
    w.particle(p)->velocity = V(speed, S());
    w.particle(q)->velocity = V(S(), -(top - S(1)));
    w.addGravity();
    clearMathErrors();
    uint16_t wrong = 0;
    for (uint16_t n = 0; n < 64; ++n) {
      w.step(S(1.0 / 256));
      const bool flagged = (w.error() & WorldError::kNonFinite) != 0 ||
                           (mathErrors() & MathError::kOverflow) != 0;
      const Particle<S, 2>& a = *w.particle(p);
      const Particle<S, 2>& b = *w.particle(q);
      if (a.position.x < S() || b.velocity.y > S()) ++wrong;  // wrapped
      if (!flagged && saturates(S()) &&
          (a.position.x == top || b.velocity.y == -top)) {
        ++wrong;
      }
      if (!isFinite(a) || !isFinite(b)) ++wrong;
    }
    clearMathErrors();
    return wrong;
  }

  // ---- Tiny dt ---------------------------------------------------------------
  // Free fall from rest for 1 s in steps of 1 / rate s. Semi-implicit Euler
  // falls g t dt / 2 too far (x_n = g dt^2 n (n + 1) / 2); rounding adds at
  // most half a unit of the velocity's last place per step, which the
  // position carries for the rest of the fall (n^2 / 2 of them, times dt),
  // and half a unit of the position's per step. Returns |error| (m) and
  // gives that bound in `bound`.
  static float freeFall(uint16_t rate, float* bound) {
    ForceWorld& w = forceWorld();
    ParticleId p = w.addParticle(V(), S(1));
    w.addGravity();
    const S dt = S(1) / S(long(rate));
    for (uint16_t n = 0; n < rate; ++n) w.step(dt);
    const float fallen = -w.particle(p)->position.y.toFloat();
    const float h = 1.0f / rate;
    const float n = rate;
    *bound = 9.81f * h / 2 + unitAt(S(), 10) / 2 * n * n / 2 * h +
             unitAt(S(), 5) / 2 * n;
    return ::fabsf(fallen - 9.81f / 2);
  }

  // ---- Pool and contact exhaustion ------------------------------------------
  // Returns how many of these went wrong: adds beyond each pool's capacity
  // give an invalid id and the pool's error bit, and leave the pool as it
  // was; more contacts than the contact pool holds are dropped with
  // kContactsDropped, counted, and the step still leaves every ball finite
  // and above the floor.
  static uint8_t exhaustion() {
    uint8_t wrong = 0;
    ContactWorld& w = contactWorld();
    for (uint8_t i = 0; i < 4; ++i) {
      if (!w.addParticle(V(S(0.1) + S(0.2) * S(int(i)), S(0.05)), S(1), S(0.05)).isValid()) ++wrong;
    }
    if (w.addParticle(V(), S(1)).isValid() || !(w.error() & WorldError::kParticlesFull)) ++wrong;
    if (w.particleCount() != 4) ++wrong;
    // The world's gravity takes no slot; gravity on one ball (times 0: no
    // pull) fills the one force slot.
    if (!w.addGravity().isValid()) ++wrong;
    const ParticleId first = w.idOf(0);
    if (!w.addGravity(first, S(0)).isValid()) ++wrong;
    if (w.addGravity(first, S(0)).isValid() || !(w.error() & WorldError::kForcesFull)) ++wrong;
    if (!w.addPlane(V(0.0, 1.0), S(0), S(0.5)).isValid()) ++wrong;
    if (!w.addCollisions(S(0.5)).isValid()) ++wrong;
    if (w.addPlane(V(1.0, 0.0), S(0), S(0.5)).isValid() ||
        !(w.error() & WorldError::kConstraintsFull)) ++wrong;
    // Four balls resting on the floor, each kept: four contacts, three
    // slots.
    w.clearError();
    bool dropped = false;
    for (uint16_t n = 0; n < 256; ++n) {
      w.step(S(1.0 / 256));
      if (w.stats().dropped != 0) dropped = true;
    }
    if (!dropped || !(w.error() & WorldError::kContactsDropped)) ++wrong;
    for (uint8_t i = 0; i < 4; ++i) {
      const Particle<S, 2>& p = w.particleAt(i);
      if (!isFinite(p) || p.position.y.toFloat() < 0.05f - 0.005f) ++wrong;
    }
    return wrong;
  }

  // ---- The checks: each runs its case, prints its lines and returns
  // whether every measured value is within its bound. The bounds and their
  // reasons are stated here, once for every scalar.

  // Semi-implicit Euler with the rods' kick-drift-kick keeps a modified
  // energy: the true one oscillates around it with a relative amplitude of
  // about omega dt / 2 (omega = sqrt(g / L) = 3.13 rad/s) and does not
  // drift. Allowed: 2 omega dt of the swing's energy over all the steps;
  // the rod's length within 8 units of the last place at 1 m (the solver
  // puts it back every step, so its error does not grow).
  static bool checkPendulum(uint32_t steps) {
    float length;
    const float energy = pendulum(steps, &length);
    bool ok = stabilityLine<S>(steps >= 100000UL ? F("pendulum-1e5-steps-energy")
                                                : F("pendulum-2e4-steps-energy"),
                               2 * 3.13f / 256, energy);
    ok &= stabilityLine<S>(F("pendulum-rod-length-m"), 8 * unitAt(S(), 1), length);
    return ok;
  }

  // Semi-implicit Euler on a spring keeps I = omega^2 x^2 + v^2 -
  // omega^2 dt x v constant, so from rest at x0 the swing reaches
  // x0 / sqrt(1 - h^2 / 4), h = omega dt, and is stable for h < 2.
  // Recommended: h <= 1 (1.155 x0); h = 1.9 is still stable (3.20 x0).
  // Rounding moves I by at most omega^2 x u + v u a step (half a unit u
  // of x and of v, times dI/dx and dI/dv), and the swing by half of I's
  // relative change: allowed the exact swing times 1 + that, worst case,
  // over the 256 steps. Neither may be flagged. Beyond, h = 2.2, the swing grows by
  // |lambda| = 2.43 a step (lambda^2 - (2 - h^2) lambda + 1 = 0) and the
  // spring force k x leaves the scalar's range after
  // ln(range / (k x0)) / ln |lambda| steps: it must be flagged (kOverflow,
  // kNonFinite) within 3 steps of that.
  static bool checkSpring(float range) {
    bool ok = true;
    uint16_t flagged;
    const float recommended = spring(1.0f, 256, &flagged);
    ok &= stabilityLine<S>(F("spring-h1-swing-x0"), springBound(1.0f, 256), recommended);
    ok &= stabilityLine<S>(F("spring-h1-flags"), 0, flagged);
    const float largest = spring(1.9f, 256, &flagged);
    ok &= stabilityLine<S>(F("spring-h1.9-swing-x0"), springBound(1.9f, 256), largest);
    ok &= stabilityLine<S>(F("spring-h1.9-flags"), 0, flagged);
    spring(2.2f, 1024, &flagged);
    const float k = 2.2f * 2.2f * 64 * 64;
    const float b = 2 - 2.2f * 2.2f;
    const float lambda = ::fabsf((b - ::sqrtf(b * b - 4)) / 2);
    const float predicted = ::logf(range / (k * 0.1f)) / ::logf(lambda);
    ok &= stabilityLine<S>(F("spring-h2.2-flagged-by-step"), predicted + 3,
                           flagged == 0 ? 65535.0f : float(flagged));
    return ok;
  }

  static float springBound(float h, uint16_t steps) {
    const float swing = 1 / ::sqrtf(1 - h * h / 4);  // in units of x0
    const float omega = h * 64, x = swing * 0.1f, v = omega * x;
    const float perStep = omega * omega * x * unitAt(S(), x) + v * unitAt(S(), v);
    const float invariant = omega * omega * 0.01f;
    return swing * (1 + steps * perStep / invariant / 2);
  }

  // A plane holds the ball exactly: after a step nothing is behind a wall
  // beyond 4 units of the position's last place; it never leaves the box;
  // restitution 1 keeps its speed within a unit of its last place per
  // bounce (at most 256 bounces in the second).
  static bool checkWall(float speed) {
    float depth;
    bool escaped;
    const float change = wall(speed, &depth, &escaped);
    bool ok = stabilityLine<S>(F("wall-200mps-depth-m"), 4 * unitAt(S(), 1), depth);
    ok &= stabilityLine<S>(F("wall-200mps-escaped"), 0, escaped ? 1 : 0);
    ok &= stabilityLine<S>(F("wall-200mps-speed-change"), 256 * unitAt(S(), speed) / speed,
                           change);
    return ok;
  }

  // Below a diameter per step (0.9 of it: 23 m/s) the head-on hit hands
  // over all the speed: allowed 8 units of the last place at that speed.
  static bool checkBallHit() {
    const float speed = 0.9f * 0.1f * 256;
    return stabilityLine<S>(F("ball-23mps-head-on-error"), 8 * unitAt(S(), speed) / speed,
                            ballHit(speed));
  }

  // 1 kg on 1 g: the outcome within 0.1 %. (In Q16.16 the 1 g is 66
  // units, 0.7 % off, which moves the outcome by 1.4e-5; the rest is
  // rounding of velocities near 1 m/s.)
  static bool checkMassRatioCollision() {
    return stabilityLine<S>(F("mass-1to1000-collision-error"), 0.001f, massRatioCollision());
  }

  // Bounds of issue 9 for rods: the length within 0.5 %, the kinetic
  // energy within 1 % over 10 s (the heavy end's velocity changes by about
  // 2 units of Q16.16 a step, so each step rounds it by up to a quarter).
  static bool checkMassRatioRod() {
    float energy;
    const float length = massRatioRod(&energy);
    bool ok = stabilityLine<S>(F("mass-1to1000-rod-length"), 0.005f, length);
    ok &= stabilityLine<S>(F("mass-1to1000-rod-energy"), 0.01f, energy);
    return ok;
  }

  // The bounds: after 2 s no ball faster than 1 mm/s, no overlap
  // deeper than 0.5 mm, for 60 s.
  static bool checkStack() {
    float overlap;
    const float fastest = stack(&overlap);
    bool ok = stabilityLine<S>(F("stack-60s-speed-mps"), 0.001f, fastest);
    ok &= stabilityLine<S>(F("stack-60s-overlap-m"), 0.0005f, overlap);
    return ok;
  }

  // ---- A chain of 8 rods -----------------------------------------------------
  // The whip chain (Scenes/Chain.hpp) falling from level for 10 s at
  // 256 Hz. Returns the largest |length / L - 1|; `energy` gets the
  // largest |E(t) - E(0)| / E_fall, `error` the world's error bits.
  static float chain(float* energy, uint8_t* error) {
    RodWorld& w = rodWorld();
    buildChain(w, 8);
    const float fall = 0.05f * 9.81f * 0.125f * 8 * 9 / 2;
    const float start = chainEnergy(w);
    float worst = 0;
    *energy = 0;
    for (uint16_t n = 0; n < 2560; ++n) {
      w.step(S(1.0 / 256));
      const float e = ::fabsf(chainEnergy(w) - start) / fall;
      if (e > *energy) *energy = e;
      for (uint8_t i = 1; i <= 8; ++i) {
        const float l = ::fabsf(distance(w.particleAt(i), w.particleAt(i - 1)) / 0.125f - 1);
        if (l > worst) worst = l;
      }
    }
    *error = w.error();
    return worst;
  }
  static float chainEnergy(const RodWorld& w) {
    float e = 0;
    for (uint8_t i = 1; i <= 8; ++i) {
      const float s = speedOf(w.particleAt(i));
      e += 0.05f * (s * s / 2 + 9.81f * w.particleAt(i).position.y.toFloat());
    }
    return e;
  }

  // Bounds of issue 9 (extras/test/RodChainTest): links within 0.5 %, energy
  // within 0.05 E_fall over 10 s at 256 Hz, no error bits.
  static bool checkChain() {
    float energy;
    uint8_t error;
    const float link = chain(&energy, &error);
    bool ok = stabilityLine<S>(F("chain-8-rods-link-error"), 0.005f, link);
    ok &= stabilityLine<S>(F("chain-8-rods-energy-error"), 0.05f, energy);
    ok &= stabilityLine<S>(F("chain-8-rods-error-bits"), 0, error);
    return ok;
  }

  // Coincident balls come apart (overlap left after 1 s within the
  // issue's 0.5 mm) and stay finite.
  static bool checkCoincident() {
    bool finite;
    const float overlap = coincident(&finite);
    bool ok = stabilityLine<S>(F("coincident-overlap-after-1s-m"), 0.0005f, overlap);
    ok &= stabilityLine<S>(F("coincident-non-finite"), 0, finite ? 0 : 1);
    return ok;
  }

  static bool checkTinyVectors() {
    return stabilityLine<S>(F("zero-and-tiny-vectors-wrong"), 0, tinyVectors());
  }

  static bool checkRangeEdge() {
    return stabilityLine<S>(F("range-edge-wrapped-or-unflagged"), 0, rangeEdge());
  }

  // The bound of freeFall(): Euler's g t dt / 2 plus rounding.
  static bool checkFreeFall(uint16_t rate, const __FlashStringHelper* name) {
    float bound;
    const float error = freeFall(rate, &bound);
    return stabilityLine<S>(name, bound, error);
  }

  static bool checkExhaustion() {
    return stabilityLine<S>(F("pool-and-contact-exhaustion-wrong"), 0, exhaustion());
  }
};

}  // namespace testing
}  // namespace tinyparticle
