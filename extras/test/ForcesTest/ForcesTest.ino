// Force generators against their physics: spring periods (anchored and
// between two particles), a bungee's slack, buoyancy's floating depth (with
// particle damping), and drag's terminal velocity.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S>
struct Checks {
  // One world type per scalar (each type instantiates the engine again).
  typedef World<S, 2, 2, 2> W;
  typedef typename W::Vec V;

  // Time between the first and the third upward zero crossing of f(t),
  // sampled every dt; the crossings are interpolated linearly.
  struct Crossings {
    float previous, first, last, dt;
    uint16_t step;
    uint8_t count;
    Crossings(float start, float dt_)
        : previous(start), first(0), last(0), dt(dt_), step(0), count(0) {}
    void add(float f) {
      ++step;
      if (previous < 0 && f >= 0 && count < 3) {
        float t = step * dt - dt * f / (f - previous);
        if (count == 0) first = t;
        last = t;
        ++count;
      }
      previous = f;
    }
    float period() const { return count == 3 ? (last - first) / 2 : -1; }
  };

  // The spring scene (1 kg, k = 100 N/m, 0.1 m from rest) at dt = 1/1024.
  static float springPeriod() {
    SpringWorld<S, 2> w;
    SpringScene scene = buildSpring(w);
    Crossings c(0.1f, 1.0f / 1024);
    for (uint16_t i = 0; i < 2 * 1024; ++i) {
      w.step(S(1.0 / 1024));
      c.add(w.particle(scene.mass)->position.x.toFloat() - 0.5f);
    }
    return c.period();
  }

  // Two masses (1 kg and 3 kg) on a spring k = 30 N/m, rest 0.5 m,
  // stretched to 0.6 m, no gravity. Returns the period of the separation;
  // `drift` gets how far the centre of mass moved (it must stay put).
  static float pairPeriod(float* drift) {
    W w;
    V left(0.0, 0.0), right(0.6, 0.0);
    ParticleId a = w.addParticle(left, S(1));
    ParticleId b = w.addParticle(right, S(3));
    w.addSpring(a, b, S(30), S(0.5));
    // The masses the scalar holds (1/3 is not exact in Q16.16): momentum is
    // conserved for those.
    const float ma = 1 / w.particle(a)->inverseMass.toFloat();
    const float mb = 1 / w.particle(b)->inverseMass.toFloat();
    const float start = 0.6f * mb / (ma + mb);
    Crossings c(0.1f, 1.0f / 1024);
    *drift = 0;
    for (uint16_t i = 0; i < 3 * 1024; ++i) {
      w.step(S(1.0 / 1024));
      float xa = w.particle(a)->position.x.toFloat();
      float xb = w.particle(b)->position.x.toFloat();
      c.add(xb - xa - 0.5f);
      float centre = (ma * xa + mb * xb) / (ma + mb) - start;
      if (fabs(centre) > *drift) *drift = fabs(centre);
    }
    return c.period();
  }

  // A bungee (k = 50 N/m, rest 1 m) to an anchor. A particle 0.5 m from the
  // anchor, at rest, no gravity, stays put for 1 s (returns how far it
  // moved); `pull` gets the speed gained in one step from 1.5 m: the force
  // is 50 * 0.5 = 25 N on 1 kg, so v = 25 / 256 m/s towards the anchor.
  static float bungee(float* pull) {
    W w;
    V anchor, near(0.5, 0.0), far(0.0, -1.5);
    ParticleId slack = w.addParticle(near, S(1));
    ParticleId taut = w.addParticle(far, S(1));
    w.addBungee(slack, anchor, S(50), S(1));
    w.addBungee(taut, anchor, S(50), S(1));
    w.step(S(1.0 / 256));
    *pull = w.particle(taut)->velocity.y.toFloat();
    for (uint16_t i = 1; i < 256; ++i) w.step(S(1.0 / 256));
    return fabs(w.particle(slack)->position.x.toFloat() - 0.5f);
  }

  // A 0.3 kg body (volume 1 litre, half-height 0.05 m) dropped into water
  // (surface y = 0) from y = 0.3 m, with damping 2/s. At rest the lift
  // 1000 * 0.001 * 9.81 * f equals the weight 0.3 * 9.81, so the submerged
  // fraction f = 0.3 and the centre rests at 0.05 - 0.1 * 0.3 = 0.02 m.
  // Returns y after 10 s; `speed` gets |v|.
  static float floating(float* speed) {
    W w;
    V start(0.0, 0.3);
    ParticleId body = w.addParticle(start, S(0.3), S(0.05));
    w.particle(body)->setDampingRate(S(2));
    w.addGravity();
    w.addBuoyancy(body, S(0), S(0.05), S(0.001), S(1000));
    for (uint16_t i = 0; i < 10 * 256; ++i) w.step(S(1.0 / 256));
    *speed = w.particle(body)->velocity.magnitude().toFloat();
    return w.particle(body)->position.y.toFloat();
  }

  // A 1 kg particle falls with drag k1 = 0.5, k2 = 0.1 for 10 s (20 time
  // constants). Returns its speed.
  static float terminal() {
    W w;
    V start(0.0, 100.0);
    ParticleId p = w.addParticle(start, S(1));
    w.addGravity();
    w.addDrag(S(0.5), S(0.1));
    for (uint16_t i = 0; i < 10 * 256; ++i) w.step(S(1.0 / 256));
    return -w.particle(p)->velocity.y.toFloat();
  }
};

static const float kPi = 3.14159265f;

