// The only place that includes <Arduino.h>. Everything else in the library
// builds without an Arduino core (the compile checks prove it); what needs
// the board (clock, pins, flash strings, Print) goes through here.
#pragma once

#if defined(ARDUINO)
#include <Arduino.h>
#define TINYPARTICLE_HAS_ARDUINO 1
#else
#define TINYPARTICLE_HAS_ARDUINO 0
#endif
