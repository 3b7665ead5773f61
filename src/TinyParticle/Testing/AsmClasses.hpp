// The classes of input that the hand-written AVR routines (FixedAvr.hpp,
// and the add/subtract in Fixed.hpp) tell apart, for the proof that they
// equal the portable reference bit for bit, flags included:
// - `make verify-asm` (extras/scripts/verify-asm) runs every structured
//   input below plus at least 10^7 random ones per routine on the simulated
//   Nano, and counts the classes on the host over the same inputs;
// - extras/test/AsmClassesTest runs a subset that still hits every class, in
//   `make test`.
//
// For each routine:
// - classify(): which branch of the assembly an input takes, computed in
//   C++ from the routine's steps (table index, normalization shift, each
//   estimate and its correction, each saturation exit). Each branch is a
//   value of a "family"; a counter per value says how often it was hit.
//   Branches that no input can take are listed in kUnreachable, with why.
// - enumerate(): structured inputs built from those classes: each table
//   entry's first and last argument, each leading-bit position, each
//   estimate's boundaries, the saturation edges, each with its +-3
//   neighbours. `full` selects all of them; otherwise a subset that still
//   reaches every class (fewer shifts per table entry).
// - randomInput(): log-uniform magnitudes (bit length uniform, then random
//   bits), random signs; near half-way points for the square root.
// - check(): the fast code (assembly on AVR) against the reference, result
//   and flags; on every target also the reference against exact integer
//   properties (correct rounding, saturation), so that the check means
//   something on the host, where the fast code is the reference.
//
// Not included by TinyParticle.h: include
// <TinyParticle/Testing/AsmClasses.hpp> after it.
#pragma once

#include <math.h>
#include <stdint.h>

#include "../Configuration.hpp"
#include "../Math/Fixed.hpp"
#include "../Math/FixedMath.hpp"
#include "../Math/MathErrors.hpp"
#include "../Math/TrigTables.hpp"
#include "../Platform/Progmem.hpp"
#include "MathTestSupport.hpp"

namespace tinyparticle {
namespace testing {

// ---- Routines and families ---------------------------------------------

enum AsmRoutine : uint8_t {
  kAsmMulQ16,   // Q16.16 multiply (avrMultiplyQ16)
  kAsmDivQ16,   // Q16.16 divide (avrDivideQ16)
  kAsmSqrtQ16,  // Q16.16 square root (avrSquareRoot, e0 = 0)
  kAsmMulQ24,   // Q24.8 multiply, through avrMultiplyQ16
  kAsmDivQ24,   // Q24.8 divide, through avrDivideQ16
  kAsmSqrtQ24,  // Q24.8 square root (avrSquareRoot, e0 = 4)
  kAsmDivQ8,    // Q8.8 divide, through avrDivideQ16
  kAsmSqrtQ8,   // Q8.8 square root (avrSquareRoot, e0 = 4)
  kAsmAtan2,    // atan2 core (avrAtan2Units) on 32-bit raw values
  kAsmAddQ32,   // 32-bit saturating add (addSaturating)
  kAsmSubQ32,   // 32-bit saturating subtract
  kAsmAddQ16,   // 16-bit saturating add (Q8.8)
  kAsmSubQ16,   // 16-bit saturating subtract
  kAsmSinQ16,   // Q16.16 sin and cos of radians (avrSinUnitsQ16); b = 1: cos
  kAsmRoutineCount
};

const uint8_t kMaxFamilies = 14;
// The most class counters any routine needs (the square roots: 374).
const uint16_t kMaxClassValues = 380;

// Families of each routine: the number of values of each, 0-terminated.
// The Q24.8 and Q8.8 multiply and divide are C++ around the Q16.16
// assembly (operands scaled by 2^8, then checked or narrowed): their
// families are that code's own branches (route, signs, outcome); the
// assembly below them has its own classes, covered by the Q16.16 proof.
#define TP_MUL_FAMILIES 4, 4, 6, 3
#define TP_DIV_FAMILIES 4, 4, 32, 128, 9, 10, 6, 2, 4, 4, 3, 4
#define TP_SQRT_FAMILIES 3, 16, 2, 192, 3, 2, 2, 4, 128, 2, 4, 2
#define TP_ADD_FAMILIES 4, 4

inline uint16_t familySize(uint8_t routine, uint8_t family) {
  static const uint16_t kMul[] = {TP_MUL_FAMILIES, 0};
  static const uint16_t kDiv[] = {TP_DIV_FAMILIES, 0};
  static const uint16_t kSqrt[] = {TP_SQRT_FAMILIES, 0};
  static const uint16_t kMul24[] = {3, 4, 4, 0};
  static const uint16_t kDiv24[] = {3, 4, 4, 0};
  static const uint16_t kDiv8[] = {2, 4, 5, 0};
  static const uint16_t kAtan[] = {5, 3, 4, 8, 2, 3, 128, 2, 128, 0};
  static const uint16_t kAdd[] = {TP_ADD_FAMILIES, 0};
  static const uint16_t kSin[] = {4, 4, 2, 128, 0};
  const uint16_t* sizes;
  switch (routine) {
    case kAsmMulQ16: sizes = kMul; break;
    case kAsmDivQ16: sizes = kDiv; break;
    case kAsmSqrtQ16: case kAsmSqrtQ24: case kAsmSqrtQ8: sizes = kSqrt; break;
    case kAsmMulQ24: sizes = kMul24; break;
    case kAsmDivQ24: sizes = kDiv24; break;
    case kAsmDivQ8: sizes = kDiv8; break;
    case kAsmAtan2: sizes = kAtan; break;
    case kAsmSinQ16: sizes = kSin; break;
    default: sizes = kAdd; break;
  }
  for (uint8_t f = 0; f < family; ++f) {
    if (sizes[f] == 0) return 0;
  }
  return sizes[family];
}

inline uint8_t familyCount(uint8_t routine) {
  uint8_t n = 0;
  while (familySize(routine, n) != 0) ++n;
  return n;
}

// Counters for one routine, saturating at the counter type's maximum.
template <typename Count>
class ClassCounts {
 public:
  explicit ClassCounts(uint8_t routine) { reset(routine); }

  void reset(uint8_t routine) {
    mRoutine = routine;
    uint16_t offset = 0;
    const uint8_t n = familyCount(routine);
    for (uint8_t f = 0; f < kMaxFamilies; ++f) {
      mOffset[f] = offset;
      if (f < n) offset = uint16_t(offset + familySize(routine, f));
    }
    mTotal = offset;
    for (uint16_t i = 0; i < kMaxClassValues; ++i) mCount[i] = 0;
  }

  void hit(uint8_t family, uint16_t value) {
    const uint16_t i = uint16_t(mOffset[family] + value);
    if (i < kMaxClassValues && Count(mCount[i] + 1) != 0) ++mCount[i];
  }

  uint8_t routine() const { return mRoutine; }
  uint16_t total() const { return mTotal; }
  Count count(uint8_t family, uint16_t value) const {
    return mCount[mOffset[family] + value];
  }

