// NewtonsCradle: five steel-like balls hang side by side on rods; the first
// is pulled out to 60 degrees and let go. It hits the row and stops, the
// last ball flies out to (almost) the same height, falls back, and the
// first one leaves again: the momentum crosses the row, the middle balls
// hardly move.
//
// Hardware: an Arduino Nano (or Uno) and its USB cable, nothing else. Open
// the Serial monitor at 115200 baud. You see an ASCII drawing of the cradle
// (rods '.', balls 'O') four times a second, and whenever an end ball
// reaches the top of its swing a line with its height (the first starts at
// 250 mm) and the largest move of the middle balls so far, in millimetres.
// After 6 s of simulated time it prints a summary and sleeps (in simavr
// that ends the run). Each swing loses a little: the impacts are a chain of
// pairs a step apart, not a single instant.
//
// What it shows: collisions with restitution 1 between equal masses pass
// the velocity on exactly (Contacts/Resolver.hpp), rods keep the balls on
// their circles (Contacts/RodSolver.hpp), and the real-time loop steps at
// 1/256 s while the drawing goes out a line at a time.
#include <TinyParticle.h>
#include <avr/sleep.h>

// Scenes/Cradle.hpp: 5 balls (r = 5 cm) on 0.5 m rods from posts 0.1 m
// apart at y = 0.8 m, gravity, collisions with restitution 1.
typedef CradleWorld<Q16_16> World2;
World2 world;

// 36 x 14 characters over x from -0.2 to 1.2 m and y from 0.2 to 0.9 m.
AsciiRenderer<World2, 36, 14> renderer(Q16_16(-0.2), Q16_16(0.2),
                                       Q16_16(0.04), Q16_16(0.05));
RealTimeLoop timing(256, 4);  // 256 steps per second, 4 frames per second

const Q16_16 kDt(1.0 / 256);
const uint32_t kRunSteps = 6 * 256UL;  // 6 s of simulated time
const float kRest = 0.8f - 0.5f;       // the balls' height at rest (m)
float middleMove = 0;                   // largest move of balls 2 to 4 (m)
bool rising[5];                         // moving up in the last step
bool drawing = false;

// An end ball whose upward motion has just stopped, well above rest: the
// top of its swing.
void track() {
  for (uint8_t k = 0; k < 5; ++k) {
    const World2::ParticleType& p = world.particleAt(k);
    const float h = p.position.y.toFloat() - kRest;
    if (k >= 1 && k <= 3) {
      const float dx = p.position.x.toFloat() - (0.3f + 0.1f * k);
      const float d = sqrt(dx * dx + h * h);
      if (d > middleMove) middleMove = d;
      continue;
    }
    const bool up = p.velocity.y > Q16_16(0);
    if (rising[k] && !up && h > 0.02f) {
      Serial.print(F("t="));
      Serial.print(timing.steps() / 256.0, 2);
      Serial.print(k == 0 ? F(" s  first") : F(" s  last"));
      Serial.print(F(" ball at the top: "));
      Serial.print(h * 1000, 0);
      Serial.print(F(" mm; middle balls moved at most "));
      Serial.print(middleMove * 1000, 1);
      Serial.println(F(" mm"));
    }
    rising[k] = up;
  }
}

void setup() {
  Serial.begin(115200);
  while (!Serial);
  Serial.println(F("NewtonsCradle: 5 balls, Q16.16, dt = 1/256 s"));
  buildCradle(world);
  Serial.print(F("first ball raised "));
  Serial.print((world.particleAt(0).position.y.toFloat() - kRest) * 1000, 0);
  Serial.println(F(" mm"));
}

void loop() {
  for (uint8_t n = timing.stepsDue(); n > 0; --n) {
    world.step(kDt);
    track();
  }
  if (!drawing && timing.frameDue()) drawing = true;
  while (drawing && Serial.availableForWrite() >= renderer.lineLength()) {
    if (renderer.drawLine(world, Serial)) drawing = false;
  }

  if (timing.steps() >= kRunSteps && !drawing) {
    Serial.print(F("Done: "));
    Serial.print(timing.steps());
    Serial.print(F(" steps, "));
    Serial.print(timing.slippedSteps());
    Serial.print(F(" skipped to keep up, world errors "));
    Serial.println(world.error());
    Serial.flush();
    cli();
    sleep_enable();
    sleep_cpu();
  }
}
