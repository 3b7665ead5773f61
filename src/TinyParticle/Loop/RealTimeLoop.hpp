// A real-time stepping loop: fixed physics steps that keep up with a clock,
// and a frame rate for rendering.
//
//   RealTimeLoop timing(256, 10);   // dt = 1/256 s, 10 frames per second
//   void loop() {
//     timing.runSteps(world);       // the steps that are due, of dt each
//     if (timing.frameDue()) renderer.draw(world, Serial);
//   }
//
// The loop is the one place that knows the step: runSteps() steps the world
// by dt<Scalar>(), and a sketch that needs dt elsewhere (a stiff spring's
// gains, its own stepping) asks timing.dt<S>() rather than writing it again.
//
// Compared with the seed (section 3.3), whose step length followed the time
// the last frame took: the step is always the same dt, so the simulation
// does not depend on how fast the board or the serial line is; when the
// sketch falls behind it catches up with at most maxCatchUp steps per call
// and then lets the clock slip (counted in slippedSteps()) instead of
// spiralling; a frame waits until the physics has caught up, but never more
// than one extra frame period; and nothing busy-waits unless the sketch asks
// for it with waitForStep(), which waits at most one step.
//
// The schedule is exact over time: a step period that is not a whole number
// of microseconds (1/256 s = 3906.25 us) carries its fraction.
#pragma once

#include <stdint.h>

#include "../Math/Fixed.hpp"
#include "../Math/Float.hpp"
#include "../Platform/Clock.hpp"
#include "../Configuration.hpp"  // detail::throughPointer()

namespace tinyparticle {

namespace detail {

// 1 / n seconds (n > 0) in the scalar, from q = floor(2^31 / n), which the
// constructor computes: rounding q to a fixed-point format's fraction bits
// (halves up) gives 1 / n to the nearest unit, exactly as
// (2^FracBits + n/2) / n does, with an add and a shift at run time instead
// of a 32-bit division (some 600 cycles on an AVR). Exact because a tie
// between two units is a whole number of q's units (for up to 30 fraction
// bits), so the part of 2^31 / n that floor() drops never moves the value
// across one.
template <typename S>
struct Reciprocal;
template <uint8_t IntBits, uint8_t FracBits>
struct Reciprocal<Fixed<IntBits, FracBits> > {
  static_assert(FracBits <= 30, "dt needs at most 30 fraction bits");
  static Fixed<IntBits, FracBits> of(uint32_t q, uint16_t) {
    typedef Fixed<IntBits, FracBits> S;
    const uint8_t shift = uint8_t(31 - FracBits);
    const uint32_t half = uint32_t(1) << (shift - 1);
    return S::fromRaw(typename S::Raw((q + half) >> shift));
  }
};
template <>
struct Reciprocal<Float> {
  static Float of(uint32_t, uint16_t n) { return Float(1.0f / float(n)); }
};

}  // namespace detail

template <class Clock>
class BasicRealTimeLoop {
 public:
  // stepsPerSecond: 1 / dt (> 0; 0 is taken as 1). framesPerSecond: 0 for
  // no frames. constexpr: a global loop costs no start-up code.
  constexpr BasicRealTimeLoop(uint16_t stepsPerSecond, uint16_t framesPerSecond,
                    uint8_t maxCatchUp = 8)
      : mStepWhole(1000000UL / atLeastOne(stepsPerSecond)),
        mStepFraction(uint16_t(1000000UL % atLeastOne(stepsPerSecond))),
        mStepsPerSecond(atLeastOne(stepsPerSecond)),
        mFramePeriod(framesPerSecond == 0 ? 0 : 1000000UL / framesPerSecond),
        mMaxCatchUp(maxCatchUp == 0 ? 1 : maxCatchUp),
        mFractionSum(0),
        mNextStep(0),
        mNextFrame(0),
        mSteps(0),
        mSlipped(0),
        mStarted(false),
        mStepQ31(0x80000000UL / atLeastOne(stepsPerSecond)) {}

  // Starts the schedule now (stepsDue() also does this on its first call).
  void start() {
    const uint32_t now = Clock::micros();
    mNextStep = now;
    mNextFrame = now;
    mFractionSum = 0;
    mStarted = true;
  }

