// Sleeping in the coarsest scalar: the bouncing balls in Q24.8 come to rest
// and fall asleep. (In Q24.8 at 1/256 s a ball slower than 0.5 m/s moves by
// nothing in a step; such balls kept their velocity, and the scene never
// slept: World/Sleep.hpp now counts a particle that a step does not move as
// at rest.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ContactChecks.hpp>

using aunit::TestRunner;
// The scene runs in src/TinyParticle/Testing/ContactChecks.hpp.
typedef tinyparticle::testing::ContactChecks<Q24_8> Checks;

// Scenes/BouncingBalls.hpp, 16 balls, within the 10 s of the benchmark
// run: all of them sleep, and none hangs in the air. A ball rests on the
// floor or on a lower ball: its gap to that is at most the contact margin
// (four units, 4/256 m) plus one unit of rounding (positions are whole
// units), 5/256 m; so is the deepest overlap (the resolver leaves depths
// below the margin, and rounding adds a unit).
test(BouncingBallsSleep_Q24_8) {
  TestRunner::setTimeout(0);
  const Checks::SettleResult r = Checks::settleBalls(10);
  assertMore((int) r.steps, 0);
  assertLessOrEqual(r.hanging, 5.0f / 256);
  assertLessOrEqual(r.deepest, 5.0f / 256);
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
