// Silent failures of issue 13 in a Float world (StabilityTest has the
// Q16.16 ones): a diverging world is flagged and its particles keep a
// finite state; steps of dt <= 0 are refused.
#include <AUnit.h>
#include <TinyParticle.h>
#include <float.h>

using aunit::TestRunner;

typedef World<Float, 2, 1, 1> W;
typedef W::Vec V;

static bool finite(Float x) { return fabs(x.toFloat()) <= FLT_MAX; }

// A plain spring with k dt^2 / m = 20000 / 64^2 = 4.9 > 4 grows by about
// 2.5 times a step and leaves float's range within about 100 steps. The
// integrator notices the first non-finite velocity or position, raises
// WorldError::kNonFinite, and leaves that particle at its last finite
// position with zero velocity.
test(DivergingWorldIsFlagged_Float) {
  W w;
  ParticleId p = w.addParticle(V(0.1, 0.05), Float(1));
  w.addSpring(p, V(), Float(20000), Float(0));
  clearMathErrors();
  uint16_t flaggedAt = 0;
  for (uint16_t n = 1; n <= 200; ++n) {
    w.step(Float(1.0 / 64));
    if (flaggedAt == 0 && w.error() != 0) flaggedAt = n;
  }
  const W::ParticleType& q = *w.particle(p);
  Serial.print(F("flagged at step "));
  Serial.print(flaggedAt);
  Serial.print(F(", x = "));
  Serial.println(q.position.x.toFloat());
  assertEqual((int) w.error(), (int) WorldError::kNonFinite);
  assertTrue(finite(q.position.x) && finite(q.position.y));
  assertTrue(q.velocity == V());
  assertMore(flaggedAt, (uint16_t) 40);
}

// A stable world is never flagged: the same spring at dt = 1/256 s.
test(StableWorldIsNotFlagged_Float) {
  W w;
  ParticleId p = w.addParticle(V(0.1, 0.05), Float(1));
  w.addSpring(p, V(), Float(20000), Float(0));
  for (uint16_t n = 0; n < 512; ++n) w.step(Float(1.0 / 256));
  assertEqual((int) w.error(), 0);
  assertLess(fabs(w.particle(p)->position.x.toFloat()), 0.2f);
}

// step(dt <= 0) does nothing and raises kBadArgument (-0 and NaN too).
test(NonPositiveDtIsRefused_Float) {
  W w;
  ParticleId p = w.addParticle(V(1.0, 2.0), Float(1));
  w.addGravity();
  w.particle(p)->velocity = V(0.5, 0.0);
  w.step(Float(-1.0 / 256));
  w.step(Float(-0.0));
  w.step(Float(NAN));
  assertEqual((int) w.error(), (int) WorldError::kBadArgument);
  assertTrue(w.particle(p)->position == V(1.0, 2.0));
  assertTrue(w.particle(p)->velocity == V(0.5, 0.0));
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
