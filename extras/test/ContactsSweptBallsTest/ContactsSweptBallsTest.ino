// Swept contacts (World::addSweptCollisions) below the speed limit: a step
// is the plain one. (Q16.16 here; ContactsSweptBallsFloatTest runs the same
// check with the other scalar; ContactsSweptTest has the fast pairs.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ContactChecks.hpp>

using aunit::TestRunner;
// The scenes run in src/TinyParticle/Testing/ContactChecks.hpp.
typedef tinyparticle::testing::ContactChecks<Q16_16> Checks;

// Below the speed limit (every ball slower than 1 m/s, a quarter of a
// radius per step) a step with swept collisions is the plain one: the
// same positions, to the last bit.
test(SweptBelowLimitIsPlain_Q16_16) {
  TestRunner::setTimeout(0);
  assertEqual(Checks::ballsChecksum(true), Checks::ballsChecksum(false));
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
