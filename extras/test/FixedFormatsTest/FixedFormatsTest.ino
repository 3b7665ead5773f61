// Q24_8 and Q8_8: multiply, divide and square root are correctly rounded
// to their own step (within half a step; ties away from zero), checked
// with exact 64-bit integer inequalities: 10^6 random pairs per operation
// on the host, a sample on the Nano; every Q8_8 square root. Results out
// of range saturate with kOverflow; x / 0 and sqrt(x < 0) raise their
// flags. The most negative raw value is among the operands.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/MathTestSupport.hpp>

using aunit::TestRunner;
// Helpers shared by the math sketches
// (src/TinyParticle/Testing/MathTestSupport.hpp).
using tinyparticle::testing::XorShift32;
using tinyparticle::testing::magnitude64;
using tinyparticle::testing::printFailure;
using tinyparticle::testing::randomRawOfLength;

#if defined(EPOXY_DUINO)
const uint32_t kRandomPairs = 1000000;
#else
const uint32_t kRandomPairs = 2500;
#endif

static XorShift32 gRandom(1234567ul);

template <typename T>
struct Rounding {
  typedef typename T::Raw Raw;
  static const uint8_t F = T::kFracBits;

  // A raw value with a random bit length (all lengths equally often),
  // random sign; sometimes the most negative value.
  static Raw randomRaw() {
    const uint8_t total = T::kTotalBits;
    const uint8_t bits = uint8_t(gRandom.next() % total);
    if (bits == total - 1 && (gRandom.next() & 7) == 0) return T::kRawMin;
    return randomRawOfLength<Raw>(gRandom, bits);
  }

  static bool multiplyIsRight(Raw a, Raw b) {
    clearMathErrors();
    const Raw r = (T::fromRaw(a) * T::fromRaw(b)).raw();
    const uint8_t flags = mathErrors();
    const int64_t p = int64_t(a) * b;
    const int64_t half = int64_t(1) << (F - 1);
    const int64_t top = (2 * int64_t(T::kRawMax) + 1) * half;
    const int64_t bottom = (2 * int64_t(T::kRawMin) - 1) * half;
    bool right;
    if (p >= top) {
      right = r == T::kRawMax && flags == MathError::kOverflow;
    } else if (p <= bottom) {
      right = r == T::kRawMin && flags == MathError::kOverflow;
    } else {
      const int64_t scaled = int64_t(r) * (int64_t(1) << F);
      const uint64_t error = magnitude64(p - scaled);
      right = flags == 0 && error <= uint64_t(half) &&
              (error < uint64_t(half) || magnitude64(scaled) > magnitude64(p));
    }
    if (!right) printFailure(Serial, F("multiply"), a, b, r);
    return right;
  }

  static bool divideIsRight(Raw a, Raw b) {
    clearMathErrors();
    const Raw r = (T::fromRaw(a) / T::fromRaw(b)).raw();
    const uint8_t flags = mathErrors();
    bool right;
    if (b == 0) {
      right = flags == MathError::kDivideByZero &&
              r == (a > 0 ? T::kRawMax : (a < 0 ? T::kRawMin : Raw(0)));
    } else {
      const bool negative = (a < 0) != (b < 0);
      const uint64_t n = magnitude64(a) << (F + 1);
      const uint64_t d = magnitude64(b);
      const uint64_t limit =
          (2 * (negative ? magnitude64(T::kRawMin) : uint64_t(T::kRawMax)) + 1) * d;
      if (n >= limit) {
        right = flags == MathError::kOverflow &&
                r == (negative ? T::kRawMin : T::kRawMax);
      } else {
        const int64_t exact = int64_t(a) * (int64_t(1) << F);
        const int64_t scaled = int64_t(r) * b;
        const uint64_t twiceError = magnitude64(exact - scaled) * 2;
        right = flags == 0 && twiceError <= d &&
                (twiceError < d || magnitude64(scaled) > magnitude64(exact)) &&
                (r == 0 || (r < 0) == negative);
      }
    }
    if (!right) printFailure(Serial, F("divide"), a, b, r);
    return right;
  }

