// Collisions and contacts with restitution: an elastic head-on collision,
// and a ball dropped on the floor (rebound height, then rest).
// (Q16.16 here; CollisionFloatTest runs the same checks with Float: the two
// scalars together no longer fit in the Nano's 30 KB of flash.)
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S>
struct Checks {
  // One world type per scalar (each type instantiates the engine again).
  typedef World<S, 2, 2, 1, 1, 2> W;
  typedef typename W::Vec V;

  // Two 1 kg balls (radius 0.05 m) meet head-on at +1 and -0.5 m/s with
  // restitution 1 and no gravity. Returns their velocities after 1 s.
  static void headOn(float* v1, float* v2, float* sideways) {
    W w;
    V left(0.2, 0.5), right(0.8, 0.5);
    ParticleId a = w.addParticle(left, S(1), S(0.05));
    ParticleId b = w.addParticle(right, S(1), S(0.05));
    w.particle(a)->velocity.x = S(1);
    w.particle(b)->velocity.x = S(-0.5);
    w.addCollisions(S(1));
    for (uint16_t i = 0; i < 256; ++i) w.step(S(1.0 / 256));
    *v1 = w.particle(a)->velocity.x.toFloat();
    *v2 = w.particle(b)->velocity.x.toFloat();
    *sideways = fabs(w.particle(a)->velocity.y.toFloat()) +
                fabs(w.particle(b)->velocity.y.toFloat());
  }

  // A ball whose bottom starts 1 m above a floor with restitution 0.5,
  // dt = 1/1024 s. Reports the highest bottom height between the first and
  // the second impact, and over the last 2 s of 10 s the lowest bottom
  // height, the highest one and the largest speed.
  static float drop(float* lowest, float* highest, float* fastest) {
    W w;
    const float radius = 0.05f;
    V start(0.0, 1.05);
    ParticleId ball = w.addParticle(start, S(1), S(radius));
    w.addGravity();
    V up(0.0, 1.0);
    w.addPlane(up, S(0), S(0.5));
    float rebound = 0;
    uint8_t impacts = 0;
    bool falling = true;
    *lowest = 10;
    *highest = -10;
    *fastest = 0;
    for (uint16_t i = 0; i < 10 * 1024; ++i) {
      w.step(S(1.0 / 1024));
      const typename W::ParticleType* p = w.particle(ball);
      float bottom = p->position.y.toFloat() - radius;
      float v = p->velocity.y.toFloat();
      if (falling && v > 0) {
        ++impacts;  // the velocity turned upwards: an impact
        falling = false;
      } else if (!falling && v < 0) {
        falling = true;
      }
      if (impacts == 1 && bottom > rebound) rebound = bottom;
      if (i >= 8 * 1024) {
        if (bottom < *lowest) *lowest = bottom;
        if (bottom > *highest) *highest = bottom;
        if (fabs(v) > *fastest) *fastest = fabs(v);
      }
    }
    return rebound;
  }

};

// Equal masses, restitution 1: the velocities swap, and momentum
// (1 * 1 + 1 * -0.5 = 0.5 kg m/s) is kept within 0.1 % of the momentum
// that flows through the collision (1.5 kg m/s exchanged).
test(ElasticHeadOn_Q16_16) {
  float v1, v2, sideways;
  Checks<Q16_16>::headOn(&v1, &v2, &sideways);
  assertNear(v1, -0.5f, 0.0015f);
  assertNear(v2, 1.0f, 0.0015f);
  assertNear(v1 + v2, 0.5f, 0.0015f);
  assertEqual(sideways, 0.0f);
}

// Restitution 0.5 halves the speed, so the rebound reaches 0.25 of the drop
// height; within 5 % of that. Then the ball rests: it sinks no more than
// 1 mm, does not hop (1 mm), and is still (1 mm/s).
test(DropRebound_Q16_16) {
  TestRunner::setTimeout(0);
  float lowest, highest, fastest;
  float rebound = Checks<Q16_16>::drop(&lowest, &highest, &fastest);
  assertNear(rebound, 0.25f, 0.05f * 0.25f);
  assertMoreOrEqual(lowest, -0.001f);
  assertLessOrEqual(highest, 0.001f);
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
