// The lever scene alone, as issue 12 measures it and as a new user would
// write it: a LeverWorld in 2D, buildLever(), a step of constant dt in
// loop(), and the end's height written to a volatile so that the step is
// kept. SCALAR 1 (Q16_16) writes the raw Q16.16 bits, 2 (Float) the float.
// MemoryBenchmark builds it with SCENE=1; it is a row beside the ladder, not
// a rung of it.
#pragma once

#include "Scalar.h"

namespace leverScene {

using measuredScalar::S;
using measuredScalar::Stored;
using measuredScalar::stored;

LeverWorld<S, 2> gWorld;
Vec2<S> gPush;  // the user's force: zero here, so the lever falls and swings
LeverScene gLever;
volatile Stored gEndY;

inline void build() { gLever = buildLever(gWorld, &gPush); }

inline void step() {
  gWorld.step(S(1.0 / 256));
  gEndY = stored(gWorld.particle(gLever.end)->position.y);
}

}  // namespace leverScene
