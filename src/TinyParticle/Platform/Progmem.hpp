// Constant tables in program memory, without the Arduino core.
//
// On AVR, flash and RAM are separate address spaces: a table declared with
// TINYPARTICLE_PROGMEM stays in flash (costing no RAM) and must be read
// with the readFlash*() functions below, which use avr-libc's LPM wrappers
// from <avr/pgmspace.h> (part of avr-libc, so no Arduino.h is needed).
// Everywhere else the attribute is empty and the functions are plain loads.
//
// Always read a TINYPARTICLE_PROGMEM table through these functions: a plain
// dereference compiles on AVR but reads RAM at the same address.
#pragma once

#include <stdint.h>

#if defined(__AVR__)
#include <avr/pgmspace.h>
#define TINYPARTICLE_PROGMEM PROGMEM
#else
#define TINYPARTICLE_PROGMEM
#endif

namespace tinyparticle {
namespace platform {

#if defined(__AVR__)

inline uint8_t readFlashU8(const uint8_t* p) { return pgm_read_byte(p); }
inline uint16_t readFlashU16(const uint16_t* p) { return pgm_read_word(p); }
inline uint32_t readFlashU32(const uint32_t* p) { return pgm_read_dword(p); }

#else

inline uint8_t readFlashU8(const uint8_t* p) { return *p; }
inline uint16_t readFlashU16(const uint16_t* p) { return *p; }
inline uint32_t readFlashU32(const uint32_t* p) { return *p; }

#endif

inline int8_t readFlashI8(const int8_t* p) {
  return int8_t(readFlashU8(reinterpret_cast<const uint8_t*>(p)));
}
inline int16_t readFlashI16(const int16_t* p) {
  return int16_t(readFlashU16(reinterpret_cast<const uint16_t*>(p)));
}
inline int32_t readFlashI32(const int32_t* p) {
  return int32_t(readFlashU32(reinterpret_cast<const uint32_t*>(p)));
}

}  // namespace platform
}  // namespace tinyparticle
