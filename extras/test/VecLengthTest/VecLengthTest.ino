// Q16_16 vectors of every length: magnitude() within 2 steps plus the
// relative error of scaling a long vector down (VecLengths::relativeError()
// in src/TinyParticle/Testing/VecChecks.hpp), for
// random 2D and 3D vectors whose components have any bit length;
// normalize() to unit length within 4 steps, parallel to the original,
// raising no flag; magnitudeAndNormalize() returns magnitude().
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/VecChecks.hpp>
#include <math.h>

using aunit::TestRunner;
// The measurements (src/TinyParticle/Testing/VecChecks.hpp).
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

// (Typedef: a comma inside a macro argument would split it.)
typedef VecLengths<Q16_16, Exact> Lengths16;

test(q16_16MagnitudeOfAnyVector) {
  assertLess(Lengths16::magnitudeError(gRandom, kRandomVectors, 31), Exact(2));
}
test(q16_16NormalizeOfAnyVector) {
  bool bad;
  assertLess(Lengths16::unitError(gRandom, kRandomVectors, 31, &bad), Exact(4));
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
