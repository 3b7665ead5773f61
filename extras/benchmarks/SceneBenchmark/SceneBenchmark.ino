// SceneBenchmark: the cost of a step of whole scenes on an ATmega328P, and
// the state they reach, for comparison with a double-precision run of the same
// scene on the PC (extras/benchmarks/host/SceneReference.cpp).
//
// One build runs one scene with one scalar and one step (SceneRun.h):
//   SCENE   1 lever, 2 pendulum, 3 spring, 4 balls (BALLS of them),
//           5 chain (BALLS beads), 6 rope, 7 pendulum_short, 8 pile (BALLS
//           of them), 9 elastic_box (BALLS), 10 cradle
//   SCALAR  1 Q16_16, 2 Q24_8, 3 Float
//   DIM     2 or 3
//   RATE    steps per second, dt = 1 / RATE s (e.g. 1024, 256, 64, 200)
//   SECONDS scene time to run (10 by default)
// It prints "C ..." cycle sums for every eighth of a second as it runs,
// "P ..." state lines at 0, 1 and 10 s and at the end, "M ..." the largest
// link and energy errors, "T ..." cycle sums, "W ..." error flags, then "E",
// and sleeps (which ends a simavr run). A chain of 16 beads does
// not fit in the Nano's RAM: it runs on an ATmega2560 (nano-build --mega).
// extras/benchmarks/tools/bench.py builds and runs every combination.
#ifndef SCENE
#define SCENE 1
#endif
#ifndef BALLS
#define BALLS 2
#endif
#ifndef SCALAR
#define SCALAR 1
#endif
#ifndef DIM
#define DIM 2
#endif
#ifndef RATE
#define RATE 256
#endif
#ifndef SECONDS
#define SECONDS 10
#endif

#include <TinyParticle.h>
#include <avr/sleep.h>

#include "SceneRun.h"
#include "TargetReport.h"

#if SCALAR == 1
typedef Q16_16 Scalar;
#elif SCALAR == 2
typedef Q24_8 Scalar;
#elif SCALAR == 3
typedef Float Scalar;
#else
#error "SCALAR must be 1, 2 or 3"
#endif

typedef scenebench::SceneSpec<Scalar, DIM, SCENE, BALLS> Spec;

void setup() {
  scenebench::paintStack();
  Serial.begin(115200);
  while (!Serial) {
  }
  Serial.print(F("# scene "));
  Serial.print(SCENE);
  Serial.print(F(" balls "));
  Serial.print(BALLS);
  Serial.print(F(" scalar "));
  Serial.print(SCALAR);
  Serial.print(F(" dim "));
  Serial.print(DIM);
  Serial.print(F(" rate "));
  Serial.print(RATE);
  Serial.print(F(" seconds "));
  Serial.println(SECONDS);
  Serial.flush();
  cycles::begin();
  scenebench::TargetReport report;
  scenebench::runScene<Spec, float>(report, RATE, SECONDS);
  Serial.println(F("E"));
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
}

void loop() {}