 private:
  uint8_t mRoutine;
  uint16_t mTotal;
  uint16_t mOffset[kMaxFamilies];
  Count mCount[kMaxClassValues];
};

// A counter that counts nothing (when only the comparisons matter).
struct NoCounts {
  void hit(uint8_t, uint16_t) {}
};

// Shifts a family index: the Q24.8 and Q8.8 routines pass their counter
// on to the Q16.16 classifiers with an offset of one family.
template <typename C>
struct FamilyOffset {
  C& counts;
  uint8_t offset;
  void hit(uint8_t family, uint16_t value) {
    counts.hit(uint8_t(family + offset), value);
  }
};

inline uint32_t magnitude32(int32_t v) {
  return v < 0 ? uint32_t(0) - uint32_t(v) : uint32_t(v);
}

inline uint8_t bitLength32(uint32_t v) {
  uint8_t n = 0;
  while (v != 0) {
    v >>= 1;
    ++n;
  }
  return n;
}

inline uint16_t recipEntry(uint8_t i) {
  return platform::readFlashU16(&detail::TrigTables<void>::kRecip[i]);
}

// ---- Multiply (avrMultiplyQ16) -----------------------------------------
// Families: 0 signs (a < 0) * 2 + (b < 0); 1 path: top bytes of |a|, |b|
// both zero (9 MULs) / only |a|'s (swap, 12 MULs) / only |b|'s (12 MULs)
// / both (saturated at once); 2 outcome: zero / ordinary / within 3 of the
// limit / saturated at the 2^31 check / saturated by byte 6 (12-MUL path)
// / saturated at once; 3 rounding: below half / tie / above half.
template <typename C>
TINYPARTICLE_NOINLINE void classifyMulQ16(int32_t a, int32_t b, C& c) {
  const uint32_t ma = magnitude32(a), mb = magnitude32(b);
  const bool negative = (a < 0) != (b < 0);
  c.hit(0, uint16_t((a < 0) * 2 + (b < 0)));
  const bool a3 = (ma >> 24) != 0, b3 = (mb >> 24) != 0;
  const uint8_t path = a3 ? (b3 ? 3 : 1) : (b3 ? 2 : 0);
  c.hit(1, path);
  const uint64_t p = uint64_t(ma) * mb;
  const uint16_t low = uint16_t(p);
  c.hit(3, low < 0x8000u ? 0 : (low == 0x8000u ? 1 : 2));
  uint8_t outcome;
  const uint64_t r = (p + 0x8000u) >> 16;
  const uint64_t limit = negative ? 0x80000000ull : 0x7fffffffull;
  if (path == 3) {
    outcome = 5;
  } else if (path != 0 && ((p + 0x8000u) >> 48) != 0) {
    outcome = 4;
  } else if (r > limit) {
    outcome = 3;
  } else if (r == 0) {
    outcome = 0;
  } else {
    outcome = r + 3 >= limit ? 2 : 1;
  }
  c.hit(2, outcome);
}

// ---- Divide (avrDivideQ16) -----------------------------------------------
// Families: 0 signs; 1 divisor: nonzero / zero with a > 0, a < 0, a = 0
// (handled in C before the assembly); 2 bit length of |b| (1..32: the
// normalization shift); 3 kRecip index of the normalized divisor; 4 the
// steps that make the interpolated reciprocal exact (-4..4, +4); 5 the
// d0 adjustments: d0 = 0 / 1 + 3 * (first stage's decrements) + second
// stage's; 6 exit: overflow in the byte shifts / in the bit shifts / top
// words >= D / rounding to 2^32 / sign check / fits; 7 first quotient word
// skipped / computed; 8, 9 corrections of words 1 and 2: none / one less /
// one more / both; 10 rounding: down / up (2r >= D) / up (2r >= 2^32);
// 11 result: zero / ordinary / within 3 of the limit / saturated.

// One quotient word of the 3-by-2 division, as the assembly does it: q of
// (u2, u1, u0) / D with the reciprocal v; returns the corrections taken.
TINYPARTICLE_NOINLINE inline uint8_t divideWordSteps(uint16_t u2, uint16_t u1, uint16_t u0,
                               uint32_t d, uint16_t v, uint16_t* q,
                               uint32_t* remainder) {
  const uint16_t d1 = uint16_t(d >> 16), d0 = uint16_t(d);
  const uint32_t qq = uint32_t(v) * u2 + ((uint32_t(u2) << 16) | u1);
  uint16_t q1 = uint16_t(qq >> 16);
  const uint16_t q0 = uint16_t(qq);
  const uint16_t r1 = uint16_t(u1 - uint16_t(uint32_t(q1) * d1));
  uint32_t r = ((uint32_t(r1) << 16) | u0) - uint32_t(q1) * d0 - d;
  q1 = uint16_t(q1 + 1);
  uint8_t corrections = 0;
  if (uint16_t(r >> 16) >= q0) {
    q1 = uint16_t(q1 - 1);
    r += d;
    corrections = 1;
  }
  if (r >= d) {
    q1 = uint16_t(q1 + 1);
    r -= d;
    corrections = uint8_t(corrections + 2);
  }
  *q = q1;
  *remainder = r;
  return corrections;
}

template <typename C>
TINYPARTICLE_NOINLINE void classifyDivQ16(int32_t a, int32_t b, C& c) {
  c.hit(0, uint16_t((a < 0) * 2 + (b < 0)));
  if (b == 0) {
    c.hit(1, a > 0 ? 1 : (a < 0 ? 2 : 3));
    return;
  }
  c.hit(1, 0);
  const bool negative = (a < 0) != (b < 0);
  const uint32_t ma = magnitude32(a), mb = magnitude32(b);
  const uint8_t n = bitLength32(mb);
  c.hit(2, uint16_t(n - 1));
  const uint32_t d = mb << (32 - n);
  const uint16_t d1 = uint16_t(d >> 16), d0 = uint16_t(d);
  c.hit(3, uint16_t((d1 >> 8) & 0x7f));
  // Normalization of W = |a| (48 bits: the numerator |a| 2^16 in words).
  uint64_t w = ma;
  uint8_t exit = 5;
  for (uint8_t k = 0; k < (32 - n) / 8 && exit == 5; ++k) {
    if ((w >> 40) != 0) exit = 0;
    w <<= 8;
  }
  for (uint8_t k = 0; k < (32 - n) % 8 && exit == 5; ++k) {
    w <<= 1;
    if ((w >> 48) != 0) exit = 1;
  }
  if (exit == 5 && (w >> 16) >= d) exit = 2;
  if (exit != 5) {
    c.hit(6, exit);
    c.hit(11, 3);
    return;
  }
  // The reciprocal: interpolated, then made exact.
  const uint8_t i = uint8_t((d1 >> 8) & 0x7f);
  const uint16_t e0 = recipEntry(i), e1 = recipEntry(uint8_t(i + 1));
  const uint16_t fall = uint16_t(e0 - e1);
  const uint16_t v0 = uint16_t(e0 - uint16_t((uint32_t(fall) * uint8_t(d1)) >> 8));
  uint16_t v = uint16_t(0xffffffffu / d1 - 0x10000u);
  int32_t fix = int32_t(v) - int32_t(v0);
  if (fix < -4) fix = -4;
  if (fix > 4) fix = 4;
  c.hit(4, uint16_t(fix + 4));
  if (d0 == 0) {
    c.hit(5, 0);
  } else {
    uint8_t dec1 = 0, dec2 = 0;
    uint16_t p = uint16_t(uint32_t(d1) * v);
    const uint16_t before = p;
    p = uint16_t(p + d0);
    if (p < before) {
      v = uint16_t(v - 1);
      dec1 = 1;
      if (p >= d1) {
        v = uint16_t(v - 1);
        p = uint16_t(p - d1);
        dec1 = 2;
      }
      p = uint16_t(p - d1);
    }
    const uint32_t t = uint32_t(v) * d0;
    const uint16_t p2 = uint16_t(p + uint16_t(t >> 16));
    if (p2 < p) {
      v = uint16_t(v - 1);
      dec2 = 1;
      if (((uint32_t(p2) << 16) | uint16_t(t)) >= d) {
        v = uint16_t(v - 1);
        dec2 = 2;
      }
    }
    c.hit(5, uint16_t(1 + dec1 * 3 + dec2));
  }
  // The two quotient words.
  uint16_t q1 = 0, q0;
  uint32_t rem;
  const uint16_t n3 = uint16_t(w >> 32), n2 = uint16_t(w >> 16),
                 n1 = uint16_t(w);
  if (n3 == 0 && uint32_t(w) < d) {
    c.hit(7, 0);
    rem = uint32_t(w);
  } else {
    c.hit(7, 1);
    c.hit(8, divideWordSteps(n3, n2, n1, d, v, &q1, &rem));
  }
  c.hit(9, divideWordSteps(uint16_t(rem >> 16), uint16_t(rem), 0, d, v, &q0,
                           &rem));
  uint32_t q = (uint32_t(q1) << 16) | q0;
  uint8_t round = 0;
  if (rem >= 0x80000000u) {
    round = 2;
  } else if (2 * rem >= d) {
    round = 1;
  }
  c.hit(10, round);
  if (round != 0) {
    ++q;
    if (q == 0) exit = 3;
  }
  if (exit == 5 && q > (negative ? 0x80000000u : 0x7fffffffu)) exit = 4;
  c.hit(6, exit);
  if (exit != 5) {
    c.hit(11, 3);
  } else {
    const uint32_t limit = negative ? 0x80000000u : 0x7fffffffu;
    c.hit(11, q == 0 ? 0 : (q + 3 >= limit ? 2 : 1));
  }
}

// ---- Square root (avrSquareRoot) --------------------------------------
// Families: 0 argument: zero / negative (C code) / positive; 1 the
// normalization: shift e - e0 (in pairs of bits); 2 path: three root bytes
// / two (e >= 9); 3 kSqrt index (normalized top byte - 64); 4 first byte a:
// the table's value / one more / table says 255 (no step); 5 first
// remainder R1 below 256 / from 256 on; 6 second byte's estimate: fits /
// clamped to 255; 7 its correction: none / one less / one more / one more
// refused at 255; 8 a - 128 (the kRecip entry of both reciprocals: a is at
// least 128); 9, 10 the same for the third byte (three-byte path only);
// 11 rounding: down / up.
template <typename C>
TINYPARTICLE_NOINLINE void classifySqrt(int32_t x, uint8_t e0, C& c) {
  if (x <= 0) {
    c.hit(0, x == 0 ? 0 : 1);
    return;
  }
  c.hit(0, 2);
  uint32_t xn = uint32_t(x);
  uint8_t e = e0;
  while ((xn >> 24) == 0) {
    xn <<= 8;
    e = uint8_t(e + 4);
  }
  while (xn < 0x40000000u) {
    xn <<= 2;
    ++e;
  }
  c.hit(1, uint16_t(e - e0));
  const uint8_t top = uint8_t(xn >> 24);
  c.hit(3, uint16_t(top - 64));
  uint32_t a =
      platform::readFlashU8(&detail::TrigTables<void>::kSqrt[top - 64]);
  const uint16_t word = uint16_t(xn >> 16);
  if (a == 255) {
    c.hit(4, 2);
  } else if ((a + 1) * (a + 1) <= word) {
    ++a;
    c.hit(4, 1);
  } else {
    c.hit(4, 0);
  }
  c.hit(8, uint16_t(a - 128));
  const uint32_t r1 = word - a * a;
  c.hit(5, r1 >= 256 ? 1 : 0);
  const uint8_t x1 = uint8_t(xn >> 8), x0 = uint8_t(xn);
  const uint16_t v = recipEntry(uint8_t(a & 0x7f));
  const uint32_t xh = (r1 << 8) | x1;
  const uint64_t estimate = xh + ((uint64_t(xh) * v) >> 16);
  uint32_t b = uint32_t(estimate >> 9);
  c.hit(6, b > 255 ? 1 : 0);
  if (b > 255) b = 255;
  int32_t r2 = int32_t((r1 << 16) | (uint32_t(x1) << 8) | x0) -
               int32_t(b * (512 * a + b));
  if (r2 < 0) {
    --b;
    r2 += int32_t(2 * (256 * a + b) + 1);
    c.hit(7, 1);
  } else if (uint32_t(r2) >= 2 * (256 * a + b) + 1) {
    if (b == 255) {
      c.hit(7, 3);
    } else {
      r2 -= int32_t(2 * (256 * a + b) + 1);
      ++b;
      c.hit(7, 2);
    }
  } else {
    c.hit(7, 0);
  }
  const uint32_t ab = (a << 8) | b;
  if (e >= 9) {
    c.hit(2, 1);
    c.hit(11, (ab >> (e - 9)) & 1);
    return;
  }
  c.hit(2, 0);
  const uint16_t f0 = recipEntry(uint8_t(a & 0x7f));
  const uint16_t f1 = recipEntry(uint8_t((a & 0x7f) + 1));
  const uint16_t v3 =
      uint16_t(f0 - uint16_t((uint32_t(uint16_t(f0 - f1)) * b) >> 8));
  const uint64_t q = uint64_t(uint32_t(r2)) * (0x10000u + v3);
  uint32_t cc = uint32_t(q >> 25);
  c.hit(9, cc > 255 ? 1 : 0);
  if (cc > 255) cc = 255;
  int64_t r3 = (int64_t(r2) << 16) - int64_t(cc) * (512 * int64_t(ab) + cc);
  if (r3 < 0) {
    --cc;
    r3 += 2 * ((int64_t(ab) << 8) + cc) + 1;
    c.hit(10, 1);
  } else if (r3 >= 2 * ((int64_t(ab) << 8) + cc) + 1) {
    if (cc == 255) {
      c.hit(10, 3);
    } else {
      r3 -= 2 * ((int64_t(ab) << 8) + cc) + 1;
      ++cc;
      c.hit(10, 2);
    }
  } else {
    c.hit(10, 0);
  }
  const uint32_t root = (ab << 8) | cc;
  if (e == 0) {
    c.hit(11, r3 > int64_t(root) ? 1 : 0);
  } else {
    c.hit(11, (root >> (e - 1)) & 1);
  }
}

// ---- atan2 (avrAtan2Units) ----------------------------------------------
// Families: 0 quadrant (y < 0) * 2 + (x < 0), 4 = both zero; 1 |y| > |x|
// / equal / less; 2 byte of big's top nonzero byte (0..3); 3 its leading
// zeros (the scale m); 4 big16 clamped to 0xffff: no / yes; 5 small16: as
// scaled / clamped after a carry / clamped to big16; 6 kRecip index;
// 7 ratio t < 2^16 / from 2^16 on (pi / 4); 8 kAtan index (t < 2^16).
template <typename C>
TINYPARTICLE_NOINLINE void classifyAtan2(int32_t y, int32_t x, C& c) {
  const uint32_t ay = magnitude32(y), ax = magnitude32(x);
  if (ay == 0 && ax == 0) {
    c.hit(0, 4);
    return;
  }
  c.hit(0, uint16_t((y < 0) * 2 + (x < 0)));
  c.hit(1, ay > ax ? 0 : (ay == ax ? 1 : 2));
  const bool steep = ay >= ax;
  const uint32_t big = steep ? ay : ax, small = steep ? ax : ay;
  uint8_t shift = 24;
  while ((big >> shift) == 0) shift = uint8_t(shift - 8);
  c.hit(2, uint16_t(shift / 8));
  const uint8_t b2 = uint8_t(big >> shift);
  const uint8_t b1 = shift >= 8 ? uint8_t(big >> (shift - 8)) : 0;
  const uint8_t b0 = shift >= 16 ? uint8_t(big >> (shift - 16)) : 0;
  const uint8_t s2 = uint8_t(small >> shift);
  const uint8_t s1 = shift >= 8 ? uint8_t(small >> (shift - 8)) : 0;
  const uint8_t s0 = shift >= 16 ? uint8_t(small >> (shift - 16)) : 0;
  uint8_t m = 1, zeros = 0;
  for (uint8_t t = b2; !(t & 0x80u); t = uint8_t(t << 1)) {
    m = uint8_t(m << 1);
    ++zeros;
  }
  c.hit(3, zeros);
  uint32_t big16 = detail::scaleWindow(b2, b1, b0, m);
  c.hit(4, big16 > 0xffffu ? 1 : 0);
  if (big16 > 0xffffu) big16 = 0xffffu;
  const uint32_t small16 = detail::scaleWindow(s2, s1, s0, m);
  c.hit(5, small16 > 0xffffu ? 1 : (small16 > big16 ? 2 : 0));
  c.hit(6, uint16_t((big16 >> 8) & 0x7f));
  // The ratio, as in the assembly (and atan2UnitsPortable).
  const uint8_t i = uint8_t((big16 >> 8) & 0x7f);
  const uint16_t r0 = recipEntry(i), r1 = recipEntry(uint8_t(i + 1));
  const uint16_t r =
      uint16_t(r0 - uint16_t((uint32_t(uint16_t(r0 - r1)) * uint8_t(big16)) >> 8));
  const uint32_t s16 = small16 > big16 ? big16 : small16;
  const uint8_t sl = uint8_t(s16), sh = uint8_t(s16 >> 8);
  const uint8_t rl = uint8_t(r), rh = uint8_t(r >> 8);
  const uint32_t sum = 0x80u + uint32_t(sl) * rh + uint32_t(sh) * rl +
                       (uint32_t(sh) * rh << 8);
  const uint32_t t = s16 + (sum >> 8);
  if (t > 0xffffu) {
    c.hit(7, 1);
  } else {
    c.hit(7, 0);
    c.hit(8, uint16_t(t >> 9));
  }
}

// ---- sin and cos of radians (avrSinUnitsQ16) --------------------------------
// a = the Q16.16 angle, b = 0 for sin, 1 for cos (a quarter turn added).
// Families: 0 function and sign: (b != 0) * 2 + (a < 0); 1 quadrant of the
// 24-bit turns (the top two bits: mirrored in 1 and 3, negative in 2 and
// 3); 2 the top of the quarter wave (p = 2^22, exactly one): no / yes;
// 3 kSin index (not at the top).
inline uint8_t sinQuarter(int32_t b) { return b != 0 ? 0x40u : 0u; }

template <typename C>
TINYPARTICLE_NOINLINE void classifySin(int32_t a, int32_t b, C& c) {
  c.hit(0, uint16_t((b != 0) * 2 + (a < 0)));
  const uint32_t t = (detail::turns24FromRadians<16>(magnitude32(a), a < 0) +
                      (uint32_t(sinQuarter(b)) << 16)) & 0xffffffu;
  c.hit(1, uint16_t(t >> 22));
  uint32_t p = t & 0x3fffffu;
  if (t & 0x400000u) p = 0x400000u - p;
  if (p == 0x400000u) {
    c.hit(2, 1);
  } else {
    c.hit(2, 0);
    c.hit(3, uint16_t(p >> 15));
  }
}

// ---- Add and subtract (addSaturating, subtractSaturating) --------------
// Families: 0 signs; 1 outcome: ordinary / within 3 of a limit /
// overflow upwards / overflow downwards.
template <typename C>
TINYPARTICLE_NOINLINE void classifyAdd(int64_t a, int64_t b, bool subtract, int64_t lo, int64_t hi,
                 C& c) {
  c.hit(0, uint16_t((a < 0) * 2 + (b < 0)));
  const int64_t s = subtract ? a - b : a + b;
  c.hit(1, s > hi ? 2 : (s < lo ? 3 : (s + 3 >= hi || s - 3 <= lo ? 1 : 0)));
}

// ---- Q24.8 multiply and divide, Q8.8 divide (C++ around the assembly) -----
// Families: 0 route: Q24.8 multiply: |b| < 2^23 (b scaled) / |a| < 2^23
// (a scaled) / neither (saturated at once); Q24.8 divide: b = 0 / |b| <
// 2^23 (the assembly) / the reference code; Q8.8 divide: b = 0 / the
// assembly. 1 signs. 2 outcome: zero / ordinary / within 3 of the limit /
// saturated (Q8.8 divide: saturated by the Q16.16 routine / by narrowing).
template <typename C>
TINYPARTICLE_NOINLINE void classifyScaled(uint8_t routine, int32_t a, int32_t b, C& c) {
  const bool smallA = a >= -0x800000l && a < 0x800000l;
  const bool smallB = b >= -0x800000l && b < 0x800000l;
  c.hit(1, uint16_t((a < 0) * 2 + (b < 0)));
  int32_t r, lo = INT32_MIN, hi = INT32_MAX;
  clearMathErrors();
  if (routine == kAsmMulQ24) {
    c.hit(0, smallB ? 0 : (smallA ? 1 : 2));
    r = Q24_8::referenceMultiply(a, b);
  } else if (routine == kAsmDivQ24) {
    c.hit(0, b == 0 ? 0 : (smallB ? 1 : 2));
    r = Q24_8::referenceDivide(a, b);
  } else {
    c.hit(0, b == 0 ? 0 : 1);
    lo = INT16_MIN;
    hi = INT16_MAX;
    r = Q8_8::referenceDivide(int16_t(a), int16_t(b));
    if (b != 0 && a != 0) {
      // Saturated already in Q16.16, or only when narrowed to 16 bits?
      const int32_t wide = Q16_16::referenceDivide(a, b * 256);
      if (wide == INT32_MAX || wide == INT32_MIN) {
        c.hit(2, 3);
        clearMathErrors();
        return;
      }
      if (wide > INT16_MAX || wide < INT16_MIN) {
        c.hit(2, 4);
        clearMathErrors();
        return;
      }
    }
  }
  const uint8_t flags = mathErrors();
  clearMathErrors();
  if (flags & MathError::kOverflow) {
    c.hit(2, 3);
  } else if (flags != 0 || r == 0) {
    c.hit(2, 0);
  } else {
    c.hit(2, (r > 0 ? hi - r : r - lo) <= 3 ? 2 : 1);
  }
}

// Any routine's classes for (a, b) (b unused by the square roots).
template <typename C>
TINYPARTICLE_NOINLINE void classify(uint8_t routine, int32_t a, int32_t b, C& c) {
  switch (routine) {
    case kAsmMulQ16: classifyMulQ16(a, b, c); break;
    case kAsmDivQ16: classifyDivQ16(a, b, c); break;
    case kAsmSqrtQ16: classifySqrt(a, 0, c); break;
    case kAsmSqrtQ24: classifySqrt(a, 4, c); break;
    case kAsmSqrtQ8: classifySqrt(int16_t(a), 4, c); break;
    case kAsmMulQ24: case kAsmDivQ24: case kAsmDivQ8:
      classifyScaled(routine, a, b, c);
      break;
    case kAsmAtan2: classifyAtan2(a, b, c); break;
    case kAsmSinQ16: classifySin(a, b, c); break;
    case kAsmAddQ32: classifyAdd(a, b, false, INT32_MIN, INT32_MAX, c); break;
    case kAsmSubQ32: classifyAdd(a, b, true, INT32_MIN, INT32_MAX, c); break;
    case kAsmAddQ16:
      classifyAdd(int16_t(a), int16_t(b), false, INT16_MIN, INT16_MAX, c);
      break;
    default:
      classifyAdd(int16_t(a), int16_t(b), true, INT16_MIN, INT16_MAX, c);
      break;
  }
}


// ---- Running one input --------------------------------------------------

// Result and flags of the fast code (the assembly on AVR) and of the
// reference, and whether the reference has the exact property it must have
// (correct rounding, saturation, flags), checked independently.
struct AsmOutcome {
  int32_t fast, reference;
  uint8_t fastFlags, referenceFlags;
  bool property;

