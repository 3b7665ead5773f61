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

// Found by extras/fuzz: between a floor and a ceiling of restitution 85
// the speed grows 85 times at each bounce, and 85^20 > FLT_MAX: the
// contacts (after the integrator's check) take the velocity past float's
// range within about 20 bounces. After every step the particle is finite
// or the world is flagged, and it ends flagged, stopped, at a finite
// position.
test(ContactsThatDivergeAreFlagged_Float) {
  typedef World<Float, 2, 1, 0, 2, 2> Walls;  // its particles: no accumulator
  Walls w;
  ParticleId p = w.addParticle(V(0.5, 0.5), Float(1));
  w.particle(p)->velocity = V(0.0, -1.0);
  w.addPlane(V(0.0, 1.0), Float(0), Float(85));
  w.addPlane(V(0.0, -1.0), Float(-1), Float(85));
  bool silent = false;
  for (uint16_t n = 0; n < 2000 && w.error() == 0; ++n) {
    w.step(Float(1.0 / 256));
    const Walls::ParticleType& q = *w.particle(p);
    const bool isFinite = finite(q.position.x) && finite(q.position.y) &&
                          finite(q.velocity.x) && finite(q.velocity.y);
    if (!isFinite && w.error() == 0) silent = true;
  }
  const Walls::ParticleType& q = *w.particle(p);
  assertFalse(silent);
  assertEqual((int) w.error(), (int) WorldError::kNonFinite);
  assertTrue(finite(q.position.x) && finite(q.position.y));
  assertTrue(q.velocity == V());
}

// A position set to inf or NaN from outside: the move finds it, each such
// component saturates (+inf to largest(), -inf to lowest(), a NaN of
// either sign to 0), the finite one stays, the particle stops and the
// world is flagged.
test(NonFinitePositionSaturates_Float) {
  World<Float, 2, 2> w;
  ParticleId a = w.addParticle(V(0.0, 1.0), Float(1));
  ParticleId b = w.addParticle(V(0.0, 0.0), Float(1));
  w.particle(a)->position.x = Float(INFINITY);
  w.particle(a)->velocity = V(1.0, 0.0);
  w.particle(b)->position = V(Float(-INFINITY), Float(-NAN));
  w.particle(b)->velocity = V(1.0, 1.0);
  w.step(Float(1.0 / 256));
  assertEqual((int) w.error(), (int) WorldError::kNonFinite);
  assertTrue(w.particle(a)->position == V(Float::largest(), Float(1.0)));
  assertTrue(w.particle(b)->position == V(Float::lowest(), Float(0.0)));
  assertTrue(w.particle(a)->velocity == V());
  assertTrue(w.particle(b)->velocity == V());
  w.clearError();
  w.particle(b)->position.y = Float(NAN);
  w.particle(b)->velocity = V(0.0, 1.0);
  w.step(Float(1.0 / 256));
  assertEqual((int) w.error(), (int) WorldError::kNonFinite);
  assertTrue(w.particle(b)->position == V(Float::lowest(), Float(0.0)));
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
