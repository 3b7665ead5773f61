// Linked for the ATmega328P by `make -C extras/checks lonerods`: scenes
// whose rods can never share a particle pay only for the lone rods' solve
// (Contacts/LoneRod.hpp). The lever (one constraint slot, no contact slot)
// must link neither the chains' solve (RodSolver's sweep, factor,
// findChains) nor the resolver, nor any float routine; Newton's cradle
// (rods hung from anchors, collisions) must link no chains' solve. Neither
// damps a particle, so neither links the damping (Core/Particle.hpp). Inputs
// and outputs are registers, so nothing is folded or optimised away.
#include <avr/io.h>

#include "TinyParticle.hpp"

using namespace tinyparticle;
typedef Q16_16 S;

LeverWorld<S, 2> lever;
CradleWorld<S> cradle;
Vec2<S> push;

int main() {
  buildLever(lever, &push);
  buildCradle(cradle);
  const S dt = S::fromRaw(int32_t(GPIOR0) << 8);
  for (;;) {
    push.y = S::fromRaw(int32_t(GPIOR1) << 8);
    lever.step(dt);
    cradle.step(dt);
    GPIOR2 = uint8_t(lever.particleAt(1).position.y.raw() ^
                     cradle.particleAt(0).position.x.raw());
  }
}
