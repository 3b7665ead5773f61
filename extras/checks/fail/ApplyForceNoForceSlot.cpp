// Must NOT compile: applyForce() in a world without a force slot
// (World<S, Dim, particles, forces = 0>): its particles keep no force
// accumulator, so the force could not act (never a silent no-op).
// expect: static assert.*no force slot.*no force accumulator.*applyForce
#include "TinyParticle.hpp"
using namespace tinyparticle;

World<Q16_16, 2, 1> world;

void setup() {
  const ParticleId p = world.addParticle(Vec2<Q16_16>(0.0, 1.0), Q16_16(1));
  world.addGravity();
  world.applyForce(p, Vec2<Q16_16>(1.0, 0.0));
}
