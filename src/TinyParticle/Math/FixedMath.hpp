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
// On AVR, atan2 runs the same steps in assembly (FixedAvr.hpp).
//
// Speed: prefer the binary-angle functions sinTurns<S>(a) / cosTurns<S>(a)
// (Turns.hpp): a radian argument first has to be multiplied by 1 / (2 pi)
// with enough bits to stay exact for any representable angle.
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

// The same for an angle with 24 bits per turn (the radian functions keep
// 8 more bits of the angle than a binary angle has).
template <typename Unused = void>
inline int32_t sinUnits24(uint32_t turns24) {
  uint32_t p = turns24 & 0x3fffffu;
  if (turns24 & 0x400000u) p = 0x400000u - p;
  uint32_t v;
  if (p == 0x400000u) {
    v = 65536;
  } else {
    const uint8_t i = uint8_t(p >> 15);
    const uint16_t fraction = uint16_t(p & 0x7fffu);
    const uint16_t y0 = platform::readFlashU16(&TrigTables<Unused>::kSin[i]);
    const uint16_t y1 = platform::readFlashU16(&TrigTables<Unused>::kSin[i + 1]);
    const uint16_t rise = uint16_t(y1 - y0);
    v = y0 + ((uint32_t(rise) * fraction + 16384u) >> 15);
  }
  return (turns24 & 0x800000u) ? -int32_t(v) : int32_t(v);
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

// round(|raw| / 2^F / (2 pi) * 2^24) mod 2^24, with the sign applied: the
// angle in 24-bit turns. floor(2^64 / (2 pi)) = 0x28BE60DB9391054A; it is
// scaled to C = that >> (8 + F), and the turn count is bits 32..55 of
// |raw| * C. Both halves of C fit 32 bits for every format, and its
// truncation errs by less than half a unit of the result.
template <uint8_t F>
inline uint32_t turns24FromRadians(uint32_t magnitude, bool negative) {
  const uint64_t kInverseTwoPi = 0x28BE60DB9391054Aull;
  const uint64_t c = kInverseTwoPi >> (8 + F);
  const uint32_t high = uint32_t(c >> 32);
  const uint32_t low = uint32_t(c);
  uint32_t t = magnitude * high + multiplyHigh32Rounded(magnitude, low);
  if (negative) t = 0u - t;
  return t & 0xffffffu;
}

template <uint8_t I, uint8_t F>
inline uint32_t turns24Of(Fixed<I, F> x) {
  typedef Fixed<I, F> T;
  return turns24FromRadians<F>(T::magnitude(x.raw()), x.raw() < 0);
}

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
      detail::sinUnits24(detail::turns24Of(x)));
}
template <uint8_t I, uint8_t F>
inline Fixed<I, F> cos(Fixed<I, F> x) {
  return detail::fixedFromUnits16<I, F>(
      detail::sinUnits24(detail::turns24Of(x) + 0x400000u));
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
