// The stability suite of issue 13, Float: the rod cases (the undamped
// pendulum, a chain of 8 rods, a 1:1000 mass ratio on a rod, a rod of
// zero length and tiny vectors). StabilitySuiteFloatTest has the others. The
// cases and bounds are in src/TinyParticle/Testing/StabilityCases.hpp.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/StabilityCases.hpp>

using aunit::TestRunner;
using tinyparticle::testing::StabilityCases;

typedef StabilityCases<Float> Cases;

// 10^5 steps (390 s of swing) on the host; on the Nano 2 x 10^4 (78 s,
// over 12 periods: the bound is the same, as the error does not drift),
// which take float arithmetic about 30 s of simulated time instead of 150.
test(Pendulum_Float) {
#if defined(EPOXY_DUINO)
  assertTrue(Cases::checkPendulum(100000UL));
#else
  assertTrue(Cases::checkPendulum(20000UL));
#endif
}
test(Chain_Float) { assertTrue(Cases::checkChain()); }
test(MassRatioRod_Float) { assertTrue(Cases::checkMassRatioRod()); }
test(TinyVectors_Float) { assertTrue(Cases::checkTinyVectors()); }

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);  // long cases: the whole run is timed by run-tests
}

void loop() { TestRunner::run(); }
