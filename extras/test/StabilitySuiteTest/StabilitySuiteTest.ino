// The stability suite of issue 13, Q16.16: contacts, springs and the range
// edge. StabilitySuiteWorldTest has tiny steps and exhausted pools,
// StabilitySuiteRodsTest the rod cases; the *FloatTest sketches run both in Float; StabilitySuiteQ24Test
// has the Q24.8 cases and the real-time loop across the wrap of micros()
// (each sketch must fit the Nano's 30 KB). The cases,
// their bounds and the reasons for them are in
// src/TinyParticle/Testing/StabilityCases.hpp; each check prints
// "STABILITY ..." lines that extras/stability/collect turns into the table
// of extras/stability/README.md.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/StabilityCases.hpp>

using aunit::TestRunner;
using tinyparticle::testing::StabilityCases;

typedef StabilityCases<Q16_16> Cases;

test(Spring_Q16_16) { assertTrue(Cases::checkSpring(32768.0f)); }
test(Wall_Q16_16) { assertTrue(Cases::checkWall(200)); }
test(BallHit_Q16_16) { assertTrue(Cases::checkBallHit()); }
test(MassRatioCollision_Q16_16) { assertTrue(Cases::checkMassRatioCollision()); }
test(Stack_Q16_16) {
  assertTrue(Cases::checkStack());
}
test(Coincident_Q16_16) { assertTrue(Cases::checkCoincident()); }
test(RangeEdge_Q16_16) { assertTrue(Cases::checkRangeEdge()); }
void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);  // long cases: the whole run is timed by run-tests
}

void loop() { TestRunner::run(); }
