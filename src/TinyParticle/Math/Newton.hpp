// Inverse square roots and unit vectors from multiplies only (Fixed and
// Float).
//
// A scene whose step never divides should not link the divide and the
// square root (about 1.7 KB of code and tables in Q16.16) for work done at
// set-up or on a rare path: a rod's first direction, the exact length of a
// rod that turned fast, a direction renormalised after a fast turn, a
// rod's 1 / L and 1 / dt (Fixed's compact reciprocal, a long division:
// Fixed.hpp; Float's by Newton's steps, below).
// For Fixed, 1 / sqrt(x) takes Newton's iterations from a first guess:
// - the argument is brought into [1/2, 2) by powers of 4 (exact upwards;
//   downwards, in fixed point, each halving rounds);
// - a parabola gives the first guess of 1 / sqrt(q), within 2.6 %;
// - each Newton step squares the relative error: two leave 1.5e-6.
// In Q16.16 the inverse square root is within 5 units of 2^-16 relative
// plus one unit (extras/test/NewtonTest checks it on every leading-bit
// position). Slower than the square root (about a dozen multiplies): for
// set-up and rare paths, not for every step. Float takes its first guess
// from the bits instead (below); on AVR its square root and the unit
// vector's divides came to about 900 B.
// Two unit vectors: the balls' contact normals, taken every step, by
// normalizeByMultiplies() (the inverse square root above); the rods', at
// set-up and on rare steps, by unitBySteps(), which in Fixed takes more
// Newton's steps on the vector itself, with no reduction nor first guess
// (and the chains' turn factor a square root by Heron's steps): a Fixed
// world with rods and no balls links no inverseSqrt() (issue 12).
#pragma once

#include <stdint.h>

#include "Fixed.hpp"
#include "Float.hpp"
#include "Scaler.hpp"
#include "Vec.hpp"
#include "Zero.hpp"

