// Swept contacts (World::addSweptCollisions): two balls that pass through
// each other within one step, far past the speed limit of plain collisions,
// still collide, as exactly as slow ones. (Q16.16 here; ContactsSweptFloatTest
// runs the same checks with the other scalar; ContactsSweptBallsTest: below
// the limit a swept world steps exactly as a plain one.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ContactChecks.hpp>

using aunit::TestRunner;
// The scenes run in src/TinyParticle/Testing/ContactChecks.hpp.
typedef tinyparticle::testing::ContactChecks<Q16_16> Checks;

// Balls of radius 2 cm head-on at 50 m/s each (the issue's case: their
// centres cross within one step of 1/256 s, 20 cm each): they bounce, keep
// the kinetic energy (restitution 1; what is left is the rounding of the
// contact normal, as for slow balls: 0.1 %), and nothing is flagged.
test(SweptHeadOn_Q16_16) {
  const Checks::SweptResult r = Checks::swept(50, 50, 0);
  assertTrue(r.ordered);
  assertNear(r.energy, 1.0f, 0.001f);
  assertEqual((int) r.error, 0);
}

// A ball at 50 m/s past one at rest whose centre is 2 cm off its line
// (half the sum of the radii): at the first touch the line of centres is
// 30 degrees off the x axis, and an elastic collision of equal masses gives
// the struck ball the velocity's component along it, 50 cos 30 = 43.30 m/s
// at +30 degrees. The first touch is found exactly on the straight paths;
// rounding is left: 0.1 % on the speed, 0.1 degree on the angle.
test(SweptOblique_Q16_16) {
  const Checks::SweptResult r = Checks::swept(50, 0, 0.02f);
  assertNear(r.struckSpeed, 43.30127f, 0.0433f);
  assertNear(r.struckAngle, 30.0f, 0.1f);
  assertNear(r.energy, 1.0f, 0.001f);
  assertEqual((int) r.error, 0);
}

// The same pass 1 mm beyond the sum of the radii: no contact, the ball at
// rest stays at rest.
test(SweptMiss_Q16_16) {
  const Checks::SweptResult r = Checks::swept(50, 0, 0.041f);
  assertEqual(r.struckSpeed, 0.0f);
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
