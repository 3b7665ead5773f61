// The pendulum scene (a rod from a fixed pivot, gravity): its period
// against the closed form, and the rod's length through a long swing.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S>
struct Checks {
  typedef PendulumWorld<S, 2> W;

  // Period of L = 1 m, theta0 = 0.2 rad at dt = 1/1024 s (exact in both
  // scalars, so time is the step count times dt). Measured between the
  // first and the third downward zero crossing of x, each found by linear
  // interpolation between the two steps around it.
  static float period() {
    W w;
    PendulumScene scene = buildPendulum(w, S(1), S(0.2), S(1));
    const float dt = 1.0f / 1024;
    float previous = w.particle(scene.bob)->position.x.toFloat();
    float first = -1, last = -1;
    uint8_t crossings = 0;
    for (uint16_t i = 1; i <= 5 * 1024 && crossings < 3; ++i) {
      w.step(S(1.0 / 1024));
      float x = w.particle(scene.bob)->position.x.toFloat();
      if (previous > 0 && x <= 0) {
        float t = i * dt - dt * x / (x - previous);
        if (crossings == 0) first = t;
        last = t;
        ++crossings;
      }
      previous = x;
    }
    return crossings == 3 ? (last - first) / 2 : -1;
  }

  // The largest |length - L| over a 10 s swing from theta0 = 0.5 rad at
  // dt = 1/256 s; `swung` tells whether the bob crossed to the other side.
  static float lengthError(bool* swung) {
    W w;
    PendulumScene scene = buildPendulum(w, S(1), S(0.5), S(1));
    float worst = 0;
    *swung = false;
    for (uint16_t i = 0; i < 10 * 256; ++i) {
      w.step(S(1.0 / 256));
      const typename W::Vec& p = w.particle(scene.bob)->position;
      float x = p.x.toFloat(), y = p.y.toFloat();
      float error = fabs(sqrt(x * x + y * y) - 1.0f);
      if (error > worst) worst = error;
      if (x < -0.4f) *swung = true;
    }
    return worst;
  }
};

// T = 2 pi sqrt(L / g) (1 + theta0^2 / 16) = 2.01108 s; within 0.5 %.
static const float kPeriod = 2 * 3.14159265f * sqrt(1.0f / 9.81f) *
                             (1 + 0.2f * 0.2f / 16);

test(PendulumPeriod_Q16_16) {
  TestRunner::setTimeout(0);
  assertNear(Checks<Q16_16>::period(), kPeriod, 0.005f * kPeriod);
}
test(PendulumPeriod_Float) {
  TestRunner::setTimeout(0);
  assertNear(Checks<Float>::period(), kPeriod, 0.005f * kPeriod);
}

test(RodKeepsLength_Q16_16) {
  TestRunner::setTimeout(0);
  bool swung;
  assertLessOrEqual(Checks<Q16_16>::lengthError(&swung), 0.001f);
  assertTrue(swung);
}
test(RodKeepsLength_Float) {
  TestRunner::setTimeout(0);
  bool swung;
  assertLessOrEqual(Checks<Float>::lengthError(&swung), 0.001f);
  assertTrue(swung);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
