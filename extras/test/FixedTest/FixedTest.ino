// Fixed basics for the three formats: constants folded at compile time,
// conversions, + and - (exact, saturating at both ends), comparisons,
// fabs/fmin/fmax/clamp, the named constants, and the sticky error flags.
// The AVR's 16-bit int and 32-bit double are exactly why these also run on
// the Nano.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

// Literals fold at compile time (a static_assert needs a constant), with
// round-to-nearest of the literal's value.
static_assert(Q16_16(0.5).raw() == 32768, "0.5 in Q16.16");
static_assert(Q16_16(-0.5).raw() == -32768, "-0.5 in Q16.16");
static_assert(Q16_16(1).raw() == 65536, "1 in Q16.16");
static_assert(Q16_16(0.15).raw() == 9830, "0.15 * 2^16 = 9830.4");
static_assert(Q16_16(-0.15).raw() == -9830, "rounds to nearest");
static_assert(Q24_8(2.5).raw() == 640, "2.5 in Q24.8");
static_assert(Q8_8(-1.25).raw() == -320, "-1.25 in Q8.8");
// Out of range, a conversion does not compile in a constant expression
// (extras/checks/fail/); at run time it saturates and raises kOverflow
// (extras/test/StabilityTest).
static_assert(Q8_8(127.998).raw() == INT16_MAX, "the largest Q8.8");
static_assert(Q8_8(-128.0).raw() == INT16_MIN, "the lowest Q8.8");
static_assert(Q16_16::pi().raw() == 205887, "round(pi 2^16)");
static_assert(Q24_8::pi().raw() == 804, "round(pi 2^8)");
static_assert(Q8_8::pi().raw() == 804, "round(pi 2^8)");
static_assert(Q16_16::epsilon().raw() == 1, "one step");
static_assert(Q16_16::lowest().raw() == INT32_MIN, "most negative");
static_assert(Q16_16::largest().raw() == INT32_MAX, "largest");

// Checks that hold for every format; returns the number of failures and
// prints the first few.
template <typename T>
struct Basics {
  typedef typename T::Raw Raw;

  static uint8_t fail(const __FlashStringHelper* what) {
    Serial.print(F("failed: "));
    Serial.println(what);
    return 1;
  }

  static uint8_t conversions() {
    uint8_t f = 0;
    // toInt rounds toward zero, like a cast from float.
    if (T(2.75).toInt() != 2) f += fail(F("toInt 2.75"));
    if (T(-2.75).toInt() != -2) f += fail(F("toInt -2.75"));
    if (T(-0.25).toInt() != 0) f += fail(F("toInt -0.25"));
    if (T::lowest().toInt() != -(int32_t(1) << (T::kIntBits - 1))) {
      f += fail(F("toInt lowest"));
    }
    // toFloat is exact for values with few bits.
    if (T(-3.5).toFloat() != -3.5f) f += fail(F("toFloat -3.5"));
    if (T::epsilon().toFloat() != 1.0f / float(int32_t(1) << T::kFracBits)) {
      f += fail(F("toFloat epsilon"));
    }
    // Integer constructors of every width agree.
    if (T(3) != T(3L) || T(3) != T(3u) || T(3) != T(3ul) || T(3) != T(3.0)) {
      f += fail(F("integer constructors"));
    }
    if (T(-7).raw() != Raw(-7 * (int32_t(1) << T::kFracBits))) {
      f += fail(F("T(-7)"));
    }
    return f;
  }

  static uint8_t addSubtract() {
    uint8_t f = 0;
    clearMathErrors();
    const T e = T::epsilon();
    if (T(1.5) + T(-2.25) != T(-0.75)) f += fail(F("1.5 - 2.25"));
    if (T(1) - e + e != T(1)) f += fail(F("steps"));
    if (T::largest() - e + e != T::largest()) f += fail(F("max - e + e"));
    if (T::lowest() + e - e != T::lowest()) f += fail(F("lowest + e - e"));
    if (mathErrors() != 0) f += fail(F("no flag in range"));
    // Saturation at both ends, with the flag.
    if (T::largest() + e != T::largest()) f += fail(F("max + e"));
    if (mathErrors() != MathError::kOverflow) f += fail(F("flag max + e"));
    clearMathErrors();
    if (T::lowest() - e != T::lowest()) f += fail(F("lowest - e"));
    if (T::largest() - T::lowest() != T::largest()) f += fail(F("max - lowest"));
    if (T::lowest() + T::lowest() != T::lowest()) f += fail(F("2 lowest"));
    if (-T::lowest() != T::largest()) f += fail(F("-lowest"));
    if (mathErrors() != MathError::kOverflow) f += fail(F("flag lowest"));
    clearMathErrors();
    // Compound forms do the same.
    T x(1);
    x += T(2);
    x -= T(0.5);
    x *= T(2);
    x /= T(5);
    if (x != T(1)) f += fail(F("compound"));
    if (mathErrors() != 0) f += fail(F("compound flag"));
    return f;
  }

