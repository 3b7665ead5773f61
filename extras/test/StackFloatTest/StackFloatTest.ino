// A resting stack of balls on the floor: it neither sinks nor jitters, and
// with the resolver's shock propagation it comes to rest.
// (Float here: StackTest runs the same checks with Q16.16; the two
// scalars together no longer fit in the Nano's 30 KB of flash.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/StackChecks.hpp>

using aunit::TestRunner;
// The scene runs in src/TinyParticle/Testing/StackChecks.hpp; the tests
// below assert on what it measures.
using tinyparticle::testing::StackChecks;

// A resting stack neither sinks nor jitters: each ball stays within 1 mm of
// its ideal height, its height varies by less than 1 mm, and it is still
// (1 mm/s) with the default iteration cap. (Without the resolver's shock
// propagation, a chain of equal masses on the floor passes each correction
// down and up again, halving it each time, and is still moving when the
// cap of 2 iterations per contact runs out.)
test(RestingStack_Float) {
  float jitter, fastest;
  assertLessOrEqual(StackChecks<Float>::stack(0, &jitter, &fastest), 0.001f);
  assertLessOrEqual(jitter, 0.001f);
  assertLessOrEqual(fastest, 0.001f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
