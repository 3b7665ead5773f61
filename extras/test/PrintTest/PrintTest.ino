// print(out, x) for scalars and vectors (Text/Print.hpp). The expected
// texts follow from the definition: raw / 2^FracBits rounded to the given
// decimals, ties away from zero, a sign only for a text that is not zero.
// Hand-worked cases first, then every bit length of random raw values
// against the same definition computed another way (64-bit integers).
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/MathTestSupport.hpp>

using aunit::TestRunner;
using tinyparticle::testing::XorShift32;
using tinyparticle::testing::randomRaw;
using tinyparticle::testing::magnitude64;

// An output that keeps what is written, as a C string.
struct Capture {
  char text[64];
  uint8_t length;
  Capture() : length(0) { text[0] = '\0'; }
  size_t write(uint8_t c) {
    if (length + 1u < sizeof(text)) {
      text[length++] = char(c);
      text[length] = '\0';
    }
    return 1;
  }
};

// The helpers sit in a struct: the Arduino builder would write broken
// prototypes for free function templates.
struct Check {
  // True if `value` prints as `expected`; otherwise says what it printed.
  static bool same(const char* text, const char* expected) {
    if (strcmp(text, expected) == 0) return true;
    Serial.print(F("printed \""));
    Serial.print(text);
    Serial.print(F("\", expected \""));
    Serial.print(expected);
    Serial.println('"');
    return false;
  }
  template <typename T>
  static bool prints(const T& value, const char* expected) {
    Capture out;
    print(out, value);
    return same(out.text, expected);
  }
  template <typename T>
  static bool prints(const T& value, uint8_t decimals, const char* expected) {
    Capture out;
    print(out, value, decimals);
    return same(out.text, expected);
  }

  // The definition again, in 64-bit integers: q = round(|raw| 10^d / 2^F),
  // then q / 10^d, a point and q % 10^d in d digits.
  template <typename S>
  static void expectedText(S x, uint8_t decimals, char* text) {
    uint64_t power = 1;
    for (uint8_t i = 0; i < decimals; ++i) power *= 10;
    const uint64_t magnitude = magnitude64(x.raw());
    const uint64_t q = (2 * magnitude * power + (uint64_t(1) << S::kFracBits)) >>
                       (S::kFracBits + 1);
    uint8_t n = 0;
    if (x.raw() < 0 && q != 0) text[n++] = '-';
    char reversed[24];
    uint8_t count = 0;
    uint64_t whole = q / power, fraction = q % power;
    for (uint8_t i = 0; i < decimals; ++i) {
      reversed[count++] = char('0' + int(fraction % 10));
      fraction /= 10;
    }
    if (decimals > 0) reversed[count++] = '.';
    do {
      reversed[count++] = char('0' + int(whole % 10));
      whole /= 10;
    } while (whole > 0);
    while (count > 0) text[n++] = reversed[--count];
    text[n] = '\0';
  }

  template <typename S>
  static bool matchesDefinition(uint32_t seed, uint16_t count,
                                uint8_t maxDecimals) {
    XorShift32 random(seed);
    char expected[40];
    for (uint16_t i = 0; i < count; ++i) {
      const S x = S::fromRaw(randomRaw<typename S::Raw>(random, S::kTotalBits - 1));
      const uint8_t decimals = uint8_t(random.next() % (maxDecimals + 1));
      expectedText(x, decimals, expected);
      Capture out;
      print(out, x, decimals);
      if (!same(out.text, expected)) return false;
    }
    return true;
  }

  // With the default decimals, any two neighbouring values print differently.
  template <typename S>
  static bool neighboursDiffer(uint32_t seed, uint16_t count) {
    XorShift32 random(seed);
    for (uint16_t i = 0; i < count; ++i) {
      typename S::Raw raw = randomRaw<typename S::Raw>(random, S::kTotalBits - 1);
      if (raw == S::kRawMax) --raw;
      Capture a, b;
      print(a, S::fromRaw(raw));
      print(b, S::fromRaw(typename S::Raw(raw + 1)));
      if (strcmp(a.text, b.text) == 0) {
        Serial.print(F("same text for two neighbours: "));
        Serial.println(a.text);
        return false;
      }
    }
    return true;
  }
};

// Defaults: the fewest decimals with 10^-d <= 2^-F (log10(2) = 0.30103):
// F = 16 needs 4.8 -> 5, F = 8 needs 2.4 -> 3.
test(DefaultDecimals) {
  assertEqual((int) Printer<Q16_16>::kDecimals, 5);
  assertEqual((int) Printer<Q24_8>::kDecimals, 3);
  assertEqual((int) Printer<Q8_8>::kDecimals, 3);
  assertEqual((int) Printer<Vec2<Q16_16> >::kDecimals, 5);
}

