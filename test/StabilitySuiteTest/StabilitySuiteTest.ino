// The stability suite of issue 13, Q16.16 (and Q24.8 where it applies):
// contacts, springs, the range edge, tiny steps, exhausted pools and the
// real-time loop across the wrap of micros(). StabilitySuiteRodsTest has
// the rod cases; the *FloatTest sketches run both in Float. The cases,
// their bounds and the reasons for them are in
// src/TinyParticle/Testing/StabilityCases.hpp; each check prints
// "STABILITY ..." lines that extras/stability/collect turns into the table
// of extras/stability/README.md.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/StabilityCases.hpp>

using aunit::TestRunner;
using tinyparticle::testing::StabilityCases;
using tinyparticle::testing::stabilityLine;

typedef StabilityCases<Q16_16> Cases;
typedef StabilityCases<Q24_8> Cases24;

test(Spring_Q16_16) { assertTrue(Cases::checkSpring(32768.0f)); }
test(Wall_Q16_16) { assertTrue(Cases::checkWall(200)); }
test(Wall_Q24_8) { assertTrue(Cases24::checkWall(200)); }
test(BallHit_Q16_16) { assertTrue(Cases::checkBallHit()); }
test(MassRatioCollision_Q16_16) { assertTrue(Cases::checkMassRatioCollision()); }
test(Stack_Q16_16) {
  TestRunner::setTimeout(0);
  assertTrue(Cases::checkStack());
}
test(Coincident_Q16_16) { assertTrue(Cases::checkCoincident()); }
test(RangeEdge_Q16_16) { assertTrue(Cases::checkRangeEdge()); }
test(RangeEdge_Q24_8) { assertTrue(Cases24::checkRangeEdge()); }
// The smallest useful step: Euler's error g t dt / 2 shrinks with dt, the
// rounding (n steps of half a unit) grows as 1 / dt; in Q16.16 they cross
// near dt = sqrt(2 u / g) = 1/570 s, and below 1/4096 s rounding is all
// that is left (extras/stability/README.md).
test(TinyDt_Q16_16) {
  bool ok = Cases::checkFreeFall(256, F("free-fall-dt-1/256-m"));
  ok &= Cases::checkFreeFall(1024, F("free-fall-dt-1/1024-m"));
  ok &= Cases::checkFreeFall(4096, F("free-fall-dt-1/4096-m"));
  ok &= Cases::checkFreeFall(16384, F("free-fall-dt-1/16384-m"));
  assertTrue(ok);
}
test(Exhaustion_Q16_16) { assertTrue(Cases::checkExhaustion()); }

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
  assertTrue(stabilityLine<Q16_16>(F("micros-wrap-steps-off-in-1s"), 0, off < 0 ? 0 : off));
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
