// The determinism scenes (Determinism/DeterminismScenes.h) on the host
// (x86-64) and on 32-bit ARM (arm-none-eabi, newlib semihosting, run by
// qemu-arm): the same lines as the Nano sketch.
#include <stdio.h>

#include "Determinism/DeterminismScenes.h"

static void report(const char* scene, uint16_t step, uint32_t hash) {
  printf("DETERMINISM %s %u %lX\n", scene, unsigned(step), (unsigned long) hash);
}

int main() {
  determinism::all(&report);
  printf("DETERMINISM done\n");
  return 0;
}