  static uint8_t comparisonsAndHelpers() {
    uint8_t f = 0;
    const T a(-1.5), b(0.25);
    if (!(a < b) || !(a <= b) || a > b || a >= b || a == b || !(a != b)) {
      f += fail(F("compare"));
    }
    if (!(T::lowest() < T::largest())) f += fail(F("ends"));
    if (fabs(a) != T(1.5) || fabs(b) != b || fabs(T()) != T()) {
      f += fail(F("fabs"));
    }
    clearMathErrors();
    if (fabs(T::lowest()) != T::largest()) f += fail(F("fabs lowest"));
    if (mathErrors() != MathError::kOverflow) f += fail(F("fabs flag"));
    if (fmin(a, b) != a || fmax(a, b) != b) f += fail(F("fmin fmax"));
    if (clamp(T(3), a, b) != b || clamp(T(-3), a, b) != a ||
        clamp(T(0), a, b) != T(0)) {
      f += fail(F("clamp"));
    }
    // pi is within half a step of the real one (where it fits).
    const float step = 1.0f / float(int32_t(1) << T::kFracBits);
    if (T::pi().toFloat() - 3.14159265f > step / 2 + 1e-6f ||
        3.14159265f - T::pi().toFloat() > step / 2 + 1e-6f) {
      f += fail(F("pi"));
    }
    if (T::largest().raw() != T::kRawMax || T::epsilon().raw() != 1) {
      f += fail(F("constants"));
    }
    return f;
  }
};

test(conversionsForEveryFormat) {
  assertEqual(Basics<Q16_16>::conversions(), (uint8_t) 0);
  assertEqual(Basics<Q24_8>::conversions(), (uint8_t) 0);
  assertEqual(Basics<Q8_8>::conversions(), (uint8_t) 0);
}

// A value known only at run time is converted by integer steps on the
// float's bits (Fixed::fromDoubleOutOfLine()), a constant by float steps
// (referenceFromDouble()): the same result and flag for every class of
// input the bits' steps tell apart. Every exponent (zero and subnormals,
// each shift left and right, infinities and NaN), both signs, and at each
// exponent the significands around its two edges: the bit worth half a
// unit of the result (below, on and above a tie, with the unit's bit odd
// and even), and the bit where the scaled value reaches 2^32.
volatile float gConverted;  // not a constant: the run-time conversion

template <typename T>
uint8_t mismatchAt(uint32_t bits) {
  float f;
  memcpy(&f, &bits, sizeof(f));
  gConverted = f;
  clearMathErrors();
  const typename T::Raw fast = T(double(gConverted)).raw();
  const uint8_t fastFlags = mathErrors();
  clearMathErrors();
  const typename T::Raw reference = T::referenceFromDouble(f);
  if (fast == reference && fastFlags == mathErrors()) return 0;
  Serial.print(F("conversion differs at bits 0x"));
  Serial.println(bits, HEX);
  return 1;
}

template <typename T>
uint16_t conversionMismatches() {
  uint16_t mismatches = 0;
  for (uint16_t exponent = 0; exponent < 256; ++exponent) {
    // The value is m 2^shift units of the result, m the significand.
    const int16_t shift =
        int16_t(exponent != 0 ? exponent : 1) - 150 + T::kFracBits;
    uint32_t m[12] = {0, 1, 0x400000ul, 0x7FFFFFul};
    uint8_t count = 4;
    if (shift < 0 && shift >= -24) {  // the half unit is bit -shift - 1
      const uint32_t half = uint32_t(1) << (-shift - 1);
      m[count++] = half - 1;
      m[count++] = half;
      m[count++] = half + 1;
      m[count++] = 3 * half;
      m[count++] = 2 * half - 1;
    }
    if (shift > 8 && shift < 32) {  // 2^32 reached at bit 32 - shift
      const uint32_t top = uint32_t(1) << (32 - shift);
      m[count++] = top - 1;
      m[count++] = top;
      m[count++] = top + 1;
    }
    for (uint8_t k = 0; k < count; ++k) {
      for (uint8_t sign = 0; sign < 2; ++sign) {
        mismatches += mismatchAt<T>((uint32_t(sign) << 31) |
                                    (uint32_t(exponent) << 23) |
                                    (m[k] & 0x7FFFFFul));
      }
    }
  }
  clearMathErrors();
  return mismatches;
}

