// Particles with inverse mass 0 never move: not under gravity, not when a
// ball hits them, not when a rod pulls them, not when a force is applied.
// (Float here: ImmovableTest runs the same check with the other scalar; the
// scene runs in src/TinyParticle/Testing/ImmovableChecks.hpp.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ImmovableChecks.hpp>

using aunit::TestRunner;
using tinyparticle::testing::ImmovableChecks;

// 3: the immovable particle stayed exactly where it was for 2 s, and the
// ball bounced off it (1 alone: it never moved but nothing hit it).
test(ImmovableNeverMoves_Float) {
  assertEqual(ImmovableChecks<Float>::immovable(), 3);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
