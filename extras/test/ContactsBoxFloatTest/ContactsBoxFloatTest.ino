// A box (World::addBox: one pass over the particles for all its walls) is
// a fast path of its 2 Dim axis planes: it must make the same contacts in
// the same order. Balls thrown about the box for 2 s, one into a corner,
// touch every wall and two at once; the positions at the end must be the
// planes' to the last bit. (2D, Float here; ContactsBoxTest runs the same check
// with the other scalar, ContactsBox3DFloatTest in 3D.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ContactChecks.hpp>

using aunit::TestRunner;
// The scenes run in src/TinyParticle/Testing/ContactChecks.hpp.
typedef tinyparticle::testing::ContactChecks<Float> Checks;

// Bits 0-3: every wall made a contact; bit 7: a ball touched two walls in
// one step.
test(BoxIsItsPlanes2D_Float) {
  TestRunner::setTimeout(0);
  uint8_t boxWalls = 0, planeWalls = 0;
  const float box = Checks::boxChecksum<2>(true, &boxWalls);
  const float planes = Checks::boxChecksum<2>(false, &planeWalls);
  assertEqual(box, planes);
  assertEqual((int) boxWalls, 0x8F);
  assertEqual((int) planeWalls, 0x8F);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
