// Contacts at rest: a row of sixteen balls on the floor stays at rest, with
// sleeping and without. (Float here; ContactsRestTest runs the same checks
// with the other scalar.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ContactChecks.hpp>

using aunit::TestRunner;
// The scenes run in src/TinyParticle/Testing/ContactChecks.hpp.
typedef tinyparticle::testing::ContactChecks<Float> Checks;

// Sixteen balls released 1 cm above the floor, side by side, restitution
// 0.8: after 2 s they rest. Resting means no ball faster than 1 mm/s (the
// issue's bound; a resting contact leaves no velocity at all) and no
// overlap with a ball or a wall deeper than 0.5 mm (the correction brings
// every depth under 31 um each step; a depth of 0.5 mm would be a ball
// sinking by what gravity adds in 16 steps). With sleeping, all sleep.
test(PileRestsSleeping_Float) {
  TestRunner::setTimeout(0);
  Checks::RestResult r = Checks::rest(60, true);
  assertLessOrEqual(r.fastest, 0.001f);
  assertLessOrEqual(r.deepest, 0.0005f);
  assertEqual((int) r.asleep, 16);
  assertEqual((int) r.error, 0);
}

// The same row without sleeping: every step resolves its contacts. 60 s on
// the PC, 10 s on the Nano (the simulation is slower).
test(PileRestsAwake_Float) {
  TestRunner::setTimeout(0);
#if defined(EPOXY_DUINO)
  Checks::RestResult r = Checks::rest(60, false);
#else
  Checks::RestResult r = Checks::rest(10, false);
#endif
  assertLessOrEqual(r.fastest, 0.001f);
  assertLessOrEqual(r.deepest, 0.0005f);
  assertEqual((int) r.asleep, 0);
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
