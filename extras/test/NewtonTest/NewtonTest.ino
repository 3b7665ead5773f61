// The multiply-only inverse square root, unit vectors (the balls'
// normalizeByMultiplies() and the rods' unitBySteps()) and turn factor of
// Math/Newton.hpp, against the exact values (double on the host, float on
// the Nano: both far finer than the bounds), on every input class they
// distinguish: each leading-bit position of the argument and its
// neighbours (the reduction by powers of two), the ends of the reduced
// range (for the rods' unit vectors in 3D, |v|^2 up to 3), zero and
// negatives, and for the turn factor both sides of its series' limit h =
// 1/32, of h = 3/8 (where its root's argument 1 - 2h needs a scaling by 4)
// and of h = 1/2.
//
// Bounds (Q16.16): after the reduction the inverse square root is in
// (0.7, 1.42]; the last Newton step rounds three products and a halving,
// about 2.5 units, and a reduction downwards rounds q by up to 2^-15
// relatively, 2^-16 in the root: 5 units of 2^-16 relative in all.
// Scaling back by 2^k keeps the relative error, and its halvings round:
// one unit more.
// A unit vector: each component within 3 units (the inverse square root's
// relative error on components below 1, plus the product's rounding). The
// turn factor in [1, 2]: 4 units (a polynomial of 4 rounded steps, or an
// inverse square root and the compact reciprocal on arguments near 1); the
// same in units of 2^-8 for Q24.8. Float (a guess from the bits and three
// Newton steps): 4 units of 2^-24 relative for the inverse square root, 8
// for the turn factor; a unit vector's components within 6 units of 2^-24
// (the root's 4, the square's and the product's roundings), from the
// smallest subnormal to the largest float; a zero, infinite or NaN
// component: false, unchanged.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Math/Newton.hpp>
#include <math.h>

using aunit::TestRunner;
using tinyparticle::detail::inverseSqrt;
using tinyparticle::detail::normalizeByMultiplies;
using tinyparticle::detail::reciprocalByMultiplies;
using tinyparticle::detail::turnDropFactor;
using tinyparticle::detail::unitBySteps;

typedef Q16_16 T;
typedef T::Raw Raw;
const double kUnit = 1.0 / 65536;

static double valueOf(T x) { return double(x.raw()) * kUnit; }

static uint16_t gFailures;
static void fail(const __FlashStringHelper* what, double x, double got,
                 double want) {
  if (++gFailures > 10) return;
  Serial.print(what);
  Serial.print(F(" x="));
  Serial.print(x, 8);
  Serial.print(F(" got "));
  Serial.print(got, 8);
  Serial.print(F(" want "));
  Serial.println(want, 8);
}

static void checkInverseSqrt(Raw q) {
  const T y = inverseSqrt(T::fromRaw(q));
  const double want = 1.0 / sqrt(valueOf(T::fromRaw(q)));
  if (fabs(valueOf(y) - want) > 5 * kUnit * want + kUnit) {
    fail(F("inverseSqrt"), valueOf(T::fromRaw(q)), valueOf(y), want);
  }
}

// Both unit vector routines: the balls' (normalizeByMultiplies) and the
// rods' (unitBySteps: Newton's steps on the vector itself, the same
// bound).
static void checkUnit(Raw a, Raw b) {
  if (a == 0 && b == 0) return;  // (below)
  const double x = a * kUnit, y = b * kUnit;
  const double length = sqrt(x * x + y * y);
  for (uint8_t way = 0; way < 2; ++way) {
    Vec2<T> v;
    v.x = T::fromRaw(a);
    v.y = T::fromRaw(b);
    const bool nonZero = way == 0 ? normalizeByMultiplies(v) : unitBySteps(v);
    if (!nonZero || fabs(valueOf(v.x) - x / length) > 3 * kUnit ||
        fabs(valueOf(v.y) - y / length) > 3 * kUnit) {
      fail(way == 0 ? F("unit") : F("unitBySteps"), x, valueOf(v.x),
           x / length);
    }
  }
}

