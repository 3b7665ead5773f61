// Generators of the sketch's own (World::addForce, World::addConstraint),
// in Q16.16 (GeneratorsFloatTest: others, in Float): written here, outside
// the library, they give the same trajectory as the built-in generator they
// copy, bit for bit. That is exact, not a
// tolerance: each copy does the same scalar operations in the same order
// on the same operands as the built-in one (Forces/Spring.hpp,
// Contacts/Plane.hpp), and the world runs both through the same runner
// (Core/Generator.hpp), so fixed point and float alike round the same way.
// A difference of one unit anywhere in 2 s of motion fails the test.
// Also: a generator's fields changed by the sketch between steps, and the
// errors of the calls that add one.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/GeneratorChecks.hpp>

using aunit::TestRunner;

// Hooke's spring from a particle to an anchor, as Forces/Spring.hpp.
template <typename S>
struct UserAnchoredSpring {
  Vec2<S> anchor;
  S stiffness;
  S restLength;
  uint16_t calls;  // steps it was run

  void apply(Particle<S, 2>& p, S) {
    ++calls;
    Vec2<S> delta = p.position;
    delta -= anchor;
    S lengthSquared = delta.magnitudeSquared();
    if (lengthSquared == S()) return;
    S length = sqrt(lengthSquared);
    S extension = length - restLength;
    S perLength = -(stiffness * extension) / length;
    p.acceleration.addScaled(delta, perLength * p.inverseMass);
  }
};

// Hooke's spring between two particles.
template <typename S>
struct UserSpring {
  S stiffness;
  S restLength;

  void apply(Particle<S, 2>& a, Particle<S, 2>& b, S) {
    Vec2<S> delta = a.position;
    delta -= b.position;
    S lengthSquared = delta.magnitudeSquared();
    if (lengthSquared == S()) return;
    S length = sqrt(lengthSquared);
    S extension = length - restLength;
    S perLength = -(stiffness * extension) / length;
    a.acceleration.addScaled(delta, perLength * a.inverseMass);
    b.acceleration.addScaled(delta, -(perLength * b.inverseMass));
  }
};

template <typename S>
struct Checks {
  typedef World<S, 2, 2, 2, 2, 4> W;
  typedef typename W::Vec V;

  // 0.5 kg on a spring (k = 40 N/m, rest 0.3 m) from (0, 1), released from
  // (0.25, 0.6) under gravity, for 2 s at dt = 1/256 s: it swings and
  // bounces (period about 0.7 s). Returns the first step at which the two
  // worlds differ, 0 when none does; `moved` tells that it did swing.
  static uint16_t anchoredSpring(bool& moved, uint16_t& calls) {
    W builtIn, user;
    const V anchor(0.0, 1.0), start(0.25, 0.6);
    ParticleId a = builtIn.addParticle(start, S(0.5));
    ParticleId b = user.addParticle(start, S(0.5));
    builtIn.addGravity();
    user.addGravity();
    builtIn.addSpring(a, anchor, S(40), S(0.3));
    UserAnchoredSpring<S> spring = {anchor, S(40), S(0.3), 0};
    if (!user.addForce(spring, b).isValid()) return 0xFFFF;
    moved = false;
    for (uint16_t n = 1; n <= 512; ++n) {
      builtIn.step(S(1.0 / 256));
      user.step(S(1.0 / 256));
      if (!testing::sameMotion(*builtIn.particle(a), *user.particle(b))) {
        return n;
      }
      if (fabs(user.particle(b)->position.x - start.x) > S(0.2)) moved = true;
    }
    calls = spring.calls;
    return 0;
  }