test(runTimeConversionMatchesConstantsBitForBit) {
  assertEqual(conversionMismatches<Q16_16>(), (uint16_t) 0);
  assertEqual(conversionMismatches<Q24_8>(), (uint16_t) 0);
  assertEqual(conversionMismatches<Q8_8>(), (uint16_t) 0);
}

// On the PC a double beyond float's range saturates before it is rounded
// to float (there the rounding would be undefined behaviour); on AVR the
// same product is an infinity, which saturates too.
test(runTimeConversionOfLargeDoubles) {
  volatile double big = 1e30, edge = 4294967296.0;
  const double huge = big * big;  // 1e60 on the PC
  clearMathErrors();
  assertTrue(Q16_16(huge) == Q16_16::largest());
  assertTrue(Q16_16(-huge) == Q16_16::lowest());
  assertTrue(Q24_8(double(edge)) == Q24_8::largest());
  assertTrue(Q8_8(-double(edge)) == Q8_8::lowest());
  assertEqual(mathErrors(), (uint8_t) MathError::kOverflow);
  clearMathErrors();
  volatile double inRange = -12345.6789;
  assertEqual(Q16_16(double(inRange)).raw(), Q16_16(-12345.6789).raw());
  assertEqual(mathErrors(), (uint8_t) MathError::kNone);
}

test(addAndSubtractSaturateAtBothEnds) {
  assertEqual(Basics<Q16_16>::addSubtract(), (uint8_t) 0);
  assertEqual(Basics<Q24_8>::addSubtract(), (uint8_t) 0);
  assertEqual(Basics<Q8_8>::addSubtract(), (uint8_t) 0);
}

test(comparisonsAndHelpers) {
  assertEqual(Basics<Q16_16>::comparisonsAndHelpers(), (uint8_t) 0);
  assertEqual(Basics<Q24_8>::comparisonsAndHelpers(), (uint8_t) 0);
  assertEqual(Basics<Q8_8>::comparisonsAndHelpers(), (uint8_t) 0);
}

test(rangesOfTheFormats) {
  // Q16.16 holds [-32768, 32768), Q24.8 [-8388608, 8388608),
  // Q8.8 [-128, 128), each to within one step.
  assertNear(Q16_16::largest().toFloat(), 32768.0f, 0.0001f);
  assertNear(Q16_16::lowest().toFloat(), -32768.0f, 0.0001f);
  assertNear(Q24_8::largest().toFloat(), 8388608.0f, 1.0f);
  assertNear(Q24_8::lowest().toFloat(), -8388608.0f, 1.0f);
  assertNear(Q8_8::largest().toFloat(), 128.0f, 0.004f);
  assertNear(Q8_8::lowest().toFloat(), -128.0f, 0.004f);
  assertEqual((int) sizeof(Q8_8), 2);
  assertEqual((int) sizeof(Q16_16), 4);
  assertEqual((int) sizeof(Q24_8), 4);
}

test(flagsAreStickyUntilCleared) {
  clearMathErrors();
  assertEqual(mathErrors(), (uint8_t) MathError::kNone);
  Q16_16 big(30000);
  big = big + big;                     // overflow
  Q16_16 q = Q16_16(1) / Q16_16();     // divide by zero
  Q16_16 r = sqrt(Q16_16(-2));         // negative sqrt
  Q16_16 fine = Q16_16(2) * Q16_16(3); // raises nothing, clears nothing
  assertTrue(big == Q16_16::largest() && q == Q16_16::largest() && r == Q16_16());
  assertTrue(fine == Q16_16(6));
  assertEqual(mathErrors(), (uint8_t) (MathError::kOverflow |
                                       MathError::kDivideByZero |
                                       MathError::kNegativeSqrt));
  clearMathErrors();
  assertEqual(mathErrors(), (uint8_t) MathError::kNone);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
