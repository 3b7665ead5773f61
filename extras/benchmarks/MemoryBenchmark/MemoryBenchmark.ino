// MemoryBenchmark: what each engine feature adds to flash, RAM and the cost of
// a step, as a cumulative ladder (Ladder.h lists the rungs). Build it once per
// rung with FEATURE = 0..12, SCALAR = 1 (Q16_16) or 2 (Float) and DIM = 2 or
// 3; extras/benchmarks/tools/bench.py does that and reads the sizes.
//
// As built for the sizes, a rung only builds its world and steps it forever.
// With BENCH_CYCLES=1 it also reports the mean cycles of a step over 256 steps
// of 1/256 s on Serial ("R <feature> <cycles per step>", then "E"); that
// build carries Serial and the timer, so its sizes are not the rung's.
#ifndef FEATURE
#define FEATURE 1
#endif
#ifndef BENCH_CYCLES
#define BENCH_CYCLES 0
#endif

#if FEATURE > 0
#include "Ladder.h"
#endif
#if BENCH_CYCLES
#include <TinyParticle.h>
#include <TinyParticle/Testing/CycleCounter.hpp>
#include <avr/sleep.h>
// The Timer1 cycle counter the benchmarks share (in the library, as a sketch
// folder cannot include another's files).
namespace cycles = tinyparticle::testing::cycles;
#endif

void setup() {
#if FEATURE > 0
  ladder::build();
#endif
#if BENCH_CYCLES
  Serial.begin(115200);
  while (!Serial) {
  }
  Serial.flush();
  cycles::begin();
#if FEATURE > 0
  const uint16_t kSteps = 256;
  uint32_t total = 0;
  for (uint16_t i = 0; i < kSteps; ++i) {
    cycles::start();
    ladder::step();
    total += cycles::stop();
  }
  // The empty window (start then stop) is measured and taken out.
  cycles::start();
  uint32_t empty = cycles::stop();
  Serial.print(F("R "));
  Serial.print(FEATURE);
  Serial.write(' ');
  Serial.println((total - kSteps * empty + kSteps / 2) / kSteps);
  Serial.print(F("# errors world "));
  Serial.print(ladder::gWorld.error());
  Serial.print(F(" math "));
  Serial.println(mathErrors());
#endif
  Serial.println(F("E"));
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
#endif
}

void loop() {
#if FEATURE > 0
  ladder::step();
#endif
}
