// The seed engine's Q16.16 arithmetic, rebuilt from the report's description
// (haptic-interface-report.txt, section 3.2.1, Code Blocks 3.2, 3.3 and 3.5)
// so that the benchmark can show the baseline in the same run. It lives here,
// not in the library: it is the thing we measure against, not something to use.
//
// What the report describes, and what this keeps:
// - multiply and divide take the magnitudes (a sign flag records the signs),
//   widen to 64 bits, shift by 16 and truncate, then multiply the result by
//   the sign (+1 or -1);
// - the square root is Turkowski's bit-by-bit method, two bits of the radicand
//   per step, 24 steps for a 16.16 number, truncating;
// - atan2 folds (x, y) into the first half-quadrant in up to three steps
//   (half turn, quarter turn, eighth turn), divides, and interpolates a table
//   of 201 values of atan on [0, 1] kept as 64-bit numbers in flash.
//
// What differs, so that nothing here is undefined behaviour: negation and
// overflowing sums are done on unsigned values (the seed wraps on AVR anyway,
// with the same instructions), a zero divisor returns 0 instead of faulting,
// and an out-of-range table argument is clamped instead of halting.
#pragma once

#include <avr/pgmspace.h>
#include <stdint.h>

#include "SeedAtanTable.h"

namespace seed {

typedef int32_t Fixed;  // 16.16, like the seed's FixedPoint

const uint8_t kShift = 16;
const Fixed kOne = Fixed(1) << kShift;
const Fixed kPi = 205887;  // round(pi * 2^16)

// Two's complement wrap-around without relying on signed overflow.
inline Fixed wrap(uint32_t u) {
  return u <= 0x7FFFFFFFUL ? Fixed(u) : Fixed(-Fixed(~u) - 1);
}
inline Fixed negate(Fixed v) { return wrap(0UL - uint32_t(v)); }

inline Fixed add(Fixed a, Fixed b) { return wrap(uint32_t(a) + uint32_t(b)); }
inline Fixed subtract(Fixed a, Fixed b) {
  return wrap(uint32_t(a) - uint32_t(b));
}

// The sign is kept as an int (+1/-1) and applied with a 32-bit multiply at
// the end, as the report's code does.
inline Fixed multiply(Fixed a, Fixed b) {
  int sign = 1;
  if (a < 0) {
    a = negate(a);
    sign = -sign;
  }
  if (b < 0) {
    b = negate(b);
    sign = -sign;
  }
  // Magnitudes up to 2^31 as uint32: their product fits int64 without overflow.
  int64_t product = int64_t(uint32_t(a)) * int64_t(uint32_t(b));
  uint32_t shifted = uint32_t(uint64_t(product >> kShift));
  return wrap(shifted * uint32_t(int32_t(sign)));
}

inline Fixed divide(Fixed num, Fixed den) {
  int sign = 1;
  if (num < 0) {
    num = negate(num);
    sign = -sign;
  }
  if (den < 0) {
    den = negate(den);
    sign = -sign;
  }
  if (den == 0) return 0;
  int64_t wide = int64_t(uint32_t(num)) << kShift;  // below 2^48: no overflow
  int64_t quotient = wide / int64_t(uint32_t(den));
  return wrap(uint32_t(uint64_t(quotient)) * uint32_t(int32_t(sign)));
}

// Turkowski's square root: the root grows one bit per step while the
// remainder takes in two more bits of the radicand (the input, then 16 zero
// bits for the fraction).
inline Fixed squareRoot(Fixed v) {
  uint32_t root = 0;
  uint32_t remainderHigh = 0;
  uint32_t remainderLow = uint32_t(v);
  uint8_t steps = 24;  // 15 + 16 / 2, plus the last one
  do {
    remainderHigh = (remainderHigh << 2) | (remainderLow >> 30);
    remainderLow <<= 2;
    root <<= 1;
    uint32_t trial = (root << 1) + 1;
    if (remainderHigh >= trial) {
      remainderHigh -= trial;
      root += 1;
    }
  } while (--steps != 0);
  return Fixed(root);
}

// atan(x) for x in [0, 1] (16.16): table index from 200 x, then a straight
// line to the next entry.
inline Fixed atanTable(Fixed x) {
  if (x < 0) x = 0;
  if (x > kOne) x = kOne;
  Fixed scaled = multiply(Fixed(200) << kShift, x);
  int16_t i = int16_t(scaled >> kShift);
  int64_t entry;
  memcpy_P(&entry, &kSeedAtanTable[i], sizeof(entry));
  Fixed low = Fixed(entry >> (32 - kShift));
  if (i + 1 > 200) return low;
  int64_t next;
  memcpy_P(&next, &kSeedAtanTable[i + 1], sizeof(next));
  Fixed high = Fixed(next >> (32 - kShift));
  Fixed within = scaled - (Fixed(i) << kShift);
  return low + multiply(high - low, within);
}

// Angle of (x, y) counter-clockwise from +x, in [0, 2 pi).
inline Fixed atan2(Fixed y, Fixed x) {
  Fixed eighths = 0;
  if (y < 0) {  // half turn: into the upper half plane
    x = negate(x);
    y = negate(y);
    eighths += 4;
  }
  if (x <= 0) {  // quarter turn clockwise: into the first quadrant
    Fixed t = x;
    x = y;
    y = negate(t);
    eighths += 2;
  }
  if (x <= y) {  // eighth turn clockwise (scaled by sqrt 2): below the diagonal
    Fixed t = subtract(y, x);
    x = add(x, y);
    y = t;
    eighths += 1;
  }
  if (x == 0) return 0;  // only for (0, 0)
  Fixed angle = atanTable(divide(y, x));
  return wrap(uint32_t(angle) +
              uint32_t(kPi >> 2) * uint32_t(eighths));
}

// The seed's Vector3D::magnitude() and normalize().
inline Fixed magnitude3(Fixed x, Fixed y, Fixed z) {
  return squareRoot(
      add(add(multiply(x, x), multiply(y, y)), multiply(z, z)));
}

struct Vector3 {
  Fixed x, y, z;
};

inline Vector3 normalize3(Vector3 v) {
  Fixed length = magnitude3(v.x, v.y, v.z);
  if (length != 0) {
    v.x = divide(v.x, length);
    v.y = divide(v.y, length);
    v.z = divide(v.z, length);
  }
  return v;
}

}  // namespace seed
