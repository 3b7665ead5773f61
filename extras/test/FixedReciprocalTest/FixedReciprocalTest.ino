// The compact reciprocal (Fixed::compactReciprocal, used at set-up for
// inverse masses and lengths, and compactReciprocalOfPositive for the
// rods' 1 / dt) equals 1 / b as the divide gives it, bit for bit and flag
// for flag, in Q16.16, Q24.8 and Q8.8: against the portable
// referenceDivide(one, b) and against the operator (on the Nano the fast
// AVR divide). Independently of both, a Q16.16 result is within half a
// step of 1 / b (exact 64-bit inequalities), or saturated with kOverflow;
// 1 / 0 gives max() and kDivideByZero.
// The classes the loop tells apart: every leading-bit position of |b|
// with its +-3 neighbours, both signs, zero, the saturating divisors (1
// and 2 steps) and the ends of the range; then random values of every bit
// length. Q8.8 is checked for every raw value on the host.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/MathTestSupport.hpp>

using aunit::TestRunner;
using tinyparticle::testing::XorShift32;
using tinyparticle::testing::magnitude64;
using tinyparticle::testing::printFailure;
using tinyparticle::testing::randomRaw;

#if defined(EPOXY_DUINO)
const uint32_t kRandomValues = 200000;
#else
const uint32_t kRandomValues = 200;
#endif

static XorShift32 gRandom(88172645ul);

// Q16.16: r = 2^32 / b within half a step, a tie away from zero, or
// saturated with kOverflow (b != 0).
static bool q16IsRight(int32_t b) {
  typedef Q16_16 T;
  clearMathErrors();
  const int32_t r = T::compactReciprocal(b);
  const uint8_t flags = mathErrors();
  const bool negative = b < 0;
  const uint64_t d = magnitude64(b);
  const uint64_t n = uint64_t(1) << 33;  // twice 2^32
  // In range when |2^32 / b| < max + 1/2 (resp. |min| + 1/2).
  const uint64_t limit = negative ? uint64_t(0x100000001ull) * d
                                  : uint64_t(0xffffffffull) * d;
  if (n >= limit) {
    return flags == MathError::kOverflow &&
           r == (negative ? T::kRawMin : T::kRawMax);
  }
  if (flags != 0 || (r < 0) != negative) return false;
  const int64_t scaled = int64_t(r) * b;  // |r b| <= 2^32 + |b|: fits
  const uint64_t twiceError =
      magnitude64(int64_t(uint64_t(1) << 32) - scaled) * 2;
  return twiceError <= d;
}

// The checks for one format (a class template: the Arduino builder writes
// no prototypes for its members).
template <typename T>
struct Checks {
  typedef typename T::Raw Raw;

  // compactReciprocal(b) == referenceDivide(one, b) == one / b, flags too.
  static bool matchesTheDivide(Raw b) {
    clearMathErrors();
    const Raw r = T::compactReciprocal(b);
    const uint8_t flags = mathErrors();
    clearMathErrors();
    const Raw reference = T::referenceDivide(T::kRawOne, b);
    const uint8_t referenceFlags = mathErrors();
    clearMathErrors();
    const Raw divided = (T(1) / T::fromRaw(b)).raw();
    const uint8_t dividedFlags = mathErrors();
    clearMathErrors();
    const Raw wrapped =
        tinyparticle::detail::compactReciprocal(T::fromRaw(b)).raw();
    const uint8_t wrappedFlags = mathErrors();
    // The variant for a positive argument (a step's dt), where it applies.
    bool positiveAgrees = true;
    if (b > 0) {
      clearMathErrors();
      const Raw positive =
          tinyparticle::detail::compactReciprocalOfPositive(T::fromRaw(b))
              .raw();
      positiveAgrees = positive == r && mathErrors() == flags;
    }
    if (r != reference || flags != referenceFlags || r != divided ||
        flags != dividedFlags || r != wrapped || flags != wrappedFlags ||
        !positiveAgrees) {
      printFailure(Serial, F("reciprocal"), long(T::kTotalBits), long(b),
                   long(r));
      return false;
    }
    return true;
  }

