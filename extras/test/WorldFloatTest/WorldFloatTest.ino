// The world's pools and handles: exhaustion, stale handles, removal
// cascades and bad arguments.
// (Nothing here steps a world: stepping is tested by the physics sketches,
// and leaving it out keeps this sketch small.)
// (Float here: WorldTest runs the same checks with Q16.16; the two
// scalars together no longer fit in the Nano's 30 KB of flash.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/WorldChecks.hpp>

using aunit::TestRunner;
// Each check builds its own world and returns a bit mask of what held: all
// bits set is a pass (src/TinyParticle/Testing/WorldChecks.hpp).
using tinyparticle::testing::WorldChecks;

// ---- tests ------------------------------------------------------------------

// Each pool refuses one object past its capacity: an invalid handle and
// its full flag (bits: particles, forces, constraints).
test(PoolExhaustion_Float) {
  assertEqual(WorldChecks<Float>::exhaustPools(), 7);
}

// A removed object's handle is stale everywhere, also once its slot is
// reused, and every function that takes one refuses it.
test(StaleHandles_Float) {
  assertEqual(WorldChecks<Float>::staleHandles(), 63);
}

// Removing a particle removes the forces and constraints that refer to it,
// and nothing else.
test(RemovalCascade_Float) {
  assertEqual(WorldChecks<Float>::removalCascade(), 15);
}

// A massless particle and a plane without a normal are refused with
// kBadArgument; clearError() clears it.
test(BadArguments_Float) {
  assertEqual(WorldChecks<Float>::badArguments(), 7);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
