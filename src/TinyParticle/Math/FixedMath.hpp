// Square root and trigonometry for Fixed.
//
// Accuracy, whatever the format (tested):
// - sqrt is correctly rounded (within half a step of the format).
// - sin, cos, sinTurns, cosTurns and atan2 are within about 4e-5 of the
//   exact value before the final rounding to the format (Q16_16: < 1e-4
//   in all; Q24_8 and Q8_8: within one step).
// The trigonometry works on 16-bit fractions internally and reads its
// tables from program memory (TrigTables.hpp: 258 bytes each for sin, atan
// and the reciprocal; a table is linked only when something uses it).
// On AVR, atan2 and the Q16.16 (and Q8.8) sin and cos run the same steps
// in assembly (FixedAvr.hpp), with the same results bit for bit.
//
// Speed: the binary-angle functions sinTurns<S>(a) / cosTurns<S>(a)
// (Turns.hpp) are the cheapest; a radian argument first has to be
// multiplied by 1 / (2 pi) with enough bits for any representable angle
// (thirteen 8 x 8 products on AVR). extras/benchmarks/ops.md has the cycles.
#pragma once

#include <stdint.h>

#include "Fixed.hpp"
#include "MathErrors.hpp"
#include "TrigTables.hpp"
#include "Turns.hpp"
#include "../Platform/Progmem.hpp"

