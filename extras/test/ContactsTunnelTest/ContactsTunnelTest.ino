// Contacts at the documented speed limit: two balls at it collide, while
// just past it the step raises WorldError::kTunnelling. (Q16.16; split from
// ContactsMotionTest, which no longer fit the Nano's flash with it.
// ContactsMotionFloatTest runs the same check with Float.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ContactChecks.hpp>

using aunit::TestRunner;
// The scenes run in src/TinyParticle/Testing/ContactChecks.hpp.
typedef tinyparticle::testing::ContactChecks<Q16_16> Checks;

// Balls of radius 2 cm head-on, each at the limit r / dt (5.12 m/s at
// 1/256 s): they bounce (keep their order) and nothing is flagged. Just past
// it (5 % faster) kTunnelling is raised, and far past it (50 m/s) too.
test(TunnellingLimit_Q16_16) {
  uint16_t error = 0;
  assertTrue(Checks::tunnel(1.0f, &error));
  assertEqual((int) (error & WorldError::kTunnelling), 0);
  Checks::tunnel(1.05f, &error);
  assertEqual((int) (error & WorldError::kTunnelling),
              (int) WorldError::kTunnelling);
  Checks::tunnel(50.0f / 5.12f, &error);
  assertEqual((int) (error & WorldError::kTunnelling),
              (int) WorldError::kTunnelling);
}

// Along the diagonal the limit is on the bound of |v| (Collisions.hpp):
// at 0.99 of it (|v| = 0.93 r / dt, though |vx| + |vy| = 1.32 r / dt) they
// bounce unflagged; 5 % past it the step raises kTunnelling.
test(TunnellingDiagonal_Q16_16) {
  uint16_t error = 0;
  assertTrue(Checks::tunnelDiagonal(0.99f, &error));
  assertEqual((int) (error & WorldError::kTunnelling), 0);
  Checks::tunnelDiagonal(1.05f, &error);
  assertEqual((int) (error & WorldError::kTunnelling),
              (int) WorldError::kTunnelling);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
