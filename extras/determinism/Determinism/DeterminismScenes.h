// The scenes of the determinism check (issue 13): the same Q16.16 scenes,
// stepped 10,000 times at dt = 1/256 s, must give bit-identical state on
// every platform. Every 1000 steps each scene reports a 32-bit FNV-1a hash
// of the raw bits of every particle's position and velocity (slot order,
// each raw value's bytes taken low to high arithmetically, so the byte
// order of the machine does not matter), then of the world's error bits
// and the math error bits.
//
// Shared by the Nano sketch (Determinism.ino, simavr, with and without
// the AVR assembly) and the host and 32-bit ARM programs (host.cpp);
// extras/determinism/compare runs them all and compares the lines.
#pragma once

#include <stdint.h>

#include <TinyParticle.hpp>

namespace determinism {

using namespace tinyparticle;

typedef void (*Report)(const char* scene, uint16_t step, uint32_t hash);

static const uint16_t kSteps = 10000;
static const uint16_t kCheckpoint = 1000;

inline uint32_t hashRaw(uint32_t h, int32_t raw) {
  const uint32_t bits = uint32_t(raw);
  for (uint8_t b = 0; b < 4; ++b) {
    h ^= (bits >> (8 * b)) & 0xFFu;
    h *= 16777619ul;
  }
  return h;
}

template <class W>
uint32_t hashWorld(const W& world) {
  uint32_t h = 2166136261ul;
  for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
    const typename W::ParticleType& p = world.particleAt(i);
    if (!p.inUse()) continue;
    for (uint8_t k = 0; k < W::kDimensions; ++k) {
      h = hashRaw(h, p.position[k].raw());
      h = hashRaw(h, p.velocity[k].raw());
    }
  }
  h = hashRaw(h, world.error());
  return hashRaw(h, mathErrors());
}

// Steps the world, calling change(world, step) before each step (null:
// nothing to change), and reports at each checkpoint.
template <class W>
void run(W& world, const char* name, Report report,
         void (*change)(uint16_t step) = nullptr) {
  const Q16_16 dt(1.0 / 256);
  clearMathErrors();
  for (uint16_t n = 1; n <= kSteps; ++n) {
    if (change != nullptr) change(n);
    world.step(dt);
    if (n % kCheckpoint == 0) report(name, n, hashWorld(world));
  }
}

// Eight balls in the box: collisions, walls, gravity, sleeping.
inline void balls(Report report) {
  BallsWorld<Q16_16, 2, 8, 16> world;
  buildBouncingBalls(world, 8);
  world.enableSleeping();
  run(world, "balls", report);
}

// The whip chain of eight rods, falling from level.
inline void chain(Report report) {
  ChainWorld<Q16_16, 2, 8> world;
  buildChain(world, 8);
  run(world, "chain", report);
}

// The lever, pushed up, then sideways, then let go.
static Vec2<Q16_16> leverPush;
inline void pushLever(uint16_t step) {
  leverPush = Vec2<Q16_16>();
  if (step >= 1000 && step < 3000) leverPush.y = Q16_16(1.5);
  if (step >= 5000 && step < 5500) leverPush.x = Q16_16(-0.75);
}
inline void lever(Report report) {
  LeverWorld<Q16_16, 2> world;
  buildLever(world, &leverPush);
  run(world, "lever", report, &pushLever);
}

// Springs: two masses in a row from an anchor, a bungee to a third that
// also hangs on a stiff spring, drag and gravity on all.
inline void springs(Report report) {
  typedef World<Q16_16, 2, 3, 6> W;
  typedef W::Vec V;
  W world;
  const ParticleId a = world.addParticle(V(0.6, 0.0), Q16_16(1));
  const ParticleId b = world.addParticle(V(1.1, 0.2), Q16_16(0.5));
  const ParticleId c = world.addParticle(V(0.3, -0.4), Q16_16(0.2));
  world.addSpring(a, V(), Q16_16(100), Q16_16(0.5));
  world.addSpring(a, b, Q16_16(50), Q16_16(0.4));
  world.addBungee(b, c, Q16_16(30), Q16_16(0.6));
  world.addStiffSpring(c, V(0.3, -0.5), Q16_16(2000), Q16_16(2),
                       Q16_16(1.0 / 256));
  world.addDrag(Q16_16(0.01), Q16_16(0.001));
  world.addGravity();
  run(world, "springs", report);
}

// The scenes in DETERMINISM_SCENES (a bit each, in the order above; all
// by default): all four do not fit the Nano's flash in one sketch, so it
// is built for a few at a time.
#ifndef DETERMINISM_SCENES
#define DETERMINISM_SCENES 15
#endif
inline void all(Report report) {
  if (DETERMINISM_SCENES & 1) balls(report);
  if (DETERMINISM_SCENES & 2) chain(report);
  if (DETERMINISM_SCENES & 4) lever(report);
  if (DETERMINISM_SCENES & 8) springs(report);
}

}  // namespace determinism
