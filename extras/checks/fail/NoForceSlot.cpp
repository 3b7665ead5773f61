// Must NOT compile: a force generator (drag) added to a world without a
// force slot (World<S, Dim, particles, forces = 0>). The world's gravity
// takes no slot: addGravity() builds there.
// expect: static assert.*no force slot.*forces > 0
#include "TinyParticle.hpp"
using namespace tinyparticle;

World<Q16_16, 2, 1> world;

void setup() {
  world.addParticle(Vec2<Q16_16>(0.0, 1.0), Q16_16(1));
  world.addGravity();
  world.addDrag(Q16_16(0.1), Q16_16(0));
}
