// Newton's cradle (Scenes/Cradle.hpp). (Q16.16 here; CradleFloatTest runs the
// same check with the other scalar.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ContactChecks.hpp>

using aunit::TestRunner;
// The scenes run in src/TinyParticle/Testing/ContactChecks.hpp.
typedef tinyparticle::testing::ContactChecks<Q16_16> Checks;

// The first ball falls from 60 degrees; after one swing the last one rises
// to at least 95 % of its height (the issue's bound: restitution 1 and equal
// masses pass the whole velocity on; what is lost is rounding and the rods'
// step) and no higher than 1 % above it, while the middle ones move less
// than 1 cm (each carries the velocity, 2.2 m/s, for about one step of
// 1/256 s: 8.6 mm).
test(NewtonsCradle_Q16_16) {
  Checks::CradleResult r = Checks::cradle();
  assertMoreOrEqual(r.rise, 0.95f);
  assertLessOrEqual(r.rise, 1.01f);  // no energy made either
  assertLess(r.middle, 0.01f);
  assertEqual((int) r.error, 0);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
