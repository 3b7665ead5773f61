// What a sketch sees before any library header: ArduinoCore-avr's Arduino.h
// defines these names as function-like macros. Forced in front of
// Instantiate.cpp (-include), it makes the library fail to build if it uses
// one of them as a name (e.g. a member function called max()), as it would
// fail in a real sketch. Like Arduino.h, it includes the C headers first, so
// that their declarations are made before the macros exist.
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#if defined(__AVR__)
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#endif

#undef abs
#define min(a, b) ((a) < (b) ? (a) : (b))
#define max(a, b) ((a) > (b) ? (a) : (b))
#define abs(x) ((x) > 0 ? (x) : -(x))
#define constrain(amt, low, high) ((amt) < (low) ? (low) : ((amt) > (high) ? (high) : (amt)))
#define round(x) ((x) >= 0 ? (long) ((x) + 0.5) : (long) ((x) - 0.5))
#define radians(deg) ((deg) * 0.017453292519943295769236907684886)
#define degrees(rad) ((rad) * 57.295779513082320876798154814105)
#define sq(x) ((x) * (x))