  static uint16_t failuresAtTheLeadingBits() {
    uint16_t failures = 0;
    for (uint8_t k = 0; k < T::kTotalBits - 1; ++k) {
      const int32_t power = int32_t(1) << k;
      for (int8_t j = -3; j <= 3; ++j) {
        const int32_t m = power + j;
        if (m < 0 || m > int32_t(T::kRawMax)) continue;
        if (!matchesTheDivide(Raw(m))) ++failures;
        if (!matchesTheDivide(Raw(-m))) ++failures;
      }
    }
    // The ends of the range and their neighbours.
    for (int8_t j = 0; j <= 3; ++j) {
      if (!matchesTheDivide(Raw(T::kRawMax - j))) ++failures;
      if (!matchesTheDivide(Raw(T::kRawMin + j))) ++failures;
    }
    return failures;
  }
};

test(zeroGivesMaxAndTheFlag) {
  clearMathErrors();
  assertEqual(Q16_16::compactReciprocal(0), Q16_16::kRawMax);
  assertEqual(mathErrors(), (uint8_t) MathError::kDivideByZero);
  clearMathErrors();
  assertEqual(Q8_8::compactReciprocal(0), Q8_8::kRawMax);
  assertEqual(mathErrors(), (uint8_t) MathError::kDivideByZero);
  assertTrue(Checks<Q16_16>::matchesTheDivide(0));
  assertTrue(Checks<Q24_8>::matchesTheDivide(0));
  assertTrue(Checks<Q8_8>::matchesTheDivide(0));
}

test(saturatingDivisors) {
  // 1 / (1 step) = 2^32 steps: beyond both ends. 1 / (2 steps) = 2^31
  // steps: lowest() exactly when negative, saturated when positive.
  clearMathErrors();
  assertEqual(Q16_16::compactReciprocal(1), Q16_16::kRawMax);
  assertEqual(Q16_16::compactReciprocal(-1), Q16_16::kRawMin);
  assertEqual(Q16_16::compactReciprocal(2), Q16_16::kRawMax);
  assertEqual(mathErrors(), (uint8_t) MathError::kOverflow);
  clearMathErrors();
  assertEqual(Q16_16::compactReciprocal(-2), Q16_16::kRawMin);
  assertEqual(Q16_16::compactReciprocal(3), (int32_t) 1431655765);
  assertEqual(mathErrors(), (uint8_t) 0);
  // Q24.8 never saturates: 1 / (1 step) is 256.0.
  assertEqual(Q24_8::compactReciprocal(1), (int32_t) 65536);
  assertEqual(mathErrors(), (uint8_t) 0);
}

test(everyLeadingBitMatchesTheDivide) {
  assertEqual(Checks<Q16_16>::failuresAtTheLeadingBits(), (uint16_t) 0);
  assertEqual(Checks<Q24_8>::failuresAtTheLeadingBits(), (uint16_t) 0);
  assertEqual(Checks<Q8_8>::failuresAtTheLeadingBits(), (uint16_t) 0);
}

test(q16IsWithinHalfAStep) {
  uint16_t failures = 0;
  for (uint8_t k = 0; k < 31; ++k) {
    for (int8_t j = -3; j <= 3; ++j) {
      const int32_t m = (int32_t(1) << k) + j;
      if (m <= 0) continue;
      if (!q16IsRight(m) || !q16IsRight(-m)) ++failures;
    }
  }
  if (!q16IsRight(INT32_MIN) || !q16IsRight(INT32_MAX)) ++failures;
  for (uint32_t i = 0; i < kRandomValues / 4; ++i) {
    const int32_t b = randomRaw<int32_t>(gRandom, 31);
    if (b != 0 && !q16IsRight(b)) ++failures;
  }
  assertEqual(failures, (uint16_t) 0);
}

test(randomValuesMatchTheDivide) {
  uint32_t failures = 0;
  for (uint32_t i = 0; i < kRandomValues && failures < 10; ++i) {
    if (!Checks<Q16_16>::matchesTheDivide(randomRaw<int32_t>(gRandom, 31))) ++failures;
    if (!Checks<Q24_8>::matchesTheDivide(randomRaw<int32_t>(gRandom, 31))) ++failures;
  }
  assertEqual(failures, (uint32_t) 0);
}

test(everyQ8_8Value) {
#if defined(EPOXY_DUINO)
  const int32_t kStride = 1;
#else
  const int32_t kStride = 257;  // a sample of every high byte
#endif
  uint32_t failures = 0;
  for (int32_t b = INT16_MIN; b <= INT16_MAX && failures < 10; b += kStride) {
    if (!Checks<Q8_8>::matchesTheDivide(int16_t(b))) ++failures;
  }
  assertEqual(failures, (uint32_t) 0);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);
}

void loop() { TestRunner::run(); }
