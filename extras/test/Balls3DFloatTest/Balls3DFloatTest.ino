// The box of balls scene (Scenes/BouncingBalls.hpp) in 3D (a 1 m cube with
// six walls): the balls stay inside, and energy only goes (restitution 0.8).
// BallsTest does the same in 2D.
// (Float here: Balls3DTest runs the same checks with Q16.16; the two
// scalars together no longer fit in the Nano's 30 KB of flash.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/BallChecks.hpp>

using aunit::TestRunner;
// The scene runs in src/TinyParticle/Testing/BallChecks.hpp; the tests
// below assert on what it measures.
using tinyparticle::testing::BallChecks;

// (Typedefs: a comma inside a macro argument would split it.)
typedef BallChecks<Float, 3> DeepFloat;

// A ball may overlap a wall by one step of travel before the contact pushes
// it out: at most 3 m/s * dt = 12 mm here. Energy: each correction of a
// penetration d lifts a ball by at most d, adding m g d = 0.1 * 9.81 * 0.012
// = 12 mJ; the bounces (restitution 0.8) take far more, so after 3 s the
// energy is lower than at the start.

test(BallsInBox3D_Float) {
  TestRunner::setTimeout(0);
  float gain, loss;
  assertLessOrEqual(DeepFloat::run(&gain, &loss), 0.012f);
  assertLessOrEqual(gain, 0.012f);
  assertMore(loss, 0.0f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
