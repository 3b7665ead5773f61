// AutoBenchmark: what each arithmetic operation costs on an ATmega328P, in
// CPU cycles, for int16, int32, int64, Q8.8, Q16.16, Q24.8 and float, with the
// seed engine's Q16.16 (rebuilt in SeedFixed.h) as the baseline.
//
// It prints, for each operation, the operands and results it computed
// ("S ..." lines, hex bits) and its cost ("C <type> <op> <cycles per call>
// <cycles inlined> <samples>"); extras/benchmarks/tools/ops.py turns that into
// ops.csv with the errors against a double-precision reference. The method is
// described in Harness.h. Runs on a Nano (Serial at 115200) or in simavr.
//
// Everything does not fit in 32 KB of flash at once, so BENCH_GROUP picks one
// part: 1 = int16, int32, int64; 2 = Q8.8; 3 = Q16.16; 4 = Q24.8; 5 = float;
// 6 = the seed's Q16.16. On a board, edit the default below and upload once
// per group. BENCH_QUICK=1 measures a few operations only (the check that
// `make test` runs, with BENCH_CHUNKS=1: 32 operand sets instead of 256).
#include <TinyParticle.h>

#include "Harness.h"
#include "Suites.h"

#ifndef BENCH_QUICK
#define BENCH_QUICK 0
#endif
#ifndef BENCH_GROUP
#define BENCH_GROUP 3
#endif

using namespace bench;

void setup() {
  Serial.begin(115200);
  while (!Serial) {
  }
  bench::begin();
#if BENCH_QUICK
  runQuick();
#elif BENCH_GROUP == 1
  runIntegers<int16_t, uint16_t>(F("int16"));
  runIntegers<int32_t, uint32_t>(F("int32"));
  runIntegers<int64_t, uint64_t>(F("int64"));
#elif BENCH_GROUP == 2
  runScalar<Q8_8>(F("Q8.8"));
#elif BENCH_GROUP == 3
  runScalar<Q16_16>(F("Q16.16"));
#elif BENCH_GROUP == 4
  runScalar<Q24_8>(F("Q24.8"));
#elif BENCH_GROUP == 5
  runScalar<Float>(F("float"));
#elif BENCH_GROUP == 6
  runSeed();
#else
#error "BENCH_GROUP must be 1 to 6"
#endif
  bench::end();
}

void loop() {}
