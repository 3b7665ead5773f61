// DoublePendulum: chaos. Two double pendulums (0.5 m arms, 1 kg bobs)
// start from the same place, except that one lower bob sits one unit of
// Q16.16 (2^-16 m, 15 micrometres) further right. Both are stepped alike;
// the difference grows about exponentially until the two swing in unrelated
// ways. The engine keeps each arm's length and each pendulum's energy; what
// it cannot keep is the future of a chaotic system from a tiny error.
//
// Hardware: any Arduino (a Nano here), nothing wired; Serial Monitor at
// 115200 baud. On the PC: `make demo DEMO=examples/DoublePendulum
// DEMO_SECONDS=30` (20 simulated seconds; the simulator needs more than the
// default 8 s of wall time for them).
//
// What you should see: every quarter second the time, each lower bob's
// position and their distance in metres. The distance starts at 0.00002
// (2^-16), stays below a millimetre for the first seconds, then grows to
// tenths of a metre: from there the two pendulums are unrelated. The last
// line gives when the distance first passed 1 cm.
#include <TinyParticle.h>
#include <avr/sleep.h>

typedef Q16_16 S;
typedef Vec2<S> V;
// Pivot and two bobs; gravity (no force slot); two rods (rods need no
// contact slot).
typedef World<S, 2, 3, 0, 2, 0> PendulumWorld2;
PendulumWorld2 worldA, worldB;
ParticleId lowerA, lowerB;

// The pivot at the origin, the upper bob level with it, the lower bob
// straight above the upper one (a start with plenty of energy), moved right
// by `nudge` units of the scalar.
ParticleId build(PendulumWorld2& world, int32_t nudge) {
  const ParticleId pivot = world.addFixedParticle(V());
  const ParticleId upper = world.addParticle(V(0.5, 0.0), S(1));
  V lowerAt(0.5, 0.5);
  lowerAt.x += S::fromRaw(nudge);
  const ParticleId lower = world.addParticle(lowerAt, S(1));
  world.addRod(upper, pivot, S(0.5));
  world.addRod(lower, upper, S(0.5));
  world.addGravity();
  return lower;
}

void setup() {
  Serial.begin(115200);
  while (!Serial);
  Serial.println(F("Two double pendulums, 2^-16 m apart at the start"));
  Serial.println(F("t (s)  lower bob A  lower bob B  distance (m)"));
  lowerA = build(worldA, 0);
  lowerB = build(worldB, 1);

  const uint16_t kStepsPerSecond = 256;
  const S dt(1.0 / kStepsPerSecond);  // exact: 1/256 s, folded at compile time
  S firstCentimetre;  // 0 until the distance passes 1 cm
  for (uint16_t i = 0; i <= 20 * kStepsPerSecond; ++i) {
    const V& a = worldA.particle(lowerA)->position;
    const V& b = worldB.particle(lowerB)->position;
    const S distance = (a - b).magnitude();
    const S t = S::fromRaw(int32_t(i) * 256);  // i / 256 s, exactly
    if (firstCentimetre == S() && distance > S(0.01)) firstCentimetre = t;
    if (i % (kStepsPerSecond / 4) == 0) {
      print(Serial, t, 2);
      Serial.print(F("  "));
      print(Serial, a, 3);
      Serial.print(F("  "));
      print(Serial, b, 3);
      Serial.print(F("  "));
      println(Serial, distance);
    }
    worldA.step(dt);
    worldB.step(dt);
  }
  Serial.print(F("The bobs were first 1 cm apart at t = "));
  print(Serial, firstCentimetre, 2);
  Serial.println(F(" s"));
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
}

void loop() {}
