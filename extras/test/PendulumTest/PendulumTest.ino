// The pendulum scene (a rod from a fixed pivot, gravity): its period
// against the closed form, and the rod's length through a long swing.
// (Q16_16 here: PendulumFloatTest runs the same checks with the other scalar; the scene
// runs in src/TinyParticle/Testing/PendulumChecks.hpp.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/PendulumChecks.hpp>

using aunit::TestRunner;
using tinyparticle::testing::PendulumChecks;

// The small-angle period with its first correction, within 0.5 %.
test(PendulumPeriod_Q16_16) {
  TestRunner::setTimeout(0);
  const float expected = PendulumChecks<Q16_16>::expectedPeriod();
  assertNear(PendulumChecks<Q16_16>::period(), expected, 0.005f * expected);
}

// The rod keeps its length within 1 mm through a 10 s swing.
test(RodKeepsLength_Q16_16) {
  TestRunner::setTimeout(0);
  bool swung;
  assertLessOrEqual(PendulumChecks<Q16_16>::lengthError(&swung), 0.001f);
  assertTrue(swung);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
