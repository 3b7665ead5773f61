// Must NOT compile: a World over a plain float (or double, or an integer)
// instead of one of the library's scalars. The first error names the valid
// ones (Math/ScalarTraits.hpp).
// expect: static assert.*the scalar must be Q16_16, Q24_8, Q8_8 .*or Float
#include "TinyParticle.hpp"
using namespace tinyparticle;

typedef float S;
World<S, 2, 2, 1, 1, 1> world;

void setup() {
  ParticleId pivot = world.addFixedParticle(Vec2<S>(0.0, 0.0));
  ParticleId bob = world.addParticle(Vec2<S>(0.479, -0.878), S(1));
  world.addRod(bob, pivot, S(1));
  world.addGravity();
  world.step(S(1.0 / 256));
}
