// A CPU cycle counter for the benchmarks: Timer1 at prescaler 1, extended past
// 16 bits by its overflow interrupt, whose own cycles are taken out again.
// (MemoryBenchmark/CycleCounter.h is the same file: each sketch folder must be
// complete on its own for the Arduino IDE.)
//
// Take Timer0's millis() interrupt out while measuring (cycleCounterBegin()
// does), and flush Serial before a measurement: their interrupts would land
// in the measured span.
#pragma once

#include <Arduino.h>
#include <avr/interrupt.h>
#include <util/delay_basic.h>

namespace cycles {

volatile uint16_t gOverflows;
uint16_t gHandlerCycles = 0;

inline void start() {
  TCCR1B = 0;
  TCNT1 = 0;
  TIFR1 = _BV(TOV1);
  gOverflows = 0;
  TCCR1B = _BV(CS10);
}

// Cycles since start(). The count is read while the timer runs: simavr reads
// a stopped Timer1 as 0.
inline uint32_t stop() {
  uint8_t sreg = SREG;
  cli();
  uint16_t count = TCNT1;
  uint16_t handled = gOverflows;
  uint16_t overflows = handled;
  if ((TIFR1 & _BV(TOV1)) && count < 0x8000) ++overflows;
  TCCR1B = 0;
  TIFR1 = _BV(TOV1);
  SREG = sreg;
  return ((uint32_t(overflows) << 16) | count) -
         uint32_t(handled) * gHandlerCycles;
}

// Stops millis(), arms the overflow interrupt and measures its cost: a
// 262,143-cycle busy loop against a 3-cycle one.
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

}  // namespace cycles

ISR(TIMER1_OVF_vect) { ++cycles::gOverflows; }
