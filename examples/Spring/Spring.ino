// Spring: a 1 kg mass on a spring (k = 100 N/m) released 0.1 m from its
// rest length, with no gravity, so it oscillates with period 0.628 s. The
// sketch runs it twice, with Hooke's spring and with the stiff spring (the
// damped-oscillator form that stays stable however stiff), and prints both
// beside the exact solution x(t) = 0.1 cos(10 t) for 2 simulated seconds.
// Then it repeats with k = 20000 N/m at a coarse dt = 1/64 s, where Hooke's
// spring blows up and the stiff spring does not.
//
// It shows the spring scene builder, addStiffSpring(), changing a force's
// parameters through its slot, and mathErrors() for what overflowed.
//
// Hardware: any Arduino (a Nano here), nothing wired; Serial Monitor at
// 115200 baud. On the PC: `make demo DEMO=examples/Spring`.
//
// What you should see: two tables of time, Hooke's spring, the stiff
// spring and the exact solution (m from the rest length). In the first all
// three agree to about a millimetre; in the second Hooke's column grows
// to metres, swinging wider step after step (Q16.16 overflows on the way,
// and the sketch says so), while the stiff spring's column follows the
// exact one.
#include <TinyParticle.h>
#include <avr/sleep.h>

typedef Q16_16 S;
typedef SpringWorld<S, 2> OneSpring;  // 1 particle, 1 force

// x - rest length of the mass in `world`.
float offset(OneSpring& world) {
  return world.particleAt(0).position.x.toFloat() - 0.5f;
}

void run(S k, uint16_t stepsPerSecond, float seconds, uint8_t printEvery) {
  OneSpring hooke, stiff;
  // 1 kg, k = 100 N/m, rest 0.5 m, released at 0.6 m; then the stiffness
  // is changed through the force's slot.
  SpringScene scene = buildSpring(hooke);
  hooke.forceParams<AnchoredSpringForce<S, 2> >(scene.spring)->stiffness = k;
  ParticleId mass = stiff.addParticle(Vec2<S>(0.6, 0.0), S(1));
  const S dt = S(1) / S(int(stepsPerSecond));
  stiff.addStiffSpring(mass, Vec2<S>(0.5, 0.0), k, S(0), dt);

  // The exact motion through the stiff spring's first two positions:
  // x(t) = 0.1 cos(w t) + q sin(w t). (For small w dt, q is about 0.)
  const float omega = sqrt(k.toFloat());
  const float h = 1.0f / stepsPerSecond;
  float q = 0;
  Serial.println(F("t (s)    Hooke      stiff      exact"));
  clearMathErrors();
  const uint16_t steps = uint16_t(seconds * stepsPerSecond);
  for (uint16_t i = 0; i <= steps; ++i) {
    if (i == 1) q = (offset(stiff) - 0.1f * cos(omega * h)) / sin(omega * h);
    if (i % printEvery == 0) {
      float t = i * h;
      Serial.print(t, 3);
      Serial.print(F("   "));
      Serial.print(offset(hooke), 5);
      Serial.print(F("   "));
      Serial.print(offset(stiff), 5);
      Serial.print(F("   "));
      Serial.println(0.1f * cos(omega * t) + q * sin(omega * t), 5);
    }
    hooke.step(dt);
    stiff.step(dt);
  }
  if (mathErrors() & MathError::kOverflow) {
    Serial.println(F("(Hooke's spring overflowed Q16.16: it saturated.)"));
  }
}

void setup() {
  Serial.begin(115200);
  while (!Serial);
  Serial.println(F("k = 100 N/m, dt = 1/256 s: both follow the exact curve"));
  run(S(100), 256, 2.0f, 16);
  Serial.println();
  Serial.println(F("k = 20000 N/m, dt = 1/64 s (w dt = 2.2 > 2): Hooke's"));
  Serial.println(F("spring grows without bound; the stiff one stays on an"));
  Serial.println(F("exact oscillation of the right frequency (the one through"));
  Serial.println(F("its first step: at such a dt the first step sets the phase)."));
  run(S(20000), 64, 0.25f, 1);
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
}

void loop() {}
