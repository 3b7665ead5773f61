// A rod does no work: a pendulum on a rod keeps its energy through a long
// swing, and a rod still absorbs a genuine pull along it (Contacts/Link.hpp
// explains how the turn of the rod is told apart from a pull).
// (Float here: RodEnergyTest runs the same checks with the other scalar; the
// scenes run in src/TinyParticle/Testing/RodEnergyChecks.hpp.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/RodEnergyChecks.hpp>

using aunit::TestRunner;
typedef tinyparticle::testing::RodEnergyChecks<Float> Checks;

// Semi-implicit Euler keeps a modified energy: the true one oscillates
// around it with a relative amplitude of about omega dt / 2, omega =
// sqrt(g / L) = 3.13 rad/s, i.e. 0.6 % at dt = 1/256 s, and does not drift.
// Allowed: twice omega dt, 2.4 % of the swing's energy, over all 10 s. (A
// rod that removes the velocity its own turn explains loses about a third
// in these 10 s.)
static const float kEnergyBound = 2 * 3.13f / 256;

test(PendulumEnergy_Float) {
  TestRunner::setTimeout(0);
  bool swung;
  assertLessOrEqual(Checks::energyError(&swung), kEnergyBound);
  assertTrue(swung);
}

// The push along the rod is absorbed (restitution 0): no bounce back (well
// under 1 % of the 1 m/s push), the bob is then at rest (within 1 % of the
// push, which also bounds what gravity adds in a step, 9.81 / 256 = 0.04
// m/s, once the rod takes it), and the rod keeps its length within 1 mm.
test(RodAbsorbsRadialPush_Float) {
  float speed, back;
  assertLessOrEqual(Checks::radialPush(&speed, &back), 0.001f);
  assertLessOrEqual(back, 0.01f);
  assertLessOrEqual(speed, 0.01f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
