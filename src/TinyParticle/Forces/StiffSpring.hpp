// Stiff ("fake") spring from a particle to an anchor, after Millington's
// damped harmonic spring: instead of Hooke's force, each step follows the
// exact solution of the damped oscillator x'' = -(k/m) x - (c/m) x', so it
// stays stable at any stiffness, where an ordinary spring with the same dt
// explodes (k dt^2 / m > 4).
//
// Millington evaluates exp, sin and cos every step and sets the acceleration
// that lands x on the analytic solution from the current position and
// velocity. With semi-implicit Euler that is not enough: the velocity it
// carries is the secant (x_n - x_n-1) / dt, and feeding that back as the
// oscillator's velocity makes the motion run at about w / sqrt(2) (checked
// numerically while writing this). Here everything that depends only on k,
// c, m and dt is folded into two gains, computed once when the spring is
// added:
//     acceleration = A (x - anchor) + B v
// chosen so that one step of the integrator is a linear map with exactly the
// eigenvalues of the oscillator over dt: the trace and determinant of
// exp(dt J), J = [[0, 1], [-k/m, -c/m]]. Then the positions obey the same
// two-term recurrence as samples of the analytic solution, so the frequency
// and the decay are exact for ever (the phase is set by the first step), and
// since those eigenvalues lie inside the unit circle the step is stable for
// any k. Undamped, this is the classic A = -4 sin^2(w dt / 2) / dt^2, B = 0.
//
// The gains are computed in float on every platform (every operation a
// single float operation, no double literal), so that a world gets the same
// bits on the PC as on the Nano, by scaling and squaring on the remainder
// exp(X) - I - X, so no term suffers cancellation even for a tiny k dt^2.
// They are only right for the dt given when adding the spring.
// The position gain is about -k/m (exactly -4 sin^2(w dt / 2) / dt^2
// undamped): a spring whose gains do not fit the scalar (in Q16.16 k/m
// beyond about 32000 N/m/kg at dt = 1/256 s, or a k that does not fit
// itself) is refused by World::addStiffSpring with WorldError::kBadArgument
// rather than run softer than asked.
#pragma once

#include <stdint.h>

#include "../Core/Generator.hpp"
#include "../Core/Particle.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"

