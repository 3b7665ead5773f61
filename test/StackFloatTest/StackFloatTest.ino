// A resting stack of balls on the floor: it neither sinks nor jitters, and
// with the resolver's shock propagation it comes to rest.
// (Float here: StackTest runs the same checks with Q16.16; the two
// scalars together no longer fit in the Nano's 30 KB of flash.)
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S>
struct Checks {
  typedef World<S, 2, 3, 1, 2, 3> W;
  typedef typename W::Vec V;

  // Three balls of radius 0.1 m stacked on a floor under gravity, released
  // 1 mm apart, restitution 0.3; `cap` is the resolver's iteration cap (0:
  // the default). Over the last second of 3 s, returns the largest height
  // error of a ball centre against its ideal place (0.1, 0.3, 0.5 m); `jitter`
  // gets the largest height range of a ball and `fastest` the largest speed.
  static float stack(uint8_t cap, float* jitter, float* fastest) {
    W w;
    V up(0.0, 1.0);
    w.addPlane(up, S(0), S(0.3));
    w.addCollisions(S(0.3));
    w.addGravity();
    w.setIterationCap(cap);
    for (uint8_t i = 0; i < 3; ++i) {
      V where(0.0, 0.101 + 0.201 * i);
      w.addParticle(where, S(1), S(0.1));
    }
    float worst = 0, low[3], high[3];
    *fastest = 0;
    for (uint16_t step = 0; step < 3 * 256; ++step) {
      w.step(S(1.0 / 256));
      if (step < 2 * 256) continue;
      for (uint8_t i = 0; i < 3; ++i) {
        const typename W::ParticleType& p = w.particleAt(i);
        float y = p.position.y.toFloat();
        float error = fabs(y - (0.1f + 0.2f * i));
        if (error > worst) worst = error;
        if (step == 2 * 256 || y < low[i]) low[i] = y;
        if (step == 2 * 256 || y > high[i]) high[i] = y;
        float speed = p.velocity.magnitude().toFloat();
        if (speed > *fastest) *fastest = speed;
      }
    }
    *jitter = 0;
    for (uint8_t i = 0; i < 3; ++i) {
      if (high[i] - low[i] > *jitter) *jitter = high[i] - low[i];
    }
    return worst;
  }
};

// A resting stack neither sinks nor jitters: each ball stays within 1 mm of
// its ideal height, its height varies by less than 1 mm, and it is still
// (1 mm/s) with the default iteration cap. (Without the resolver's shock
// propagation, a chain of equal masses on the floor passes each correction
// down and up again, halving it each time, and is still moving when the
// cap of 2 iterations per contact runs out.)
test(RestingStack_Float) {
  float jitter, fastest;
  assertLessOrEqual(Checks<Float>::stack(0, &jitter, &fastest), 0.001f);
  assertLessOrEqual(jitter, 0.001f);
  assertLessOrEqual(fastest, 0.001f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
