// Projectile: a 0.1 kg ball thrown at (4, 6) m/s against linear air drag
// (a force of 0.05 N s/m times the velocity, against it), beside the exact
// trajectory of that motion:
//   x(t) = (vx / k) (1 - e^-kt),
//   y(t) = ((vy + g / k) / k) (1 - e^-kt) - g t / k,   k = 0.05 / 0.1 = 0.5/s.
// It flies twice, with steps of 1/256 s and of 1/1024 s. The engine's
// integrator (semi-implicit Euler) is first order: its error grows with t
// and is proportional to dt, about g t dt / 2 (the rounding of Q16.16 adds
// a little, more with more steps).
//
// Hardware: any Arduino (a Nano here), nothing wired; Serial Monitor at
// 115200 baud, or `make demo DEMO=examples/Projectile` on the PC.
//
// What you should see: for each flight, every 0.125 s, the time, the
// simulated and the exact position (m) and their distance in millimetres,
// until the ball comes back down to its start height. The error grows
// along the flight, to a few centimetres with the longer step and several
// times less with the shorter one.
#include <TinyParticle.h>
#include <avr/sleep.h>
#include <math.h>

typedef Q16_16 S;
typedef Vec2<S> V;
typedef World<S, 2, 1, 1> ProjectileWorld;  // 1 ball; drag (gravity takes no slot)

const float kMass = 0.1f;         // kg
const float kDrag = 0.05f;        // N s/m
const float kThrowX = 4.0f;       // m/s
const float kThrowY = 6.0f;       // m/s
const float kG = 9.81f;           // m/s^2

// The exact position at time t (s), in float.
V exact(float t) {
  const float k = kDrag / kMass;
  const float rise = 1.0f - exp(-k * t);
  return V(S(kThrowX / k * rise),
           S((kThrowY + kG / k) / k * rise - kG * t / k));
}

void fly(uint16_t stepsPerSecond) {
  ProjectileWorld world;
  const ParticleId ball = world.addParticle(V(), S(kMass));
  world.particle(ball)->velocity = V(S(kThrowX), S(kThrowY));
  world.addGravity();
  world.addDrag(ball, S(kDrag), S(0));
  const S dt = S(1) / S(int(stepsPerSecond));

  Serial.print(F("dt = 1/"));
  Serial.print(stepsPerSecond);
  Serial.println(F(" s"));
  Serial.println(F("t (s)   simulated (m)       exact (m)           error (mm)"));
  const uint16_t printEvery = stepsPerSecond / 8;
  for (uint16_t i = 0;; ++i) {
    const V& at = world.particle(ball)->position;
    const bool landed = i > 0 && at.y < S();
    if (i % printEvery == 0 || landed) {
      const float t = float(i) / stepsPerSecond;
      const V expected = exact(t);
      print(Serial, Float(t), 3);
      Serial.print(F("   "));
      print(Serial, at, 4);
      Serial.print(F("   "));
      print(Serial, expected, 4);
      Serial.print(F("   "));
      println(Serial, (at - expected).magnitude() * S(1000), 2);
    }
    if (landed) break;
    world.step(dt);
  }
}

void setup() {
  Serial.begin(115200);
  while (!Serial);
  fly(256);
  Serial.println();
  fly(1024);
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
}

void loop() {}