namespace tinyparticle {

namespace detail {

// The exponential's parts while it is summed and squared (see
// stiffSpringGains()): x = X, term its last term, r = exp(X) - I - X so
// far. 2x2 matrices, row-major.
struct StiffSpringSeries {
  float x[4];
  float term[4];
  float r[4];
};

// out = a b, each entry one product, one product and one sum in this
// order: the same bits on every platform. (out may alias neither.)
TINYPARTICLE_NOINLINE inline void stiffSpringProduct(const float* a,
                                                     const float* b,
                                                     float* out) {
  for (uint8_t i = 0; i < 4; i += 2) {
    out[i] = a[i] * b[0] + a[i + 1] * b[2];
    out[i + 1] = a[i] * b[1] + a[i + 1] * b[3];
  }
}

// The series' next term, term X / n, added to r.
TINYPARTICLE_NOINLINE inline void addSeriesTerm(StiffSpringSeries& s,
                                                uint8_t n) {
  float next[4];
  stiffSpringProduct(s.term, s.x, next);
  for (uint8_t i = 0; i < 4; ++i) {
    s.term[i] = next[i] / n;
    s.r[i] += s.term[i];
  }
}

// X doubled: exp(2Y) - I = 2N + N^2 with N = exp(Y) - I, so r(2Y) =
// 2 r(Y) + N^2.
TINYPARTICLE_NOINLINE inline void doubleSeries(StiffSpringSeries& s) {
  float n[4], square[4];
  for (uint8_t i = 0; i < 4; ++i) n[i] = s.x[i] + s.r[i];
  stiffSpringProduct(n, n, square);
  for (uint8_t i = 0; i < 4; ++i) {
    s.r[i] = 2.0f * s.r[i] + square[i];
    s.x[i] *= 2.0f;
  }
}

// Gains A and B for x'' = -w2 x - c x' and step h (see above). Setup-time
// code, about two hundred float operations, out of line and in parts:
// written out, it cost the Spring example 1,144 B more (issue 12).
TINYPARTICLE_NOINLINE inline void stiffSpringGains(float w2, float c, float h,
                                                   float* gainA,
                                                   float* gainB) {
  // X = h J / 2^s with J = [[0, 1], [-w2, -c]], small enough for Taylor.
  float scale = h;
  uint8_t squarings = 0;
  float norm = h * (1.0f + (w2 < 0 ? -w2 : w2) + (c < 0 ? -c : c));
  while (norm > 0.5f && squarings < 60) {
    norm *= 0.5f;
    scale *= 0.5f;
    ++squarings;
  }
  // r = exp(X) - I - X = X^2/2! + X^3/3! + ..., from the term X itself
  // (x and term start equal), then X doubled back to h J.
  StiffSpringSeries s = {{0.0f, scale, -w2 * scale, -c * scale},
                         {0.0f, scale, -w2 * scale, -c * scale},
                         {0.0f, 0.0f, 0.0f, 0.0f}};
  for (uint8_t n = 2; n <= 14; ++n) addSeriesTerm(s, n);
  while (squarings-- > 0) doubleSeries(s);
  const float* r = s.r;
  // M = exp(h J) = I + h J + r. Its determinant is e^y with y = -c h; its
  // trace is 2 + y + r11 + r22. e2 = e^y - 1 - y, by series while small.
  const float y = -c * h;
  float e2;
  if (y > -0.5f) {
    e2 = 0.0f;
    float power = y;
    for (uint8_t n = 2; n <= 16; ++n) {
      power = power * y / n;
      e2 += power;
    }
  } else {
    const float m11 = 1.0f + r[0], m12 = h + r[1];
    const float m21 = -w2 * h + r[2], m22 = 1.0f + y + r[3];
    e2 = (m11 * m22 - m12 * m21) - 1.0f - y;
  }
  // One step maps (x, v) by [[1 + A h^2, h + B h^2], [A h, 1 + B h]], whose
  // determinant is 1 + B h and trace 2 + A h^2 + B h: match them to M's.
  *gainB = (y + e2) / h;
  *gainA = (r[0] + r[3] - e2) / (h * h);
}

}  // namespace detail

// A generator class (Core/Generator.hpp), run for one particle.
template <typename S, uint8_t Dim>
struct StiffSpringForce {
  static const uint8_t kShape = SlotShape::kAnchorable;
  Vec<S, Dim> anchor;
  S positionGain;  // A, 1/s^2 (negative)
  S velocityGain;  // B, 1/s

  // The gains for stiffness k (N/m, >= 0) and damping (N s/m, >= 0) on a
  // particle of the given inverse mass, exact for steps of dt (> 0),
  // computed in float on every platform. False (nothing set) when an
  // argument is out of range, when k or damping did not fit the scalar (it
  // arrives saturated: S::largest()), or when a gain would not fit it.
  static bool make(StiffSpringForce& out, const Vec<S, Dim>& anchor, S k,
                   S damping, S dt, S inverseMass) {
    const float limit = S::largest().toFloat();
    float gainA = 0.0f, gainB = 0.0f;
    if (detail::isPositive(dt) && !detail::isNegative(k) &&
        !detail::isNegative(damping) && k < S::largest() &&
        damping < S::largest()) {
      const float inverse = inverseMass.toFloat();
      detail::stiffSpringGains(k.toFloat() * inverse,
                               damping.toFloat() * inverse, dt.toFloat(),
                               &gainA, &gainB);
    } else {
      return false;
    }
    // Within (-limit, limit), which also leaves out inf and NaN.
    if (!(gainA > -limit && gainA < limit && gainB > -limit &&
          gainB < limit)) {
      return false;
    }
    out.anchor = anchor;
    out.positionGain = S(gainA);
    out.velocityGain = S(gainB);
    return true;
  }

  void apply(Particle<S, Dim>& p, S) const {
    p.acceleration.addScaled(p.position - anchor, positionGain);
    if (velocityGain != S()) {  // 0 when undamped
      p.acceleration.addScaled(p.velocity, velocityGain);
    }
  }
};

}  // namespace tinyparticle
