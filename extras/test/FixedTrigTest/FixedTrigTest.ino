// Fixed trigonometry against the C library: sinTurns/cosTurns (binary
// angles), sin/cos (radians), atan2, radiansToTurns and atan2Turns.
// Q16_16 must be within 1e-4 of the exact value (the goal; the tables are
// built for about 4e-5: interpolation error <= 2.1 steps of 2^-16 plus the
// final rounding); Q24_8 and Q8_8 within one step of their format.
// The host compares with double over every binary angle and the whole
// range of arguments; the Nano with avr-libc's float functions, where
// float represents the argument exactly (|x| < 256 in Q16_16).
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/MathTestSupport.hpp>
#include <math.h>

using aunit::TestRunner;
// Helpers shared by the math sketches
// (src/TinyParticle/Testing/MathTestSupport.hpp).
using tinyparticle::testing::XorShift32;
using tinyparticle::testing::exactValue;
using tinyparticle::testing::randomRaw;

#if defined(EPOXY_DUINO)
const uint16_t kAngleStride = 1;     // every binary angle
const uint32_t kRandomArguments = 200000;
typedef double Exact;
#else
const uint16_t kAngleStride = 97;
const uint32_t kRandomArguments = 400;
typedef float Exact;
#endif

static const Exact kTwoPi = Exact(6.283185307179586);

static XorShift32 gRandom(362436069ul);

template <typename T>
struct Trig {
  typedef typename T::Raw Raw;

  static Exact value(T x) { return exactValue<Exact>(x); }
  static Exact distance(T x, Exact exact) {
    Exact d = value(x) - exact;
    return d < 0 ? -d : d;
  }

  // Largest error of sinTurns/cosTurns over binary angles.
  static Exact turnsError() {
    Exact worst = 0;
    for (uint32_t a = 0; a < 65536ul; a += kAngleStride) {
      const uint16_t t = uint16_t(a);
      const Exact angle = Exact(a) * kTwoPi / Exact(65536.0);
      const Exact es = distance(sinTurns<T>(t), sin(angle));
      const Exact ec = distance(cosTurns<T>(t), cos(angle));
      if (es > worst) worst = es;
      if (ec > worst) worst = ec;
    }
    return worst;
  }

  // A raw argument whose value the reference type represents exactly.
  static Raw randomAngle(uint8_t maxBits) {
    return randomRaw<Raw>(gRandom, maxBits);
  }

  // Largest error of sin and cos over random radian arguments of up to
  // maxBits raw bits, and the largest binary-angle error of radiansToTurns
  // (in binary-angle units).
  static Exact radiansError(uint8_t maxBits, uint16_t* turnsError) {
    Exact worst = 0;
    *turnsError = 0;
    for (uint32_t i = 0; i < kRandomArguments; ++i) {
      const T x = T::fromRaw(randomAngle(maxBits));
      const Exact v = value(x);
      const Exact es = distance(sin(x), sin(v));
      const Exact ec = distance(cos(x), cos(v));
      if (es > worst) worst = es;
      if (ec > worst) worst = ec;
      // Binary angle: v / 2 pi * 65536 rounded, modulo one turn.
      Exact turns = v / kTwoPi * Exact(65536.0);
      turns -= Exact(65536.0) * floor(turns / Exact(65536.0));
      const uint16_t expected = uint16_t(uint32_t(turns + Exact(0.5)) & 0xffffu);
      const uint16_t got = radiansToTurns(x);
      const uint16_t diff = uint16_t(got - expected);
      const uint16_t off = diff < 32768u ? diff : uint16_t(0u - diff);
      if (off > *turnsError) *turnsError = off;
    }
    return worst;
  }

