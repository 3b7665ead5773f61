// World::clear() (issue 13): it empties a world in place, without building
// a World temporary on the Nano's small stack, and every handle from before
// becomes stale.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

typedef World<Q16_16, 2, 2, 2, 2, 2> W;
typedef W::Vec V;

// clear() empties the world in place: every handle from before is stale
// (also once its slot is reused), the error bits and statistics are reset,
// and the cleared world then steps exactly like a new one.
test(ClearEmptiesInPlace) {
  static W w, fresh;  // static: two worlds on the Nano's stack would be a lot
  ParticleId a = w.addParticle(V(0.0, 1.0), Q16_16(1));
  ParticleId b = w.addParticle(V(0.0, 0.0), Q16_16(1));
  ForceId g = w.addGravity();
  ForceId s = w.addSpring(a, b, Q16_16(10), Q16_16(1));
  ConstraintId r = w.addRod(a, b, Q16_16(1));
  ConstraintId floor = w.addPlane(V(0.0, 1.0), Q16_16(-5), Q16_16(0.5));
  w.addParticle(V(), Q16_16(1));  // pool full: an error bit
  w.step(Q16_16(1.0 / 256));
  assertNotEqual((int) w.error(), 0);
  w.clear();
  assertEqual((int) w.particleCount(), 0);
  assertEqual((int) w.error(), 0);
  assertEqual((int) w.contactCount(), 0);
  assertTrue(w.particle(a) == nullptr && w.particle(b) == nullptr);
  assertTrue(w.force(s) == nullptr);
  assertTrue(w.constraint(r) == nullptr && w.constraint(floor) == nullptr);
  // The world's gravity is off: removing it again is refused.
  assertTrue(w.uniformAcceleration() == V());
  assertFalse(w.removeForce(g));
  w.clearError();
  // The same slots again: the old handles still miss.
  ParticleId c = w.addParticle(V(0.0, 1.0), Q16_16(1));
  ForceId g2 = w.addGravity();
  ConstraintId r2 = w.addPlane(V(0.0, 1.0), Q16_16(-5), Q16_16(0.5));
  assertEqual((int) c.index, (int) a.index);
  assertTrue(w.particle(a) == nullptr && w.particle(c) != nullptr);
  assertTrue(g2.isValid() && w.uniformAcceleration() == W::standardGravity());
  assertTrue(w.constraint(r) == nullptr && w.constraint(r2) != nullptr);
  // A new world with the same scene, stepped alike: the same bits.
  ParticleId d = fresh.addParticle(V(0.0, 1.0), Q16_16(1));
  fresh.addGravity();
  fresh.addPlane(V(0.0, 1.0), Q16_16(-5), Q16_16(0.5));
  for (uint8_t i = 0; i < 10; ++i) {
    w.step(Q16_16(1.0 / 256));
    fresh.step(Q16_16(1.0 / 256));
  }
  assertTrue(w.particle(c)->position == fresh.particle(d)->position);
  assertTrue(w.particle(c)->velocity == fresh.particle(d)->velocity);
  assertEqual((int) w.error(), 0);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
