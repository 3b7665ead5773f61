// The box of balls scene (Scenes/BouncingBalls.hpp), as the examples and
// the benchmarks build it: the balls stay inside the walls, and energy only
// goes (restitution 0.8). Balls3DTest does the same in 3D.
// (Q16_16 here: BallsFloatTest runs the same check with the other scalar; the
// scene runs in src/TinyParticle/Testing/BallChecks.hpp.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/BallChecks.hpp>

using aunit::TestRunner;

// (A typedef: a comma inside a macro argument would split it.)
typedef tinyparticle::testing::BallChecks<Q16_16, 2> Flat;

// A ball may overlap a wall by one step of travel before the contact pushes
// it out: at most 3 m/s * dt = 12 mm here. Energy: each correction of a
// penetration d lifts a ball by at most d, adding m g d = 0.1 * 9.81 * 0.012
// = 12 mJ; the bounces (restitution 0.8) take far more, so after 3 s the
// energy is lower than at the start.
test(BallsInBox2D_Q16_16) {
  TestRunner::setTimeout(0);
  float gain, loss;
  assertLessOrEqual(Flat::run(&gain, &loss), 0.012f);
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
