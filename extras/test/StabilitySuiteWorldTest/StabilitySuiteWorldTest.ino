// The stability suite of issue 13, Q16.16: tiny steps and exhausted pools
// (split from StabilitySuiteTest, which has the contacts, springs and the
// range edge, to fit the Nano's 30 KB). The cases, their bounds and the
// reasons for them are in src/TinyParticle/Testing/StabilityCases.hpp;
// each check prints "STABILITY ..." lines that extras/stability/collect
// turns into the table of extras/stability/README.md.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/StabilityCases.hpp>

using aunit::TestRunner;
using tinyparticle::testing::StabilityCases;

typedef StabilityCases<Q16_16> Cases;

// The smallest useful step: Euler's error g t dt / 2 shrinks with dt, the
// worst case of rounding (half a unit a step) grows as 1 / dt; the rows of
// extras/stability/README.md show where the measured error stops falling.
test(TinyDt_Q16_16) {
  bool ok = Cases::checkFreeFall(256, F("free-fall-dt-1/256-m"));
  ok &= Cases::checkFreeFall(1024, F("free-fall-dt-1/1024-m"));
  ok &= Cases::checkFreeFall(4096, F("free-fall-dt-1/4096-m"));
  ok &= Cases::checkFreeFall(16384, F("free-fall-dt-1/16384-m"));
  assertTrue(ok);
}
test(Exhaustion_Q16_16) { assertTrue(Cases::checkExhaustion()); }

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);  // long cases: the whole run is timed by run-tests
}

void loop() { TestRunner::run(); }
