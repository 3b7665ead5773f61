// Must NOT compile: Particle::addForce() on a particle of a world without a
// force slot (its ParticleType keeps no force accumulator).
// expect: static assert.*no force slot.*no force accumulator.*addForce
#include "TinyParticle.hpp"
using namespace tinyparticle;

World<Q16_16, 2, 1> world;

void setup() {
  const ParticleId p = world.addParticle(Vec2<Q16_16>(0.0, 1.0), Q16_16(1));
  world.particle(p)->addForce(Vec2<Q16_16>(1.0, 0.0));
}