// The rods' unit vector in 3D, where the scaled |v|^2 reaches 3 (its
// first step's case): components a, b, c, each within 3 units.
static void checkUnit3(Raw a, Raw b, Raw c) {
  Vec3<T> v;
  v.x = T::fromRaw(a);
  v.y = T::fromRaw(b);
  v.z = T::fromRaw(c);
  const double x = a * kUnit, y = b * kUnit, z = c * kUnit;
  const double length = sqrt(x * x + y * y + z * z);
  if (!unitBySteps(v) || fabs(valueOf(v.x) - x / length) > 3 * kUnit ||
      fabs(valueOf(v.y) - y / length) > 3 * kUnit ||
      fabs(valueOf(v.z) - z / length) > 3 * kUnit) {
    fail(F("unitBySteps 3D"), x, valueOf(v.x), x / length);
  }
}

static double turnFactorOf(double h) {
  return h >= 0.5 ? 2.0 : 2.0 / (1.0 + sqrt(1.0 - 2.0 * h));
}

static void checkTurn(Raw h) {
  const T f = turnDropFactor(T::fromRaw(h));
  const double want = turnFactorOf(h * kUnit);
  if (fabs(valueOf(f) - want) > 4 * kUnit) {
    fail(F("turnDropFactor"), h * kUnit, valueOf(f), want);
  }
}

// Each leading-bit position of a positive raw value and its neighbours.
#define FOR_EACH_LEADING_BIT(check)                             \
  for (uint8_t s = 0; s < 31; ++s) {                            \
    const int32_t p = int32_t(1) << s;                          \
    for (int8_t d = -2; d <= 2; ++d) {                          \
      if (p + d > 0) check(Raw(p + d));                         \
    }                                                           \
  }                                                             \
  check(Raw(INT32_MAX));                                        \
  check(Raw(INT32_MAX - 1))

test(inverseSqrtAtEveryLeadingBit) {
  gFailures = 0;
  FOR_EACH_LEADING_BIT(checkInverseSqrt);
  // The reduced range [1/2, 2) inside, in steps of 1/256.
  for (Raw q = 32768; q < 131072; q += 256) checkInverseSqrt(q);
  assertEqual(gFailures, (uint16_t)0);
  clearMathErrors();
  assertTrue(inverseSqrt(T(0)) == T(0));
  assertTrue(inverseSqrt(T(-1)) == T(0));
  assertTrue(inverseSqrt(T::lowest()) == T(0));
  assertTrue(inverseSqrt(T(4)) == T(0.5));
  assertEqual(mathErrors(), (uint8_t)0);
}

test(unitVectorsAtEveryLeadingBit) {
  gFailures = 0;
  const Raw others[] = {0, 1, -1, 46341, -65536, 1234567, INT32_MAX,
                        -INT32_MAX};
  for (uint8_t s = 0; s < 31; ++s) {
    const int32_t p = int32_t(1) << s;
    for (int8_t d = -1; d <= 1; ++d) {
      for (uint8_t k = 0; k < sizeof(others) / sizeof(others[0]); ++k) {
        checkUnit(p + d, others[k]);
        checkUnit(others[k], -(p + d));
      }
    }
  }
  assertEqual(gFailures, (uint16_t)0);
  Vec2<T> zero;
  assertFalse(normalizeByMultiplies(zero));
  assertTrue(zero.x == T(0) && zero.y == T(0));
  assertFalse(unitBySteps(zero));
  assertTrue(zero.x == T(0) && zero.y == T(0));
}