  // Largest error of atan2 over (y, x) on a grid of magnitudes from one
  // step to the top of the range, every sign, and random pairs; and of
  // atan2Turns, in binary-angle units.
  static Exact atan2Error(uint16_t* turnsError) {
    Exact worst = 0;
    *turnsError = 0;
    for (uint32_t i = 0; i < kRandomArguments * 4; ++i) {
      const Raw y = randomAngle(T::kTotalBits - 1);
      const Raw x = randomAngle(T::kTotalBits - 1);
      check(T::fromRaw(y), T::fromRaw(x), &worst, turnsError);
    }
    for (uint8_t i = 0; i < T::kTotalBits - 1; i += 3) {
      for (uint8_t j = 0; j < T::kTotalBits - 1; j += 3) {
        const Raw a = Raw((int32_t(1) << i) + i);
        const Raw b = Raw((int32_t(1) << j) - 1 + j);
        for (uint8_t s = 0; s < 4; ++s) {
          check(T::fromRaw((s & 1) ? Raw(-a) : a),
                T::fromRaw((s & 2) ? Raw(-b) : b), &worst, turnsError);
        }
      }
    }
    return worst;
  }

  static void check(T y, T x, Exact* worst, uint16_t* turnsError) {
    const Exact exact = atan2(value(y), value(x));
    const Exact e = distance(atan2(y, x), exact);
    if (e > *worst) *worst = e;
    Exact turns = exact / kTwoPi * Exact(65536.0);
    if (turns < 0) turns += Exact(65536.0);
    const uint16_t expected = uint16_t(uint32_t(turns + Exact(0.5)) & 0xffffu);
    const uint16_t diff = uint16_t(atan2Turns(y, x) - expected);
    const uint16_t off = diff < 32768u ? diff : uint16_t(0u - diff);
    if (off > *turnsError) *turnsError = off;
  }
};

test(q16_16SinCosTurns) {
  assertLess(Trig<Q16_16>::turnsError(), Exact(1e-4));
}

test(q16_16SinCosRadians) {
  uint16_t turns;
  // Float holds Q16_16 values exactly below 256 (24 bits).
  assertLess(Trig<Q16_16>::radiansError(23, &turns), Exact(1e-4));
  assertLessOrEqual(turns, (uint16_t) 1);
#if defined(EPOXY_DUINO)
  // The whole range (double is exact for every Q16_16 value).
  assertLess(Trig<Q16_16>::radiansError(31, &turns), Exact(1e-4));
  assertLessOrEqual(turns, (uint16_t) 1);
#endif
}