// T = 2 pi sqrt(m / k) = 0.62832 s. Semi-implicit Euler shifts the period
// by (w dt)^2 / 24 = 4e-6 at dt = 1/1024; 0.2 % leaves room for rounding.
test(SpringPeriod_Q16_16) {
  TestRunner::setTimeout(0);
  const float expected = 2 * kPi * sqrt(1.0f / 100);
  assertNear(Checks<Q16_16>::springPeriod(), expected, 0.002f * expected);
}
test(SpringPeriod_Float) {
  TestRunner::setTimeout(0);
  const float expected = 2 * kPi * sqrt(1.0f / 100);
  assertNear(Checks<Float>::springPeriod(), expected, 0.002f * expected);
}

// Two bodies: T = 2 pi sqrt(mu / k) with mu = 1 * 3 / (1 + 3) = 0.75 kg,
// 0.99346 s. The spring's forces are equal and opposite, so the centre of
// mass stays put up to rounding: each step rounds every velocity and
// position by up to u / 2, a random walk whose spread after n = 3072 steps
// is about u (dt n^1.5 / 4 + sqrt(n) / 3.5), 0.4 mm for Q16.16 (u = 2^-16)
// and far less for float. Five times that: 2 mm and 0.02 mm. (A missing
// reaction force would move it by centimetres.)
test(SpringPair_Q16_16) {
  TestRunner::setTimeout(0);
  float drift;
  const float expected = 2 * kPi * sqrt(0.75f / 30);
  assertNear(Checks<Q16_16>::pairPeriod(&drift), expected, 0.002f * expected);
  assertLessOrEqual(drift, 0.002f);
}
test(SpringPair_Float) {
  TestRunner::setTimeout(0);
  float drift;
  const float expected = 2 * kPi * sqrt(0.75f / 30);
  assertNear(Checks<Float>::pairPeriod(&drift), expected, 0.002f * expected);
  assertLessOrEqual(drift, 0.00002f);
}

test(BungeeSlack_Q16_16) {
  float pull;
  assertEqual(Checks<Q16_16>::bungee(&pull), 0.0f);
  assertNear(pull, 25.0f / 256, 1.0f / 65536);
}
test(BungeeSlack_Float) {
  float pull;
  assertEqual(Checks<Float>::bungee(&pull), 0.0f);
  assertNear(pull, 25.0f / 256, 1e-6f);
}

// Damped at 2/s, the bob's motion (w = 18 rad/s) decays as exp(-t): after
// 10 s, 0.3 m becomes 14 um. Within 1 mm and 1 mm/s.
test(BuoyancyFloats_Q16_16) {
  TestRunner::setTimeout(0);
  float speed;
  assertNear(Checks<Q16_16>::floating(&speed), 0.02f, 0.001f);
  assertLessOrEqual(speed, 0.001f);
}
test(BuoyancyFloats_Float) {
  TestRunner::setTimeout(0);
  float speed;
  assertNear(Checks<Float>::floating(&speed), 0.02f, 0.001f);
  assertLessOrEqual(speed, 0.001f);
}

// Buoyancy's set-up in Q16.16 is fixed point (no float routine): 1 / (2
// depth) within 1 step of the exact value of its (rounded) input, and the
// full force density * volume * 9.81 within half a step per rounding: when
// density * 9.81 is formed first, 0.5 |volume| + 0.5 steps; when density *
// volume is (density above 3276 kg/m^3), 0.5 * 9.81 + 0.5; plus 9.81's own
// rounding in Q16.16, 2.5e-7 of the force. Each compared with the exact
// value for the rounded inputs, computed in float: the bound adds float's
// own errors (6e-8 of the value per rounding, the result's conversion to
// float included). No flag is raised.
test(BuoyancySetUpIsFixedPoint_Q16_16) {
  typedef Q16_16 S;
  typedef BuoyancyForce<S, 2> B;
  static const float kCases[][4] = {
      // half-height, volume, density, bound in steps for the force
      {0.05f, 0.001f, 1000.0f, 0.51f},   // ForcesTest's body in water
      {0.03f, 0.0001f, 1000.0f, 0.51f},  // the memory ladder's
      {0.01f, 0.0001f, 13534.0f, 5.41f}, // mercury: the other order
      {2.0f, 0.5f, 1.2f, 0.75f},         // a balloon in air
      {0.001f, 3.0f, -800.0f, 2.0f}};    // a negative density
  const float step = 1.0f / 65536;
  for (uint8_t i = 0; i < sizeof(kCases) / sizeof(kCases[0]); ++i) {
    const S depth(kCases[i][0]), volume(kCases[i][1]), density(kCases[i][2]);
    B b;
    clearMathErrors();
    assertTrue(B::make(b, S(0), depth, volume, density));
    assertEqual(mathErrors(), (uint8_t) 0);
    const float inverse = 0.5f / depth.toFloat();
    assertNear(b.invTwiceDepth.toFloat(), inverse,
               step + fabs(inverse) * 1.2e-7f);
    const float force = density.toFloat() * volume.toFloat() * 9.81f;
    assertNear(b.fullForce.toFloat(), force,
               kCases[i][3] * step + fabs(force) * (2.5e-7f + 1.8e-7f));
  }
}

// k1 v + k2 v^2 = m g: v = (-k1 + sqrt(k1^2 + 4 k2 m g)) / (2 k2) = 7.7154
// m/s. The step's fixed point is exactly that speed; 0.1 %.
test(DragTerminalVelocity_Q16_16) {
  TestRunner::setTimeout(0);
  const float expected = (-0.5f + sqrt(0.25f + 4 * 0.1f * 9.81f)) / 0.2f;
  assertNear(Checks<Q16_16>::terminal(), expected, 0.001f * expected);
}
test(DragTerminalVelocity_Float) {
  TestRunner::setTimeout(0);
  const float expected = (-0.5f + sqrt(0.25f + 4 * 0.1f * 9.81f)) / 0.2f;
  assertNear(Checks<Float>::terminal(), expected, 0.001f * expected);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
