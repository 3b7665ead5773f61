// HelloParticle: a ball dropped from 1 m onto a floor. Shows a World, a
// particle, gravity, a floor, real-time stepping and print(). Needs only a
// board (a Nano) and the Serial Monitor at 115200 baud; on the PC,
// `make demo DEMO=examples/HelloParticle`. You should see the ball's (x, y)
// in metres ten times a second: y falls, bounces lower and lower, then
// rests at 0.05 (its radius).
#include <TinyParticle.h>

typedef Q16_16 S;                // the scalar: Q16_16, Q24_8 or Float
World<S, 2, 1, 0, 1, 1> world;   // 2D; 1 particle, no force slot, 1 plane, 1 contact
RealTimeLoop timing(256, 10);    // 256 steps (dt = 1/256 s), 10 lines a second
ParticleId ball;

void setup() {
  Serial.begin(115200);
  ball = world.addParticle(Vec2<S>(0.0, 1.0), S(1), S(0.05));  // 1 kg, r 5 cm
  world.addGravity();
  world.addPlane(Vec2<S>(0.0, 1.0), S(0), S(0.5));  // floor y = 0, bounce 0.5
}

void loop() {
  timing.runSteps(world);
  if (timing.frameDue()) println(Serial, world.particle(ball)->position);
}