  bool same() const {
    return fast == reference && fastFlags == referenceFlags;
  }
};

// r = round(p / 2^f), ties away from zero, or saturated with the flag.
TINYPARTICLE_NOINLINE inline bool roundedProduct(int64_t p, uint8_t f, int32_t lo, int32_t hi,
                           int32_t r, uint8_t flags) {
  const int64_t half = int64_t(1) << (f - 1);
  if (p >= (2 * int64_t(hi) + 1) * half) {
    return r == hi && flags == MathError::kOverflow;
  }
  if (p <= (2 * int64_t(lo) - 1) * half) {
    return r == lo && flags == MathError::kOverflow;
  }
  const int64_t e = p - int64_t(r) * (int64_t(1) << f);
  return flags == 0 && (p >= 0 ? (e >= -half && e < half)
                               : (e > -half && e <= half));
}

// r = round(a 2^f / b), ties away from zero, saturated, x / 0 flagged.
TINYPARTICLE_NOINLINE inline bool roundedQuotient(int32_t a, int32_t b, uint8_t f, int32_t lo,
                            int32_t hi, int32_t r, uint8_t flags) {
  if (b == 0) {
    return flags == MathError::kDivideByZero &&
           r == (a > 0 ? hi : (a < 0 ? lo : 0));
  }
  const bool negative = (a < 0) != (b < 0);
  const uint64_t num = uint64_t(magnitude32(a)) << f;
  const uint64_t den = magnitude32(b);
  const uint64_t limit = negative ? uint64_t(-int64_t(lo)) : uint64_t(hi);
  // The rounded quotient exceeds limit when num / den >= limit + 1/2.
  if (2 * num >= den * (2 * limit + 1)) {
    return flags == MathError::kOverflow && r == (negative ? lo : hi);
  }
  if (flags != 0) return false;
  if (r != 0 && (r < 0) != negative) return false;
  const int64_t m = int64_t(r < 0 ? -int64_t(r) : int64_t(r));
  const int64_t e = int64_t(num) - m * int64_t(den);  // |e| <= den / 2
  return 2 * e >= -int64_t(den) && 2 * e < int64_t(den);
}

// r = round(sqrt(x 2^f)): (2r - 1)^2 <= 4 x 2^f < (2r + 1)^2.
TINYPARTICLE_NOINLINE inline bool roundedRoot(int32_t x, uint8_t f, int32_t r, uint8_t flags) {
  if (x < 0) return r == 0 && flags == MathError::kNegativeSqrt;
  if (flags != 0 || r < 0) return false;
  const int64_t n4 = int64_t(x) << (f + 2);
  const int64_t below = (2 * int64_t(r) - 1) * (2 * int64_t(r) - 1);
  const int64_t above = (2 * int64_t(r) + 1) * (2 * int64_t(r) + 1);
  return (r == 0 ? n4 < 1 : below <= n4) && n4 < above;
}

TINYPARTICLE_NOINLINE inline bool saturatedSum(int64_t s, int32_t lo, int32_t hi, int32_t r,
                         uint8_t flags) {
  if (s > hi) return r == hi && flags == MathError::kOverflow;
  if (s < lo) return r == lo && flags == MathError::kOverflow;
  return r == s && flags == 0;
}

// atan2 in units of 2^-16 rad within this many units of the exact angle
// (about 1e-4 rad; FixedTrigTest holds Q16.16 atan2 to that).
const int32_t kAtan2ToleranceUnits = 6;

template <typename Exact>
TINYPARTICLE_NOINLINE bool atan2Close(int32_t y, int32_t x, int32_t units) {
  if (y == 0 && x == 0) return units == 0;
  const Exact exact = Exact(::atan2(Exact(y), Exact(x))) * Exact(65536);
  const Exact e = Exact(units) - exact;
  return e <= Exact(kAtan2ToleranceUnits) && e >= -Exact(kAtan2ToleranceUnits);
}

// sin and cos in units of 2^-16 within this many units of the exact value
// (4.6e-5; FixedTrigTest holds Q16.16 sin and cos within 1e-4).
const int32_t kSinToleranceUnits = 3;

template <typename Exact>
TINYPARTICLE_NOINLINE bool sinClose(int32_t x, int32_t b, int32_t units) {
  const Exact angle = Exact(x) / Exact(65536);
  const Exact exact = (b != 0 ? Exact(::cos(angle)) : Exact(::sin(angle))) *
                      Exact(65536);
  const Exact e = Exact(units) - exact;
  return e <= Exact(kSinToleranceUnits) && e >= -Exact(kSinToleranceUnits);
}

// Whether r (with flags fl) is what routine must return for (a, b), by
// exact properties rather than the reference's formula.
TINYPARTICLE_NOINLINE inline bool referenceHasProperty(uint8_t routine,
                                                       int32_t a, int32_t b,
                                                       int32_t r, uint8_t fl) {
  const int16_t a16 = int16_t(a), b16 = int16_t(b);
  bool property;
  switch (routine) {
    case kAsmMulQ16:
      property = roundedProduct(int64_t(a) * b, 16, INT32_MIN, INT32_MAX, r, fl);
      break;
    case kAsmDivQ16:
      property = roundedQuotient(a, b, 16, INT32_MIN, INT32_MAX, r, fl);
      break;
    case kAsmSqrtQ16: property = roundedRoot(a, 16, r, fl); break;
    case kAsmMulQ24:
      property = roundedProduct(int64_t(a) * b, 8, INT32_MIN, INT32_MAX, r, fl);
      break;
    case kAsmDivQ24:
      property = roundedQuotient(a, b, 8, INT32_MIN, INT32_MAX, r, fl);
      break;
    case kAsmSqrtQ24: property = roundedRoot(a, 8, r, fl); break;
    case kAsmDivQ8:
      property = roundedQuotient(a16, b16, 8, INT16_MIN, INT16_MAX, r, fl);
      break;
    case kAsmSqrtQ8: property = roundedRoot(a16, 8, r, fl); break;
    case kAsmAtan2:
#if defined(__AVR__)
      property = fl == 0 && atan2Close<float>(a, b, r);
#else
      property = fl == 0 && atan2Close<double>(a, b, r);
#endif
      break;
    case kAsmSinQ16:
#if defined(__AVR__)
      property = fl == 0 && sinClose<float>(a, b, r);
#else
      property = fl == 0 && sinClose<double>(a, b, r);
#endif
      break;
    case kAsmAddQ32:
      property = saturatedSum(int64_t(a) + b, INT32_MIN, INT32_MAX, r, fl);
      break;
    case kAsmSubQ32:
      property = saturatedSum(int64_t(a) - b, INT32_MIN, INT32_MAX, r, fl);
      break;
    case kAsmAddQ16:
      property = saturatedSum(int32_t(a16) + b16, INT16_MIN, INT16_MAX, r, fl);
      break;
    default:
      property = saturatedSum(int32_t(a16) - b16, INT16_MIN, INT16_MAX, r, fl);
      break;
  }
  return property;
}

// Runs routine on (a, b): fast code and reference, flags cleared before
// each. With property, also checks the reference's exact property (not on
// AVR).
TINYPARTICLE_NOINLINE inline AsmOutcome runAsmRoutine(uint8_t routine, int32_t a, int32_t b,
                                bool property) {
  AsmOutcome o;
  o.property = true;
  const int16_t a16 = int16_t(a), b16 = int16_t(b);
  clearMathErrors();
  switch (routine) {
    case kAsmMulQ16: o.fast = Q16_16::multiply(a, b); break;
    case kAsmDivQ16: o.fast = Q16_16::divide(a, b); break;
    case kAsmSqrtQ16: o.fast = Q16_16::squareRoot(a); break;
    case kAsmMulQ24: o.fast = Q24_8::multiply(a, b); break;
    case kAsmDivQ24: o.fast = Q24_8::divide(a, b); break;
    case kAsmSqrtQ24: o.fast = Q24_8::squareRoot(a); break;
    case kAsmDivQ8: o.fast = Q8_8::divide(a16, b16); break;
    case kAsmSqrtQ8: o.fast = Q8_8::squareRoot(a16); break;
    case kAsmAtan2:
      o.fast = detail::atan2Units(a, b, magnitude32(a), magnitude32(b));
      break;
    case kAsmSinQ16: o.fast = detail::sinUnitsQ16<void>(a, sinQuarter(b)); break;
    case kAsmAddQ32: o.fast = Q16_16::add(a, b); break;
    case kAsmSubQ32: o.fast = Q16_16::subtract(a, b); break;
    case kAsmAddQ16: o.fast = Q8_8::add(a16, b16); break;
    default: o.fast = Q8_8::subtract(a16, b16); break;
  }
  o.fastFlags = mathErrors();
  clearMathErrors();
  switch (routine) {
    case kAsmMulQ16: o.reference = Q16_16::referenceMultiply(a, b); break;
    case kAsmDivQ16: o.reference = Q16_16::referenceDivide(a, b); break;
    case kAsmSqrtQ16: o.reference = Q16_16::referenceSquareRoot(a); break;
    case kAsmMulQ24: o.reference = Q24_8::referenceMultiply(a, b); break;
    case kAsmDivQ24: o.reference = Q24_8::referenceDivide(a, b); break;
    case kAsmSqrtQ24: o.reference = Q24_8::referenceSquareRoot(a); break;
    case kAsmDivQ8: o.reference = Q8_8::referenceDivide(a16, b16); break;
    case kAsmSqrtQ8: o.reference = Q8_8::referenceSquareRoot(a16); break;
    case kAsmAtan2: o.reference = detail::atan2UnitsPortable<void>(a, b); break;
    case kAsmSinQ16:
      o.reference = detail::sinUnitsOfRadians<16, void>(magnitude32(a), a < 0,
                                                        sinQuarter(b));
      break;
    case kAsmAddQ32: o.reference = Q16_16::referenceAdd(a, b); break;
    case kAsmSubQ32: o.reference = Q16_16::referenceSubtract(a, b); break;
    case kAsmAddQ16: o.reference = Q8_8::referenceAdd(a16, b16); break;
    default: o.reference = Q8_8::referenceSubtract(a16, b16); break;
  }
  o.referenceFlags = mathErrors();
  clearMathErrors();
#if defined(__AVR__)
  // Not on AVR (64-bit arithmetic and float atan2 do not fit the flash
  // next to a test): the host checks the same inputs.
  (void)property;
#else
  if (property) {
    o.property = referenceHasProperty(routine, a, b, o.reference,
                                      o.referenceFlags);
  }
#endif
  return o;
}

// ---- Structured inputs ----------------------------------------------------

inline int32_t signedFrom(uint32_t u) { return Q16_16::toSigned(u); }

// Edge values of 32 bits: -3..3, and +-(2^n + d) for n = 1..31,
// d = -3..3 (wrapping at 2^31: the values next to INT32_MIN and
// INT32_MAX). 441 of them.
const uint16_t kEdges32 = 7 + 31 * 7 * 2;
inline int32_t edge32(uint16_t i) {
  if (i < 7) return int32_t(i) - 3;
  i = uint16_t(i - 7);
  const uint8_t n = uint8_t(1 + i / 14);
  const int8_t d = int8_t(i % 7) - 3;
  const uint32_t m = (uint32_t(1) << n) + uint32_t(int32_t(d));
  return signedFrom((i / 7) % 2 ? uint32_t(0) - m : m);
}

// The same for 16 bits: -3..3 and +-(2^n + d), n = 1..15. 217 of them.
const uint16_t kEdges16 = 7 + 15 * 7 * 2;
inline int16_t edge16(uint16_t i) {
  if (i < 7) return int16_t(int16_t(i) - 3);
  i = uint16_t(i - 7);
  const uint8_t n = uint8_t(1 + i / 14);
  const int8_t d = int8_t(i % 7) - 3;
  const uint16_t m = uint16_t((1u << n) + uint16_t(int16_t(d)));
  return Q8_8::toSigned(uint16_t((i / 7) % 2 ? uint16_t(0u - m) : m));
}

// A fixed scramble of an index, for choosing operands and signs in the
// structured sets without a generator's state.
inline uint32_t scramble(uint32_t v) {
  v ^= v >> 16;
  v *= 0x7feb352du;
  v ^= v >> 15;
  v *= 0x846ca68bu;
  v ^= v >> 16;
  return v;
}

// A log-uniform magnitude (bit length 1..maxBits) from a scrambled index.
inline uint32_t logUniform(uint32_t h, uint8_t maxBits) {
  const uint8_t bits = uint8_t(1 + (h % maxBits));
  const uint32_t m = scramble(h) >> (32 - bits);
  return m | (uint32_t(1) << (bits - 1));
}

inline int32_t withSign(uint32_t m, bool negative) {
  return signedFrom(negative ? uint32_t(0) - m : m);
}

// All pairs of edge values (full) or every 29th (the subset), 32 or 16
// bits.
template <typename V>
void edgePairs(bool full, bool sixteen, V& v) {
  const uint16_t n = sixteen ? kEdges16 : kEdges32;
  const uint8_t step = full ? 1 : 29;
  for (uint16_t i = 0; i < n; ++i) {
    const int32_t a = sixteen ? int32_t(edge16(i)) : edge32(i);
    for (uint16_t j = uint16_t(i % step); j < n; j = uint16_t(j + step)) {
      v(a, sixteen ? int32_t(edge16(j)) : edge32(j));
    }
  }
}

template <typename V>
void enumerateMul(bool full, V& v) {
  edgePairs(full, false, v);
  // Products at the saturation edge: |a b| / 2^16 = 2^31 + d, all signs.
  for (uint8_t n = 17; n <= 31; ++n) {
    for (uint8_t k = 0; k < 2; ++k) {
      const uint32_t ma = (uint32_t(1) << (n - 1)) |
                          (scramble(n * 2u + k) >> (33 - n));
      const uint32_t mb0 = uint32_t(((uint64_t(1) << 47) + ma / 2) / ma);
      for (int8_t d = -3; d <= 3; ++d) {
        const uint32_t mb = mb0 + uint32_t(int32_t(d));
        if (mb > 0x7fffffffu) continue;
        for (uint8_t s = 0; s < 4; ++s) {
          v(withSign(ma, s & 1), withSign(mb, s & 2));
          v(withSign(mb, s & 1), withSign(ma, s & 2));
        }
      }
    }
  }
  // Ties: |a| = 2^k, |b| = m 2^(16 - k) + 2^(15 - k) + d.
  for (uint8_t k = 0; k <= 15; ++k) {
    const uint32_t m = scramble(k) >> (k + 2);
    for (int8_t d = -1; d <= 1; ++d) {
      const uint32_t mb = ((m << (16 - k)) | (uint32_t(1) << (15 - k))) +
                          uint32_t(int32_t(d));
      for (uint8_t s = 0; s < 4; ++s) {
        v(withSign(uint32_t(1) << k, s & 1), withSign(mb & 0x7fffffffu, s & 2));
      }
    }
  }
}

// A normalized 32-bit value (top bit set) shifted down to bit length n.
inline uint32_t shiftedTo(uint32_t normalized, uint8_t n) {
  return normalized >> (32 - n);
}

// Each kRecip entry's first and last value (end 0, 1) at each bit length n
// (full) or at one n per entry and end (subset: n = 1 + (i iStep + end
// endStep) % 32), +-3 (d): edge(i, end, n, d, x, h) for each such x that is
// nonzero and at most 2^31, with h a scrambled hash of (i, end, n, d).
// Divide and atan2 both look up kRecip by the top byte of their divisor.
template <typename Edge>
void forEachRecipEdge(bool full, uint8_t iStep, uint8_t endStep, Edge edge) {
  for (uint8_t i = 0; i < 128; ++i) {
    for (uint8_t end = 0; end < 2; ++end) {
      const uint32_t dn = end ? ((uint32_t(129 + i) << 24) - 1)
                              : (uint32_t(128 + i) << 24);
      for (uint8_t n = 1; n <= 32; ++n) {
        if (!full && n != 1 + (i * iStep + end * endStep) % 32u) continue;
        const uint32_t x0 = shiftedTo(dn, n);
        for (int8_t d = -3; d <= 3; ++d) {
          const uint32_t x = x0 + uint32_t(int32_t(d));
          if (x == 0 || x > 0x80000000u) continue;
          const uint32_t h = scramble((uint32_t(i) << 16) ^ (uint32_t(end) << 15) ^
                                      (uint32_t(n) << 8) ^ uint32_t(d + 3));
          edge(i, end, n, d, x, h);
        }
      }
    }
  }
}

template <typename V>
void enumerateDiv(bool full, V& v) {
  edgePairs(full, false, v);
  // Each kRecip entry's first and last divisor, at each bit length (full)
  // or one per entry and end (subset), +-3; numerators: log-uniform, one
  // with a quotient near 2^31, one near 2^16 (the first quotient word).
  forEachRecipEdge(full, 7, 3, [&v](uint8_t, uint8_t, uint8_t, int8_t,
                                    uint32_t mb, uint32_t h) {
    const bool sa = h & 1, sb = h & 2;
    const int32_t b = withSign(mb, sb);
    v(withSign(logUniform(h >> 2, 31), sa), b);
    if (mb <= 0x10000u) {
      v(withSign(mb << 15, sa), b);
      v(withSign((mb << 15) - 1 - (h >> 30), sa), b);
    }
    v(withSign(mb < 0x7ffffffdu ? mb + (h >> 30) : mb, sa), b);
    v(withSign(mb - 1, sa), b);
  });
}

// Square roots: each kSqrt entry's first and last argument at each shift
// (full) or at one shift per entry (subset), +-3; each first root byte a
// at the edges of its remainder R1 (0, 255, 256, 2a) with the low word 0
// or 0xffff; each 16-bit root's square and the value below; special
// arguments. limit: 2^31 - 1 or 2^15 - 1 (Q8.8).
template <typename V>
void sqrtNeighbours(uint32_t x, int32_t limit, V& v) {
  for (int8_t d = -3; d <= 3; ++d) {
    const uint32_t y = x + uint32_t(int32_t(d));
    if (y <= uint32_t(limit)) v(int32_t(y), 0);
  }
}

template <typename V>
void enumerateSqrt(bool full, V& v) {
  const int32_t limit = INT32_MAX;
  for (int8_t d = -3; d <= 3; ++d) v(int32_t(d), 0);
  for (uint8_t d = 0; d < 4; ++d) {
    v(INT32_MIN + d, 0);
    v(INT32_MAX - d, 0);
  }
  for (uint16_t top = 64; top < 256; ++top) {
    for (uint8_t end = 0; end < 2; ++end) {
      const uint32_t xn = end ? ((uint32_t(top + 1) << 24) - 1)
                              : (uint32_t(top) << 24);
      for (uint8_t k = 0; k < 16; ++k) {
        if (!full && k != (top + end * 7u) % 16) continue;
        sqrtNeighbours(xn >> (2 * k), limit, v);
      }
    }
  }
  for (uint32_t a = 128; a < 256; ++a) {
    const uint32_t words[4] = {a * a, a * a + 255, a * a + 256,
                               (a + 1) * (a + 1) - 1};
    for (uint8_t j = 0; j < 8; ++j) {
      const uint32_t xn = (words[j / 2] << 16) | ((j & 1) ? 0xffffu : 0);
      for (uint8_t k = 0; k < 16; ++k) {
        if (!full && k != (a + j) % 16) continue;
        sqrtNeighbours(xn >> (2 * k), limit, v);
      }
    }
  }
  for (uint32_t r = 0x8000u; r < 0x10000u; r += full ? 1 : 37) {
    const uint32_t xn = r * r;
    const uint8_t k = uint8_t(1 + r % 4), k2 = uint8_t(9 + r % 7);
    v(int32_t(xn >> (2 * k)), 0);
    v(int32_t((xn - 1) >> (2 * k)), 0);
    v(int32_t(xn >> (2 * k2)), 0);
    v(int32_t((xn - 1) >> (2 * k2)), 0);
  }
}

template <typename V>
void enumerateAtan2(bool full, V& v) {
  edgePairs(full, false, v);
  // Each kRecip entry's first and last big magnitude, at each bit length
  // (full) or one per entry and end (subset), +-3, with a ratio that walks
  // through the kAtan entries; signs and the larger of |y|, |x| vary.
  forEachRecipEdge(full, 5, 11, [&v](uint8_t i, uint8_t end, uint8_t n, int8_t d,
                                     uint32_t big, uint32_t h) {
    const uint32_t j = (i * 5u + n + end + uint32_t(d + 3)) % 129;
    const uint32_t small = uint32_t((uint64_t(big) * j + 127) / 128);
    const int32_t sb = withSign(big, h & 1);
    const int32_t ss = withSign(small, h & 2);
    if (h & 4) {
      v(sb, ss);
    } else {
      v(ss, sb);
    }
  });
  // Each kAtan entry's edge: small = big j / 128 + d, for a few bigs.
  for (uint16_t j = 0; j <= 128; ++j) {
    for (uint8_t k = 0; k < 8; ++k) {
      if (!full && k != j % 8) continue;
      static const uint8_t kBits[8] = {8, 9, 15, 16, 17, 24, 25, 31};
      const uint32_t big = (uint32_t(1) << kBits[k]) - 1 - (j & 1);
      const uint32_t small0 = uint32_t((uint64_t(big) * j + 64) / 128);
      for (int8_t d = -3; d <= 3; ++d) {
        const uint32_t small = small0 + uint32_t(int32_t(d));
        if (small > big + 3) continue;
        const uint32_t h = scramble(j * 64u + k * 8u + uint32_t(d + 3));
        const int32_t sb = withSign(big, h & 1);
        const int32_t ss = withSign(small, h & 2);
        if (h & 4) {
          v(sb, ss);
        } else {
          v(ss, sb);
        }
      }
    }
  }
}

// sin and cos: the edge values (full only: the inputs below reach every
// class); then each kSin entry boundary of each quadrant, at turns
// k + j 2^15 / 2^24 (j = 0..512, quadrant edges at multiples of 128) for
// k = 0, 1 and the last whole turns that fit (5213 to 5215: the range
// reduction at both ends of the range), the nearest raw angle +-3, both
// signs, sin and cos (full); one k, sign and function each (subset).
template <typename V>
void enumerateSin(bool full, V& v) {
  if (full) {
    for (uint16_t i = 0; i < 2 * kEdges32; ++i) v(edge32(i / 2), i & 1);
  }
  // Raw units (2^-16 rad) per turn, 2 pi 2^16 = 411774 + 54545 / 2^16, and
  // per kSin entry (2^15 / 2^24 turn), 2 pi 2^7 = 804 + 16235 / 2^16: 32-bit
  // arithmetic, within 0.01 of the exact raw angle.
  for (uint16_t j = 0; j <= 4 * 128; ++j) {  // entry boundary j 2^15
    // k: whole turns; s: sign (bit 0) and function (bit 1).
    const uint8_t kFirst = full ? 0 : uint8_t(j % 5);
    for (uint8_t k = kFirst; k < (full ? 5 : kFirst + 1); ++k) {
      const uint32_t turns = k < 2 ? k : 5211u + k;
      const uint32_t x0 = turns * 411774u + uint32_t(j) * 804u +
          ((turns * 54545u + uint32_t(j) * 16235u + 32768u) >> 16);
      for (uint8_t d = 0; d <= 6; ++d) {
        const uint32_t x = x0 + d - 3;
        if (x > 0x7fffffffu) continue;
        const uint8_t sFirst = full ? 0 : uint8_t((j + k + d) & 3);
        for (uint8_t s = sFirst; s < (full ? 4 : sFirst + 1); ++s) {
          v(withSign(x, s & 1), int32_t(s >> 1));
        }
      }
    }
  }
}

template <typename V>
void visitWitnesses(uint8_t routine, V& v);

// Every structured input of routine (full, or the subset).
template <typename V>
void enumerateStructured(uint8_t routine, bool full, V& v) {
  visitWitnesses(routine, v);
  switch (routine) {
    case kAsmMulQ16: enumerateMul(full, v); break;
    case kAsmDivQ16: enumerateDiv(full, v); break;
    case kAsmMulQ24: case kAsmDivQ24:
      // The C++ around the Q16.16 routines: the edge pairs reach all its
      // classes; the full proof adds the Q16.16 routines' structured sets.
      if (full) {
        if (routine == kAsmMulQ24) enumerateMul(true, v);
        else enumerateDiv(true, v);
      } else {
        edgePairs(false, false, v);
      }
      break;
    case kAsmSqrtQ16: case kAsmSqrtQ24: enumerateSqrt(full, v); break;
    case kAsmSqrtQ8:
      // Every 16-bit argument, negative ones too (the subset: every 7th).
      for (int32_t x = INT16_MIN; x <= INT16_MAX; x += full ? 1 : 7) v(x, 0);
      break;
    case kAsmDivQ8: case kAsmAddQ16: case kAsmSubQ16:
      edgePairs(full, true, v);
      break;
    case kAsmAtan2: enumerateAtan2(full, v); break;
    case kAsmSinQ16: enumerateSin(full, v); break;
    default: edgePairs(full, false, v); break;
  }
}

// ---- Random inputs --------------------------------------------------------

// The generator of the random inputs: a 32-bit linear congruential step
// (Knuth's MMIX multiplier's low half, Numerical Recipes' constants) with
// the high half folded onto the low one, so no output bit has a short
// period. One 32-bit multiply per number: the proof draws 3 * 10^7 of
// them per routine on the simulated Nano, where XorShift32's 32-bit shifts
// are loops costing more than the routines under test.
class AsmRandom {
 public:
  explicit AsmRandom(uint32_t seed) : mState(seed) {}
  uint32_t next() {
    mState = mState * 1664525u + 1013904223u;
    return mState ^ (mState >> 16);
  }

