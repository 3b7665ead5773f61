// The real-time loop against a fake clock: the exact long-term step rate,
// the catch-up cap, and frames that wait for the physics but not forever.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

// A clock the test moves by hand.
struct FakeClock {
  static uint32_t now;
  static uint32_t micros() { return now; }
};
uint32_t FakeClock::now = 0;

typedef BasicRealTimeLoop<FakeClock> Loop;

// Polls every millisecond for `seconds`, running what is due; returns the
// steps run. `frames` gets the frames drawn.
static uint32_t poll(Loop& timing, uint16_t seconds, uint16_t* frames) {
  uint32_t steps = 0;
  *frames = 0;
  for (uint32_t ms = 1; ms <= 1000UL * seconds; ++ms) {
    FakeClock::now = ms * 1000;
    steps += timing.stepsDue();
    if (timing.frameDue()) ++*frames;
  }
  return steps;
}

// 256 steps a second, a step every 3906.25 us, due at 0, 3906.25, ...:
// those due up to 10 s are 2561, with no drift from the quarter
// microsecond. Frames at 10 per second, due at 0, 100 ms, ..., 10 s: 101.
test(ExactStepRate) {
  FakeClock::now = 0;
  Loop timing(256, 10);
  timing.start();
  uint16_t frames;
  assertEqual((unsigned long) poll(timing, 10, &frames), 2561UL);
  assertEqual((int) frames, 101);
  assertEqual((unsigned long) timing.slippedSteps(), 0UL);
}

// A 100 ms stall: 26 steps were due (0 to 97.66 ms); 8 run at once, the
// other 18 are dropped and counted, and the schedule restarts from now.
test(CatchUpCap) {
  FakeClock::now = 0;
  Loop timing(256, 0, 8);
  timing.start();
  FakeClock::now = 100000;
  assertEqual((int) timing.stepsDue(), 8);
  assertEqual((unsigned long) timing.slippedSteps(), 18UL);
  FakeClock::now = 101000;
  assertEqual((int) timing.stepsDue(), 0);
  FakeClock::now = 104000;
  assertEqual((int) timing.stepsDue(), 1);
}

// While steps are pending a frame waits, but at most one extra period.
test(FrameWaitsForPhysics) {
  FakeClock::now = 0;
  Loop timing(256, 10);
  timing.start();
  timing.stepsDue();
  assertTrue(timing.frameDue());  // the first frame, at 0
  FakeClock::now = 150000;        // steps pending: the sketch fell behind
  assertFalse(timing.frameDue());
  FakeClock::now = 200000;        // a whole period late: draw anyway
  assertTrue(timing.frameDue());
  FakeClock::now = 210000;
  assertFalse(timing.frameDue());
}

// waitForStep() returns at once when a step is due; microsToNextStep()
// tells how long until the next one.
test(NextStep) {
  FakeClock::now = 0;
  Loop timing(256, 0);
  timing.start();
  assertEqual((int) timing.stepsDue(), 1);
  FakeClock::now = 1000;
  assertEqual((unsigned long) timing.microsToNextStep(), 2906UL);
  FakeClock::now = 3906;
  timing.waitForStep();  // due: returns at once
  assertEqual((unsigned long) timing.microsToNextStep(), 0UL);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