  static bool rootIsRight(Raw x) {
    clearMathErrors();
    const Raw r = sqrt(T::fromRaw(x)).raw();
    const uint8_t flags = mathErrors();
    bool right;
    if (x < 0) {
      right = r == 0 && flags == MathError::kNegativeSqrt;
    } else {
      const int64_t n4 = int64_t(x) * 4 * (int64_t(1) << F);
      const int64_t r2 = 2 * int64_t(r);
      right = flags == 0 && r >= 0 && (r == 0 || (r2 - 1) * (r2 - 1) <= n4) &&
              n4 < (r2 + 1) * (r2 + 1);
    }
    if (!right) printFailure(Serial, F("sqrt"), x, 0, r);
    return right;
  }

  static uint32_t randomPairs() {
    uint32_t failures = 0;
    for (uint32_t i = 0; i < kRandomPairs && failures < 10; ++i) {
      const Raw a = randomRaw(), b = randomRaw();
      if (!multiplyIsRight(a, b)) ++failures;
      if (!divideIsRight(a, b)) ++failures;
      if (!rootIsRight(a)) ++failures;
    }
    return failures;
  }

  // Every pair of a few edge values, both signs.
  static uint32_t edgePairs() {
    const Raw edges[] = {0, 1, 2, 3, Raw(T::kRawOne / 2), Raw(T::kRawOne - 1),
                         T::kRawOne, Raw(T::kRawOne + 1), Raw(T::kRawMax / 2),
                         Raw(T::kRawMax - 1), T::kRawMax, T::kRawMin};
    const uint8_t n = sizeof(edges) / sizeof(edges[0]);
    uint32_t failures = 0;
    for (uint8_t i = 0; i < n; ++i) {
      for (uint8_t j = 0; j < n; ++j) {
        for (uint8_t s = 0; s < 4; ++s) {
          const Raw a = (s & 1) && edges[i] != T::kRawMin ? Raw(-edges[i]) : edges[i];
          const Raw b = (s & 2) && edges[j] != T::kRawMin ? Raw(-edges[j]) : edges[j];
          if (!multiplyIsRight(a, b) || !divideIsRight(a, b)) ++failures;
        }
      }
      if (!rootIsRight(edges[i])) ++failures;
    }
    return failures;
  }
};

test(q24_8EdgePairs) { assertEqual(Rounding<Q24_8>::edgePairs(), (uint32_t) 0); }
test(q24_8RandomPairs) {
  assertEqual(Rounding<Q24_8>::randomPairs(), (uint32_t) 0);
}
test(q8_8EdgePairs) { assertEqual(Rounding<Q8_8>::edgePairs(), (uint32_t) 0); }
test(q8_8RandomPairs) {
  assertEqual(Rounding<Q8_8>::randomPairs(), (uint32_t) 0);
}
test(q8_8EverySquareRoot) {
  uint32_t failures = 0;
  for (int32_t x = INT16_MIN; x <= INT16_MAX && failures < 10; ++x) {
    if (!Rounding<Q8_8>::rootIsRight(int16_t(x))) ++failures;
  }
  assertEqual(failures, (uint32_t) 0);
}

test(saturationAndFlags) {
  clearMathErrors();
  assertTrue(Q8_8(100) * Q8_8(2) == Q8_8::largest());
  assertTrue(Q8_8(-100) * Q8_8(2) == Q8_8::lowest());
  assertTrue(Q8_8(-64) * Q8_8(2) == Q8_8::lowest());  // exactly -128: fits
  assertTrue(Q8_8::lowest() / Q8_8(-1) == Q8_8::largest());
  assertTrue(Q24_8(5000000) + Q24_8(5000000) == Q24_8::largest());
  assertTrue(Q24_8(-5000000) * Q24_8(2) == Q24_8::lowest());
  assertEqual(mathErrors(), (uint8_t) MathError::kOverflow);
  clearMathErrors();
  assertTrue(Q8_8(1) / Q8_8(0) == Q8_8::largest());
  assertTrue(Q24_8(-1) / Q24_8(0) == Q24_8::lowest());
  assertEqual(mathErrors(), (uint8_t) MathError::kDivideByZero);
  clearMathErrors();
  assertTrue(sqrt(Q24_8(-4)) == Q24_8(0));
  assertTrue(sqrt(Q8_8::lowest()) == Q8_8(0));
  assertEqual(mathErrors(), (uint8_t) MathError::kNegativeSqrt);
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
