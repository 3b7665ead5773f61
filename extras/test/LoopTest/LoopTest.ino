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
// The constructor is constexpr: a global loop needs no start-up code (this
// does not compile otherwise).
constexpr Loop kConstantLoop(1000, 30);

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

// dt<S>() is 1 / stepsPerSecond to the nearest unit: 1/256 s is 256 units
// of 2^-16 exactly; 1/1000 s is 65.536 units, so 66; 1/3 s in Q24_8 is
// 85.33 units, so 85; Float's is the float nearest to 1/1000.
test(StepLength) {
  assertEqual((long) Loop(256, 0).dt<Q16_16>().raw(), 256L);
  assertEqual((long) Loop(1000, 0).dt<Q16_16>().raw(), 66L);
  assertEqual((long) Loop(3, 0).dt<Q24_8>().raw(), 85L);
  assertEqual((long) Loop(1, 0).dt<Q8_8>().raw(), 256L);
  assertTrue(Loop(1000, 0).dt<Float>().toFloat() == 1.0f / 1000);
  // 0 steps a second is taken as 1 (no division by zero): dt = 1 s.
  assertEqual((int) Loop(0, 0).stepsPerSecond(), 1);
  assertEqual((long) Loop(0, 0).dt<Q16_16>().raw(), 65536L);
}

// dt<S>() comes from floor(2^31 / n), rounded to the format's fraction
// bits: it must equal the nearest unit, (2^F + n/2) / n, for every rate.
// Classes: powers of two (q exact), odd parts up to the largest (where the
// dropped part of q is closest to moving a value across a tie), the most
// fraction bits (Fixed<2, 30>: one bit to spare). Every rate on the host;
// on the Nano every power of two and a stride.
template <typename S>
struct Nearest {
  static bool dt(uint16_t n) {
    const uint32_t one = uint32_t(1) << S::kFracBits;
    return uint32_t(Loop(n, 0).dt<S>().raw()) == (one + n / 2) / n;
  }
};

test(StepLengthEveryRate) {
#ifdef EPOXY_DUINO
  const uint16_t stride = 1;
#else
  const uint16_t stride = 251;
#endif
  for (uint32_t n = 1; n <= 65535; n += stride) {
    assertTrue(Nearest<Q16_16>::dt(uint16_t(n)));
    assertTrue(Nearest<Q24_8>::dt(uint16_t(n)));
    assertTrue(Nearest<Q8_8>::dt(uint16_t(n)));
    assertTrue((Nearest<Fixed<2, 30> >::dt(uint16_t(n))));
  }
  for (uint32_t n = 1; n <= 65535; n *= 2) {
    assertTrue(Nearest<Q16_16>::dt(uint16_t(n)));
    assertTrue(Nearest<Q8_8>::dt(uint16_t(n)));
  }
  assertTrue(Nearest<Q16_16>::dt(65535));
}

// runSteps() steps the world as often as stepsDue() says, by dt<S>():
// 10 ms at 256 steps a second covers the steps due at 0, 3.9 and 7.8 ms.
struct CountingWorld {
  typedef Q16_16 Scalar;
  uint8_t steps;
  Q16_16 last;
  CountingWorld() : steps(0), last() {}
  void step(Q16_16 dt) {
    ++steps;
    last = dt;
  }
};

test(RunSteps) {
  FakeClock::now = 0;
  Loop timing(256, 0);
  timing.start();
  CountingWorld world;
  FakeClock::now = 10000;
  assertEqual((int) timing.runSteps(world), 3);
  assertEqual((int) world.steps, 3);
  assertEqual((long) world.last.raw(), 256L);
  assertEqual((int) timing.runSteps(world), 0);
  assertEqual((int) world.steps, 3);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
