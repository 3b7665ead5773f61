// GeneratorBenchmark: what a generator costs when the sketch writes it,
// against the same generator built in. One build runs one case (GENERATOR):
//   0  no generator: the baseline the flash of the others is measured from
//   1  the built-in anchored spring (World::addSpring), on one particle
//   2  the same spring written in this sketch (World::addForce)
//   3  the built-in drag (World::addDrag), on each of the 4 particles
//   4  the same drag written as a sketch would (World::addForce)
//   5  the built-in plane of any normal (World::addPlane), for each particle
//   6  the same plane written as a sketch would (World::addConstraint)
// The sketch-written drag and plane are the classes the generator tests
// check bit for bit against the built-ins (Testing/GeneratorChecks.hpp).
// Every case has the same world (Q16.16, 2D: 4 particles, gravity) and
// steps it 512 times at 1/256 s, timing each step with Timer1
// (Testing/CycleCounter.hpp, the empty window taken out). It prints
// "R <case> <cycles of all steps> <steps> <x raw> <y raw>" (the final
// position of particle 0: a built-in case and its sketch copy must end in
// the same place), then "E", and sleeps. extras/benchmarks/tools/generators.py
// builds and runs every case and writes extras/benchmarks/generators.csv.
#ifndef GENERATOR
#define GENERATOR 1
#endif

#include <TinyParticle.h>
#include <avr/sleep.h>

#include <TinyParticle/Testing/CycleCounter.hpp>
#include <TinyParticle/Testing/GeneratorChecks.hpp>

using namespace tinyparticle::testing;

typedef Q16_16 S;
typedef World<S, 2, 4, 2, 1, 4> W;
typedef W::Vec V;
W world;

struct SketchSpring {  // Forces/Spring.hpp's anchored spring
  V anchor;
  S stiffness, restLength;
  void apply(W::ParticleType& p, S) {
    V delta = p.position;
    delta -= anchor;
    S lengthSquared = delta.magnitudeSquared();
    if (lengthSquared == S()) return;
    S length = sqrt(lengthSquared);
    S extension = length - restLength;
    S perLength = -(stiffness * extension) / length;
    p.acceleration.addScaled(delta, perLength * p.inverseMass);
  }
};

SketchSpring spring = {V(0.0, 1.0), S(40), S(0.3)};
UserDrag<W> drag = {S(0.3), S(0.1)};
UserPlane<W> plane = {V(-0.6, 0.8), S(0)};

void build() {
  for (uint8_t i = 0; i < 4; ++i) {
    ParticleId p = world.addParticle(V(0.1 + 0.2 * i, 0.6), S(0.5), S(0.05));
    world.particle(p)->velocity = V(1.0 - 0.5 * i, 0.5);
  }
  world.addGravity();
  const ParticleId first = world.idOf(0);
  (void)first;
#if GENERATOR == 1
  world.addSpring(first, spring.anchor, spring.stiffness, spring.restLength);
#elif GENERATOR == 2
  world.addForce(spring, first);
#elif GENERATOR == 3
  world.addDrag(drag.k1, drag.k2);
#elif GENERATOR == 4
  world.addForce(drag);
#elif GENERATOR == 5
  world.addPlane(plane.normal, plane.offset, S(0.5));
#elif GENERATOR == 6
  world.addConstraint(plane, S(0.5));
#endif
}

void setup() {
  Serial.begin(115200);
  while (!Serial) {
  }
  build();
  Serial.flush();
  cycles::begin();
  cycles::start();
  const uint32_t window = cycles::stop();
  uint32_t total = 0;
  const uint16_t kSteps = 512;
  for (uint16_t i = 0; i < kSteps; ++i) {
    cycles::start();
    world.step(S(1.0 / 256));
    total += cycles::stop() - window;
  }
  const V& x = world.particleAt(0).position;
  Serial.print(F("R "));
  Serial.print(GENERATOR);
  Serial.print(' ');
  Serial.print(total);
  Serial.print(' ');
  Serial.print(kSteps);
  Serial.print(' ');
  Serial.print(x.x.raw());
  Serial.print(' ');
  Serial.println(x.y.raw());
  Serial.println('E');
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
}

void loop() {}
