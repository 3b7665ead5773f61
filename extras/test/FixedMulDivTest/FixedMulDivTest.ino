// Q16_16 multiply and divide are correctly rounded: the result r of a * b
// satisfies |a b / 2^16 - r| <= 1/2 (ties away from zero), checked with
// exact 64-bit integer inequalities, not by recomputing the library's
// formula; a result that does not fit saturates and raises kOverflow,
// x / 0 saturates with x's sign and raises kDivideByZero.
// Checked over edge values (all pairs), then random pairs: 10^6 of each on
// the host, a sample on the Nano, where the fast AVR code must also equal
// the portable reference bit for bit.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/MathTestSupport.hpp>

using aunit::TestRunner;
// Helpers shared by the math sketches
// (src/TinyParticle/Testing/MathTestSupport.hpp).
using tinyparticle::testing::XorShift32;
using tinyparticle::testing::magnitude64;
using tinyparticle::testing::printFailure;

typedef Q16_16 T;
typedef T::Raw Raw;

#if defined(EPOXY_DUINO)
const uint32_t kRandomPairs = 1000000;
#else
const uint32_t kRandomPairs = 3000;
#endif

// Values where rounding, carries, signs and saturation change behaviour.
static const int32_t kEdges[] PROGMEM = {
    0, 1, -1, 2, -2, 3, 0x7fff, 0x8000, -0x8000, 0x8001, 0xffff, 0x10000,
    -0x10000, 0x10001, 0x17fff, 0x18000, 0xb504, 0xb505, 0xffffff, 0x1000000,
    -0x1000000, 0x7fffff, 0x800000, 0xb504f3, 0xb504f4, 0x5a827a, 0x5a827b,
    0x40000000, 0x3fffffff, 0x7fff8000, 0x7fff7fff, 0x55555555, 0x2aaaaaab,
    -0x2aaaaaab, 12345678, -98765, 0x7ffffffe, 0x7fffffff, -0x7fffffff,
    INT32_MIN};
const uint8_t kEdgeCount = sizeof(kEdges) / sizeof(kEdges[0]);

static int32_t edge(uint8_t i) {
  return int32_t(pgm_read_dword(&kEdges[i]));
}

static XorShift32 gRandom(2463534242ul);
// Magnitudes spread evenly over the 31 bit lengths, random sign.
static int32_t randomRaw() {
  const uint8_t bits = uint8_t(gRandom.next() % 32);
  uint32_t m =
      bits == 0 ? 0 : (gRandom.next() >> (32 - bits)) | (1ul << (bits - 1));
  if (m > 0x7ffffffful) m = 0x7ffffffful;
  return (gRandom.next() & 1) ? -int32_t(m) : int32_t(m);
}

// r = a * b / 2^16 correctly rounded, or saturated with the flag.
static bool multiplyIsRight(Raw a, Raw b, Raw r, uint8_t flags) {
  const int64_t p = int64_t(a) * b;  // the exact result times 2^16
  // In range when (2 min - 1) 2^15 < p < (2 max + 1) 2^15 (a tie at the
  // ends rounds away from zero, out of range).
  const int64_t top = (2 * int64_t(T::kRawMax) + 1) << 15;
  const int64_t bottom = (2 * int64_t(T::kRawMin) - 1) * 32768;
  if (p >= top) return r == T::kRawMax && flags == MathError::kOverflow;
  if (p <= bottom) return r == T::kRawMin && flags == MathError::kOverflow;
  if (flags != 0) return false;
  const int64_t scaled = int64_t(r) * 65536;
  const uint64_t error = magnitude64(p - scaled);  // |p - r 2^16|
  if (error > 32768) return false;
  // A tie must have gone away from zero: |r 2^16| > |p|.
  if (error == 32768) return magnitude64(scaled) > magnitude64(p);
  return true;
}

