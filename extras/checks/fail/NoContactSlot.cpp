// Must NOT compile: a floor (a plane) in a world without a contact slot
// (World<S, Dim, particles, forces, constraints, contacts = 0>): every
// contact with it would be dropped. (Rods need no contact slot.)
// expect: static assert.*no contact slot.*contacts > 0
#include "TinyParticle.hpp"
using namespace tinyparticle;

World<Q16_16, 2, 1, 1, 1, 0> world;

void setup() {
  world.addParticle(Vec2<Q16_16>(0.0, 1.0), Q16_16(1), Q16_16(0.1));
  world.addGravity();
  world.addPlane(Vec2<Q16_16>(0.0, 1.0), Q16_16(0), Q16_16(0.5));
}
