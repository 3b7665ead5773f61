// BouncingBalls: 16 balls in a 1 m box, bouncing off the walls and each
// other (restitution 0.8) under gravity, drawn as ASCII frames on the Serial
// monitor (115200 baud) for a few seconds.
//
// It shows the real-time loop (fixed 1/128 s steps that keep up with the
// clock, frames at 8 per second), the renderer drawing one line at a time
// only when the serial buffer has room (the physics never waits for the
// serial line), and the engine's statistics. After 6 s of simulated time it
// prints a summary and sleeps; in simavr that ends the run. (The benchmark
// runs this scene at 1/256 s; a Nano cannot do 256 steps of 16 balls a
// second, so the real-time loop would let time slip. At 1/128 s the speed
// limit of these 3 cm balls is 3.84 m/s, Contacts/Collisions.hpp: balls
// falling from the top row stay just under it.) It leaves sleeping off
// (World::enableSleeping() would link about 700 bytes more): the balls
// settle on the floor and stay still without it, and the Nano keeps up.
//
// Hardware: any Arduino with 2 KB of RAM or more (a Nano here), nothing
// wired. On the PC it is `make demo`.
//
// What you should see: a 40 x 20 box of 'O's (one per ball) that fall,
// bounce off the floor, the walls and each other, and settle along the
// bottom; under each frame the time and the contacts and resolver
// iterations of the last step; at the end one summary line.
#include <TinyParticle.h>
#include <avr/sleep.h>

// The box of balls (Scenes/BouncingBalls.hpp) in Q16.16, 2D: 16 balls,
// gravity (no force slot), 4 walls and the collisions, 24 contacts (the benchmark uses
// 32; 24 keep this sketch within the Nano's RAM with Serial's buffers).
typedef BallsWorld<Q16_16, 2, 16, 24> BoxWorld;
BoxWorld world;

// 40 x 20 characters over the 1 m x 1 m box. Each ball is one 'O' at its
// centre (ParticleShape::kPoints; filled circles, 2-3 characters wide,
// would link about 550 bytes more), and there is no spring or rod to draw,
// so none of the line code is linked (LinkShape::kNone).
AsciiRenderer<BoxWorld, 40, 20, ParticleShape::kPoints, LinkShape::kNone>
    renderer(Q16_16(0), Q16_16(0), Q16_16(0.025), Q16_16(0.05));
// 128 steps per second (dt = 1/128 s), 8 frames per second: the one place
// that sets the step.
RealTimeLoop timing(128, 8);

const uint32_t kRunSteps = 6 * 128UL;  // 6 s of simulated time
bool drawing = false;
uint8_t maxIterations = 0;

// A label and a number (one routine for every field: less flash than a
// pair of calls at each).
void printField(const __FlashStringHelper* label, uint32_t value) {
  Serial.print(label);
  Serial.print(value);
}

void setup() {
  Serial.begin(115200);
  while (!Serial);
  Serial.println(F("BouncingBalls: 16 balls, Q16.16, dt = 1/128 s"));
  buildBouncingBalls(world, 16);
}

void loop() {
  if (timing.runSteps(world) > 0 &&
      world.stats().iterations > maxIterations) {
    maxIterations = world.stats().iterations;  // of the last step run
  }

  // A frame starts when one is due, then goes out a line at a time.
  if (!drawing && timing.frameDue()) drawing = true;
  while (drawing && Serial.availableForWrite() >= renderer.lineLength()) {
    if (renderer.drawLine(world, Serial)) {
      drawing = false;
      // steps / 128 s in whole milliseconds: 1000 / 128 = 125 / 16 (no
      // float routine linked, and no division).
      printField(F("t="), (timing.steps() * 125) >> 4);
      printField(F(" ms  contacts "), world.stats().contacts);
      printField(F("  iterations "), world.stats().iterations);
      Serial.println();
    }
  }

  if (timing.steps() >= kRunSteps && !drawing) {
    printField(F("Done: "), timing.steps());
    printField(F(" steps, "), timing.slippedSteps());
    printField(F(" skipped to keep up, most resolver iterations in a step: "),
               maxIterations);
    Serial.println();
    Serial.flush();
    cli();
    sleep_enable();
    sleep_cpu();
  }
}