// r = a 2^16 / b correctly rounded, or saturated with the flag (b != 0).
static bool divideIsRight(Raw a, Raw b, Raw r, uint8_t flags) {
  const bool negative = (a < 0) != (b < 0);
  const uint64_t n = magnitude64(a) << 17;  // 2 |a| 2^16
  const uint64_t d = magnitude64(b);
  // |q| = n / (2 d) in range when below max + 1/2 (positive) or
  // |min| + 1/2 (negative): n < (2 max + 1) d, resp. (2 |min| + 1) d.
  const uint64_t limit = negative ? uint64_t(0x100000001ull) * d
                                  : uint64_t(0xffffffffull) * d;
  if (n >= limit) {
    return flags == MathError::kOverflow &&
           r == (negative ? T::kRawMin : T::kRawMax);
  }
  if (flags != 0) return false;
  if (a != 0 && r != 0 && ((r < 0) != negative)) return false;
  // 2 |a 2^16 - r b| <= |b|, and a tie goes away from zero.
  const int64_t exact = int64_t(a) * 65536;
  const int64_t scaled = int64_t(r) * b;
  const uint64_t twiceError = magnitude64(exact - scaled) * 2;
  if (twiceError > d) return false;
  if (twiceError == d) return magnitude64(scaled) > magnitude64(exact);
  return true;
}

// Checks multiply and divide of one pair, through the operators (fast
// path) and the reference; both must be right and, on the Nano, equal.
static bool pairIsRight(Raw a, Raw b) {
  clearMathErrors();
  const Raw m = (T::fromRaw(a) * T::fromRaw(b)).raw();
  const uint8_t mFlags = mathErrors();
  clearMathErrors();
  const Raw mRef = T::referenceMultiply(a, b);
  const uint8_t mRefFlags = mathErrors();
  if (!multiplyIsRight(a, b, m, mFlags) || m != mRef || mFlags != mRefFlags) {
    printFailure(Serial, F("multiply"), a, b, m);
    return false;
  }
  if (b == 0) return true;
  clearMathErrors();
  const Raw q = (T::fromRaw(a) / T::fromRaw(b)).raw();
  const uint8_t qFlags = mathErrors();
  clearMathErrors();
  const Raw qRef = T::referenceDivide(a, b);
  const uint8_t qRefFlags = mathErrors();
  if (!divideIsRight(a, b, q, qFlags) || q != qRef || qFlags != qRefFlags) {
    printFailure(Serial, F("divide"), a, b, q);
    return false;
  }
  return true;
}

test(edgePairsAreCorrectlyRounded) {
  uint16_t failures = 0;
  for (uint8_t i = 0; i < kEdgeCount; ++i) {
    for (uint8_t j = 0; j < kEdgeCount; ++j) {
      if (!pairIsRight(edge(i), edge(j))) ++failures;
      const Raw negated = edge(i) == INT32_MIN ? edge(i) : Raw(-edge(i));
      if (!pairIsRight(negated, edge(j))) {
        ++failures;
      }
    }
  }
  assertEqual(failures, (uint16_t) 0);
}

test(randomPairsAreCorrectlyRounded) {
  uint32_t failures = 0;
  for (uint32_t i = 0; i < kRandomPairs && failures < 10; ++i) {
    if (!pairIsRight(randomRaw(), randomRaw())) ++failures;
  }
  assertEqual(failures, (uint32_t) 0);
}

test(tiesRoundAwayFromZero) {
  // Products and quotients that fall exactly half-way between two steps.
  uint32_t failures = 0;
  for (uint32_t i = 0; i < kRandomPairs / 10 && failures < 10; ++i) {
    // a * 2^15 (b = 0.5) is a tie whenever a is odd.
    const Raw a = Raw(randomRaw() | 1);
    if (!pairIsRight(a, 0x8000) || !pairIsRight(a, -0x8000)) ++failures;
    // (2k + 1) / 2^17 * 2^16 / 1 ... : a / 2 with odd a (b = 2.0).
    if (!pairIsRight(a, 0x20000) || !pairIsRight(a, -0x20000)) ++failures;
  }
  assertEqual(failures, (uint32_t) 0);
  // The sign symmetry that ties away from zero buys: (-a) b == -(a b).
  const T half(0.5);
  const T tiny = T::fromRaw(3);
  assertTrue((-tiny) * half == -(tiny * half));
  assertTrue((-tiny) / T(2) == -(tiny / T(2)));
}