 private:
  uint32_t mState;
};

// 2^n - 1 for n = 0..32, from a table: a variable shift of 32 bits is a
// loop on AVR, and the random inputs are made 10^7 times per routine.
inline uint32_t lowMask(uint8_t n) {
  static const uint32_t kMasks[33] TINYPARTICLE_PROGMEM = {
      0x0, 0x1, 0x3, 0x7, 0xf, 0x1f, 0x3f, 0x7f, 0xff, 0x1ff, 0x3ff, 0x7ff,
      0xfff, 0x1fff, 0x3fff, 0x7fff, 0xffff, 0x1ffff, 0x3ffff, 0x7ffff,
      0xfffff, 0x1fffff, 0x3fffff, 0x7fffff, 0xffffff, 0x1ffffff, 0x3ffffff,
      0x7ffffff, 0xfffffff, 0x1fffffff, 0x3fffffff, 0x7fffffff, 0xffffffff};
  return platform::readFlashU32(&kMasks[n]);
}

// A bit length uniform in 0..bits from 8 random bits (bits < 256).
inline uint8_t randomLength(uint8_t random8, uint8_t bits) {
  return uint8_t((uint16_t(random8) * uint8_t(bits + 1)) >> 8);
}

// A random raw value: bit length uniform in 0..bits, then random bits
// below it, random sign (bits is 32 or 16; the value wraps like the raw
// type). `choice` supplies 8 bits for the length and 1 for the sign.
inline int32_t randomLogUniform(AsmRandom& random, uint8_t bits,
                                uint16_t choice) {
  const uint32_t m = random.next() & lowMask(randomLength(uint8_t(choice), bits));
  const uint32_t u = (choice & 0x100u) ? uint32_t(0) - m : m;
  return bits == 16 ? int32_t(Q8_8::toSigned(uint16_t(u))) : signedFrom(u);
}

// A random square-root argument: three in four log-uniform and positive,
// the others next to a point where rounding flips, (k + 1/2)^2 / 2^f; one
// in 64 negative. f = the format's fraction bits.
inline int32_t randomRootArgument(AsmRandom& random, uint8_t f,
                                  int32_t limit) {
  const uint32_t choice = random.next();
  if ((choice & 63) == 0) return -int32_t(random.next() >> 1) - 1;
  if ((choice & 192) != 0) {
    const uint8_t n = uint8_t(1 + randomLength(uint8_t(choice >> 8), 30));
    const uint32_t x = random.next() & lowMask(n);
    return int32_t(x & uint32_t(limit));
  }
  const uint64_t maxRoot = uint64_t(limit) << f;
  uint32_t k = random.next() & lowMask(uint8_t(9 + randomLength(uint8_t(choice >> 16), 23)));
  uint64_t half = uint64_t(k) * k + k;
  while (half >= maxRoot) {
    k >>= 1;
    half = uint64_t(k) * k + k;
  }
  const uint32_t x = uint32_t(half >> f) + ((choice >> 24) & 1);
  return int32_t(x > uint32_t(limit) ? uint32_t(limit) : x);
}

inline void randomInput(uint8_t routine, AsmRandom& random, int32_t* a,
                        int32_t* b) {
  *b = 0;
  switch (routine) {
    case kAsmSqrtQ16: *a = randomRootArgument(random, 16, INT32_MAX); break;
    case kAsmSqrtQ24: *a = randomRootArgument(random, 8, INT32_MAX); break;
    case kAsmSqrtQ8: *a = randomRootArgument(random, 8, INT16_MAX); break;
    case kAsmSinQ16: {
      // Half log-uniform, half uniform over the whole range; sin or cos.
      const uint32_t choice = random.next();
      *a = (choice & 0x200u) ? signedFrom(random.next())
                             : randomLogUniform(random, 32, uint16_t(choice));
      *b = int32_t((choice >> 10) & 1u);
      break;
    }
    default: {
      const uint8_t bits =
          (routine == kAsmDivQ8 || routine == kAsmAddQ16 || routine == kAsmSubQ16)
              ? 16 : 32;
      const uint32_t choice = random.next();
      *a = randomLogUniform(random, bits, uint16_t(choice));
      *b = randomLogUniform(random, bits, uint16_t(choice >> 16));
      break;
    }
  }
}

// ---- Coverage ---------------------------------------------------------------

// The branches no input can take, with the reason (numbers as in
// extras/verify-asm/README.md):
// 1 divide: the interpolated reciprocal is within [-3, +1] of exact for
//   every d1 (VerifyHost tables checks all 32768);
// 2 divide: of the d0 adjustments, "none in the first stage, two in the
//   second" never occurs (VerifyHost tables checks all 2^31 divisors);
// 3 divide: rounding cannot carry the quotient to 2^32: that needs
//   0 < 2^32 |b| - |a| 2^16 <= |b| / 2, a multiple of 2^16, so |b| >= 2^17
//   and |a| > 2^33;
// 4 square root: a correct prefix leaves a next digit of at most 255, so
//   "one more" is never refused at 255;
// 5 Q8.8 divide: |a 2^8 / b| <= 2^23 never saturates in Q16.16;
// 6 atan2: small <= big with the same window and scale, so small16 <=
//   big16 <= 0xffff: no clamp is ever needed.
struct AsmUnreachable {
  uint8_t routine, family, value, reason;
};

inline bool isUnreachable(uint8_t routine, uint8_t family, uint16_t value) {
  static const AsmUnreachable kList[] TINYPARTICLE_PROGMEM = {
      {kAsmDivQ16, 4, 0, 1}, {kAsmDivQ16, 4, 6, 1}, {kAsmDivQ16, 4, 7, 1},
      {kAsmDivQ16, 4, 8, 1}, {kAsmDivQ16, 5, 3, 2}, {kAsmDivQ16, 6, 3, 3},
      {kAsmSqrtQ16, 7, 3, 4}, {kAsmSqrtQ16, 10, 3, 4},
      {kAsmSqrtQ24, 7, 3, 4}, {kAsmSqrtQ24, 10, 3, 4},
      {kAsmDivQ8, 2, 3, 5},
      {kAsmAtan2, 4, 1, 6}, {kAsmAtan2, 5, 1, 6}, {kAsmAtan2, 5, 2, 6}};
  for (uint8_t i = 0; i < sizeof(kList) / sizeof(kList[0]); ++i) {
    const uint8_t* e = &kList[i].routine;
    if (platform::readFlashU8(e) == routine &&
        platform::readFlashU8(e + 1) == family &&
        platform::readFlashU8(e + 2) == value) {
      return true;
    }
  }
  return false;
}

// The Q8.8 square root is checked on every argument: its classes are
// whatever 16-bit arguments reach (some shifts need longer ones), so
// coverage is not required class by class.
inline bool routineIsExhaustive(uint8_t routine) {
  return routine == kAsmSqrtQ8;
}

// Inputs that reach classes the structured subset misses, found among
// random inputs by `VerifyHost w <routine> <count> <seed>`; both the subset
// and the full proof include them.
struct AsmWitness {
  uint8_t routine;
  int32_t a, b;
};

template <typename V>
void visitWitnesses(uint8_t routine, V& v) {
  static const AsmWitness kList[] TINYPARTICLE_PROGMEM = {
      {kAsmDivQ16, 101, 8484516},       // reciprocal 3 below exact
      {kAsmDivQ16, -3968252, -65},      // word 1: one more
      {kAsmDivQ16, -2008372920, 287652137},  // word 2: one more
      {kAsmSqrtQ16, 935325026, 0},      // third byte: one more
      {kAsmSqrtQ24, 1284382403, 0},     // third byte: one more
      // sin and cos: turns exactly at the top of the quarter wave
      // (searched near multiples of pi / 2 on the host).
      {kAsmSinQ16, 1750043, 0}, {kAsmSinQ16, -1750043, 0},
      {kAsmSinQ16, 2470649, 1}, {kAsmSinQ16, -2470649, 1}};
  for (uint8_t i = 0; i < sizeof(kList) / sizeof(kList[0]); ++i) {
    if (platform::readFlashU8(&kList[i].routine) != routine) continue;
    v(int32_t(platform::readFlashU32(
          reinterpret_cast<const uint32_t*>(&kList[i].a))),
      int32_t(platform::readFlashU32(
          reinterpret_cast<const uint32_t*>(&kList[i].b))));
  }
}

// ---- Shards of the full proof -------------------------------------------

// What one run of the proof covers: `kind` 0 = the full structured set
// (every parts-th input from the part-th), 1 = every argument in
// [first, last) (square roots), 2 = `count` random inputs from `seed`.
struct AsmShard {
  uint8_t routine, kind;
  uint32_t first, last;  // kind 0: part, parts; kind 1: range; kind 2: count, seed
};

// Calls v(a, b) on every input of the shard. The same inputs, in the same
// order, on every target: the host counts the classes of what the Nano
// compared, and a checksum of the inputs shows that both saw the same.
template <typename V>
struct EveryNth {
  V& v;
  uint32_t part, parts, index;
  void operator()(int32_t a, int32_t b) {
    if (index++ % parts == part) v(a, b);
  }
};

template <typename V>
void forEachShardInput(const AsmShard& shard, V& v) {
  if (shard.kind == 0) {
    EveryNth<V> every = {v, shard.first, shard.last, 0};
    enumerateStructured(shard.routine, true, every);
  } else if (shard.kind == 1) {
    for (uint32_t x = shard.first; x < shard.last; ++x) v(int32_t(x), 0);
  } else {
    AsmRandom random(shard.last);
    for (uint32_t i = 0; i < shard.first; ++i) {
      int32_t a, b;
      randomInput(shard.routine, random, &a, &b);
      v(a, b);
    }
  }
}

// An order-dependent checksum of the inputs (FNV-1a style, 32 bits).
inline uint32_t mixInput(uint32_t h, int32_t a, int32_t b) {
  h = (h ^ uint32_t(a)) * 16777619u;
  return (h ^ uint32_t(b)) * 16777619u;
}

}  // namespace testing
}  // namespace tinyparticle
