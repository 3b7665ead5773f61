// Rigid links in Q16.16 (Contacts/RodSolver.hpp): chains keep their links
// and their energy at 256 and 1024 steps a second. Bounds (issue 9): link
// error <= 0.5 %, energy error <= 0.05 E_fall over 10 s. (RodCasesTest has
// the lever, loops, removal, mass ratio and a rod with a plane.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ChainChecks.hpp>

using aunit::TestRunner;
using tinyparticle::testing::ChainChecks;
using tinyparticle::testing::ChainResult;

typedef Q16_16 S;

test(chainOfEightAt256Hz) {
  const ChainResult r = ChainChecks<S>::run(8, 256, 2560);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
  assertEqual(r.error, (uint16_t) 0);
}

// The double pendulum at the coarse step too: issue 9 bounds chains of two
// and eight at both step rates.
test(doublePendulumAt256Hz) {
  const ChainResult r = ChainChecks<S>::run(2, 256, 2560);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
  assertEqual(r.error, (uint16_t) 0);
}

test(doublePendulumAt1024Hz) {
  const ChainResult r = ChainChecks<S>::run(2, 1024, 10240);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
  assertEqual(r.error, (uint16_t) 0);
}

#if defined(EPOXY_DUINO)
test(chainOfEightAt1024Hz) {
  const ChainResult r = ChainChecks<S>::run(8, 1024, 10240);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
}
#endif

#if defined(EPOXY_DUINO)
// Sixteen beads (issue 9 runs them on a simulated Mega: the Nano's RAM is
// too small). At 1024 steps a second, the bounds of eight.
test(chainOfSixteenAt1024Hz) {
  const ChainResult r = ChainChecks<S, 16>::run(16, 1024, 10240);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
  assertEqual(r.error, (uint16_t) 0);
}

// The whip at 256 steps a second: its end turns by tens of degrees in a
// step, the passes along the chain converge slowly or diverge, and such
// steps are taken as two halves (RodSolver::step()). The bounds of eight.
test(chainOfSixteenAt256Hz) {
  const ChainResult r = ChainChecks<S, 16>::run(16, 256, 2560);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
  assertEqual(r.error, (uint16_t) 0);
}
#endif

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);
}

void loop() { TestRunner::run(); }
