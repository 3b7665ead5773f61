// Generators of the sketch's own, in Float (GeneratorsTest: springs and a
// plane for every particle, in Q16.16): a drag on every particle and a
// plane for one particle, written here, give the same trajectories as the
// built-in drag and plane, bit for bit. Exact, not a tolerance: each copy
// does the same float operations in the same order on the same operands as
// the built-in one (Forces/Drag.hpp, Contacts/Plane.hpp), through the same
// runners (Core/Generator.hpp); a difference in the last bit anywhere in
// 2 s of motion fails the test. Also the kind tags.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/GeneratorChecks.hpp>

using aunit::TestRunner;

typedef Float S;
typedef World<S, 2, 3, 2, 2, 4> W;  // one world type for every test
typedef W::Vec V;

// Three particles of 0.2, 1 and 3 kg thrown at 4 m/s in different
// directions under gravity and drag (k1 = 0.3 N s/m, k2 = 0.1 N s^2/m^2),
// for 2 s at 1/256 s. Returns the first step at which the worlds differ,
// 0 when none does; `slowed`: the lightest lost most of its speed.
static uint16_t dragOnEach(bool& slowed) {
  W builtIn, user;
  W* worlds[2] = {&builtIn, &user};
  const float masses[3] = {0.2f, 1.0f, 3.0f};
  for (uint8_t k = 0; k < 2; ++k) {
    for (uint8_t i = 0; i < 3; ++i) {
      ParticleId id = worlds[k]->addParticle(V(0.0, 0.0), S(masses[i]));
      worlds[k]->particle(id)->velocity = V(4.0 - 2.0 * i, 1.0 + i);
    }
    worlds[k]->addGravity();
  }
  builtIn.addDrag(S(0.3), S(0.1));
  testing::UserDrag<W> drag = {S(0.3), S(0.1)};
  if (!user.addForce(drag).isValid()) return 0xFFFF;
  for (uint16_t n = 1; n <= 512; ++n) {
    builtIn.step(S(1.0 / 256));
    user.step(S(1.0 / 256));
    for (uint8_t i = 0; i < 3; ++i) {
      if (!testing::sameMotion(builtIn.particleAt(i), user.particleAt(i))) {
        return n;
      }
    }
  }
  // Without drag it would fall at 19.6 m/s after 2 s; its terminal speed,
  // 0.3 v + 0.1 v^2 = 0.2 * 9.81, is 3.2 m/s.
  slowed = user.particleAt(0).velocity.magnitude() < S(4);
  return 0;
}

test(UserDragSameAsBuiltIn) {
  bool slowed = false;
  assertEqual(dragOnEach(slowed), (uint16_t) 0);
  assertTrue(slowed);
}

test(UserConstraintForOneSameAsBuiltInPlane) {
  bool touched = false;
  assertEqual(testing::tiltedPlaneAgainstBuiltIn<W>(true, touched),
              (uint16_t) 0);
  assertTrue(touched);
}

typedef DragForce<S, 2> Drag;
typedef SpringForce<S, 2> PairSpring;
typedef AnchoredSpringForce<S, 2> AnchoredSpring;

test(KindTags) {
  W w;
  ParticleId p = w.addParticle(W::Vec(0.0, 1.0), S(1));
  ParticleId q = w.addParticle(W::Vec(0.0, 2.0), S(1));
  ForceId drag = w.addDrag(S(0.1), S(0));
  ForceId spring = w.addSpring(p, W::Vec(), S(5), S(1));
  // (2 force slots, 2 constraint slots)
  assertTrue(w.forceParams<Drag>(drag) != nullptr);
  assertTrue(w.forceParams<PairSpring>(drag) == nullptr);
  assertTrue(w.forceParams<PairSpring>(spring) == nullptr);
  AnchoredSpring* s = w.forceParams<AnchoredSpring>(spring);
  assertTrue(s != nullptr);
  assertTrue(s->stiffness == S(5));
  ConstraintId floor = w.addPlane(W::Vec(0.0, 1.0), S(0), S(0));
  ConstraintId rod = w.addRod(p, q, S(1));
  assertFalse(w.setLength(floor, S(2)));
  assertTrue(w.setLength(rod, S(0.5)));
  assertTrue(w.constraintParams<W::LinkParamsType>(rod)->length == S(0.5));
  assertTrue(w.removeForce(drag));
  assertTrue(w.forceParams<Drag>(drag) == nullptr);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