namespace tinyparticle {

// Correctly rounded square root. sqrt of a negative number returns 0 and
// raises MathError::kNegativeSqrt.
template <uint8_t I, uint8_t F>
inline Fixed<I, F> sqrt(Fixed<I, F> x) {
  return Fixed<I, F>::fromRaw(Fixed<I, F>::squareRoot(x.raw()));
}

namespace detail {

// Dependent on a template parameter, so that a table is instantiated (and
// linked) only where a function that reads it is itself instantiated.
template <typename T>
struct TablesFor {
  typedef TrigTables<void> Type;
};

// ---- Conversions between the internal units and a format -----------------

// A value in units of 2^-16 (|v| < 2^18) rounded to Fixed<I, F>, ties
// away from zero, saturated (only formats that cannot hold pi or 1 can
// overflow here). 32-bit arithmetic only: this runs after every sin,
// cos and atan2.
template <uint8_t I, uint8_t F>
inline Fixed<I, F> fixedFromUnits16(int32_t v) {
  typedef Fixed<I, F> T;
  typedef typename T::Raw Raw;
  // Q16.16 (and any 32-bit format with 16 fraction bits, I >= 16): the
  // units are the representation, and |v| < 2^18 fits.
  if (F == 16 && I >= 16) return T::fromRaw(Raw(v));
  const bool negative = v < 0;
  uint32_t m = negative ? uint32_t(0) - uint32_t(v) : uint32_t(v);
  if (F < 16) {
    const uint8_t shift = F < 16 ? 16 - F : 1;
    m = (m + (uint32_t(1) << (shift - 1))) >> shift;
  } else if (F > 16) {
    const uint8_t shift = F > 16 ? F - 16 : 0;
    if (m > (uint32_t(T::kRawMax) >> shift)) {
      return T::fromRaw(T::overflow(negative));
    }
    m <<= shift;
  }
  if (m > uint32_t(T::kRawMax) + (negative ? 1u : 0u)) {
    return T::fromRaw(T::overflow(negative));
  }
  // In range: -m computed in unsigned arithmetic, then reinterpreted.
  return T::fromRaw(negative ? T::toSigned(typename T::URaw(0u - m))
                             : Raw(m));
}

// (rise * fraction + 128) >> 8 for a 16-bit rise and an 8-bit fraction,
// from two 8 x 8 products: single MUL instructions on AVR, where a
// 16 x 16 multiply is a library call.
inline uint16_t scaleByFraction8(uint16_t rise, uint8_t fraction) {
  // (unsigned products: 255 * 255 does not fit a 16-bit int)
  const uint16_t low = uint16_t(uint16_t(uint8_t(rise)) * fraction);
  const uint16_t high = uint16_t(uint16_t(uint8_t(rise >> 8)) * fraction);
  return uint16_t(high + ((low + 128u) >> 8));
}

// ---- sin -------------------------------------------------------------------

// sin of a binary angle (65536 per turn) in units of 2^-16, in
// [-65536, 65536]: a quarter-wave table, 128 steps, linear interpolation.
// (The table helpers are templates so that a table is instantiated, and
// linked, only by a sketch that calls them.)
template <typename Unused = void>
inline int32_t sinUnits(uint16_t turns) {
  uint16_t p = turns & 0x3fffu;              // angle within the quadrant
  if (turns & 0x4000u) p = 0x4000u - p;      // 2nd and 4th: mirrored
  uint32_t v;
  if (p == 0x4000u) {
    v = 65536;                               // the top: exactly one
  } else {
    const uint8_t i = uint8_t(p >> 7);
    const uint8_t fraction = uint8_t(uint8_t(p) << 1);  // 7 bits, as 8
    const uint16_t y0 = platform::readFlashU16(&TrigTables<Unused>::kSin[i]);
    const uint16_t y1 = platform::readFlashU16(&TrigTables<Unused>::kSin[i + 1]);
    // kSin[128] is stored as 0: the 16-bit difference still comes out right.
    const uint16_t rise = uint16_t(y1 - y0);
    v = uint32_t(y0) + scaleByFraction8(rise, fraction);  // may be 65536
  }
  return (turns & 0x8000u) ? -int32_t(v) : int32_t(v);
}

// Byte j of v.
inline uint8_t byteOf(uint64_t v, uint8_t j) { return uint8_t(v >> (8 * j)); }
// a * b as 16 bits: one MUL on AVR.
TINYPARTICLE_ALWAYS_INLINE uint16_t product8(uint8_t a, uint8_t b) {
#if defined(__AVR__)
  // Hide the operands' origin: gcc would otherwise merge neighbouring
  // 8 x 8 products back into 16 x 16 ones (three MULs and more registers).
  asm("" : "+r"(a));
#endif
  return uint16_t(uint16_t(a) * b);
}

// The same for an angle with 24 bits per turn (the radian functions keep
// 8 more bits of the angle than a binary angle has), with the same steps
// in 16-bit arithmetic and 8 x 8 products (single MULs on AVR): entry
// p >> 15 of the quadrant's angle p, interpolated over its 15-bit fraction
// f as kSin[i] + (rise f + 2^14) >> 15.
template <typename Unused = void>
inline int32_t sinUnits24(uint32_t turns24) {
  const uint8_t top = uint8_t(turns24 >> 16);
  // p = (high, low): the angle within the quadrant, 22 bits; mirrored
  // (2^22 - p) in the 2nd and 4th quadrants.
  uint8_t high = uint8_t(top & 0x3fu);
  uint16_t low = uint16_t(turns24);
  if (top & 0x40u) {
    high = uint8_t(0x40u - high - (low != 0 ? 1u : 0u));
    low = uint16_t(0u - low);
  }
  uint32_t v;
  if (high == 0x40u) {
    v = 65536;  // the top: exactly one
  } else {
    const uint8_t i = uint8_t(uint8_t(high << 1) | uint8_t(low >> 15));
    const uint8_t f0 = uint8_t(low), f1 = uint8_t(uint8_t(low >> 8) & 0x7fu);
    const uint16_t y0 = platform::readFlashU16(&TrigTables<Unused>::kSin[i]);
    const uint16_t y1 =
        platform::readFlashU16(&TrigTables<Unused>::kSin[i + 1]);
    // kSin[128] is stored as 0: the 16-bit difference still comes out right.
    const uint16_t rise = uint16_t(y1 - y0);  // below 2^10
    const uint8_t r0 = uint8_t(rise), r1 = uint8_t(rise >> 8);
    // rise f + 2^14 = r1 f1 2^16 + 2^8 m + (the low byte of r0 f0), with m
    // below 2^16 (r1 < 4, f1 < 2^7), so the result is 2 r1 f1 + m >> 7.
    const uint16_t m = uint16_t(product8(r0, f1) + product8(r1, f0) +
                                (product8(r0, f0) >> 8) + 0x40u);
    v = y0 + uint32_t(uint16_t((product8(r1, f1) << 1) + (m >> 7)));
  }
  return (top & 0x80u) ? -int32_t(v) : int32_t(v);
}

// The high 32 bits of a * b + 2^31 (a rounded 32 x 32 multiply), from four
// 16 x 16 products, which is much cheaper than a 64-bit multiply on AVR.
inline uint32_t multiplyHigh32Rounded(uint32_t a, uint32_t b) {
  const uint16_t a0 = uint16_t(a), a1 = uint16_t(a >> 16);
  const uint16_t b0 = uint16_t(b), b1 = uint16_t(b >> 16);
  const uint32_t low = uint32_t(a0) * b0;
  const uint32_t mid1 = uint32_t(a1) * b0;
  const uint32_t mid2 = uint32_t(a0) * b1;
  // Bits 16..47 of the sum of the middle products and the carry of low,
  // plus the rounding bit 2^31 (bit 15 of this 2^16-scaled sum).
  const uint32_t middle =
      (low >> 16) + uint16_t(mid1) + uint16_t(mid2) + 0x8000u;
  return uint32_t(a1) * b1 + (mid1 >> 16) + (mid2 >> 16) + (middle >> 16);
}

// The angle in 24-bit turns: |raw| / 2^F / (2 pi) * 2^24 mod 2^24, with the
// sign applied. floor(2^64 / (2 pi)) = 0x28BE60DB9391054A is scaled to
// C = that >> (8 + F) (its truncation errs by less than half a unit of the
// result), and the turns are bits 32..55 of |raw| * C, summed byte by byte
// from the 8 x 8 products of the bytes of |raw| (m0..m3) and of C (c0..c7)
// (single MULs on AVR, 16-bit sums). Products below 2^32 are left out and
// replaced by their typical carry (kCarryEstimate, with the rounding half
// unit): the result is within 4 units of 2^-24 turn (1.5e-6 rad) of
// |raw| / 2^F / (2 pi), which FixedTrigTest checks.
template <uint8_t F>
inline uint32_t turns24FromRadians(uint32_t magnitude, bool negative) {
  const uint64_t kInverseTwoPi = 0x28BE60DB9391054Aull;
  const uint64_t c = kInverseTwoPi >> (8 + F);
  const uint8_t m0 = uint8_t(magnitude), m1 = uint8_t(magnitude >> 8);
  const uint8_t m2 = uint8_t(magnitude >> 16), m3 = uint8_t(magnitude >> 24);
  // The products of weight 2^24 (only their high bytes count), 2^32,
  // 2^40 and 2^48 (only their low bytes count).
  const uint16_t p30 = product8(m0, byteOf(c, 3));
  const uint16_t p31 = product8(m1, byteOf(c, 2));
  const uint16_t p32 = product8(m2, byteOf(c, 1));
  const uint16_t p33 = product8(m3, byteOf(c, 0));
  const uint16_t p40 = product8(m0, byteOf(c, 4));
  const uint16_t p41 = product8(m1, byteOf(c, 3));
  const uint16_t p42 = product8(m2, byteOf(c, 2));
  const uint16_t p43 = product8(m3, byteOf(c, 1));
  const uint16_t p50 = product8(m0, byteOf(c, 5));
  const uint16_t p51 = product8(m1, byteOf(c, 4));
  const uint16_t p52 = product8(m2, byteOf(c, 3));
  const uint16_t p53 = product8(m3, byteOf(c, 2));
  const uint8_t p6 = uint8_t(
      product8(m0, byteOf(c, 6)) + product8(m1, byteOf(c, 5)) +
      product8(m2, byteOf(c, 4)) + product8(m3, byteOf(c, 3)));
  // Bytes 4, 5 and 6 of the sum, each with the carry of the one below.
  const uint8_t kCarryEstimate = 3;
  uint16_t sum = uint16_t(kCarryEstimate + (p30 >> 8) + (p31 >> 8) +
                          (p32 >> 8) + (p33 >> 8) + uint8_t(p40) +
                          uint8_t(p41) + uint8_t(p42) + uint8_t(p43));
  const uint8_t t0 = uint8_t(sum);
  sum = uint16_t((sum >> 8) + (p40 >> 8) + (p41 >> 8) + (p42 >> 8) +
                 (p43 >> 8) + uint8_t(p50) + uint8_t(p51) + uint8_t(p52) +
                 uint8_t(p53));
  const uint8_t t1 = uint8_t(sum);
  const uint8_t t2 = uint8_t((sum >> 8) + (p50 >> 8) + (p51 >> 8) +
                             (p52 >> 8) + (p53 >> 8) + p6);
  uint32_t t = (uint32_t(t2) << 16) | uint16_t((uint16_t(t1) << 8) | t0);
  if (negative) t = 0u - t;
  return t & 0xffffffu;
}

template <uint8_t I, uint8_t F>
inline uint32_t turns24Of(Fixed<I, F> x) {
  typedef Fixed<I, F> T;
  return turns24FromRadians<F>(T::magnitude(x.raw()), x.raw() < 0);
}

// sin of a radian angle (quarter = 0) or cos (quarter = 0x40: a quarter
// turn, added to the top byte of the 24-bit turns), in units of 2^-16,
// for a raw value with F fraction bits and its magnitude.
template <uint8_t F, typename U>
inline int32_t sinUnitsOfRadians(uint32_t magnitude, bool negative,
                                 uint8_t quarter) {
  return sinUnits24<U>(turns24FromRadians<F>(magnitude, negative) +
                       (uint32_t(quarter) << 16));
}

// The same for a Q16.16 raw value; on AVR in assembly (avrSinUnitsQ16,
// FixedAvr.hpp: the same result bit for bit).
template <typename U>
inline int32_t sinUnitsQ16(int32_t raw, uint8_t quarter) {
#if TINYPARTICLE_AVR_ASM_MUL
  // The assembly reads kSin by name: keep the table.
  asm volatile("" : : "m"(TrigTables<U>::kSin[0]));
  return avrSinUnitsQ16(raw, quarter);
#else
  const uint32_t magnitude =
      raw < 0 ? uint32_t(0) - uint32_t(raw) : uint32_t(raw);
  return sinUnitsOfRadians<16, U>(magnitude, raw < 0, quarter);
#endif
}

// A format with at most 16 fraction bits and at most 16 integer bits
// (Q16.16, Q8.8) takes the Q16.16 steps on its value scaled exactly to
// Q16.16; the others (Q24.8) their own.
template <uint8_t I, uint8_t F>
struct SinOfRadians {
  typedef typename Fixed<I, F>::Raw Raw;
  static const bool kAsQ16 = F <= 16 && I <= 16;
  template <typename U>
  static int32_t units(Raw raw, uint8_t quarter) {
    if (kAsQ16) {
      const int32_t scale = int32_t(1) << (kAsQ16 ? 16 - F : 0);
      return sinUnitsQ16<U>(int32_t(raw) * scale, quarter);
    }
    return sinUnitsOfRadians<F, U>(Fixed<I, F>::magnitude(raw), raw < 0,
                                   quarter);
  }
};

// ---- atan2 -----------------------------------------------------------------

// round(pi / 2 * 2^16) and round(pi * 2^16).
const uint32_t kHalfPiUnits = 102944u;
const uint32_t kPiUnits = 205887u;

// x * m / 256, truncated, for a window of three bytes x = (x2, x1, x0) and
// a power of two m with x2 * m < 256: three 8 x 8 products.
inline uint32_t scaleWindow(uint8_t x2, uint8_t x1, uint8_t x0, uint8_t m) {
  return (uint32_t(uint8_t(x2 * m)) << 8) + uint16_t(x1 * m) +
         (uint16_t(x0 * m) >> 8);
}

// atan2(y, x) in units of 2^-16 rad, in [-pi, pi], atan2(0, 0) = 0 (y and x
// are raw values of any format, widened to 32 bits). These are exactly the
// steps of the AVR assembly (avrAtan2Units in FixedAvr.hpp), so both give
// the same result bit for bit on every input (`make verify-asm` proves it
// on the simulated Nano):
// 1. big = the larger magnitude (|y| when they are equal), small = the
//    other; a window of three bytes from big's top nonzero byte, scaled by
//    m = 2^(leading zeros of that byte) and truncated to 16 bits: big16 in
//    [2^15, 2^16), small16 <= big16.
// 2. r ~ 2^32 / big16 - 2^16 from kRecip, interpolated (truncated).
// 3. t = small16 + (small16 r + 2^15 - (low bytes' product)) >> 16, the
//    ratio small / big in units of 2^-16 (the product of the two low bytes
//    is left out, as in the assembly: at most one unit less).
// 4. atan from kAtan: entry t >> 9, fraction bits 1..8 of t, rounded;
//    t >= 2^16 gives pi / 4.
// 5. pi / 2 - that when big was |y|; pi - that when x < 0; negated when
//    y < 0.
// Each truncation moves the result by at most a unit or two of 2^-16 rad
// (FixedTrigTest holds the total within 1e-4 rad).
// (U only delays the instantiation of the tables; any type will do.)
template <typename U>
inline int32_t atan2UnitsPortable(int32_t y, int32_t x) {
  typedef typename TablesFor<U>::Type Tables;
  const uint32_t ay = y < 0 ? uint32_t(0) - uint32_t(y) : uint32_t(y);
  const uint32_t ax = x < 0 ? uint32_t(0) - uint32_t(x) : uint32_t(x);
  const bool steep = ay >= ax;
  const uint32_t big = steep ? ay : ax;
  const uint32_t small = steep ? ax : ay;
  if (big == 0) return 0;
  // 1. The window: the top nonzero byte of big and the two below it.
  uint8_t shift = 24;
  while ((big >> shift) == 0) shift = uint8_t(shift - 8);
  const uint8_t b2 = uint8_t(big >> shift);
  const uint8_t b1 = shift >= 8 ? uint8_t(big >> (shift - 8)) : 0;
  const uint8_t b0 = shift >= 16 ? uint8_t(big >> (shift - 16)) : 0;
  const uint8_t s2 = uint8_t(small >> shift);
  const uint8_t s1 = shift >= 8 ? uint8_t(small >> (shift - 8)) : 0;
  const uint8_t s0 = shift >= 16 ? uint8_t(small >> (shift - 16)) : 0;
  uint8_t m = 1;
  for (uint8_t top = b2; !(top & 0x80u); top = uint8_t(top << 1)) {
    m = uint8_t(m << 1);
  }
  uint32_t big16 = scaleWindow(b2, b1, b0, m);
  if (big16 > 0xffffu) big16 = 0xffffu;
  uint32_t small16 = scaleWindow(s2, s1, s0, m);
  if (small16 > big16) small16 = big16;
  // 2. The reciprocal, interpolated between two entries of kRecip.
  const uint8_t i = uint8_t((big16 >> 8) & 0x7fu);
  const uint16_t r0 = platform::readFlashU16(&Tables::kRecip[i]);
  const uint16_t r1 =
      platform::readFlashU16(&Tables::kRecip[i + 1]);
  const uint16_t fall = uint16_t(r0 - r1);
  const uint16_t r =
      uint16_t(r0 - uint16_t((uint32_t(fall) * uint8_t(big16)) >> 8));
  // 3. The ratio.
  const uint8_t sLow = uint8_t(small16), sHigh = uint8_t(small16 >> 8);
  const uint8_t rLow = uint8_t(r), rHigh = uint8_t(r >> 8);
  const uint32_t sum = 0x80u + uint32_t(sLow) * rHigh +
                       uint32_t(sHigh) * rLow +
                       (uint32_t(sHigh) * rHigh << 8);
  const uint32_t t = small16 + (sum >> 8);
  // 4. atan(t / 2^16).
  uint32_t a;
  if (t > 0xffffu) {
    a = platform::readFlashU16(&Tables::kAtan[128]);
  } else {
    const uint8_t j = uint8_t(t >> 9);
    const uint16_t y0 = platform::readFlashU16(&Tables::kAtan[j]);
    const uint16_t y1 =
        platform::readFlashU16(&Tables::kAtan[j + 1]);
    a = uint16_t(y0 + scaleByFraction8(uint16_t(y1 - y0), uint8_t(t >> 1)));
  }
  // 5. The quadrant.
  if (steep) a = kHalfPiUnits - a;
  if (x < 0) a = kPiUnits - a;
  return y < 0 ? -int32_t(a) : int32_t(a);
}

// atan2 in units of 2^-16 rad, in [-pi, pi]. atan2(0, 0) = 0.
template <typename Raw, typename URaw>
inline int32_t atan2Units(Raw y, Raw x, URaw ay, URaw ax) {
  (void)ay;
  (void)ax;
#if TINYPARTICLE_AVR_ASM_MUL
  typedef typename TablesFor<Raw>::Type Tables;
  asm volatile("" : : "m"(Tables::kRecip[0]), "m"(Tables::kAtan[0]));
  return avrAtan2Units(y, x);  // the same steps in assembly
#else
  return atan2UnitsPortable<Raw>(int32_t(y), int32_t(x));
#endif
}

// ---- Binary angles for Fixed --------------------------------------------

template <uint8_t I, uint8_t F>
struct TurnsOf<Fixed<I, F> > {
  static Fixed<I, F> sinTurns(uint16_t turns) {
    return fixedFromUnits16<I, F>(sinUnits(turns));
  }
  static Fixed<I, F> cosTurns(uint16_t turns) {
    return fixedFromUnits16<I, F>(sinUnits(uint16_t(turns + 0x4000u)));
  }
};

}  // namespace detail

// sin and cos of an angle in radians, any representable angle.
template <uint8_t I, uint8_t F>
inline Fixed<I, F> sin(Fixed<I, F> x) {
  return detail::fixedFromUnits16<I, F>(
      detail::SinOfRadians<I, F>::template units<void>(x.raw(), 0));
}
template <uint8_t I, uint8_t F>
inline Fixed<I, F> cos(Fixed<I, F> x) {
  return detail::fixedFromUnits16<I, F>(
      detail::SinOfRadians<I, F>::template units<void>(x.raw(), 0x40u));
}

// The angle of the point (x, y) in radians, in [-pi, pi], like C's atan2
// (y first). atan2(0, 0) is 0. In formats that cannot hold pi the result
// saturates.
template <uint8_t I, uint8_t F>
inline Fixed<I, F> atan2(Fixed<I, F> y, Fixed<I, F> x) {
  typedef Fixed<I, F> T;
  return detail::fixedFromUnits16<I, F>(detail::atan2Units(
      y.raw(), x.raw(), T::magnitude(y.raw()), T::magnitude(x.raw())));
}

// The binary angle nearest to `radians`, wrapped into one turn.
template <uint8_t I, uint8_t F>
inline uint16_t radiansToTurns(Fixed<I, F> angle) {
  return uint16_t((detail::turns24Of(angle) + 0x80u) >> 8);
}

// The angle of (x, y) as a binary angle (65536 per turn), [0, 65536).
template <uint8_t I, uint8_t F>
inline uint16_t atan2Turns(Fixed<I, F> y, Fixed<I, F> x) {
  typedef Fixed<I, F> T;
  const int32_t a = detail::atan2Units(y.raw(), x.raw(),
                                       T::magnitude(y.raw()),
                                       T::magnitude(x.raw()));
  // Turns = a / (2 pi); 683565276 = round(2^32 / (2 pi)).
  const uint32_t m = a < 0 ? uint32_t(-a) : uint32_t(a);
  const uint16_t t =
      uint16_t(detail::multiplyHigh32Rounded(m, 683565276u));
  return a < 0 ? uint16_t(0u - t) : t;
}

}  // namespace tinyparticle