namespace tinyparticle {
namespace detail {

// a + b, a - b and -a out of line: a Fixed sum saturates in about 14 B of
// code where it is written out, a call takes 4 and about 10 cycles more.
// For rare paths (a fast turn, a rod whose two ends move), and for the
// lone rods' solve (about 90 B of Q16.16, 46 cycles of the lever's step).
// Other scalars: the plain operations.
template <typename S>
inline S sumOutOfLine(S a, S b) {
  return a + b;
}
template <uint8_t I, uint8_t F>
TINYPARTICLE_NOINLINE Fixed<I, F> sumOutOfLine(Fixed<I, F> a, Fixed<I, F> b) {
  return a + b;
}
template <typename S>
inline S differenceOutOfLine(S a, S b) {
  return a - b;
}
template <uint8_t I, uint8_t F>
TINYPARTICLE_NOINLINE Fixed<I, F> differenceOutOfLine(Fixed<I, F> a,
                                                      Fixed<I, F> b) {
  return a - b;
}
template <typename S>
inline S negativeOutOfLine(S a) {
  return -a;
}
template <uint8_t I, uint8_t F>
inline Fixed<I, F> negativeOutOfLine(Fixed<I, F> a) {
  return differenceOutOfLine(Fixed<I, F>(), a);
}

// Other scalars (a host's double) have a compact divide and square root:
// for them the functions below are the plain formulas. Newton's steps are
// for Fixed and for Float: on AVR a float's square root and the unit
// vector's divides came to about 900 B, for set-up and the rare paths.

// 1 / sqrt(q) for q > 0 (q <= 0 gives 0).
template <typename S>
inline S inverseSqrt(S q) {
  return isPositive(q) ? S(1) / sqrt(q) : S();
}
// Float, for a normal q > 0 (what the rods and the balls pass: their
// callers reject or scale the rest, so that they link none of the
// subnormal's scaling below): a first guess from the bits (halving the
// exponent by a shift of the whole word, within 3.5 %), then three Newton
// steps (1.7e-3, 4.5e-6, then the rounding of the last step: a few units
// of 2^-24).
TINYPARTICLE_NOINLINE inline Float inverseSqrtOfNormal(Float q) {
  uint32_t bits = 0x5F3759DFul - (floatBits(q) >> 1);
  float guess;
  memcpy(&guess, &bits, sizeof(guess));
  Float y(guess);
  const Float halfQ = half(q);
  for (uint8_t i = 0; i < 3; ++i) y *= Float(1.5) - halfQ * y * y;
  return y;
}
// Float, any q: a subnormal q is scaled by 2^24 first (exact), its root by
// 2^12 after. Infinity gives 0; q <= 0 and NaN give 0, as for the other
// scalars.
TINYPARTICLE_NOINLINE inline Float inverseSqrt(Float q) {
  if (!isPositive(q)) return Float();
  Float scale(1);
  if (floatBits(q) < 0x00800000ul) {  // subnormal
    q *= Float(16777216.0);
    scale = Float(4096.0);
  }
  return inverseSqrtOfNormal(q) * scale;
}
// Fixed: q is brought into [1/2, 2) by factors of 4 (exact upwards;
// downwards the halvings round), then a parabola in steps of 2^-8, within
// 2.6 %, and Newton's steps, each squaring the relative error (times
// 1.5): one leaves 1e-3 (enough for 10 fraction bits), two 1.5e-6 (18
// bits), three 4e-12. The root is scaled back by the same powers of 2; a
// result beyond the format saturates and raises MathError::kOverflow.
template <uint8_t I, uint8_t F>
TINYPARTICLE_NOINLINE Fixed<I, F> inverseSqrt(Fixed<I, F> q) {
  typedef Fixed<I, F> S;
  const uint8_t kSteps = F <= 10 ? 1 : (F <= 18 ? 2 : 3);
  if (!isPositive(q)) return S();
  int8_t doublings = 0;  // 1 / sqrt(q) = 2^doublings / sqrt(q')
  while (q < S(0.5)) {
    q += q;
    q += q;
    ++doublings;
  }
  while (!(q < S(2))) {
    q = half(half(q));
    --doublings;
  }
  S y = S(483.0 / 256) - q * (S(297.0 / 256) - q * S(74.0 / 256));
  for (uint8_t i = 0; i < kSteps; ++i) y = y * (S(1.5) - half(q * y * y));
  for (; doublings > 0; --doublings) y += y;
  for (; doublings < 0; ++doublings) y = half(y);
  return y;
}

// 1 / x for x > 0, for set-up and rare paths (a rod's 1 / L, 1 / dt, the
// turn factor): the compact reciprocal of Fixed (a long division, no
// table), the plain one for other scalars (a host's double).
template <typename S>
TINYPARTICLE_ALWAYS_INLINE S reciprocalByMultiplies(S x) {
  return compactReciprocalOfPositive(x);
}
// Float: without the float divide (which a sketch whose step never
// divides then does not link), as the square of 1 / sqrt(x) by
// inverseSqrtOfNormal() (linked anyway for the rods' unit vectors: a guess
// and Newton's steps of its own cost 40 B more), within about 2e-6, then
// one Newton step r += r
// (1 - x r), which squares that and leaves the step's rounding: within 2
// units of 2^-24, for x from 2^-126 (the smallest normal) to below 2^126.
// Any other x (from 2^126 on, where 1 / x is below the smallest normal;
// infinity, NaN, subnormals, 0 and negatives, which break the promise of a
// positive x) gives 0.
TINYPARTICLE_NOINLINE inline Float reciprocalByMultiplies(Float x) {
  // One compare: x <= 0 (the sign bit, or +0), subnormals, and from 2^126
  // on (infinity and NaN too) wrap above the range.
  if (floatBits(x) - 0x00800000ul >= 0x7E000000ul) return Float();
  const Float y = inverseSqrtOfNormal(x);
  Float r = y * y;
  r += r * (Float(1) - x * r);
  return r;
}

// v scaled to unit length; false (v unchanged) for a zero vector.
template <typename S, uint8_t N>
inline bool normalizeByMultiplies(Vec<S, N>& v) {
  return v.normalize();
}
// Float: the largest component's magnitude, read from the bits (positive
// floats order as integers), 2^e, is brought to about 1 by two exact
// multiplies by 2^(-e/2), so that the squares neither overflow nor vanish;
// then v (1 / sqrt(|v|^2)). A component that is infinite or NaN has no
// direction: false, v unchanged, as for a zero vector.
template <uint8_t N>
TINYPARTICLE_NOINLINE bool normalizeByMultiplies(Vec<Float, N>& v) {
  uint32_t top = 0;
  for (uint8_t i = 0; i < N; ++i) {
    const uint32_t magnitude = floatBits(v[i]) & 0x7FFFFFFFul;
    if (magnitude > top) top = magnitude;
  }
  if (top == 0 || top >= 0x7F800000ul) return false;
  // Biased exponent E in [0, 254]: the factor 2^(63 - E/2), as a biased
  // exponent 64 + (254 - E) / 2, is normal at both ends.
  const uint32_t scaleBits = (64ul + ((254ul - (top >> 23)) >> 1)) << 23;
  float scale;
  memcpy(&scale, &scaleBits, sizeof(scale));
  v *= Float(scale);
  v *= Float(scale);
  v *= inverseSqrtOfNormal(dotOutOfLine(v, v));  // |v|^2 is about 1 now
  return true;
}

// Fixed: the largest component brought into [1/2, 1) by powers of two,
// so that short vectors keep their bits and long ones cannot overflow;
// false (v unchanged) for a zero vector. The largest magnitude's leading
// bit is that of all magnitudes' raw bits or-ed together: it is tracked
// in those bits (unsigned shifts), which costs no fabs() and no compares
// of Fixed values.
// (kUp: into [2^kUp / 2, 2^kUp) instead.)
template <uint8_t kUp = 0, uint8_t I, uint8_t F, uint8_t N>
inline bool scaleLargestIntoHalfToOne(Vec<Fixed<I, F>, N>& v) {
  typedef Fixed<I, F> S;
  typedef typename S::URaw U;
  U bits = 0;
  for (uint8_t i = 0; i < N; ++i) {
    const typename S::Raw r = v[i].raw();
    bits = U(bits | (r < 0 ? U(U(0) - U(r)) : U(r)));
  }
  if (bits == 0) return false;
  const U kHalf = U(U(1) << (F - 1 + kUp));  // the raw bits of 2^kUp / 2
  while (bits < kHalf) {
    bits = U(bits << 1);
    // (The rods' (kUp > 0), for set-up and rare steps, through the *= that
    // they link anyway: Vec's += then stays written out where a sketch
    // uses it once, 22 B less of rung 9. The balls', every step, keep the
    // faster add.)
    if (kUp > 0) {
      v *= S(2);
    } else {
      v += v;
    }
  }
  while (bits >= U(kHalf << 1)) {
    bits = U(bits >> 1);
    v *= S(0.5);
  }
  return true;
}
// Fixed: v / |v| = v (1 / sqrt(|v|^2)), v scaled as above.
template <uint8_t I, uint8_t F, uint8_t N>
TINYPARTICLE_NOINLINE bool normalizeByMultiplies(Vec<Fixed<I, F>, N>& v) {
  if (!scaleLargestIntoHalfToOne(v)) return false;
  v *= inverseSqrt(dotOutOfLine(v, v));
  return true;
}

// A rod's unit direction (its first, or one far off its length or after a
// fast turn: Contacts/RodSolver.hpp): set-up and rare steps, where flash
// counts and cycles hardly do (issue 12). The plain unit vector for other
// scalars (a host's double).
template <typename S, uint8_t N>
inline bool unitBySteps(Vec<S, N>& v) {
  return normalizeByMultiplies(v);
}
// Fixed: v scaled by powers of two, then Newton's steps from below on v
// itself, v <- v (1.5 - |v|^2 / 2) in units of the length sought, with
// no inverse square root apart (from 1, with its own routine and call:
// the lever's 100 B more). About three times the multiplies of
// normalizeByMultiplies(): the balls' contact normals, taken every step,
// keep that one.
// Coarse formats (10 fraction bits or fewer: Q24.8) keep the balls' routine:
// their rods normalise nearly every step (a direction within 1/256 of a
// unit vector is within one unit of Q24.8), and the lever in Q24.8 kept
// its energy worse with these steps (extras/benchmarks: 0.106 -> 1.16 in
// 3D at 64 Hz).
template <uint8_t I, uint8_t F, uint8_t N>
TINYPARTICLE_NOINLINE bool unitBySteps(Vec<Fixed<I, F>, N>& v) {
  if (F <= 10) return normalizeByMultiplies(v);
  typedef Fixed<I, F> S;
  // The largest component into [R / 2, R), R = 2^kUp, then v brought to
  // length 2R, as large as the format lets |v|^2 be: the rounding of v at
  // each step below turns it by far less than a unit of the result.
  // (|v|^2 up to 4 R^2 = 2^(2 kUp + 2) below 2^(I - 1), and 1 / 8R^2 a
  // value of the format.)
  const uint8_t kUp = I < 4 ? 0
                      : (I - 4) / 2 < (F - 3) / 2 ? (I - 4) / 2 : (F - 3) / 2;
  if (!scaleLargestIntoHalfToOne<kUp>(v)) return false;
  // l = |v| / 2R, in [1/4, sqrt(3) / 2): l <- l (1.5 - l^2 / 2) rises
  // to 1 from below, within 3e-7 after seven steps (20 fraction bits),
  // 1e-13 after eight.
  const uint8_t kSteps = F <= 20 ? 7 : 8;
  const S kHalfOverLength2 = S(1.0 / (8 * double(1ul << (2 * kUp))));
  for (uint8_t i = 0; i < kSteps; ++i) {
    v *= differenceOutOfLine(S(1.5), dotOutOfLine(v, v) * kHalfOverLength2);
  }
  v *= S(1.0 / (2 * double(1ul << kUp)));
  return true;
}

// Float: v (1 / sqrt(|v|^2)) by inverseSqrtOfNormal() (a guess from the
// bits and Newton's steps: linked anyway, for a fast turn's factor and
// the reciprocal), without the balls' scaling by powers of two: a rod's
// span is metres, far from the ends of the float range. Where |v|^2 is
// not a normal float (|v| below about 1e-19 or above 1.8e19, or a
// component infinite or NaN) v has no direction here: false, v unchanged,
// as for a zero vector (a rod's direction is then kept, or taken as any at
// set-up).
template <uint8_t N>
TINYPARTICLE_NOINLINE bool unitBySteps(Vec<Float, N>& v) {
  const Float q = dotOutOfLine(v, v);
  // One compare: 0, subnormals, infinity and NaN wrap above the range.
  if (floatBits(q) - 0x00800000ul >= 0x7F000000ul) return false;
  v *= inverseSqrtOfNormal(q);
  return true;
}

// Whether the lone rods test a direction's length by its components'
// magnitudes (Contacts/RodSolver.hpp, setDirection()): for Float, where
// |x| is a bit and the square two float multiplies (360 cycles of the
// lever's step for 2 B); not for Fixed, where the square's test is 64 B
// smaller for about 170 cycles.
template <typename S>
constexpr bool nearUnitByMagnitudes(S) {
  return true;
}
template <uint8_t I, uint8_t F>
constexpr bool nearUnitByMagnitudes(Fixed<I, F>) {
  return false;
}

// 2 / (1 + sqrt(1 - 2h)) for h >= 0: what a rod that turns by t = sqrt(2h)
// radians in a step drops along itself, in units of the second order
// form's t^2 / 2 (Contacts/RodSolver.hpp, positionSpeed()). From h = 1/2
// (a turn of 1 rad) the rod cannot reach its length in the step: the
// square root is taken as 0, and the factor is 2.
template <typename S>
inline S turnDropFactor(S h) {
  if (!(h < S(0.5))) return S(2);
  return S(2) / (S(1) + sqrt(S(1) - (h + h)));
}
// Float: as Fixed below, the series up to h = 1/32 with the terms up to
// h^4 (the rest is below 4.2e-8, 0.7 units of 2^-24), then the formula,
// through inverseSqrtOfNormal() (which a Float world's rods link anyway
// for their unit vectors: unitBySteps(), above). h >= 0 is compared by
// its bits (isAboveNonNegative(), Math/Zero.hpp): no float compare
// linked.
inline Float turnDropFactor(Float h) {
  typedef Float S;
  if (!isAboveNonNegative(h, S(1.0 / 32))) {
    return S(1) + h * (S(0.5) + h * (S(0.5) + h * (S(0.625) + h * S(0.875))));
  }
  if (!isBelowNonNegative(h, Float(0.5))) return Float(2);
  const Float m = Float(1) - (h + h);
  const Float r =
      reciprocalByMultiplies(Float(1) + m * inverseSqrtOfNormal(m));
  return r + r;
}
// Fixed: up to h = 1/32 (a turn of 1/4 rad) the series 1 + h/2 + h^2/2 +
// 5h^3/8 + 7h^4/8 + 21h^5/16 + ... (Catalan numbers over powers of 2),
// whose term in h^n is below 1.4 (1/32)^n there: cut after the last term
// that reaches half a unit of the format (h^3 for 16 fraction bits: the
// rest is below 9e-7; h for 8 bits: below 5e-4). Beyond (rare: a whip)
// the formula, with sqrt(m) by Heron's steps and the compact reciprocal
// (linked anyway for 1 / L and 1 / dt), m = 1 - 2h brought into [1/4, 1)
// by powers of 4 (exact) and the root scaled back by halvings: a Fixed
// world's rods link no inverseSqrt() (issue 12: 380 B of Q16.16).
template <uint8_t I, uint8_t F>
Fixed<I, F> turnDropFactor(Fixed<I, F> h) {
  typedef Fixed<I, F> S;
  const uint8_t kTerms = F < 10 ? 1 : (F < 15 ? 2 : (F < 20 ? 3 : 4));
  if (!(h > S(1.0 / 32))) {
    // (Horner's rule from the last term kept: no sum with a zero.)
    S p = S();
    if (kTerms >= 4) p = h * S(0.875);
    if (kTerms >= 3) {
      p = h * (kTerms > 3 ? sumOutOfLine(S(0.625), p) : S(0.625));
    }
    if (kTerms >= 2) p = h * (kTerms > 2 ? sumOutOfLine(S(0.5), p) : S(0.5));
    return sumOutOfLine(S(1),
                        h * (kTerms > 1 ? sumOutOfLine(S(0.5), p) : S(0.5)));
  }
  if (!(h < S(0.5))) return S(2);
  S m = S(1) - sumOutOfLine(h, h);
  if (F <= 10) {  // as unitBySteps() for coarse formats
    const S r = reciprocalByMultiplies(sumOutOfLine(S(1), m * inverseSqrt(m)));
    return sumOutOfLine(r, r);
  }
  uint8_t halvings = 0;
  while (m < S(0.25)) {
    m = sumOutOfLine(m, m);
    m = sumOutOfLine(m, m);
    ++halvings;
  }
  // sqrt(m) by Heron's steps r <- (r + m / r) / 2 from r = 1, which fall
  // to it from above: from m = 1/4, five leave 1e-15 (a reciprocal by
  // multiplies each, for a whip's rare step: 150 B less than Newton's
  // steps from 1).
  S root = S(1);
  for (uint8_t i = 0; i < 5; ++i) {
    root = half(sumOutOfLine(root, m * reciprocalByMultiplies(root)));
  }
  for (; halvings > 0; --halvings) root = half(root);
  const S r = reciprocalByMultiplies(sumOutOfLine(S(1), root));
  return sumOutOfLine(r, r);
}

}  // namespace detail
}  // namespace tinyparticle
