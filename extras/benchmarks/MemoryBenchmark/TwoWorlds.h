// Two World types in one sketch (issue 12: "the shared part once"): the
// lever scene's LeverWorld, and beside it a world of other capacities (3
// particles, 2 forces, 2 constraints) holding a second lever. Both are built
// with buildLever() and stepped with the same dt. Its flash minus the lever
// scene's is what a second World type costs a sketch: only what cannot be
// shared between the two types. MemoryBenchmark builds it with SCENE=2.
#pragma once

#include "Scalar.h"

namespace twoWorlds {

using measuredScalar::S;
using measuredScalar::Stored;
using measuredScalar::stored;

LeverWorld<S, 2> gWorld;        // the lever scene's world (its errors are reported)
World<S, 2, 3, 2, 2, 0> gOther;  // another type: other capacities
Vec2<S> gPush;
LeverScene gLever;
LeverScene gOtherLever;
volatile Stored gEndY;

inline void build() {
  gLever = buildLever(gWorld, &gPush);
  gOtherLever = buildLever(gOther, &gPush, S(0.3));
}

inline void step() {
  gWorld.step(S(1.0 / 256));
  gOther.step(S(1.0 / 256));
  // Both ends' heights reach the volatile (an xor of the raw bits, or a sum).
#if SCALAR == 1
  gEndY = stored(gWorld.particle(gLever.end)->position.y) ^
          stored(gOther.particle(gOtherLever.end)->position.y);
#else
  gEndY = stored(gWorld.particle(gLever.end)->position.y) +
          stored(gOther.particle(gOtherLever.end)->position.y);
#endif
}

}  // namespace twoWorlds
