// Rigid links in Q16.16 (Contacts/RodSolver.hpp): closed loops stay
// bounded, and flag when their lengths cannot all be met; a rod removed at
// run time lets go; a 1:1000 mass ratio on a rod. The cases share one world
// type (each world type is a copy of the engine in flash). RodPlaneTest has
// a rod and a plane on one particle, RodLoneTest the lever's energy at 1 kHz.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

typedef Q16_16 S;
typedef World<S, 2, 4, 1, 5, 2> CaseWorld;
// One world for all cases, emptied by each (seven would not fit the RAM),
// in place (gWorld = CaseWorld() would build a second one on the stack).
CaseWorld gWorld;
CaseWorld& freshWorld() {
  gWorld.clear();
  return gWorld;
}

// A square of four rods with one diagonal: rigid, and its lengths can all
// be met. It falls onto a pivot corner and swings; every rod within 1 %.
test(squareWithDiagonalHolds) {
  CaseWorld& w = freshWorld();
  ParticleId c[4];
  c[0] = w.addFixedParticle(Vec2<S>(0.0, 0.0));
  c[1] = w.addParticle(Vec2<S>(0.2, 0.0), S(0.1));
  c[2] = w.addParticle(Vec2<S>(0.2, 0.2), S(0.1));
  c[3] = w.addParticle(Vec2<S>(0.0, 0.2), S(0.1));
  for (uint8_t i = 0; i < 4; ++i) w.addRod(c[i], c[(i + 1) % 4], S(0.2));
  w.addRod(c[1], c[3], S(0.28284271));
  w.addGravity();
  float worst = 0;
  for (uint16_t k = 0; k < 1024; ++k) {
    w.step(S(1.0 / 256));
    for (uint8_t i = 0; i < 4; ++i) {
      const Vec2<S> d = w.particle(c[i])->position -
                        w.particle(c[(i + 1) % 4])->position;
      const float e = ::fabsf(d.magnitude().toFloat() / 0.2f - 1);
      if (e > worst) worst = e;
    }
  }
  assertLess(worst, 0.01f);
  assertEqual((uint16_t) (w.error() & WorldError::kRodsUnsatisfied), (uint16_t) 0);
}

// A triangle whose sides (0.1, 0.1, 0.3) break the triangle inequality:
// it cannot be held. The world flags it and stays finite and in place.
test(impossibleLoopIsFlaggedAndBounded) {
  CaseWorld& w = freshWorld();
  ParticleId a = w.addParticle(Vec2<S>(0.0, 0.0), S(0.1));
  ParticleId b = w.addParticle(Vec2<S>(0.1, 0.0), S(0.1));
  ParticleId c = w.addParticle(Vec2<S>(0.05, 0.08), S(0.1));
  w.addRod(a, b, S(0.1));
  w.addRod(b, c, S(0.1));
  w.addRod(c, a, S(0.3));
  for (uint16_t k = 0; k < 512; ++k) w.step(S(1.0 / 256));
  assertNotEqual((uint16_t) (w.error() & WorldError::kRodsUnsatisfied), (uint16_t) 0);
  for (uint8_t i = 0; i < 3; ++i) {
    assertLess(fabs(w.particleAt(i).position.x).toFloat(), 10.0f);
    assertLess(fabs(w.particleAt(i).position.y).toFloat(), 10.0f);
  }
}

// Three beads hang from a pivot; the middle rod is removed: the lower
// bead falls freely (its speed after 0.25 s is g t within 2 %), the upper
// one still swings on its rod.
test(removedRodLetsGo) {
  CaseWorld& w = freshWorld();
  ParticleId p0 = w.addFixedParticle(Vec2<S>(0.0, 0.0));
  ParticleId p1 = w.addParticle(Vec2<S>(0.0, -0.1), S(0.05));
  ParticleId p2 = w.addParticle(Vec2<S>(0.0, -0.2), S(0.05));
  w.addRod(p1, p0, S(0.1));
  ConstraintId middle = w.addRod(p2, p1, S(0.1));
  w.addGravity();
  for (uint8_t k = 0; k < 64; ++k) w.step(S(1.0 / 256));
  assertTrue(w.removeConstraint(middle));
  for (uint8_t k = 0; k < 64; ++k) w.step(S(1.0 / 256));
  assertNear(w.particle(p2)->velocity.y.toFloat(), -9.81f * 0.25f, 0.05f);
  const float l1 = w.particle(p1)->position.magnitude().toFloat();
  assertNear(l1, 0.1f, 0.0005f);
  assertEqual(w.error(), (uint16_t) 0);
}

// 1 kg and 1000 kg on a 0.5 m rod, no gravity, spinning at 2 m/s: the rod
// holds to 0.5 % and the kinetic energy to 1 %. (Momentum is not asserted:
// the heavy end's velocity changes by about 2 units of Q16.16 per step, so
// each step rounds it by up to a quarter of its change.)
test(massRatioOneToAThousand) {
  CaseWorld& w = freshWorld();
  ParticleId light = w.addParticle(Vec2<S>(0.5, 0.0), S(1));
  ParticleId heavy = w.addParticle(Vec2<S>(0.0, 0.0), S(1000));
  w.addRod(light, heavy, S(0.5));
  w.particle(light)->velocity = Vec2<S>(0.0, 2.0);
  float worst = 0, energy = 0;
  for (uint16_t k = 0; k < 1024; ++k) {
    w.step(S(1.0 / 256));
    const float v2 = w.particle(light)->velocity.magnitudeSquared().toFloat();
    const float h2 = w.particle(heavy)->velocity.magnitudeSquared().toFloat();
    const float e = ::fabsf((v2 + 1000 * h2) / 4.0f - 1);
    if (e > energy) energy = e;
    const Vec2<S> d =
        w.particle(light)->position - w.particle(heavy)->position;
    const float l = ::fabsf(d.magnitude().toFloat() / 0.5f - 1);
    if (l > worst) worst = l;
  }
  assertLess(worst, 0.005f);
  assertLess(energy, 0.01f);
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
