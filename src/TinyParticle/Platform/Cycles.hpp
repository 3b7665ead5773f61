// Timing and pin hooks for the profiler (Debug/Profile.hpp).
//
// Cycle counting uses Timer1 as a free-running 16-bit counter. The Servo
// library also uses Timer1, so a sketch with a servo profiles with pins
// (TINYPARTICLE_PROFILE 2) instead.
#pragma once

#include <stdint.h>

#include "Arduino.hpp"

#if defined(__AVR__)
#include <avr/io.h>
#endif

namespace tinyparticle {
namespace platform {

// Starts Timer1 counting CPU cycles (prescaler 1). Elsewhere: nothing.
inline void startCycleCounter() {
#if defined(__AVR__)
  TCCR1A = 0;
  TCCR1B = _BV(CS10);
#endif
}

// The counter's low 16 bits; a difference of two readings is exact for spans
// shorter than 65,536 cycles. 0 where there is no such counter.
inline uint16_t cycleCount() {
#if defined(__AVR__)
  return TCNT1;
#else
  return 0;
#endif
}

inline void setupPin(uint8_t pin) {
#if TINYPARTICLE_HAS_ARDUINO
  pinMode(pin, OUTPUT);
  digitalWrite(pin, LOW);
#else
  (void)pin;
#endif
}

inline void writePin(uint8_t pin, bool high) {
#if TINYPARTICLE_HAS_ARDUINO
  digitalWrite(pin, high ? HIGH : LOW);
#else
  (void)pin;
  (void)high;
#endif
}

}  // namespace platform
}  // namespace tinyparticle