// sin and cos at every kSin entry boundary of every quadrant (turns
// j 2^15 / 2^24, j = 0..512), +-3 raw steps, at 0 and 1 whole turns and
// (host) at the last whole turns of the range, 5213..5215, both signs:
// within 1e-4. On the host also the range reduction: the 24-bit turns
// within 4 units of 2^-24 turn of the exact angle (FixedMath.hpp's bound).
// (The Nano takes one turn count, two steps and one sign per boundary:
// float sin is slow there.)
test(q16_16RadiansAtTableBoundaries) {
  typedef Q16_16 T;
  Exact worst = 0, worstTurns = 0;
  for (uint16_t j = 0; j <= 512; ++j) {
#if defined(EPOXY_DUINO)
    for (uint8_t k = 0; k < 5; ++k) {
      for (int8_t d = -3; d <= 3; ++d) {
        for (uint8_t negative = 0; negative < 2; ++negative) {
#else
    for (uint8_t k = uint8_t(j % 2); k == j % 2; ++k) {
      for (int8_t d = -1; d <= 0; ++d) {
        for (uint8_t negative = uint8_t(j % 3 == 0); negative == (j % 3 == 0);
             ++negative) {
#endif
          const uint32_t turns = k < 2 ? k : 5211u + k;
          // Raw units per turn 2 pi 2^16 = 411774 + 54545 / 2^16, per
          // boundary 2 pi 2^7 = 804 + 16235 / 2^16.
          const uint32_t x = turns * 411774u + uint32_t(j) * 804u +
              ((turns * 54545u + uint32_t(j) * 16235u + 32768u) >> 16) +
              uint32_t(int32_t(d));
          if (x > 0x7fffffffu) continue;
          const T a = T::fromRaw(negative ? -int32_t(x) : int32_t(x));
          const Exact v = Trig<T>::value(a);
          const Exact es = Trig<T>::distance(sin(a), sin(v));
          const Exact ec = Trig<T>::distance(cos(a), cos(v));
          if (es > worst) worst = es;
          if (ec > worst) worst = ec;
#if defined(EPOXY_DUINO)
          Exact t = v / kTwoPi * Exact(16777216.0);
          t -= Exact(16777216.0) * floor(t / Exact(16777216.0));
          Exact e = Exact(tinyparticle::detail::turns24Of(a)) - t;
          if (e > Exact(8388608.0)) e -= Exact(16777216.0);
          if (e < -Exact(8388608.0)) e += Exact(16777216.0);
          if (fabs(e) > worstTurns) worstTurns = fabs(e);
#endif
        }
      }
    }
  }
  assertLess(worst, Exact(1e-4));
  assertLessOrEqual(worstTurns, Exact(4));
}

test(q16_16Atan2) {
  uint16_t turns;
  assertLess(Trig<Q16_16>::atan2Error(&turns), Exact(1e-4));
  // 1e-4 rad is 1.04 binary-angle units; with the final rounding, 2.
  assertLessOrEqual(turns, (uint16_t) 2);
}

test(q24_8AndQ8_8WithinOneStep) {
  const Exact step = Exact(1) / 256;
  uint16_t turns;
  assertLessOrEqual(Trig<Q24_8>::turnsError(), step);
  assertLessOrEqual(Trig<Q8_8>::turnsError(), step);
  assertLessOrEqual(Trig<Q24_8>::radiansError(23, &turns), step);
  assertLessOrEqual(Trig<Q8_8>::radiansError(15, &turns), step);
  assertLessOrEqual(Trig<Q24_8>::atan2Error(&turns), step);
  assertLessOrEqual(Trig<Q8_8>::atan2Error(&turns), step);
}

test(exactAnglesAndSpecialCases) {
  typedef Q16_16 T;
  assertTrue(sinTurns<T>(0) == T(0));
  assertTrue(sinTurns<T>(16384) == T(1));
  assertTrue(sinTurns<T>(32768) == T(0));
  assertTrue(sinTurns<T>(49152) == T(-1));
  assertTrue(cosTurns<T>(0) == T(1));
  assertTrue(cosTurns<T>(32768) == T(-1));
  assertTrue(sinTurns<Q8_8>(16384) == Q8_8(1));
  // |sin| <= 1 at every angle, and sin(-a) = -sin(a) exactly.
  uint16_t bad = 0;
  for (uint32_t a = 0; a < 65536ul; a += 61) {
    const T s = sinTurns<T>(uint16_t(a));
    if (fabs(s) > T(1) || sinTurns<T>(uint16_t(0u - a)) != -s) ++bad;
  }
  assertEqual(bad, (uint16_t) 0);
  // atan2 follows C: atan2(0, 0) = 0, atan2(0, -x) = pi, quadrants.
  clearMathErrors();
  assertTrue(atan2(T(0), T(0)) == T(0));
  assertTrue(atan2(T(0), T(-2)) == T::pi());
  assertTrue(atan2(T(0), T(3)) == T(0));
  assertNear(atan2(T(1), T(0)).toFloat(), 1.5707963f, 1e-4f);
  assertNear(atan2(T(-1), T(0)).toFloat(), -1.5707963f, 1e-4f);
  assertNear(atan2(T(-1), T(-1)).toFloat(), -2.3561945f, 1e-4f);
  assertNear(atan2(T::lowest(), T::lowest()).toFloat(), -2.3561945f, 1e-4f);
  assertEqual(atan2Turns(T(0), T(-1)), (uint16_t) 32768);
  assertEqual(atan2Turns(T(-1), T(0)), (uint16_t) 49152);
  assertEqual(mathErrors(), (uint8_t) 0);
  // pi does not fit Fixed<2, 30>: atan2 saturates, with the flag.
  typedef Fixed<2, 30> Tiny;
  assertTrue(atan2(Tiny(0), Tiny(-1)) == Tiny::largest());
  assertEqual(mathErrors(), (uint8_t) MathError::kOverflow);
  clearMathErrors();
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
