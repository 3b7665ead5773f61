// The stability suite of issue 13 in Q24.8, where it applies: large
// values (the wall at 200 m/s, the range edge at 8.4e6 m) rather than
// fine ones (a unit is 3.9 mm), and the real-time loop across the wrap of
// micros(). Cases and bounds: src/TinyParticle/Testing/StabilityCases.hpp.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/StabilityCases.hpp>

using aunit::TestRunner;
using tinyparticle::testing::StabilityCases;
using tinyparticle::testing::stabilityLine;

typedef StabilityCases<Q24_8> Cases24;

test(Wall_Q24_8) { assertTrue(Cases24::checkWall(200)); }
test(RangeEdge_Q24_8) { assertTrue(Cases24::checkRangeEdge()); }

// The real-time loop across the wrap of micros() (every 71.6 minutes):
// started half a second before it, over one second it must run 256 or
// 257 steps at 256 Hz, as anywhere else (the first step is due at once,
// the 257th exactly at 1 s). On the host a fake clock that moves 50 us a
// read; on the Nano the core's own micros(), its overflow counter set to
// just before the wrap.
#if defined(EPOXY_DUINO)
struct WrapClock {
  static uint32_t now;
  static uint32_t micros() { return now += 50; }
  static void presetBeforeWrap(uint32_t us) { now = uint32_t(0) - us; }
};
uint32_t WrapClock::now = 0;
#else
extern volatile unsigned long timer0_overflow_count;
struct WrapClock : ArduinoClock {
  // micros() = (overflows * 256 + TCNT0) * 4 us at 16 MHz.
  static void presetBeforeWrap(uint32_t us) {
    noInterrupts();
    timer0_overflow_count = (uint32_t(0) - us) / 4 / 256;
    interrupts();
  }
};
#endif

test(MicrosWrap) {
  WrapClock::presetBeforeWrap(500000UL);
  BasicRealTimeLoop<WrapClock> timing(256, 0);
  timing.start();
  const uint32_t begin = WrapClock::micros();
  uint32_t now = begin;
  uint16_t steps = 0;
  while (now - begin < 1000000UL) {
    steps += timing.stepsDue();
    now = WrapClock::micros();
  }
  assertTrue(now < begin);  // it did wrap
  const float off = steps > 256 ? steps - 257 : 256 - steps;
  assertTrue(stabilityLine<tinyparticle::testing::NoScalar>(F("micros-wrap-steps-off-in-1s"), 0, off < 0 ? 0 : off));
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);  // long cases: the whole run is timed by run-tests
}

void loop() { TestRunner::run(); }
