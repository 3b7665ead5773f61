// The stiff spring (Forces/StiffSpring.hpp) against the closed form of the
// damped oscillator, and stable where an ordinary spring explodes.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S>
struct Checks {
  typedef World<S, 2, 1, 1> W;
  typedef typename W::Vec V;

  // 1 kg, k = 2000 N/m, c = 5 N s/m, dt = 1/256 s, released at rest 0.1 m
  // from the anchor (0.2, 0.3) along (0.6, -0.8). The closed form is
  // s(t) = exp(-c t / 2) (P cos(g t) + Q sin(g t)), g = sqrt(k - c^2 / 4),
  // through s(0) = 0.1 and the first step's s(dt) (the first step sets the
  // phase). Returns the largest |s_n - s(n dt)| over 1 s.
  static float trackError() {
    W w;
    const V anchor(0.2, 0.3);
    const V start(0.26, 0.22);
    ParticleId p = w.addParticle(start, S(1));
    w.addStiffSpring(p, anchor, S(2000), S(5), S(1.0 / 256));
    const float h = 1.0f / 256, c = 5, g = sqrt(2000.0f - c * c / 4);
    const float P = 0.1f;
    float Q = 0;
    float worst = 0;
    for (uint16_t n = 1; n <= 256; ++n) {
      w.step(S(1.0 / 256));
      const V d = w.particle(p)->position - anchor;
      const float s = 0.6f * d.x.toFloat() - 0.8f * d.y.toFloat();
      const float t = n * h;
      if (n == 1) Q = (s * exp(c * h / 2) - P * cos(g * h)) / sin(g * h);
      const float expected = exp(-c * t / 2) * (P * cos(g * t) + Q * sin(g * t));
      if (fabs(s - expected) > worst) worst = fabs(s - expected);
    }
    return worst;
  }

  // k = 20000 N/m on 1 kg at dt = 1/64 s: w dt = 2.21, beyond the limit 2 of
  // an ordinary spring. Released at rest 0.1 m from the anchor for 2 s.
  // Returns the largest |x| of the stiff spring; `plain` gets the largest
  // |x| of an ordinary spring with the same k.
  static float stable(float* plain) {
    W stiff, hooke;
    V start(0.1, 0.0), anchor;
    ParticleId a = stiff.addParticle(start, S(1));
    stiff.addStiffSpring(a, anchor, S(20000), S(0), S(1.0 / 64));
    ParticleId b = hooke.addParticle(start, S(1));
    hooke.addSpring(b, anchor, S(20000), S(0));
    float worst = 0;
    *plain = 0;
    for (uint16_t n = 0; n < 128; ++n) {
      stiff.step(S(1.0 / 64));
      hooke.step(S(1.0 / 64));
      float x = fabs(stiff.particle(a)->position.x.toFloat());
      if (x > worst) worst = x;
      x = fabs(hooke.particle(b)->position.x.toFloat());
      if (x > *plain) *plain = x;
    }
    return worst;
  }
};

// Rounding: each step rounds three products (u / 2 each) and the stable
// map does not amplify errors, so after n = 256 steps the error is at most
// 1.5 n u: 0.0059 m for Q16.16 (u = 2^-16), 3e-6 m for float near 0.1 m
// (u = 2^-27). A frequency off by 1 % would be off by 0.045 m by then.
test(StiffSpringTracksClosedForm_Q16_16) {
  assertLessOrEqual(Checks<Q16_16>::trackError(), 1.5f * 256 / 65536);
}
test(StiffSpringTracksClosedForm_Float) {
  assertLessOrEqual(Checks<Float>::trackError(), 3e-6f);
}

// Undamped, the stiff spring keeps the amplitude that its first step sets:
// x0 / cos(w dt / 2) = 0.1 / cos(1.105) = 0.2223 m (plus 0.1 % for
// rounding). The ordinary spring grows by 2.5 times a step: past 1 m.
test(StiffSpringStable_Q16_16) {
  float plain;
  const float bound = 0.1f / cos(sqrt(20000.0f) / 64 / 2);
  assertLessOrEqual(Checks<Q16_16>::stable(&plain), bound * 1.001f);
  assertMore(plain, 1.0f);
}
test(StiffSpringStable_Float) {
  float plain;
  const float bound = 0.1f / cos(sqrt(20000.0f) / 64 / 2);
  assertLessOrEqual(Checks<Float>::stable(&plain), bound * 1.001f);
  assertMore(plain, 1.0f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
