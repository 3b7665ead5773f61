// The stability suite of issue 13 in Float: contacts, springs, the range
// edge, tiny steps, exhausted pools, and inf and NaN written into a world.
// StabilitySuiteRodsFloatTest has the rod cases; StabilitySuiteTest the
// Q16.16 ones. Cases and bounds: src/TinyParticle/Testing/StabilityCases.hpp.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/StabilityCases.hpp>
#include <float.h>

using aunit::TestRunner;
using tinyparticle::testing::StabilityCases;
using tinyparticle::testing::stabilityLine;

typedef StabilityCases<Float> Cases;
typedef Vec2<Float> V;

test(Spring_Float) { assertTrue(Cases::checkSpring(FLT_MAX)); }
test(Wall_Float) { assertTrue(Cases::checkWall(200)); }
test(BallHit_Float) { assertTrue(Cases::checkBallHit()); }
test(MassRatioCollision_Float) { assertTrue(Cases::checkMassRatioCollision()); }
test(Stack_Float) {
  assertTrue(Cases::checkStack());
}
test(Coincident_Float) { assertTrue(Cases::checkCoincident()); }
test(RangeEdge_Float) { assertTrue(Cases::checkRangeEdge()); }
test(TinyDt_Float) {
  bool ok = Cases::checkFreeFall(256, F("free-fall-dt-1/256-m"));
  ok &= Cases::checkFreeFall(1024, F("free-fall-dt-1/1024-m"));
  ok &= Cases::checkFreeFall(4096, F("free-fall-dt-1/4096-m"));
  ok &= Cases::checkFreeFall(16384, F("free-fall-dt-1/16384-m"));
  assertTrue(ok);
}
test(Exhaustion_Float) { assertTrue(Cases::checkExhaustion()); }

// NaN in one ball's velocity, +inf in another's position, a third left
// alone, all falling: after one step the world is flagged (kNonFinite),
// the two are stopped at finite positions (the inf one saturated at
// Float::largest()), and the third fell exactly as in free fall:
// v = -g dt, y = y0 - g dt^2. Counts what went wrong (bound 0).
test(NanAndInfInjected_Float) {
  Cases::ContactWorld& w = Cases::contactWorld();
  w.addGravity();
  ParticleId a = w.addParticle(V(0.2, 0.5), Float(1));
  ParticleId b = w.addParticle(V(0.4, 0.5), Float(1));
  ParticleId c = w.addParticle(V(0.6, 0.5), Float(1));
  w.particle(a)->velocity.x = Float(double(NAN));
  w.particle(b)->position.y = Float(double(INFINITY));
  w.step(Float(1.0 / 256));
  uint8_t wrong = 0;
  if (w.error() != WorldError::kNonFinite) ++wrong;
  for (uint8_t i = 0; i < 3; ++i) {
    if (!Cases::isFinite(w.particleAt(i))) ++wrong;
  }
  if (!(w.particle(a)->velocity == V()) || !(w.particle(b)->velocity == V())) ++wrong;
  if (!(w.particle(b)->position.y == Float::largest())) ++wrong;
  const float g = Float(9.81).toFloat();  // gravity as the world has it
  const float v = w.particle(c)->velocity.y.toFloat();
  const float y = w.particle(c)->position.y.toFloat();
  if (!(::fabsf(v + g / 256) <= 1e-6f) || !(::fabsf(y - (0.5f - g / 65536)) <= 1e-6f)) ++wrong;
  assertTrue(stabilityLine<Float>(F("nan-and-inf-injected-wrong"), 0, wrong));
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);  // long cases: the whole run is timed by run-tests
}

void loop() { TestRunner::run(); }
