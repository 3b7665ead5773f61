// Collisions and contacts with restitution: an elastic head-on collision,
// and a ball dropped on the floor (rebound height, then rest).
// (Q16.16 here; CollisionFloatTest runs the same checks with Float: the two
// scalars together no longer fit in the Nano's 30 KB of flash.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/CollisionChecks.hpp>

using aunit::TestRunner;
// The scenes run in src/TinyParticle/Testing/CollisionChecks.hpp; the tests
// below assert on what they measure.
using tinyparticle::testing::CollisionChecks;

// Equal masses, restitution 1: the velocities swap, and momentum
// (1 * 1 + 1 * -0.5 = 0.5 kg m/s) is kept within 0.1 % of the momentum
// that flows through the collision (1.5 kg m/s exchanged).
test(ElasticHeadOn_Q16_16) {
  float v1, v2, sideways;
  CollisionChecks<Q16_16>::headOn(&v1, &v2, &sideways);
  assertNear(v1, -0.5f, 0.0015f);
  assertNear(v2, 1.0f, 0.0015f);
  assertNear(v1 + v2, 0.5f, 0.0015f);
  assertEqual(sideways, 0.0f);
}

// Restitution 0.5 halves the speed, so the rebound reaches 0.25 of the drop
// height; within 5 % of that. Then the ball rests: it sinks no more than
// 1 mm, does not hop (1 mm), and is still (1 mm/s).
test(DropRebound_Q16_16) {
  TestRunner::setTimeout(0);
  float lowest, highest, fastest;
  float rebound = CollisionChecks<Q16_16>::drop(&lowest, &highest, &fastest);
  assertNear(rebound, 0.25f, 0.05f * 0.25f);
  assertMoreOrEqual(lowest, -0.001f);
  assertLessOrEqual(highest, 0.001f);
  assertLessOrEqual(fastest, 0.001f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
