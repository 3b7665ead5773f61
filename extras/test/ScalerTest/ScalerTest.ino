// The engine's arithmetic shortcuts give exactly what the plain operations
// give: the multiply by dt as a shift (Scaler), halving, and the tests of
// the sign from the bits (Math/Scaler.hpp, Math/Zero.hpp). A scene then
// computes the same bits with or without them.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;
using tinyparticle::Scaler;
namespace shortcuts = tinyparticle::detail;

// Raw values to try: the edges of the range, small values around the
// rounding boundaries of a shift by 8 and 16 bits, and a spread of others
// from a fixed-seed generator.
static const long kEdges[] = {
    0L,       1L,      -1L,      127L,    -127L,    128L,     -128L,
    129L,     -129L,   383L,     -384L,   32767L,   -32768L,  32768L,
    -32769L,  65535L,  -65536L,  98304L,  -98304L,  8388607L, -8388608L,
    2147483647L, -2147483647L - 1};

template <uint8_t I, uint8_t F>
struct FixedChecks {
  typedef tinyparticle::Fixed<I, F> T;
  typedef typename T::Raw Raw;

  static Raw clip(long v) {
    return v > long(T::kRawMax) ? T::kRawMax
         : v < long(T::kRawMin) ? T::kRawMin
         : Raw(v);
  }

  // Returns the number of raw values for which the shortcut and the
  // multiply disagree (and the flags they raise).
  static int mismatches(T factor) {
    const Scaler<T> scaler(factor);
    int bad = 0;
    uint32_t seed = 12345;
    for (int i = 0; i < 600; ++i) {
      long v;
      if (i < int(sizeof(kEdges) / sizeof(kEdges[0]))) {
        v = kEdges[i];
      } else {
        seed = seed * 1103515245ul + 12345ul;
        v = long(seed >> (i % 24));  // magnitudes spread over the range
        if (seed & 0x80000000ul) v = -v;
      }
      const T x = T::fromRaw(clip(v));
      tinyparticle::clearMathErrors();
      const T expected = x * factor;
      const uint8_t expectedFlags = tinyparticle::mathErrors();
      tinyparticle::clearMathErrors();
      const T got = scaler(x);
      const T half = shortcuts::half(x);
      if (got != expected || tinyparticle::mathErrors() != expectedFlags ||
          half != x * T(0.5)) {
        ++bad;
      }
    }
    return bad;
  }
};

// (Typedefs: a comma inside a macro argument would split it.)
typedef FixedChecks<16, 16> Checks16;
typedef FixedChecks<24, 8> Checks24;
typedef FixedChecks<8, 8> Checks8;

test(ScalerIsTheMultiply_Q16_16) {
  assertEqual(Checks16::mismatches(Q16_16(1.0 / 256)), 0);    // one byte
  assertEqual(Checks16::mismatches(Q16_16(1.0 / 65536)), 0);  // two bytes
  assertEqual(Checks16::mismatches(Q16_16(1.0 / 1024)), 0);   // multiply
  assertEqual(Checks16::mismatches(Q16_16(0.3)), 0);
}
test(ScalerIsTheMultiply_Q24_8) {
  assertEqual(Checks24::mismatches(Q24_8(1.0 / 256)), 0);
  assertEqual(Checks24::mismatches(Q24_8(0.5)), 0);
}
test(ScalerIsTheMultiply_Q8_8) {
  assertEqual(Checks8::mismatches(Q8_8(1.0 / 256)), 0);
  assertEqual(Checks8::mismatches(Q8_8(0.25)), 0);
}

// Floats: normal values (exact), values whose product is subnormal or zero
// (the multiply decides), zeros, infinities.
static const float kFloats[] = {
    0.0f,    -0.0f,   1.0f,   -1.0f,    3.0e-3f,  -7.5f,   123456.0f,
    1.5e-38f, -1.2e-38f, 3.0e-36f, 1.0e30f, -3.4e38f, 1.0f / 0.0f,
    -1.0f / 0.0f};

static bool sameBits(Float a, Float b) {
  return shortcuts::floatBits(a) == shortcuts::floatBits(b);
}

test(ScalerIsTheMultiply_Float) {
  const Float factors[] = {Float(1.0 / 256), Float(1.0 / 1024), Float(0.3)};
  for (uint8_t f = 0; f < 3; ++f) {
    const Scaler<Float> scaler(factors[f]);
    for (uint8_t i = 0; i < sizeof(kFloats) / sizeof(kFloats[0]); ++i) {
      const Float x(kFloats[i]);
      assertTrue(sameBits(scaler(x), x * factors[f]));
      assertTrue(sameBits(shortcuts::half(x), x * Float(0.5)));
    }
  }
}

// The sign tests agree with the compares, -0 and NaN included.
test(SignTestsAreTheCompares_Float) {
  const float nan = 0.0f / 0.0f;
  for (uint8_t i = 0; i <= sizeof(kFloats) / sizeof(kFloats[0]); ++i) {
    const Float x(i < sizeof(kFloats) / sizeof(kFloats[0]) ? kFloats[i] : nan);
    assertEqual(shortcuts::isZero(x), x == Float());
    assertEqual(shortcuts::isNegative(x), x < Float());
    assertEqual(shortcuts::isPositive(x), Float() < x);
  }
}
test(SignTestsAreTheCompares_Q16_16) {
  for (uint8_t i = 0; i < sizeof(kEdges) / sizeof(kEdges[0]); ++i) {
    const Q16_16 x = Q16_16::fromRaw(kEdges[i]);
    assertEqual(shortcuts::isZero(x), x == Q16_16());
    assertEqual(shortcuts::isNegative(x), x < Q16_16());
    assertEqual(shortcuts::isPositive(x), Q16_16() < x);
  }
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
