// Pendulum: a 1 kg bob on a 1 m rod, released at 0.5 rad. The whole scene
// is the first dozen lines below; the sketch then prints its angle and the
// small-angle theory's angle ten times a second, and draws it now and then,
// for 10 simulated seconds.
//
// It shows a World sized for the scene, a fixed pivot, a rod, gravity for
// one particle, and world.step() at a fixed dt.
//
// Hardware: any Arduino (a Nano here), nothing wired; Serial Monitor at
// 115200 baud. On the PC: `make demo DEMO=examples/Pendulum`.
//
// What you should see: a table of time, angle and the small-angle theory's
// angle, the two swinging between about -0.5 and 0.5 rad and slowly
// drifting apart (the theory is for small swings), with an ASCII picture
// of the pendulum every 2.5 s.
#include <TinyParticle.h>
#include <avr/sleep.h>

typedef Q16_16 S;               // the scalar: Q16_16, Q24_8 or Float
World<S, 2, 2, 0, 1, 0> world;  // 2D; 2 particles, no force slot, 1 rod, no contacts
ParticleId bob;

void setupPendulum() {
  ParticleId pivot = world.addFixedParticle(Vec2<S>(0.0, 0.0));
  // 1 kg at (sin 0.5, -cos 0.5): 1 m from the pivot, 0.5 rad out.
  bob = world.addParticle(Vec2<S>(0.479426, -0.877583), S(1), S(0.05));
  world.addRod(bob, pivot, S(1));
  world.addGravity();  // the world's gravity: the pivot is fixed, the bob falls
}

// A rod and no spring: only rods and cables are drawn, and the renderer
// links no code for the force slots.
AsciiRenderer<World<S, 2, 2, 0, 1, 0>, 41, 12, ParticleShape::kCircles,
              LinkShape::kRodsAndCables>
    renderer(S(-1.025), S(-1.1), S(0.05), S(0.1));

void setup() {
  Serial.begin(115200);
  while (!Serial);
  setupPendulum();
  Serial.println(F("t (s)  angle (rad)  small-angle theory"));
  const uint16_t kStepsPerSecond = 256;
  const S dt(1.0 / kStepsPerSecond);  // exact: 1/256 s, folded at compile time
  const float omega = sqrt(9.81f / 1.0f);
  for (uint16_t i = 0; i <= 10 * kStepsPerSecond; ++i) {
    if (i % (kStepsPerSecond / 10) == 0) {  // about ten times a second
      const Vec2<S>& p = world.particle(bob)->position;
      float angle = atan2(p.x, -p.y).toFloat();
      float t = float(i) / kStepsPerSecond;
      Serial.print(t, 2);
      Serial.print(F("   "));
      Serial.print(angle, 4);
      Serial.print(F("   "));
      Serial.println(0.5f * cos(omega * t), 4);
    }
    if (i % (kStepsPerSecond * 5 / 2) == 0) {  // every 2.5 s
      renderer.draw(world, Serial);
    }
    world.step(dt);
  }
  Serial.println(F("(The theory is for small swings: at 0.5 rad the real"));
  Serial.println(F(" period is 1.6 % longer, so the two drift apart.)"));
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
}

void loop() {}
