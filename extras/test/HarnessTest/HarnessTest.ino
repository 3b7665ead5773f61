// Checks the ground every other test stands on, on the host and on the Nano:
// flash strings and tables read back intact, the clock advances as delay()
// says, integer widths are what the target promises, and the library header
// builds in a sketch.
#include <AUnit.h>
#include <TinyParticle.h>

static const uint16_t kWords[] PROGMEM = {0u, 1u, 0x1234u, 0xfffeu, 0xffffu};
static const uint32_t kLongs[] PROGMEM = {0ul, 65536ul, 0x89abcdeful};

test(flashStringReadsBackByteForByte) {
  const char* f = reinterpret_cast<const char*>(F("TinyParticle"));
  const char* ram = "TinyParticle";
  for (uint8_t i = 0; i <= 12; ++i) {
    assertEqual((char) pgm_read_byte(f + i), ram[i]);
  }
  assertEqual(F("TinyParticle"), ram);
}

test(flashTablesReadBackExactly) {
  // Every value must survive the store in flash unchanged (no rounding,
  // no byte-order mix-up): compare with the same constants written in code.
  assertEqual((unsigned int) pgm_read_word(&kWords[2]), 0x1234u);
  assertEqual((unsigned int) pgm_read_word(&kWords[4]), 0xffffu);
  assertEqual((unsigned long) pgm_read_dword(&kLongs[1]), 65536ul);
  assertEqual((unsigned long) pgm_read_dword(&kLongs[2]), 0x89abcdeful);
}

test(delayAdvancesMillisAndMicros) {
  // delay(50) must move millis() by at least 49 (the AVR millis() counter
  // steps by 1.024 ms, so one step may be skipped) and not by absurdly much:
  // 500 ms leaves room for a loaded host or a slow simulator.
  unsigned long m0 = millis();
  unsigned long u0 = micros();
  delay(50);
  unsigned long dm = millis() - m0;
  unsigned long du = micros() - u0;
  assertMoreOrEqual(dm, 49ul);
  assertLess(dm, 500ul);
  // micros() agrees with millis() to within its own 1.024 ms step plus 4 us
  // resolution: |du/1000 - dm| <= 2.
  assertNear(du / 1000ul, dm, 2ul);
}

test(integerWidthsMatchTheTarget) {
#if defined(__AVR__)
  assertEqual((unsigned int) sizeof(int), 2u);     // the ATmega328P's int
  assertEqual((unsigned int) sizeof(double), 4u);  // avr-gcc: double is float
#else
  assertMoreOrEqual((unsigned int) sizeof(int), 4u);
#endif
  assertEqual((unsigned int) sizeof(int32_t), 4u);
}

void setup() {
#if ! defined(EPOXY_DUINO)
  delay(1000);   // real boards: wait for the serial monitor
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { aunit::TestRunner::run(); }
