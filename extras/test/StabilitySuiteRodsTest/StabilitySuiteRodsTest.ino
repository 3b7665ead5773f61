// The stability suite of issue 13, Q16.16: the rod cases in motion (the
// undamped pendulum, a chain of 8 rods). StabilitySuiteRodEdgesTest has the
// rod edge cases, StabilitySuiteTest the others (one sketch would not fit
// the Nano's flash). The
// cases and bounds are in src/TinyParticle/Testing/StabilityCases.hpp.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/StabilityCases.hpp>

using aunit::TestRunner;
using tinyparticle::testing::StabilityCases;

typedef StabilityCases<Q16_16> Cases;

// 10^5 steps: 390 s of swing.
test(Pendulum_Q16_16) {
  assertTrue(Cases::checkPendulum(100000UL));
}
test(Chain_Q16_16) { assertTrue(Cases::checkChain()); }

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);  // long cases: the whole run is timed by run-tests
}

void loop() { TestRunner::run(); }
