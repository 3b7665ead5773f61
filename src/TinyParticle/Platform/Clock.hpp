// Clocks for the real-time loop (Loop/RealTimeLoop.hpp). A clock is any type
// with a static uint32_t micros() that counts microseconds and wraps around;
// tests use a fake one.
#pragma once

#include <stdint.h>

#include "Arduino.hpp"

namespace tinyparticle {

#if TINYPARTICLE_HAS_ARDUINO
// The board's micros(): 4 us resolution on a 16 MHz AVR, wraps after 71 min.
struct ArduinoClock {
  static uint32_t micros() { return ::micros(); }
};
#endif

}  // namespace tinyparticle
