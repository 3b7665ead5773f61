// Lone rods in Q16.16, 3D (Contacts/RodSolver.hpp, solveLone()): the lone
// rods' solve against the chains' solve of the same rod
// (Testing/LoneRodChecks.hpp), in the cases whose code differs from 2D:
// the span, directions and speed across the rod. (RodLoneTest has the 2D
// cases; one world type per sketch leaves the Nano flash to spare.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/LoneRodChecks.hpp>

using aunit::TestRunner;
using namespace tinyparticle::testing;

typedef Q16_16 S;
typedef LoneRodChecks<S, 3> Checks;
Checks::W gWorld;

// A conical swing: level, pushed sideways at 1 m/s; slow turns at 256
// steps a second (anchored), fast ones at 64 (the moving end at b).
test(loneMatchesChainsIn3D) {
  const Vec3<S> start(0.15, 0.0, 0.0), push(0.0, 0.0, 1.0);
  assertLess(Checks::difference(gWorld, kLoneAnchored, start, push,
                                S(1.0 / 256), 256),
             Checks::bound(256));
  assertLess(Checks::difference(gWorld, kLoneEndIsB, start, push,
                                S(1.0 / 64), 64),
             Checks::bound(64));
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);
}

void loop() { TestRunner::run(); }
