// The world's pools and handles: exhaustion, stale handles, removal
// cascades, bad arguments, and what a particle and an empty pool cost.
// (Nothing here steps a world: stepping is tested by the physics sketches,
// and leaving it out keeps this sketch small.)
// (Q16.16 here; WorldFloatTest runs the same checks with Float: the two
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
test(PoolExhaustion_Q16_16) {
  assertEqual(WorldChecks<Q16_16>::exhaustPools(), 7);
}

// A removed object's handle is stale everywhere, also once its slot is
// reused, and every function that takes one refuses it.
test(StaleHandles_Q16_16) {
  assertEqual(WorldChecks<Q16_16>::staleHandles(), 63);
}

// Removing a particle removes the forces and constraints that refer to it,
// and nothing else.
test(RemovalCascade_Q16_16) {
  assertEqual(WorldChecks<Q16_16>::removalCascade(), 15);
}

// A massless particle and a plane without a normal are refused with
// kBadArgument; clearError() clears it.
test(BadArguments_Q16_16) {
  assertEqual(WorldChecks<Q16_16>::badArguments(), 7);
}

// The issue's memory goal: a 2D Q16.16 particle that collides takes at most
// 36 bytes (the seed's took 68).
test(ParticleSize) {
  assertLessOrEqual((unsigned) sizeof(Particle<Q16_16, 2>), 36u);
  assertLessOrEqual((unsigned) sizeof(Particle<Float, 2>), 36u);
}

// Pools of capacity 0 take no RAM: a world with one particle and no other
// pool is the particle plus a few bytes of bookkeeping.
test(EmptyPoolsCostNothing) {
  typedef World<Q16_16, 2, 1> Bare;
  assertLessOrEqual((unsigned) sizeof(Bare),
                    (unsigned) (sizeof(Particle<Q16_16, 2>) + 8));
  typedef World<Q16_16, 2, 1, 1> WithForce;
  assertMoreOrEqual((unsigned) (sizeof(WithForce) - sizeof(Bare)),
                    (unsigned) sizeof(WithForce::ForceSlot) - 3);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
