// A rod does no work: a pendulum on a rod keeps its energy through a long
// swing, and a rod still absorbs a genuine pull along it (Contacts/Link.hpp
// explains how the turn of the rod is told apart from a pull).
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S>
struct Checks {
  typedef PendulumWorld<S, 2> W;

  // Energy per unit mass, with the height counted from the pivot:
  // v^2 / 2 + g y.
  static float energy(const typename W::ParticleType& bob) {
    float vx = bob.velocity.x.toFloat(), vy = bob.velocity.y.toFloat();
    return (vx * vx + vy * vy) / 2 + 9.81f * bob.position.y.toFloat();
  }

  // L = 1 m, theta0 = 0.5 rad, dt = 1/256 s, for 10 s (almost 5 periods).
  // Returns the largest |E(t) - E(0)| over the swing, divided by the energy
  // that the swing exchanges, g L (1 - cos theta0) (what the bob would
  // have at the bottom); `swung` tells whether it still reaches the other
  // side at the end.
  static float energyError(bool* swung) {
    W w;
    PendulumScene scene = buildPendulum(w, S(1), S(0.5), S(1));
    const typename W::ParticleType& bob = *w.particle(scene.bob);
    const float start = energy(bob);
    const float swing = 9.81f * 0.12241744f;  // 1 - cos 0.5
    float worst = 0;
    *swung = false;
    for (uint16_t i = 0; i < 10 * 256; ++i) {
      w.step(S(1.0 / 256));
      float error = fabs(energy(bob) - start);
      if (error > worst) worst = error;
      if (i >= 9 * 256 && bob.position.x.toFloat() < -0.45f) *swung = true;
    }
    return worst / swing;
  }

  // The bob hangs at rest, and is pushed straight away from the pivot at
  // 1 m/s (gravity on). Returns the largest |length - L| over 1 s; `speed`
  // gets the largest speed from the second step on, and `back` the
  // velocity towards the pivot after the first step (a bounce would be
  // +1 m/s).
  static float radialPush(float* speed, float* back) {
    W w;
    PendulumScene scene = buildPendulum(w, S(1), S(0), S(1));
    typename W::ParticleType& bob = *w.particle(scene.bob);
    bob.velocity.y = S(-1);
    float worst = 0;
    *speed = 0;
    for (uint16_t i = 0; i < 256; ++i) {
      w.step(S(1.0 / 256));
      float x = bob.position.x.toFloat(), y = bob.position.y.toFloat();
      float error = fabs(sqrt(x * x + y * y) - 1.0f);
      if (error > worst) worst = error;
      float vx = bob.velocity.x.toFloat(), vy = bob.velocity.y.toFloat();
      if (i == 0) *back = vy;
      if (i > 0 && sqrt(vx * vx + vy * vy) > *speed) {
        *speed = sqrt(vx * vx + vy * vy);
      }
    }
    return worst;
  }
};

// Semi-implicit Euler keeps a modified energy: the true one oscillates
// around it with a relative amplitude of about omega dt / 2, omega =
// sqrt(g / L) = 3.13 rad/s, i.e. 0.6 % at dt = 1/256 s, and does not drift.
// Allowed: twice omega dt, 2.4 % of the swing's energy, over all 10 s. (A
// rod that removes the velocity its own turn explains loses about a third
// in these 10 s.)
static const float kEnergyBound = 2 * 3.13f / 256;

test(PendulumEnergy_Q16_16) {
  TestRunner::setTimeout(0);
  bool swung;
  assertLessOrEqual(Checks<Q16_16>::energyError(&swung), kEnergyBound);
  assertTrue(swung);
}
test(PendulumEnergy_Float) {
  TestRunner::setTimeout(0);
  bool swung;
  assertLessOrEqual(Checks<Float>::energyError(&swung), kEnergyBound);
  assertTrue(swung);
}

// The push along the rod is absorbed (restitution 0): no bounce back (well
// under 1 % of the 1 m/s push), the bob is then at rest (within 1 % of the
// push, which also bounds what gravity adds in a step, 9.81 / 256 = 0.04
// m/s, once the rod takes it), and the rod keeps its length within 1 mm.
test(RodAbsorbsRadialPush_Q16_16) {
  float speed, back;
  assertLessOrEqual(Checks<Q16_16>::radialPush(&speed, &back), 0.001f);
  assertLessOrEqual(back, 0.01f);
  assertLessOrEqual(speed, 0.01f);
}
test(RodAbsorbsRadialPush_Float) {
  float speed, back;
  assertLessOrEqual(Checks<Float>::radialPush(&speed, &back), 0.001f);
  assertLessOrEqual(back, 0.01f);
  assertLessOrEqual(speed, 0.01f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
