// Contacts in motion: elastic collisions of small balls keep the kinetic
// energy, and sixteen elastic balls in a box keep it for 10 s. (Q16.16 here;
// ContactsMotionFloatTest runs the same checks with the other scalar, and
// the speed limit's; ContactsTunnelTest the speed limit's in Q16.16: with
// them this sketch no longer fit the Nano's flash.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ContactChecks.hpp>

using aunit::TestRunner;
// The scenes run in src/TinyParticle/Testing/ContactChecks.hpp.
typedef tinyparticle::testing::ContactChecks<Q16_16> Checks;

// Restitution 1 keeps the kinetic energy exactly; what is left is rounding.
// The contact normal of balls of radius 1 cm is unit length to a few units
// of 2^-16 (about 1e-4 of their distance in Q16.16), and an energy error is
// about eight times the normal's length error: 0.1 % (the issue's bound)
// leaves room. Head-on, then 1 cm and 1.7 cm off the line (oblique).
test(ElasticSmallBalls_Q16_16) {
  assertNear(Checks::elasticRatio(0.01f, 1.0f, 0.0f), 1.0f, 0.001f);
  assertNear(Checks::elasticRatio(0.01f, 1.0f, 0.01f), 1.0f, 0.001f);
  assertNear(Checks::elasticRatio(0.01f, 1.0f, 0.017f), 1.0f, 0.001f);
  assertNear(Checks::elasticRatio(0.01f, 0.2f, 0.005f), 1.0f, 0.001f);
}

// Sixteen balls, restitution 1, no gravity, 10 s (a few hundred
// collisions): the kinetic energy within 0.1 % all along.
test(ElasticBox_Q16_16) {
  TestRunner::setTimeout(0);
  assertLessOrEqual(Checks::elasticBoxError(10), 0.001f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
