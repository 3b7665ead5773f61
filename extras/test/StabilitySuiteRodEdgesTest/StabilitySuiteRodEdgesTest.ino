// The stability suite of issue 13, Q16.16: the rod edge cases (a 1:1000
// mass ratio on a rod, a rod of zero length and tiny vectors).
// StabilitySuiteRodsTest has the rods in motion. The
// cases and bounds are in src/TinyParticle/Testing/StabilityCases.hpp.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/StabilityCases.hpp>

using aunit::TestRunner;
using tinyparticle::testing::StabilityCases;

typedef StabilityCases<Q16_16> Cases;

test(MassRatioRod_Q16_16) { assertTrue(Cases::checkMassRatioRod()); }
test(TinyVectors_Q16_16) { assertTrue(Cases::checkTinyVectors()); }

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);  // long cases: the whole run is timed by run-tests
}

void loop() { TestRunner::run(); }