  // The number of steps to run now, 0 to maxCatchUp. If even more are due,
  // the backlog is dropped and the schedule restarts from now.
  // (Through a pointer the compiler does not know, here and in frameDue():
  // a global loop's members are then reached with 2-byte instructions on
  // an AVR rather than 4-byte ones at fixed addresses: 134 B less in
  // HapticLever.)
  uint8_t stepsDue() { return detail::throughPointer(this)->countDue(); }

  // True when a frame should be drawn: its time has come and no step is
  // due (or it has already waited a whole extra frame period).
  bool frameDue() { return detail::throughPointer(this)->takeFrame(); }

 private:
  uint8_t countDue() {
    if (!mStarted) start();
    const uint32_t now = Clock::micros();
    uint8_t due = 0;
    // One place advances the schedule (its code is then in flash once).
    while (reached(now, mNextStep)) {
      if (due == mMaxCatchUp) {
        // Still behind after the most we may run: let the clock slip.
        mSlipped += (now - mNextStep) / mStepWhole + 1;
        mNextStep = now;
      } else {
        ++due;
      }
      advanceStep();
    }
    mSteps += due;
    return due;
  }

  bool takeFrame() {
    if (mFramePeriod == 0 || !mStarted) return false;
    const uint32_t now = Clock::micros();
    if (!reached(now, mNextFrame)) return false;
    const bool behind = reached(now, mNextStep);
    if (behind && now - mNextFrame < mFramePeriod) return false;
    mNextFrame += mFramePeriod;
    if (reached(now, mNextFrame)) mNextFrame = now + mFramePeriod;
    return true;
  }

 public:
  // Waits until the next step is due: at most one step period.
  void waitForStep() const {
    while (!reached(Clock::micros(), mNextStep)) {
    }
  }

  // Microseconds until the next step is due (0 if it is due).
  uint32_t microsToNextStep() const {
    const uint32_t now = Clock::micros();
    return reached(now, mNextStep) ? 0 : mNextStep - now;
  }

  // The step, dt = 1 / stepsPerSecond s, in the scalar S: the nearest
  // value for fixed point (exact for powers of two: 1/256 s in Q16_16).
  template <typename S>
  S dt() const {
    return detail::Reciprocal<S>::of(mStepQ31, mStepsPerSecond);
  }

  // Runs the steps that are due now (stepsDue()) on `world`, each of
  // dt<Scalar>(); returns how many ran (0 to maxCatchUp).
  template <class W>
  uint8_t runSteps(W& world) {
    const uint8_t due = stepsDue();
    if (due == 0) return 0;
    const typename W::Scalar step = dt<typename W::Scalar>();
    for (uint8_t n = due; n > 0; --n) world.step(step);
    return due;
  }

  uint32_t steps() const { return mSteps; }
  // Steps that were due but never run, because the sketch fell behind.
  uint32_t slippedSteps() const { return mSlipped; }
  uint16_t stepsPerSecond() const { return mStepsPerSecond; }

 private:
  static constexpr uint16_t atLeastOne(uint16_t n) { return n == 0 ? 1 : n; }

  // now >= t on a wrapping clock (valid for spans below 35 minutes).
  static bool reached(uint32_t now, uint32_t t) {
    return (now - t) < 0x80000000UL;
  }

  void advanceStep() {
    mNextStep += mStepWhole;
    uint32_t sum = uint32_t(mFractionSum) + mStepFraction;
    if (sum >= mStepsPerSecond) {
      sum -= mStepsPerSecond;
      ++mNextStep;
    }
    mFractionSum = uint16_t(sum);
  }

  const uint32_t mStepWhole;      // whole microseconds per step
  const uint16_t mStepFraction;   // and this many 1/stepsPerSecond us
  const uint16_t mStepsPerSecond;
  const uint32_t mFramePeriod;    // us, 0: no frames
  const uint8_t mMaxCatchUp;
  uint16_t mFractionSum;
  uint32_t mNextStep;
  uint32_t mNextFrame;
  uint32_t mSteps;
  uint32_t mSlipped;
  bool mStarted;
  // Last, so that the fields before keep their offsets (the device
  // simulator in extras/hil reads mSteps and mSlipped by offset).
  const uint32_t mStepQ31;        // floor(2^31 / stepsPerSecond)
};

#if TINYPARTICLE_HAS_ARDUINO
typedef BasicRealTimeLoop<ArduinoClock> RealTimeLoop;
#endif

}  // namespace tinyparticle
