// The lists of operations AutoBenchmark runs, per type. In a header rather
// than in the .ino, because the Arduino builder's prototype generation does
// not cope with function templates in a sketch.
#pragma once

#include <TinyParticle.h>

#include "Harness.h"
#include "Ops.h"

namespace bench {

// The four arithmetic operations of an integer type.
template <typename T, typename U>
void runIntegers(const __FlashStringHelper* name) {
  Fill arith = Pools<T>::arithmetic;
  runBinary<IntAdd<T, U> >(name, F("add"), kSeedArithmetic, arith);
  runBinary<IntSub<T, U> >(name, F("sub"), kSeedArithmetic, arith);
  runBinary<IntMul<T, U> >(name, F("mul"), kSeedArithmetic, arith);
  runBinary<IntDiv<T> >(name, F("div"), kSeedArithmetic, arith);
}

// Everything a scalar of the library offers.
template <typename S>
void runScalar(const __FlashStringHelper* name) {
  typedef Pools<S> Pool;
  runBinary<Add<S> >(name, F("add"), kSeedArithmetic, Pool::arithmetic);
  runBinary<Sub<S> >(name, F("sub"), kSeedArithmetic, Pool::arithmetic);
  runBinary<Mul<S> >(name, F("mul"), kSeedArithmetic, Pool::arithmetic);
  runBinary<Div<S> >(name, F("div"), kSeedArithmetic, Pool::arithmetic);
  runUnary<Sqrt<S> >(name, F("sqrt"), kSeedPositive, Pool::positive);
  runBinary<Atan2<S> >(name, F("atan2"), kSeedArithmetic, Pool::arithmetic);
  runUnary<Sin<S> >(name, F("sin"), kSeedAngles, Pool::angles);
  runUnary<Cos<S> >(name, F("cos"), kSeedAngles, Pool::angles);
  runUnary<SinTurns<S> >(name, F("sin_turns"), kSeedTurns, fillTurns);
  runUnary<CosTurns<S> >(name, F("cos_turns"), kSeedTurns, fillTurns);
  runVector<Magnitude<S, 2> >(name, F("mag2"), kSeedVec2,
                              Pool::template vectors<2>);
  runVector<Normalize<S, 2> >(name, F("norm2"), kSeedVec2,
                              Pool::template vectors<2>);
  runVector<Magnitude<S, 3> >(name, F("mag3"), kSeedVec3,
                              Pool::template vectors<3>);
  runVector<Normalize<S, 3> >(name, F("norm3"), kSeedVec3,
                              Pool::template vectors<3>);
}

inline void runSeed() {
  const __FlashStringHelper* name = F("seed_Q16.16");
  typedef Pools<Q16_16> Pool;
  runBinary<SeedAdd>(name, F("add"), kSeedArithmetic, Pool::arithmetic);
  runBinary<SeedSub>(name, F("sub"), kSeedArithmetic, Pool::arithmetic);
  runBinary<SeedMul>(name, F("mul"), kSeedArithmetic, Pool::arithmetic);
  runBinary<SeedDiv>(name, F("div"), kSeedArithmetic, Pool::arithmetic);
  runUnary<SeedSqrt>(name, F("sqrt"), kSeedPositive, Pool::positive);
  runBinary<SeedAtan2>(name, F("atan2"), kSeedArithmetic, Pool::arithmetic);
  runVector<SeedMagnitude>(name, F("mag3"), kSeedVec3, Pool::vectors<3>);
  runVector<SeedNormalize>(name, F("norm3"), kSeedVec3, Pool::vectors<3>);
}

// The quick check: a few operations, one chunk each.
inline void runQuick() {
  runBinary<Mul<Q16_16> >(F("Q16.16"), F("mul"), kSeedArithmetic,
                          Pools<Q16_16>::arithmetic);
  runUnary<Sqrt<Q16_16> >(F("Q16.16"), F("sqrt"), kSeedPositive,
                          Pools<Q16_16>::positive);
  runBinary<Mul<Float> >(F("float"), F("mul"), kSeedArithmetic,
                         Pools<Float>::arithmetic);
  runBinary<SeedMul>(F("seed_Q16.16"), F("mul"), kSeedArithmetic,
                     Pools<Q16_16>::arithmetic);
}

}  // namespace bench