// Every leading bit in 3D: three equal components (|v|^2 = 3 after the
// scaling), one with two others of the same or a neighbouring size, and
// the largest and smallest raw values.
test(rodUnitVectors3dAtEveryLeadingBit) {
  gFailures = 0;
  for (uint8_t s = 0; s < 31; ++s) {
    const int32_t p = int32_t(1) << s;
    for (int8_t d = -1; d <= 1; ++d) {
      if (p + d <= 0) continue;
      checkUnit3(p + d, p + d, p + d);
      checkUnit3(-(p + d), p, -(p - 1 > 0 ? p - 1 : 1));
      checkUnit3(p + d, 0, 0);
      checkUnit3(1, -(p + d), INT32_MAX);
    }
  }
  checkUnit3(INT32_MAX, INT32_MAX, INT32_MAX);
  checkUnit3(-INT32_MAX, 1, -1);
  assertEqual(gFailures, (uint16_t)0);
  Vec3<T> zero;
  assertFalse(unitBySteps(zero));
  assertTrue(zero.x == T(0) && zero.y == T(0) && zero.z == T(0));
}

test(turnFactorOnBothSidesOfItsLimits) {
  gFailures = 0;
  // 0, the threshold of a turn (1/512), the series' end (1/32), the
  // reach of the rod (1/2), in Q16.16 units, with neighbours.
  const Raw edges[] = {0, 128, 2048, 24576, 32768, 65536};
  for (uint8_t k = 0; k < sizeof(edges) / sizeof(edges[0]); ++k) {
    for (int8_t d = -3; d <= 3; ++d) {
      if (edges[k] + d >= 0) checkTurn(edges[k] + d);
    }
  }
  for (Raw h = 0; h < 40000; h += 97) checkTurn(h);
  assertEqual(gFailures, (uint16_t)0);
}

// Q24.8 takes fewer steps (two Newton steps, the series cut after h):
// the same bounds in its units of 2^-8, every h from 0 to past 1/2.
test(q24_8InverseSqrtAndTurnFactor) {
  typedef Q24_8 C;
  const double unit = 1.0 / 256;
  gFailures = 0;
  for (uint8_t s = 0; s < 31; ++s) {
    for (int8_t d = -2; d <= 2; ++d) {
      const int32_t raw = (int32_t(1) << s) + d;
      if (raw <= 0) continue;
      const double q = raw * unit;
      const double got = inverseSqrt(C::fromRaw(raw)).raw() * unit;
      const double want = 1.0 / sqrt(q);
      if (fabs(got - want) > 5 * unit * want + unit) {
        fail(F("Q24.8 inverseSqrt"), q, got, want);
      }
    }
  }
  for (int32_t raw = 0; raw <= 160; ++raw) {
    const double got = turnDropFactor(C::fromRaw(raw)).raw() * unit;
    const double want = turnFactorOf(raw * unit);
    if (fabs(got - want) > 4 * unit) {
      fail(F("Q24.8 turnDropFactor"), raw * unit, got, want);
    }
  }
  // The rods' unit vector (five steps for 8 bits): (p, p), within 3 units.
  for (uint8_t s = 0; s < 31; ++s) {
    const int32_t raw = int32_t(1) << s;
    Vec2<C> v(C::fromRaw(raw), C::fromRaw(-raw));
    const double want = sqrt(0.5);
    if (!unitBySteps(v) || fabs(v.x.raw() * unit - want) > 3 * unit ||
        fabs(v.y.raw() * unit + want) > 3 * unit) {
      fail(F("Q24.8 unitBySteps"), raw * unit, v.x.raw() * unit, want);
    }
  }
  assertEqual(gFailures, (uint16_t)0);
}

// The rods' compares of non-negative Float values by their bits
// (Math/Zero.hpp: isBelowNonNegative, isAboveNonNegative, isEqualPositive)
// against the float compares, for every class of input the bits order: +0,
// subnormals, the smallest normal, each constant the rods compare with and
// its neighbours a unit away, large and the largest finite values, and
// infinity. NaN, which the float compares call neither below nor above,
// is above everything (documented there).
static float floatOfBits(uint32_t bits) {
  float f;
  memcpy(&f, &bits, sizeof(f));
  return f;
}

