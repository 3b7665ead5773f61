// The scenes' random generator: its short path for a span of 257 (no
// division) gives x % 257 for every 16-bit draw x, and the general path
// is the plain remainder.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

// The reference: the remainder by the division routine. (noinline: the
// compiler must not reduce it to the short path.)
static __attribute__((noinline)) int16_t byDivision(uint16_t x,
                                                     uint16_t span,
                                                     int16_t limit) {
  return int16_t(int16_t(x % span) - limit);
}

// Every draw, limit 128 (span 257): the classes the short path tells apart
// (low byte at least the high byte, or below it; 0 and 0xFFFF) are all in.
// The count of mismatches is asserted, so one assert covers 65,536 draws.
test(Span257EveryDraw) {
  uint16_t mismatches = 0;
  uint16_t x = 0;
  do {
    if (SceneRandom::fromDraw(x, 128) != byDivision(x, 257, 128)) {
      ++mismatches;
    }
  } while (++x != 0);
  assertEqual((unsigned) mismatches, 0u);
  assertEqual((int) SceneRandom::fromDraw(0, 128), -128);
  assertEqual((int) SceneRandom::fromDraw(256, 128), 128);  // 256 % 257
  assertEqual((int) SceneRandom::fromDraw(0xFFFF, 128),
              int(65535L % 257) - 128);
}

// Other spans take the remainder: a sample of draws for limits 1 and 100.
test(OtherSpans) {
  for (uint16_t x = 0; x < 2000; x = uint16_t(x + 7)) {
    assertEqual((int) SceneRandom::fromDraw(x, 1), (int) byDivision(x, 3, 1));
    assertEqual((int) SceneRandom::fromDraw(x, 100),
                (int) byDivision(x, 201, 100));
  }
}

// symmetric() draws the generator's next number and reduces it: within
// [-limit, limit], and the same sequence as next() reduced by division.
test(SymmetricFollowsNext) {
  SceneRandom a(2024), b(2024);
  for (uint8_t i = 0; i < 200; ++i) {
    const int16_t value = a.symmetric(128);
    assertEqual((int) value, (int) byDivision(b.next(), 257, 128));
    assertTrue(value >= -128 && value <= 128);
  }
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