  // Two 1 kg particles on a spring (k = 30 N/m, rest 0.5 m), 0.8 m apart
  // and moving apart at 0.4 m/s: it oscillates along and across.
  static uint16_t pairSpring(bool& moved) {
    W builtIn, user;
    UserSpring<S> spring = {S(30), S(0.5)};
    ParticleId a[2], b[2];
    W* worlds[2] = {&builtIn, &user};
    ParticleId* ids[2] = {a, b};
    for (uint8_t k = 0; k < 2; ++k) {
      ids[k][0] = worlds[k]->addParticle(V(0.0, 0.0), S(1));
      ids[k][1] = worlds[k]->addParticle(V(0.8, 0.1), S(1));
      worlds[k]->particle(ids[k][1])->velocity = V(0.4, 0.3);
    }
    builtIn.addSpring(a[0], a[1], S(30), S(0.5));
    if (!user.addForce(spring, b[0], b[1]).isValid()) return 0xFFFF;
    moved = false;
    for (uint16_t n = 1; n <= 512; ++n) {
      builtIn.step(S(1.0 / 256));
      user.step(S(1.0 / 256));
      for (uint8_t i = 0; i < 2; ++i) {
        if (!testing::sameMotion(*builtIn.particle(a[i]),
                                 *user.particle(b[i]))) {
          return n;
        }
      }
      if (user.particle(b[1])->position.x < S(0.6)) moved = true;
    }
    return 0;
  }
};

test(UserForceSameAsBuiltInSpring) {
  bool moved = false;
  uint16_t calls = 0;
  assertEqual(Checks<Q16_16>::anchoredSpring(moved, calls), (uint16_t) 0);
  assertTrue(moved);
  assertEqual(calls, (uint16_t) 512);  // once a step
}

test(UserPairForceSameAsBuiltInSpring) {
  bool moved = false;
  assertEqual(Checks<Q16_16>::pairSpring(moved), (uint16_t) 0);
  assertTrue(moved);
}

test(UserConstraintSameAsBuiltInPlane) {
  bool touched = false;
  assertEqual(
      testing::tiltedPlaneAgainstBuiltIn<Checks<Q16_16>::W>(false, touched),
      (uint16_t) 0);
  assertTrue(touched);
}

// The sketch moves its generator between steps (the Magnet example's dial):
// a spring whose anchor jumps pulls the other way from the next step on.
// One world type for every test: each type instantiates the engine again.
typedef Checks<Q16_16>::W W;

test(UserGeneratorFieldsTakeEffect) {
  W w;
  ParticleId p = w.addParticle(W::Vec(0.0, 0.0), Q16_16(1));
  UserAnchoredSpring<Q16_16> spring = {W::Vec(1.0, 0.0), Q16_16(10),
                                       Q16_16(0), 0};
  w.addForce(spring, p);
  w.step(Q16_16(1.0 / 256));
  assertTrue(w.particle(p)->velocity.x > Q16_16());  // towards +x
  spring.anchor = W::Vec(-1.0, 0.0);
  for (uint8_t i = 0; i < 10; ++i) w.step(Q16_16(1.0 / 256));
  assertTrue(w.particle(p)->velocity.x < Q16_16());  // now towards -x
}

// Errors of the user calls: a stale particle, a pair of one particle, a
// full pool; each an invalid id and its error bit, as for the built-ins.
test(UserGeneratorErrors) {
  W w;
  UserAnchoredSpring<Q16_16> spring = {W::Vec(), Q16_16(1), Q16_16(0), 0};
  UserSpring<Q16_16> pair = {Q16_16(1), Q16_16(0)};
  ParticleId p = w.addParticle(W::Vec(), Q16_16(1));
  assertFalse(w.addForce(spring, ParticleId(1, 7)).isValid());
  assertEqual((uint16_t) w.error(), (uint16_t) WorldError::kStaleHandle);
  w.clearError();
  assertFalse(w.addForce(pair, p, p).isValid());
  assertEqual((uint16_t) w.error(), (uint16_t) WorldError::kBadArgument);
  w.clearError();
  assertTrue(w.addForce(spring, p).isValid());
  assertTrue(w.addForce(pair, p, w.addParticle(W::Vec(), Q16_16(1))).isValid());
  assertFalse(w.addForce(spring).isValid());  // 2 force slots
  assertEqual((uint16_t) w.error(), (uint16_t) WorldError::kForcesFull);
}

// What a slot holds is its kind, not its layout or its indices: typed
// parameters are found only in a slot of that class, setLength() takes
// only rods and cables (an anchored plane is not one), and removing a
// generator frees its kind.
void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
