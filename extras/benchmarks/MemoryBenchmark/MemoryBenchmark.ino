// MemoryBenchmark: what each engine feature adds to flash, RAM and the cost of
// a step, as a cumulative ladder (Ladder.h lists the rungs). Build it once per
// rung with FEATURE = 0..12, SCALAR = 1 (Q16_16) or 2 (Float) and DIM = 2 or
// 3; extras/benchmarks/tools/bench.py does that and reads the sizes. Beside
// the ladder, SCENE = 1 builds a whole scene instead of a rung: the lever
// alone (LeverScene.h; SCALAR as above, always 2D); SCENE = 2 that lever and
// a second one in a World of another type (TwoWorlds.h).
//
// As built for the sizes, a rung only builds its world and steps it forever.
// With BENCH_CYCLES=1 it also reports the mean cycles of a step over 256 steps
// on Serial ("R <feature, or S<scene>> <cycles per step>", then "E"); that
// build carries Serial and the timer, so its sizes are not the rung's.
#ifndef FEATURE
#define FEATURE 1
#endif
#ifndef SCENE
#define SCENE 0
#endif
#ifndef BENCH_CYCLES
#define BENCH_CYCLES 0
#endif

#define MEMORY_TEXT(x) #x
#define MEMORY_LABEL(x) MEMORY_TEXT(x)
#if SCENE == 1
#include "LeverScene.h"
namespace measured = leverScene;
#define MEASURED 1
#define ROW_LABEL "S" MEMORY_LABEL(SCENE)
#elif SCENE == 2
#include "TwoWorlds.h"
namespace measured = twoWorlds;
#define MEASURED 1
#define ROW_LABEL "S" MEMORY_LABEL(SCENE)
#elif SCENE != 0
#error "SCENE must be 0 (a rung of the ladder), 1 (the lever scene) or 2 (two World types)"
#elif FEATURE > 0
#include "Ladder.h"
namespace measured = ladder;
#define MEASURED 1
#define ROW_LABEL MEMORY_LABEL(FEATURE)
#else
#define MEASURED 0
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
#if MEASURED
  measured::build();
#endif
#if BENCH_CYCLES
  Serial.begin(115200);
  while (!Serial) {
  }
  Serial.flush();
  cycles::begin();
#if MEASURED
  const uint16_t kSteps = 256;
  uint32_t total = 0;
  for (uint16_t i = 0; i < kSteps; ++i) {
    cycles::start();
    measured::step();
    total += cycles::stop();
  }
  // The empty window (start then stop) is measured and taken out.
  cycles::start();
  uint32_t empty = cycles::stop();
  Serial.print(F("R " ROW_LABEL " "));
  Serial.println((total - kSteps * empty + kSteps / 2) / kSteps);
  Serial.print(F("# errors world "));
  Serial.print(measured::gWorld.error());
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
#if MEASURED
  measured::step();
#endif
}
