// A box (World::addBox: one pass over the particles for all its walls) is
// a fast path of its 2 Dim axis planes: it must make the same contacts in
// the same order. Balls thrown about the box for 2 s, one into a corner,
// touch every wall and several at once; the positions at the end must be
// the planes' to the last bit. (3D, Q16.16 here; ContactsBox3DFloatTest
// runs the same check with the other scalar, ContactsBoxTest in 2D.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ContactChecks.hpp>

using aunit::TestRunner;
// The scenes run in src/TinyParticle/Testing/ContactChecks.hpp.
typedef tinyparticle::testing::ContactChecks<Q16_16> Checks;

// Bits 0-5: every wall made a contact; bit 7: a ball touched two walls in
// one step.
test(BoxIsItsPlanes3D_Q16_16) {
  TestRunner::setTimeout(0);
  uint8_t boxWalls = 0, planeWalls = 0;
  const float box = Checks::boxChecksum<3>(true, &boxWalls);
  const float planes = Checks::boxChecksum<3>(false, &planeWalls);
  assertEqual(box, planes);
  assertEqual((int) boxWalls, 0xBF);
  assertEqual((int) planeWalls, 0xBF);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
