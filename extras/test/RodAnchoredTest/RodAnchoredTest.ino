// A world whose rods all hang from anchors is solved by the lone rods
// alone (Contacts/LoneRod.hpp), without the chains' solve, Q16.16 2D: two
// pendulums keep their rods' lengths; a second anchored rod on a particle
// is refused (kBadArgument), and taken once a rod between two particles
// has brought the chains' solve.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

typedef Q16_16 S;
typedef Vec2<S> V;
typedef World<S, 2, 3, 1, 4, 0> Anchored;

Anchored gAnchored;

test(anchoredRodsOnePerParticle) {
  Anchored& w = gAnchored;
  w.clear();
  const ParticleId a = w.addParticle(V(0.0, -0.5), S(0.1));
  const ParticleId b = w.addParticle(V(0.2, -0.5), S(0.1));
  assertTrue(w.addRod(a, V(0.0, 0.0), S(0.5)).isValid());
  assertTrue(w.addRod(b, V(0.2, 0.0), S(0.5)).isValid());
  // A second anchored rod on a: refused, nothing else changed.
  assertFalse(w.addRod(a, V(-0.3, -0.5), S(0.3)).isValid());
  assertEqual(w.error(), (uint16_t)WorldError::kBadArgument);
  w.clearError();
  // The two pendulums swing, each on its rod.
  w.addGravity();
  w.particle(a)->velocity = V(1.0, 0.0);
  for (uint16_t k = 0; k < 256; ++k) w.step(S(1.0 / 256));
  assertEqual(w.error(), (uint16_t)0);
  const float la = w.particleAt(0).position.magnitude().toFloat();
  const float lb =
      (w.particleAt(1).position - V(0.2, 0.0)).magnitude().toFloat();
  assertLess(::fabsf(la - 0.5f), RodSolver<Anchored>::tolerance().toFloat());
  assertLess(::fabsf(lb - 0.5f), RodSolver<Anchored>::tolerance().toFloat());
  // A rod between the two particles brings the chains' solve: now a takes
  // its second anchored rod, and the three rods are held together.
  assertTrue(w.addRod(a, b, S(0.2)).isValid());
  assertTrue(w.addRod(a, V(-0.3, -0.5), S(0.3)).isValid());
  assertEqual(w.error(), (uint16_t)0);
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
