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
typedef Q16_16 S;
typedef CradleWorld<S> World2;
World2 world;

// 36 x 14 characters over x from -0.2 to 1.2 m and y from 0.2 to 0.9 m.
// Rods and no spring: only rods and cables are drawn (no code for the
// force slots linked).
AsciiRenderer<World2, 36, 14, ParticleShape::kCircles,
              LinkShape::kRodsAndCables>
    renderer(S(-0.2), S(0.2), S(0.04), S(0.05));
RealTimeLoop timing(256, 4);  // 256 steps per second, 4 frames per second

const S kDt(1.0 / 256);
const uint32_t kRunSteps = 6 * 256UL;  // 6 s of simulated time
const S kRest(0.8 - 0.5);              // the balls' height at rest (m)
S middleMove;                          // largest move of balls 2 to 4 (m)
bool rising[5];                        // moving up in the last step
bool drawing = false;

// A length in m printed in mm, with `decimals` decimals. (Fixed-point
// arithmetic and printing only: the sketch links no float routine.)
void printMillimetres(S metres, uint8_t decimals) {
  print(Serial, metres * S(1000), decimals);
}

// An end ball whose upward motion has just stopped, well above rest: the
// top of its swing.
void track() {
  for (uint8_t k = 0; k < 5; ++k) {
    const World2::ParticleType& p = world.particleAt(k);
    const S h = p.position.y - kRest;
    if (k >= 1 && k <= 3) {
      const Vec2<S> offset(p.position.x - (S(0.3) + S(0.1) * S(int(k))), h);
      const S d = offset.magnitude();
      if (d > middleMove) middleMove = d;
      continue;
    }
    const bool up = p.velocity.y > S(0);
    if (rising[k] && !up && h > S(0.02)) {
      Serial.print(F("t="));
      // steps / 256 s: the raw steps as the integer part's fraction bits.
      print(Serial, S::fromRaw(int32_t(timing.steps() << 8)), 2);
      Serial.print(k == 0 ? F(" s  first") : F(" s  last"));
      Serial.print(F(" ball at the top: "));
      printMillimetres(h, 0);
      Serial.print(F(" mm; middle balls moved at most "));
      printMillimetres(middleMove, 1);
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
  printMillimetres(world.particleAt(0).position.y - kRest, 0);
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
