// The rungs of the memory ladder (issue 4, item 8). Each rung keeps every
// feature of the rungs below it and adds one:
//
//   0  empty sketch (no library)
//   1  a world with 1 particle and gravity
//   2  + drag
//   3  + a spring between two particles (the second particle comes here)
//   4  + a spring to an anchor
//   5  + a bungee
//   6  + buoyancy
//   7  + a stiff spring
//   8  + a custom force
//   9  + a rod (rods take no contacts)
//  10  + a cable (and a contact pool of 8)
//  11  + planes: the walls of a box (2 x DIM planes)
//  12  + particle-particle collisions
//
// Every parameter is read from a volatile (see the inputs below), and every
// step's result is written to a volatile, so the compiler can neither fold
// the set-up nor drop the step. The values make a small, well-behaved
// scene; only the cost matters.
#pragma once

#include "Scalar.h"

#ifndef DIM
#define DIM 2
#endif

namespace ladder {

using measuredScalar::S;
using measuredScalar::Stored;
// A constant as stored (folded at compile time: the inputs are static data).
#if SCALAR == 1
#define LADDER_STORE(v) (Q16_16(v).raw())
#else
#define LADDER_STORE(v) (Float(v).toFloat())
#endif

const uint8_t kParticles = FEATURE >= 3 ? 2 : 1;
// Force slots: one per generator from rung 2 on (drag ... custom force);
// the world's gravity takes none.
const uint8_t kForces = FEATURE >= 8 ? 7 : FEATURE >= 2 ? FEATURE - 1 : 0;
const uint8_t kConstraints = FEATURE >= 12   ? 3 + 2 * DIM
                             : FEATURE >= 11 ? 2 + 2 * DIM
                             : FEATURE >= 10 ? 2
                             : FEATURE >= 9  ? 1
                                             : 0;
const uint8_t kContacts = FEATURE >= 10 ? 8 : 0;

typedef World<S, DIM, kParticles, kForces, kConstraints, kContacts> LadderWorld;
typedef LadderWorld::Vec V;

// The inputs, each a volatile of its own (a vector: DIM of them in an
// array), declared with the first rung that reads it, so that a rung pays
// only for the inputs it reads: their initial values sit in flash (.data),
// and the linker keeps a volatile even when nothing reads it. The
// scaffolding is not the library's cost.
#if DIM == 3
#define LADDER_VECTOR(x, y, z) {LADDER_STORE(x), LADDER_STORE(y), LADDER_STORE(z)}
#else
#define LADDER_VECTOR(x, y, z) {LADDER_STORE(x), LADDER_STORE(y)}
#endif
volatile Stored gPositionA[DIM] = LADDER_VECTOR(0.3, 0.5, 0.0);
volatile Stored gMass = LADDER_STORE(0.1);             // kg
volatile Stored gRadius = LADDER_STORE(0.03);          // m
volatile Stored gDt = LADDER_STORE(1.0 / 256);         // s
#if FEATURE >= 2
volatile Stored gDrag1 = LADDER_STORE(0.01);           // drag k1
volatile Stored gDrag2 = LADDER_STORE(0.01);           // drag k2
#endif
#if FEATURE >= 3
volatile Stored gPositionB[DIM] = LADDER_VECTOR(0.5, 0.5, 0.0);
volatile Stored gStiffness = LADDER_STORE(20.0);       // spring, N/m
volatile Stored gRestLength = LADDER_STORE(0.2);       // m
#endif
#if FEATURE >= 4
volatile Stored gAnchor[DIM] = LADDER_VECTOR(0.5, 0.8, 0.0);
#endif
#if FEATURE >= 6
volatile Stored gSurface = LADDER_STORE(0.2);          // water surface, m
volatile Stored gDepth = LADDER_STORE(0.03);           // buoyancy depth, m
volatile Stored gVolume = LADDER_STORE(0.0001);        // m^3
volatile Stored gDensity = LADDER_STORE(1000.0);       // kg/m^3
#endif
#if FEATURE >= 7
volatile Stored gDamping = LADDER_STORE(0.5);          // stiff spring, N s/m
#endif
#if FEATURE >= 9
volatile Stored gRodLength = LADDER_STORE(0.2);        // m
#endif
#if FEATURE >= 10
volatile Stored gCableLength = LADDER_STORE(0.35);     // m
volatile Stored gRestitution = LADDER_STORE(0.5);
#endif
#if FEATURE >= 11
volatile Stored gBoxLow[DIM] = LADDER_VECTOR(0.0, 0.0, -0.5);
volatile Stored gBoxHigh[DIM] = LADDER_VECTOR(1.0, 1.0, 0.5);
#endif

#if SCALAR == 1
inline S input(volatile Stored& v) { return S::fromRaw(v); }
#else
inline S input(volatile Stored& v) { return S(double(v)); }
#endif

inline V vectorAt(volatile Stored (&v)[DIM]) {
  V result;
  for (uint8_t k = 0; k < DIM; ++k) result[k] = input(v[k]);
  return result;
}

LadderWorld gWorld;
V gUserForce;  // the custom force: the sketch would write it between steps
volatile Stored gSink;

inline void build() {
  ParticleId a = gWorld.addParticle(vectorAt(gPositionA), input(gMass),
                                    input(gRadius));
  (void)a;  // its first use comes with the spring rung
  gWorld.addGravity();
#if FEATURE >= 2
  gWorld.addDrag(input(gDrag1), input(gDrag2));
#endif
#if FEATURE >= 3
  ParticleId b = gWorld.addParticle(vectorAt(gPositionB), input(gMass),
                                    input(gRadius));
  gWorld.addSpring(a, b, input(gStiffness), input(gRestLength));
#endif
#if FEATURE >= 4
  gWorld.addSpring(b, vectorAt(gAnchor), input(gStiffness), input(gRestLength));
#endif
#if FEATURE >= 5
  gWorld.addBungee(a, vectorAt(gAnchor), input(gStiffness), input(gRestLength));
#endif
#if FEATURE >= 6
  gWorld.addBuoyancy(input(gSurface), input(gDepth), input(gVolume),
                     input(gDensity));
#endif
#if FEATURE >= 7
  gWorld.addStiffSpring(b, vectorAt(gAnchor), input(gStiffness),
                        input(gDamping), input(gDt));
#endif
#if FEATURE >= 8
  gWorld.addCustomForce(a, &gUserForce);
#endif
#if FEATURE >= 9
  gWorld.addRod(a, b, input(gRodLength));
#endif
#if FEATURE >= 10
  gWorld.addCable(b, vectorAt(gAnchor), input(gCableLength),
                  input(gRestitution));
#endif
#if FEATURE >= 11
  gWorld.addBox(vectorAt(gBoxLow), vectorAt(gBoxHigh), input(gRestitution));
#endif
#if FEATURE >= 12
  gWorld.addCollisions(input(gRestitution));
#endif
}

inline void step() {
  gWorld.step(input(gDt));
  gSink = measuredScalar::stored(gWorld.particleAt(0).position.y);
}

}  // namespace ladder
