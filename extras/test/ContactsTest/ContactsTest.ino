// Contact generators: a cable (slack, then taut with a bounce) and a plane
// with a sloped normal.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S>
struct Checks {
  typedef World<S, 2, 1, 0, 1, 1> W;
  typedef typename W::Vec V;

  // A particle on a 1 m cable (restitution 0.5) to an anchor starts 0.5 m
  // from it, moving away at 1 m/s, no gravity. Returns the speed while the
  // cable is slack (after 0.25 s) in `slack`, the largest distance reached,
  // and the velocity after 1 s (after the bounce).
  static float cable(float* slack, float* farthest) {
    W w;
    V anchor, start(0.5, 0.0);
    ParticleId p = w.addParticle(start, S(1));
    w.particle(p)->velocity.x = S(1);
    w.addCable(p, anchor, S(1), S(0.5));
    *farthest = 0;
    for (uint16_t i = 0; i < 256; ++i) {
      w.step(S(1.0 / 256));
      float x = w.particle(p)->position.x.toFloat();
      if (x > *farthest) *farthest = x;
      if (i == 63) *slack = w.particle(p)->velocity.x.toFloat();
    }
    return w.particle(p)->velocity.x.toFloat();
  }

  // A ball moving at (-1, -1) m/s meets the plane x + y >= 0.5 (normal
  // (1, 1) / sqrt 2, restitution 1), no gravity. After the bounce its
  // velocity is (1, 1): the normal part reversed. `along` gets the speed
  // along the plane, which must stay 0.
  static float slope(float* along) {
    W w;
    V normal(1.0, 1.0), start(0.6, 0.6);
    w.addPlane(normal, S(0.35355339), S(1));  // 0.5 / sqrt 2
    ParticleId p = w.addParticle(start, S(1));
    w.particle(p)->velocity = V(-1.0, -1.0);
    for (uint16_t i = 0; i < 128; ++i) w.step(S(1.0 / 256));
    const V& v = w.particle(p)->velocity;
    *along = v.x.toFloat() - v.y.toFloat();
    return v.x.toFloat();
  }

};

// Slack: the speed is untouched. Taut: it comes back at 0.5 m/s
// (restitution 0.5); the cable overshoots by at most one step of travel
// (1/256 m), corrected in that step.
test(Cable_Q16_16) {
  float slack = 0, farthest;  // 0: a speed never written fails below
  float back = Checks<Q16_16>::cable(&slack, &farthest);
  assertEqual(slack, 1.0f);
  assertNear(back, -0.5f, 0.001f);
  assertLessOrEqual(farthest, 1.0f + 1.0f / 256);
}
test(Cable_Float) {
  float slack = 0, farthest;  // 0: a speed never written fails below
  float back = Checks<Float>::cable(&slack, &farthest);
  assertEqual(slack, 1.0f);
  assertNear(back, -0.5f, 0.001f);
  assertLessOrEqual(farthest, 1.0f + 1.0f / 256);
}

// The normal part of (-1, -1) is all of it: it comes back as (1, 1). The
// plane normal is rounded to the scalar (Q16.16: 2^-17), hence 0.001.
test(SlopedPlane_Q16_16) {
  float along;
  assertNear(Checks<Q16_16>::slope(&along), 1.0f, 0.001f);
  assertNear(along, 0.0f, 0.001f);
}
test(SlopedPlane_Float) {
  float along;
  assertNear(Checks<Float>::slope(&along), 1.0f, 0.001f);
  assertNear(along, 0.0f, 0.001f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