test(floatBitComparesMatchTheCompares) {
  using tinyparticle::detail::floatBits;
  using tinyparticle::detail::isAboveNonNegative;
  using tinyparticle::detail::isBelowNonNegative;
  using tinyparticle::detail::isEqualPositive;
  const float limits[] = {1.0f / 512, 1.0f / 32,       1.0f / 16,
                          0.5f,       1.0f - 1.0f / 64, 1.0f + 1.0f / 64,
                          1.5f,       1.0f - 1.0f / 256, 1.0f + 1.0f / 256};
  const uint32_t others[] = {0, 1, 0x007FFFFFul, 0x00800000ul,
                             0x3F800000ul, 0x7149F2CAul, 0x7F7FFFFFul,
                             0x7F800000ul};
  const uint8_t kLimits = sizeof(limits) / sizeof(limits[0]);
  const uint8_t kOthers = sizeof(others) / sizeof(others[0]);
  uint16_t mismatches = 0;
  for (uint8_t j = 0; j < kLimits; ++j) {
    const Float limit(limits[j]);
    const uint32_t bits = floatBits(limit);
    for (uint8_t k = 0; k < kOthers + 3; ++k) {
      // The limit itself and its neighbours, then the other classes.
      const float x = floatOfBits(k < 3 ? bits + k - 1 : others[k - 3]);
      if (isBelowNonNegative(Float(x), limit) != (x < limits[j])) ++mismatches;
      if (isAboveNonNegative(Float(x), limit) != (x > limits[j])) ++mismatches;
      if (x > 0.0f && isEqualPositive(Float(x), limit) != (x == limits[j])) {
        ++mismatches;
      }
    }
    const Float nan(floatOfBits(0x7FC00000ul));
    assertFalse(isBelowNonNegative(nan, limit));
    assertTrue(isAboveNonNegative(nan, limit));
  }
  assertEqual(mismatches, (uint16_t)0);
}

#if defined(EPOXY_DUINO)
// Float: the same reductions by powers of two, from 2^-100 to 2^100.
test(floatInverseSqrtAndTurnFactor) {
  gFailures = 0;
  for (int e = -100; e <= 100; ++e) {
    for (int d = -1; d <= 1; ++d) {
      const float q = ldexpf(1.0f + float(d) * 1.1920929e-7f, e);
      const double want = 1.0 / sqrt(double(q));
      const double got = inverseSqrt(Float(q)).toFloat();
      if (fabs(got - want) > 4 * 5.9604645e-8 * want) {
        fail(F("float inverseSqrt"), q, got, want);
      }
    }
  }
  for (int i = 0; i <= 600; ++i) {
    const double h = i / 1000.0;
    const double got = turnDropFactor(Float(float(h))).toFloat();
    const double want = turnFactorOf(double(float(h)));
    if (fabs(got - want) > 8 * 5.9604645e-8 * want) {
      fail(F("float turnDropFactor"), h, got, want);
    }
  }
  assertEqual(gFailures, (uint16_t)0);
}

static uint32_t floatBitsOf(Float x) {
  return tinyparticle::detail::floatBits(x);
}

static float floatWithBits(uint32_t bits) {
  float f;
  memcpy(&f, &bits, sizeof(f));
  return f;
}

// The reciprocal without the float divide: Newton's steps from a guess
// from the bits. Every exponent of a normal x whose reciprocal is normal
// (2^-126 to below 2^126), each with the ends of the significand, its
// middle and a few inside (the guess's error depends on the significand
// alone): within 2 units of 2^-24 relative (the last step's rounding).
// Any other x (beyond that range, infinity, NaN, subnormals, 0 and
// negatives) gives 0.
test(floatReciprocalAtEveryExponent) {
  gFailures = 0;
  const uint32_t significands[] = {0, 1, 2, 0x123456, 0x3504F3, 0x400000,
                                   0x5A827A, 0x7FFFFE, 0x7FFFFF};
  for (uint32_t e = 1; e < 253; ++e) {
    for (uint8_t k = 0; k < sizeof(significands) / sizeof(significands[0]);
         ++k) {
      const float x = floatWithBits((e << 23) | significands[k]);
      const double want = 1.0 / double(x);
      const double got = reciprocalByMultiplies(Float(x)).toFloat();
      if (fabs(got - want) > 2 * 5.9604645e-8 * want) {
        fail(F("float reciprocal"), x, got, want);
      }
    }
  }
  assertEqual(gFailures, (uint16_t)0);
  const float outside[] = {ldexpf(1.0f, 126), 3.4e38f, INFINITY, NAN,
                           -NAN, 0.0f, -0.0f, -1.0f, 1.0e-40f, -INFINITY,
                           floatWithBits(0x007FFFFFul)};
  for (uint8_t k = 0; k < sizeof(outside) / sizeof(outside[0]); ++k) {
    assertTrue(floatBitsOf(reciprocalByMultiplies(Float(outside[k]))) == 0);
  }
}