// Worked by hand: 2^-16 = 0.0000152587..., 65535 / 65536 = 0.9999847...,
// 0x8000 / 65536 = 0.5, 2^-8 = 0.00390625.
test(FixedByHand) {
  assertTrue(Check::prints(Q16_16(), "0.00000"));
  assertTrue(Check::prints(Q16_16::fromRaw(1), "0.00002"));
  assertTrue(Check::prints(Q16_16::fromRaw(-1), "-0.00002"));
  assertTrue(Check::prints(Q16_16::fromRaw(65535), "0.99998"));
  assertTrue(Check::prints(Q16_16::fromRaw(0x18000), "1.50000"));
  assertTrue(Check::prints(Q16_16(-1), "-1.00000"));
  assertTrue(Check::prints(Q16_16::fromRaw(INT32_MIN), "-32768.00000"));
  assertTrue(Check::prints(Q16_16::fromRaw(INT32_MAX), "32767.99998"));
  assertTrue(Check::prints(Q24_8::fromRaw(1), "0.004"));
  assertTrue(Check::prints(Q24_8::fromRaw(-1), 2, "0.00"));        // -0.0039: no sign
  assertTrue(Check::prints(Q24_8::fromRaw(128), 0, "1"));          // 0.5: tie, away
  assertTrue(Check::prints(Q24_8::fromRaw(-128), 0, "-1"));
  assertTrue(Check::prints(Q24_8::fromRaw(-64), 0, "0"));          // -0.25
  assertTrue(Check::prints(Q8_8::fromRaw(INT16_MIN), "-128.000"));
  assertTrue(Check::prints(Q8_8::fromRaw(INT16_MAX), "127.996"));  // 127 + 255/256
  // 0.99998 to 4 decimals carries into the whole part.
  assertTrue(Check::prints(Q16_16::fromRaw(65535), 4, "1.0000"));
  // 12345.6787109375 (the README's example) with every digit, and 10 at most.
  assertTrue(Check::prints(Q16_16(12345.6789), 10, "12345.6787109375"));
  assertTrue(Check::prints(Q16_16(12345.6789), 12, "12345.6787109375"));
}

test(VectorsAndLines) {
  assertTrue(Check::prints(Vec2<Q16_16>(0.5, -0.25), "(0.50000, -0.25000)"));
  assertTrue(Check::prints(Vec3<Q24_8>(1.0, 2.0, -3.5), 1, "(1.0, 2.0, -3.5)"));
  Capture out;
  println(out, Q16_16(2), 1);
  assertTrue(Check::same(out.text, "2.0\r\n"));
}

test(FixedAgainstDefinition) {
  assertTrue(Check::matchesDefinition<Q16_16>(0x1234567u, 200, 8));
  assertTrue(Check::matchesDefinition<Q24_8>(0x89abcdeu, 100, 6));
  assertTrue(Check::matchesDefinition<Q8_8>(0x2468aceu, 100, 6));
}

test(NeighboursDiffer) {
  assertTrue(Check::neighboursDiffer<Q16_16>(0x5555u, 200));
  assertTrue(Check::neighboursDiffer<Q24_8>(0x7777u, 100));
  assertTrue(Check::neighboursDiffer<Q8_8>(0x9999u, 100));
}

// Float: values exact in binary, so the text follows from the same rule.
test(FloatByHand) {
  assertTrue(Check::prints(Float(0.5), "0.50000"));
  assertTrue(Check::prints(Float(-1.25), 1, "-1.3"));   // 12.5 tenths: tie, away
  assertTrue(Check::prints(Float(2.5), 0, "3"));
  assertTrue(Check::prints(Float(0.1), "0.10000"));
  assertTrue(Check::prints(Float(-0.000001), "0.00000"));
  assertTrue(Check::prints(Float(1e12), "1.00000e+12"));
  assertTrue(Check::prints(Float(-1.5e30), 2, "-1.50e+30"));
  assertTrue(Check::prints(Float(1e9), 0, "1e+09"));
  assertTrue(Check::prints(Float(9.999996e9), "1.00000e+10"));  // 9.999996 carries
  assertTrue(Check::prints(Float(3.0e38) * Float(10), "inf"));
  assertTrue(Check::prints(-(Float(3.0e38) * Float(10)), "-inf"));
  assertTrue(Check::prints(Float(3.0e38) * Float(10) * Float(0), "nan"));
  assertTrue(Check::prints(Vec2<Float>(1.0, -2.0), 1, "(1.0, -2.0)"));
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
