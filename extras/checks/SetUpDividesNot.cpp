// Linked for the ATmega328P by `make -C extras/checks nodivide`: a scene
// whose step never divides (particles under gravity, drag and buoyancy,
// set up with masses) links neither the fast divide (avrDivideQ16) nor any
// float routine: the set-up's inverse masses and buoyancy's constants come
// from fixed point and the compact reciprocal (Fixed::compactReciprocal),
// which must be linked. A spring divides in its step: a second program
// with one must link the fast divide, so the check can tell. With
// LEVER_ONLY, the lever alone (its rod takes Newton's steps and the compact
// reciprocal) must link neither the fast divide nor the square root, which
// the drag's step above takes and the spring's program links. Inputs and
// outputs are registers, so nothing is folded.
#include <avr/io.h>

#include "TinyParticle.hpp"

using namespace tinyparticle;
typedef Q16_16 S;
typedef World<S, 2, 2, 4> W;

#if LEVER_ONLY
LeverWorld<S, 2> lever;
Vec2<S> push;
#else
W world;
#endif

static S input(uint8_t shift) {
  return S::fromRaw(int32_t(GPIOR0) << shift);
}

#if LEVER_ONLY
int main() {
  buildLever(lever, &push);
  const S dt = input(8);
  for (;;) {
    push.y = input(2);
    lever.step(dt);
    GPIOR2 = uint8_t(lever.particleAt(1).position.y.raw());
  }
}
#else
int main() {
  const ParticleId a = world.addParticle(W::Vec(input(8), input(9)), input(10));
  const ParticleId b = world.addParticle(W::Vec(input(9), input(8)), input(11));
  world.addGravity();
  world.addDrag(input(4), input(5));
  world.addBuoyancy(input(6), input(7), input(3), input(16));
#if WITH_SPRING
  world.addSpring(a, b, input(12), input(10));
#else
  (void)a;
  (void)b;
#endif
  const S dt = input(8);
  for (;;) {
    world.step(dt);
    GPIOR2 = uint8_t(world.particleAt(1).position.y.raw());
  }
}
#endif
