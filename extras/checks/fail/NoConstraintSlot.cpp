// Must NOT compile: a rod added to a world without a constraint slot
// (World<S, Dim, particles, forces, constraints = 0, ...>). At run time the
// rod would not exist and the bob would fall; the error says what to size.
// expect: static assert.*no constraint slot.*constraints > 0
#include "TinyParticle.hpp"
using namespace tinyparticle;

typedef Q16_16 S;
World<S, 2, 2, 1, 0> world;

void setup() {
  ParticleId pivot = world.addFixedParticle(Vec2<S>(0.0, 0.0));
  ParticleId bob = world.addParticle(Vec2<S>(0.479, -0.878), S(1));
  world.addRod(bob, pivot, S(1));
}