// Both unit vector routines: the balls' at every exponent; the rods'
// (unitBySteps) where |v|^2 is a normal float, and false (v unchanged)
// where it is not (a factor 2 either side of the limits, for the
// rounding of |v|^2, may go either way, but must be right).
static void checkFloatUnit(float x, float y) {
  const double length2 = double(x) * x + double(y) * y;
  const double length = sqrt(length2);
  const double bound = 6 * 5.9604645e-8;
  const double smallest = ldexp(1.0, -126), largest = 3.4028234e38;
  for (uint8_t way = 0; way < 2; ++way) {
    Vec2<Float> v;
    v.x = Float(x);
    v.y = Float(y);
    const bool nonZero = way == 0 ? normalizeByMultiplies(v) : unitBySteps(v);
    if (way == 1 && !nonZero) {
      if ((length2 > 2 * smallest && length2 < largest / 2) ||
          floatBitsOf(v.x) != floatBitsOf(Float(x)) ||
          floatBitsOf(v.y) != floatBitsOf(Float(y))) {
        fail(F("float unitBySteps refused"), x, y, length2);
      }
      continue;
    }
    if (!nonZero || fabs(v.x.toFloat() - x / length) > bound ||
        fabs(v.y.toFloat() - y / length) > bound) {
      fail(way == 0 ? F("float unit") : F("float unitBySteps"), x,
           v.x.toFloat(), x / length);
    }
  }
}

// The rods' unit vector in 3D, equal components, where |v|^2 is normal.
static void checkFloatUnit3(float x) {
  if (!(3.0 * x * x > ldexp(1.0, -125) && 3.0 * x * x < 1.0e38)) return;
  Vec3<Float> v(Float(x), Float(-x), Float(x));
  const double want = 1.0 / sqrt(3.0);
  const double bound = 6 * 5.9604645e-8;
  if (!unitBySteps(v) || fabs(v.x.toFloat() - want) > bound ||
      fabs(v.y.toFloat() + want) > bound ||
      fabs(v.z.toFloat() - want) > bound) {
    fail(F("float unitBySteps 3D"), x, v.x.toFloat(), want);
  }
}

test(floatUnitVectorsAtEveryExponent) {
  gFailures = 0;
  const float others[] = {0.0f, 1.0f, -3.0f, 1.0e-30f, -1.0e30f, 1.4e-45f,
                          3.4e38f};
  for (int e = -149; e <= 127; ++e) {
    const float p = ldexpf(1.0f, e);
    for (uint8_t k = 0; k < sizeof(others) / sizeof(others[0]); ++k) {
      checkFloatUnit(p, others[k]);
      checkFloatUnit(-others[k], -p);
    }
    checkFloatUnit3(p);
  }
  assertEqual(gFailures, (uint16_t)0);
  const float bad[] = {0.0f, INFINITY, -INFINITY, NAN};
  for (uint8_t k = 0; k < 4; ++k) {
    Vec2<Float> v(Float(bad[k]), Float(0.0f));
    assertFalse(normalizeByMultiplies(v));
    assertTrue(floatBitsOf(v.x) == floatBitsOf(Float(bad[k])));
    assertFalse(unitBySteps(v));
    assertTrue(floatBitsOf(v.x) == floatBitsOf(Float(bad[k])));
  }
}
#endif

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);
}

void loop() { TestRunner::run(); }
