// A rod and a plane acting on the same particle in one step, as the
// HapticLever's stops do (Contacts/RodSolver.hpp with Contacts/Plane.hpp), in
// Q16.16.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

typedef Q16_16 S;
typedef World<S, 2, 2, 1, 2, 1> PlaneWorld;
PlaneWorld gWorld;

// The HapticLever's stops: a rod and a plane on the same end. The lever
// falls from level onto a stop 30 degrees down (restitution 0.5): the
// rod keeps its length within 0.5 % through the bounce, and the end comes
// back up with about half its speed.
test(rodAndPlaneOnOneParticle) {
  PlaneWorld& w = gWorld;
  LeverScene lever;
  lever.pivot = w.addFixedParticle(Vec2<S>(0.0, 0.0));
  lever.end = w.addParticle(Vec2<S>(0.15, 0.0), S(0.1), S(0.01));
  w.addRod(lever.end, lever.pivot, S(0.15));
  w.addGravity();
  // The stop: the line through the pivot at -30 degrees, facing up.
  w.addPlane(Vec2<S>(0.5, 0.8660254), S(-0.01), S(0.5));
  const PlaneWorld::ParticleType& end = *w.particle(lever.end);
  float worst = 0, fastest = 0, rebound = 0;
  for (uint16_t k = 0; k < 256; ++k) {
    w.step(S(1.0 / 256));
    const float l = end.position.magnitude().toFloat();
    if (::fabsf(l / 0.15f - 1) > worst) worst = ::fabsf(l / 0.15f - 1);
    const float vy = end.velocity.y.toFloat();
    if (-vy > fastest) fastest = -vy;
    if (vy > rebound) rebound = vy;
  }
  assertLess(worst, 0.005f);
  assertNear(rebound / fastest, 0.5f, 0.1f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);
}

void loop() { TestRunner::run(); }
