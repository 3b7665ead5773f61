// Benchmark support: a CPU cycle counter for the ATmega328P. Timer1 counts
// cycles (prescaler 1) and its overflow interrupt extends the count past 16
// bits; the interrupt's own cycles are measured once (begin()) and taken out
// of every reading.
//
// Used by the sketches in extras/benchmarks (AutoBenchmark, MemoryBenchmark,
// SceneBenchmark). Not included by TinyParticle.h, and not for sketches that
// use Timer1 otherwise (Servo, the profiler's cycle mode). Include it from
// exactly one file of a sketch, after <TinyParticle.h>: it defines the
// Timer1 overflow interrupt and the counter's variables.
//
//   cycles::begin();                  // once: stops millis(), calibrates
//   cycles::start();
//   ...code under test...
//   uint32_t spent = cycles::stop();  // includes the empty window: measure
//                                     // start() + stop() alone, subtract it
//
// Flush Serial before a measurement: its interrupts would land in the span.
// Only avr-libc headers here (no Arduino.h), so the compile checks cover it
// on their AVR targets.
#pragma once

#if !defined(__AVR__)
#error "CycleCounter.hpp counts cycles with the AVR's Timer1"
#endif

#include <avr/interrupt.h>
#include <avr/io.h>
#include <stdint.h>
#include <util/delay_basic.h>

namespace tinyparticle {
namespace testing {
namespace cycles {

// Overflows since start(), counted by the interrupt below.
volatile uint16_t gOverflows;
// What one run of that interrupt costs, in cycles (measured by begin()).
uint16_t gHandlerCycles = 0;

inline void start() {
  TCCR1B = 0;
  TCNT1 = 0;
  TIFR1 = _BV(TOV1);
  gOverflows = 0;
  TCCR1B = _BV(CS10);
}

// Cycles since start(), less the overflow handlers that ran. The count is
// read while the timer runs: simavr reads a stopped Timer1 as 0.
inline uint32_t stop() {
  uint8_t sreg = SREG;
  cli();
  uint16_t count = TCNT1;
  uint16_t handled = gOverflows;
  uint16_t overflows = handled;
  // A wrap whose handler has not run yet, and that came before the read.
  if ((TIFR1 & _BV(TOV1)) && count < 0x8000) ++overflows;
  TCCR1B = 0;
  TIFR1 = _BV(TOV1);
  SREG = sreg;
  return ((uint32_t(overflows) << 16) | count) -
         uint32_t(handled) * gHandlerCycles;
}

// Stops Timer0 (the millis() tick, which would land in measured spans),
// enables the overflow interrupt and measures its cost: a 262,143-cycle busy
// loop against a 3-cycle one; what the long one takes beyond 262,140 more
// cycles is the handlers that ran.
inline void begin() {
  TIMSK0 = 0;
  TCCR1A = 0;
  TIMSK1 = _BV(TOIE1);
  sei();
  gHandlerCycles = 0;
  start();
  _delay_loop_2(1);
  uint32_t shortLoop = stop();
  start();
  _delay_loop_2(0);
  uint32_t longLoop = stop();
  uint16_t handled = gOverflows;
  if (handled > 0) {
    gHandlerCycles =
        uint16_t((longLoop - shortLoop - 262140UL + handled / 2) / handled);
  }
}

// The cost of one overflow interrupt, as begin() measured it.
inline uint16_t handlerCycles() { return gHandlerCycles; }

}  // namespace cycles
}  // namespace testing
}  // namespace tinyparticle

ISR(TIMER1_OVF_vect) { ++tinyparticle::testing::cycles::gOverflows; }
