// What the Nano reports during a scene run: the cycles of every step (summed
// over the first 2 s, over the last second, and over every eighth of a
// second for the cycles-against-time plot), the state of every particle
// at t = 0, 1 s, 10 s and at the end, as the exact bits of the scalar in hex,
// and the largest link and energy errors of the run.
#pragma once

#include <Arduino.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/CycleCounter.hpp>
#include <string.h>

// The Timer1 cycle counter the benchmarks share (in the library, as a sketch
// folder cannot include another's files).
namespace cycles = tinyparticle::testing::cycles;

namespace scenebench {

inline void printHex(uint32_t v, uint8_t digits) {
  Serial.write(' ');
  while (digits-- > 0) {
    uint8_t nibble = uint8_t(v >> (4 * digits)) & 0xF;
    Serial.write(nibble < 10 ? '0' + nibble : 'a' + nibble - 10);
  }
}

template <uint8_t I, uint8_t F>
inline void printScalar(Fixed<I, F> v) {
  printHex(uint32_t(v.raw()), (I + F) / 4);
}
inline void printScalar(Float v) {
  float f = v.toFloat();
  uint32_t bits;
  memcpy(&bits, &f, sizeof(bits));
  printHex(bits, 8);
}

// Stack headroom: the free RAM between the end of the static data and the
// stack is filled with a pattern at start-up; what is still intact at the end
// was never reached by the stack. (Nothing here uses the heap.)
extern "C" uint8_t __heap_start;
const uint8_t kPaint = 0xA5;

inline void paintStack() {
  uint8_t here;
  for (uint8_t* p = &__heap_start; p < &here - 32; ++p) *p = kPaint;
}

inline uint16_t stackHeadroom() {
  uint16_t n = 0;
  for (const uint8_t* p = &__heap_start; p < (const uint8_t*)RAMEND && *p == kPaint;
       ++p) {
    ++n;
  }
  return n;
}

class TargetReport {
 public:
  TargetReport()
      : mFirst(0), mFirstSteps(0), mLast(0), mLastSteps(0), mFirst300(0),
        mWindow(0), mSlice(0), mSliceSteps(0), mSlices(0) {
    // The empty measuring window, taken out of every step.
    cycles::start();
    mWindow = cycles::stop();
  }

  void beforeStep() { cycles::start(); }

  void afterStep(uint32_t step, uint16_t perSecond, uint8_t seconds) {
    uint32_t spent = cycles::stop() - mWindow;
    if (step <= 300) mFirst300 += spent;
    if (step <= 2 * uint32_t(perSecond)) {
      mFirst += spent;
      ++mFirstSteps;
    }
    if (step > uint32_t(seconds - 1) * perSecond) {
      mLast += spent;
      ++mLastSteps;
    }
    // "C <eighth of a second> <cycles> <steps>", outside the timed span.
    mSlice += spent;
    ++mSliceSteps;
    const uint16_t perSlice = perSecond >= 8 ? perSecond / 8 : 1;
    if (mSliceSteps >= perSlice) {
      Serial.print(F("C "));
      Serial.print(mSlices++);
      Serial.write(' ');
      Serial.print(mSlice);
      Serial.write(' ');
      Serial.println(mSliceSteps);
      Serial.flush();
      mSlice = 0;
      mSliceSteps = 0;
    }
  }

  // "P <t> <index> <inverse mass> <position...> <velocity...>"
  template <class W>
  void state(const W& world, uint8_t seconds) {
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const typename W::ParticleType& p = world.particleAt(i);
      if (!p.inUse()) continue;
      Serial.print(F("P "));
      Serial.print(seconds);
      Serial.write(' ');
      Serial.print(i);
      printScalar(p.inverseMass);
      for (uint8_t k = 0; k < W::kDimensions; ++k) printScalar(p.position[k]);
      for (uint8_t k = 0; k < W::kDimensions; ++k) printScalar(p.velocity[k]);
      Serial.println();
    }
    Serial.flush();  // no UART interrupt inside the next timed step
  }

  // "M <largest link error> <largest energy error>" as float bits (the
  // energy error is negative where the scene has no reference energy).
  void errors(float link, float energy) {
    Serial.print(F("M"));
    printScalar(Float(link));
    printScalar(Float(energy));
    Serial.println();
    Serial.flush();
  }

  // "T <span> <cycles> <steps>" for the first 2 s, the last second and the
  // first 300 steps (the engine issue's lever figure), and the error flags
  // ("W <world error> <math errors>").
  template <class W>
  void finish(const W& world) {
    Serial.print(F("T first "));
    Serial.print(mFirst);
    Serial.write(' ');
    Serial.println(mFirstSteps);
    Serial.print(F("T last "));
    Serial.print(mLast);
    Serial.write(' ');
    Serial.println(mLastSteps);
    Serial.print(F("T first300 "));
    Serial.print(mFirst300);
    Serial.println(F(" 300"));
    Serial.print(F("W "));
    Serial.print(world.error());
    Serial.write(' ');
    Serial.println(mathErrors());
    Serial.print(F("# stack headroom "));
    Serial.println(stackHeadroom());
  }

 private:
  uint32_t mFirst;
  uint16_t mFirstSteps;
  uint32_t mLast;
  uint16_t mLastSteps;
  uint32_t mFirst300;
  uint32_t mWindow;
  uint32_t mSlice;       // cycles of the current eighth of a second
  uint16_t mSliceSteps;  // and its steps
  uint16_t mSlices;
};

}  // namespace scenebench
