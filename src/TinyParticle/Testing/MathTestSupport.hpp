// Test support for the math sketches (extras/test/Fixed*Test, extras/test/Vec*Test): a
// fixed-sequence random generator, random raw values of every bit length,
// exact values of fixed-point numbers, and a line that describes a failed
// operation.
//
// Not included by TinyParticle.h: include
// <TinyParticle/Testing/MathTestSupport.hpp> after it. Templates and inline
// functions only, so a sketch pays for what it calls.
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "../Platform/Arduino.hpp"

// Fixed texts of the failure lines: from flash on an Arduino.
#if TINYPARTICLE_HAS_ARDUINO
#define TINYPARTICLE_TESTING_TEXT(text) F(text)
#else
#define TINYPARTICLE_TESTING_TEXT(text) (text)
#endif

namespace tinyparticle {
namespace testing {

// xorshift32 (Marsaglia): the same sequence on every run and every target,
// so a failure found on the host can be replayed on the Nano. Each sketch
// keeps one generator with its own seed (the seed must not be 0).
class XorShift32 {
 public:
  explicit constexpr XorShift32(uint32_t seed) : mState(seed) {}

  uint32_t next() {
    uint32_t x = mState;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return mState = x;
  }

 private:
  uint32_t mState;
};

// A raw value of `bits` random bits (at most 31; 0 gives 0) with a random
// sign. Raw is the storage type (int16_t or int32_t) and must hold the bits.
template <typename Raw>
Raw randomRawOfLength(XorShift32& random, uint8_t bits) {
  const uint32_t m = bits == 0 ? 0 : random.next() >> (32 - bits);
  return (random.next() & 1) ? Raw(-int32_t(m)) : Raw(m);
}

// The same with a length drawn from 0..maxBits, each equally often: the
// magnitudes spread evenly on a log scale, so small and large values are
// tested alike.
template <typename Raw>
Raw randomRaw(XorShift32& random, uint8_t maxBits) {
  const uint8_t bits = uint8_t(random.next() % (maxBits + 1));
  return randomRawOfLength<Raw>(random, bits);
}

// The exact value of a fixed-point number (raw / 2^F) in a floating type
// (double on the host; on AVR double is float, exact for 24 bits).
template <typename Exact, typename T>
Exact exactValue(T x) {
  return Exact(x.raw()) / Exact(int32_t(1) << T::kFracBits);
}

// |v| without overflow, even for INT64_MIN.
inline uint64_t magnitude64(int64_t v) {
  return v < 0 ? uint64_t(0) - uint64_t(v) : uint64_t(v);
}

// Prints "<what> a=<a> b=<b> got <r>" on its own line: the operands and the
// result of a failed binary operation, in raw steps. Out is any Print-like
// output (Serial). Out of line: one copy however many checks call it.
template <typename Out, typename Text>
TINYPARTICLE_NOINLINE void printFailure(Out& out, Text what, long a, long b,
                                        long r) {
  out.print(what);
  out.print(TINYPARTICLE_TESTING_TEXT(" a="));
  out.print(a);
  out.print(TINYPARTICLE_TESTING_TEXT(" b="));
  out.print(b);
  out.print(TINYPARTICLE_TESTING_TEXT(" got "));
  out.println(r);
}

}  // namespace testing
}  // namespace tinyparticle
