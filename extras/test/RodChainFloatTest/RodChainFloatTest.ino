// Rigid links in Float (Contacts/RodSolver.hpp): the chain of eight and
// the double pendulum keep their links within 0.5 % and their energy within
// 0.05 E_fall over 10 s at 256 steps a second, and (on the host: float is
// slow on the Nano) at 1024 (bounds of issue 9).
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/ChainChecks.hpp>

using aunit::TestRunner;
using tinyparticle::testing::ChainChecks;
using tinyparticle::testing::ChainResult;

test(chainOfEightAt256Hz) {
  const ChainResult r = ChainChecks<Float>::run(8, 256, 2560);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
  assertEqual(r.error, (uint16_t) 0);
}

// The double pendulum at the coarse step too: issue 9 bounds chains of two
// and eight at both step rates.
test(doublePendulumAt256Hz) {
  const ChainResult r = ChainChecks<Float>::run(2, 256, 2560);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
  assertEqual(r.error, (uint16_t) 0);
}

#if defined(EPOXY_DUINO)
test(doublePendulumAt1024Hz) {
  const ChainResult r = ChainChecks<Float>::run(2, 1024, 10240);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
}

test(chainOfEightAt1024Hz) {
  const ChainResult r = ChainChecks<Float>::run(8, 1024, 10240);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
  assertEqual(r.error, (uint16_t) 0);
}
#endif

#if defined(EPOXY_DUINO)
// Sixteen beads (issue 9 runs them on a simulated Mega: the Nano's RAM is
// too small). At 1024 steps a second, the bounds of eight.
test(chainOfSixteenAt1024Hz) {
  const ChainResult r = ChainChecks<Float, 16>::run(16, 1024, 10240);
  assertLess(r.linkError, 0.005f);
  assertLess(r.energyError, 0.05f);
  assertEqual(r.error, (uint16_t) 0);
}

// The whip at 256 steps a second: its end turns by tens of degrees in a
// step, the passes along the chain converge slowly or diverge, and such
// steps are taken as two halves (RodSolver::step()). The bounds of eight.
test(chainOfSixteenAt256Hz) {
  const ChainResult r = ChainChecks<Float, 16>::run(16, 256, 2560);
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
