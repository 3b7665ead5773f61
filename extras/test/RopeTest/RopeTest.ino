// The rope (Scenes/Chain.hpp, buildRope) settles into the discrete catenary
// (Testing/RopeChecks.hpp, computed by extras/benchmarks/tools/catenary.py):
// seven beads of 0.05 kg on eight rigid links of 0.1 m between posts 0.6 m
// apart, damped at 1/s, after 20 s at dt = 1/256 s. Bounds: the sag (the
// lowest bead's depth) within 0.5 % of the catenary's, every bead within
// 1 mm of its place on the catenary, bead k and bead 8 - k mirror images
// about x = 0.3 m to 1 mm. Q16.16 here (RopeFloatTest has float: the two do not fit
// in one sketch's flash on the Nano).
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/RopeChecks.hpp>

using aunit::TestRunner;
using tinyparticle::testing::RopeChecks;
using tinyparticle::testing::RopeResult;

void report(const __FlashStringHelper* name, const RopeResult& r) {
  Serial.print(F("# rope "));
  Serial.print(name);
  Serial.print(F(": sag error "));
  Serial.print(r.sagError * 100, 4);
  Serial.print(F(" %, worst bead "));
  Serial.print(r.worstBead * 1000, 4);
  Serial.print(F(" mm, asymmetry "));
  Serial.print(r.asymmetry * 1000, 4);
  Serial.println(F(" mm"));
}

test(ropeQ16_16HangsInTheCatenary) {
  const RopeResult r = RopeChecks<Q16_16>::settle();
  report(F("Q16.16"), r);
  assertLess(r.sagError, 0.005f);
  assertLess(r.worstBead, 0.001f);
  assertLess(r.asymmetry, 0.001f);
  assertEqual(r.error, (uint16_t) 0);
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
