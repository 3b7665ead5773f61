// A contact pool too small for a landing row of balls: defined and flagged.
// (Float here; ContactsPoolTest runs the same check with the other
// scalar.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ContactChecks.hpp>

using aunit::TestRunner;
// The scene runs in src/TinyParticle/Testing/ContactChecks.hpp.
typedef tinyparticle::testing::ContactChecks<Float> Checks;

// Sixteen balls landing side by side need about 30 contacts; a pool of 8
// drops the least severe ones each step: the step goes on (defined),
// flags kContactsDropped, counts the drops, and every ball's centre stays
// in the box (within 1 mm).
test(ContactPoolOverflow_Float) {
  TestRunner::setTimeout(0);
  uint16_t error = 0;
  uint8_t dropped = 0;
  assertTrue(Checks::overflow(3, &error, &dropped));
  assertEqual((int) (error & WorldError::kContactsDropped),
              (int) WorldError::kContactsDropped);
  assertMore((int) dropped, 0);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
