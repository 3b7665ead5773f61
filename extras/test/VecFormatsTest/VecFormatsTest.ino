// Q24_8 and Q8_8 vectors: the arithmetic of VecTest, and vectors of every
// length with the properties of VecLengthTest, each format with its own
// step and relative error.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/VecChecks.hpp>
#include <math.h>

using aunit::TestRunner;
// The arithmetic of VecTest and the length checks of VecLengthTest
// (src/TinyParticle/Testing/VecChecks.hpp).
using tinyparticle::testing::VecArithmetic;
using tinyparticle::testing::VecLengths;
using tinyparticle::testing::XorShift32;

#if defined(EPOXY_DUINO)
const uint32_t kRandomVectors = 200000;
typedef double Exact;
#else
const uint32_t kRandomVectors = 600;
typedef float Exact;
#endif

static XorShift32 gRandom(521288629ul);

// (Typedefs: a comma inside a macro argument would split it.)
typedef VecLengths<Q24_8, Exact> Lengths24;
typedef VecLengths<Q8_8, Exact> Lengths8;

test(arithmeticForQ24_8AndQ8_8) {
  assertTrue(VecArithmetic<Q24_8>::vec2());
  assertTrue(VecArithmetic<Q24_8>::vec3());
  assertTrue(VecArithmetic<Q8_8>::vec2());
  assertTrue(VecArithmetic<Q8_8>::vec3());
}

test(q24_8AndQ8_8Magnitudes) {
  assertLess(Lengths24::magnitudeError(gRandom, kRandomVectors, 31), Exact(2));
  assertLess(Lengths8::magnitudeError(gRandom, kRandomVectors, 15), Exact(2));
}

test(q24_8AndQ8_8Normalize) {
  bool bad;
  assertLess(Lengths24::unitError(gRandom, kRandomVectors, 31, &bad), Exact(4));
  assertFalse(bad);
  assertLess(Lengths8::unitError(gRandom, kRandomVectors, 15, &bad), Exact(4));
  assertFalse(bad);
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
