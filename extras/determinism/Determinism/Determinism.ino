// The determinism scenes on the Nano (see DeterminismScenes.h): prints one
// line "DETERMINISM <scene> <step> <hash>" per checkpoint, then
// "DETERMINISM done", then sleeps (simavr stops). Built by
// extras/determinism/compare with and without TINYPARTICLE_AVR_ASM.
#include <TinyParticle.h>
#include <avr/sleep.h>

#include "DeterminismScenes.h"

static void report(const char* scene, uint16_t step, uint32_t hash) {
  Serial.print(F("DETERMINISM "));
  Serial.print(scene);
  Serial.print(' ');
  Serial.print(step);
  Serial.print(' ');
  Serial.println(hash, HEX);
}

void setup() {
  Serial.begin(115200);
  determinism::all(&report);
  Serial.println(F("DETERMINISM done"));
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
}

void loop() {}