// Pairs whose exact result lies within a few steps of the ends of the
// range, where saturation starts: a product or quotient of about
// +-(2^31 + k) steps, k = -3..3.
test(resultsNextToTheLimits) {
  uint32_t failures = 0;
  for (uint32_t i = 0; i < kRandomPairs / 20 && failures < 10; ++i) {
    const int64_t k = int64_t(gRandom.next() % 7) - 3;
    const int64_t target = (gRandom.next() & 1) ? -(2147483648ll + k)
                                                 : 2147483648ll + k;
    // Multiply: b of at least 1.0, a = target 2^16 / b rounded down.
    int32_t b = randomRaw();
    if (b > -65536 && b < 65536) b = b < 0 ? b - 65536 : b + 65536;
    int64_t a = target * 65536 / b;
    if (a >= INT32_MIN && a <= INT32_MAX) {
      for (int8_t d = -1; d <= 1; ++d) {
        const int64_t ad = a + d;
        if (ad >= INT32_MIN && ad <= INT32_MAX && !pairIsRight(Raw(ad), b)) {
          ++failures;
        }
      }
    }
    // Divide: b below 1.0, a = target b / 2^16.
    b = Raw(randomRaw() % 65536);
    if (b == 0) b = 1;
    a = target * b / 65536;
    for (int8_t d = -1; d <= 1; ++d) {
      const int64_t ad = a + d;
      if (ad >= INT32_MIN && ad <= INT32_MAX && !pairIsRight(Raw(ad), b)) {
        ++failures;
      }
    }
  }
  assertEqual(failures, (uint32_t) 0);
  // One exact case each way: 715827883 * 3 = 2^31 + 1 steps.
  clearMathErrors();
  assertTrue(T::fromRaw(-715827883) * T(3) == T::lowest());
  assertEqual(mathErrors(), (uint8_t) MathError::kOverflow);
  clearMathErrors();
  assertEqual((T::fromRaw(-715827882) * T(3)).raw(), (Raw) -2147483646);
  assertEqual(mathErrors(), (uint8_t) 0);
}

test(saturationAtBothEnds) {
  clearMathErrors();
  assertTrue(T(200) * T(200) == T::largest());
  assertEqual(mathErrors(), (uint8_t) MathError::kOverflow);
  clearMathErrors();
  assertTrue(T(-200) * T(200) == T::lowest());
  assertTrue(T(30000) / T(0.5) == T::largest());
  assertTrue(T(-30000) / T(0.5) == T::lowest());
  assertTrue(T::lowest() * T(-1) == T::largest());
  assertTrue(T::lowest() / T(-1) == T::largest());
  assertEqual(mathErrors(), (uint8_t) MathError::kOverflow);
  // The most negative value itself is reachable without overflow.
  clearMathErrors();
  assertTrue(T(-16384) * T(2) == T::lowest());
  assertTrue(T(16384) * T(-2) == T::lowest());
  assertTrue(T(-16384) / T(0.5) == T::lowest());
  assertTrue(T::lowest() * T(1) == T::lowest());
  assertTrue(T::lowest() / T(1) == T::lowest());
  assertEqual(mathErrors(), (uint8_t) 0);
}

test(divisionByZeroSaturatesWithTheSign) {
  clearMathErrors();
  assertTrue(T(3) / T(0) == T::largest());
  assertEqual(mathErrors(), (uint8_t) MathError::kDivideByZero);
  assertTrue(T(-3) / T(0) == T::lowest());
  assertTrue(T::lowest() / T(0) == T::lowest());
  assertTrue(T::epsilon() / T(0) == T::largest());
  assertTrue(T(0) / T(0) == T(0));
  assertEqual(mathErrors(), (uint8_t) MathError::kDivideByZero);
  clearMathErrors();
  assertEqual(T::referenceDivide(5, 0), T::kRawMax);
  assertEqual(mathErrors(), (uint8_t) MathError::kDivideByZero);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);  // 10^6 pairs take a while on the host
}

void loop() { TestRunner::run(); }
