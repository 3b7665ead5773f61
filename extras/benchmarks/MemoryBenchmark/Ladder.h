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
// Every parameter is read from a volatile array, and every step's result is
// written to a volatile, so the compiler can neither fold the set-up nor drop
// the step. The values make a small, well-behaved scene; only the cost matters.
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
const uint8_t kForces = FEATURE >= 8 ? 8 : FEATURE;
const uint8_t kConstraints = FEATURE >= 12   ? 3 + 2 * DIM
                             : FEATURE >= 11 ? 2 + 2 * DIM
                             : FEATURE >= 10 ? 2
                             : FEATURE >= 9  ? 1
                                             : 0;
const uint8_t kContacts = FEATURE >= 10 ? 8 : 0;

typedef World<S, DIM, kParticles, kForces, kConstraints, kContacts> LadderWorld;
typedef LadderWorld::Vec V;

// Indices into the inputs; a vector takes three in a row (z unused in 2D).
enum : uint8_t {
  kPositionA = 0,
  kPositionB = 3,
  kAnchor = 6,
  kBoxLow = 9,
  kBoxHigh = 12,
  kMass = 15,
  kRadius,
  kDrag1,
  kDrag2,
  kStiffness,
  kRestLength,
  kSurface,
  kDepth,
  kVolume,
  kDensity,
  kDamping,
  kDt,
  kRodLength,
  kCableLength,
  kRestitution,
  kInputCount
};

volatile Stored gInputs[kInputCount] = {
    LADDER_STORE(0.3), LADDER_STORE(0.5), LADDER_STORE(0.0),   // A
    LADDER_STORE(0.5), LADDER_STORE(0.5), LADDER_STORE(0.0),   // B
    LADDER_STORE(0.5), LADDER_STORE(0.8), LADDER_STORE(0.0),   // anchor
    LADDER_STORE(0.0), LADDER_STORE(0.0), LADDER_STORE(-0.5),  // box low
    LADDER_STORE(1.0), LADDER_STORE(1.0), LADDER_STORE(0.5),   // box high
    LADDER_STORE(0.1),     // mass, kg
    LADDER_STORE(0.03),    // radius, m
    LADDER_STORE(0.01),    // drag k1
    LADDER_STORE(0.01),    // drag k2
    LADDER_STORE(20.0),    // spring stiffness, N/m
    LADDER_STORE(0.2),     // rest length, m
    LADDER_STORE(0.2),     // water surface, m
    LADDER_STORE(0.03),    // buoyancy depth, m
    LADDER_STORE(0.0001),  // volume, m^3
    LADDER_STORE(1000.0),  // density, kg/m^3
    LADDER_STORE(0.5),     // stiff spring damping, N s/m
    LADDER_STORE(1.0 / 256),  // dt, s
    LADDER_STORE(0.2),     // rod length, m
    LADDER_STORE(0.35),    // cable length, m
    LADDER_STORE(0.5),     // restitution
};

#if SCALAR == 1
inline S input(uint8_t i) { return S::fromRaw(gInputs[i]); }
#else
inline S input(uint8_t i) { return S(double(gInputs[i])); }
#endif

inline V vectorAt(uint8_t i) {
  V v;
  for (uint8_t k = 0; k < DIM; ++k) v[k] = input(i + k);
  return v;
}

LadderWorld gWorld;
V gUserForce;  // the custom force: the sketch would write it between steps
volatile Stored gSink;

inline void build() {
  ParticleId a = gWorld.addParticle(vectorAt(kPositionA), input(kMass),
                                    input(kRadius));
  (void)a;  // its first use comes with the spring rung
  gWorld.addGravity();
#if FEATURE >= 2
  gWorld.addDrag(input(kDrag1), input(kDrag2));
#endif
#if FEATURE >= 3
  ParticleId b = gWorld.addParticle(vectorAt(kPositionB), input(kMass),
                                    input(kRadius));
  gWorld.addSpring(a, b, input(kStiffness), input(kRestLength));
#endif
#if FEATURE >= 4
  gWorld.addSpring(b, vectorAt(kAnchor), input(kStiffness), input(kRestLength));
#endif
#if FEATURE >= 5
  gWorld.addBungee(a, vectorAt(kAnchor), input(kStiffness), input(kRestLength));
#endif
#if FEATURE >= 6
  gWorld.addBuoyancy(input(kSurface), input(kDepth), input(kVolume),
                     input(kDensity));
#endif
#if FEATURE >= 7
  gWorld.addStiffSpring(b, vectorAt(kAnchor), input(kStiffness),
                        input(kDamping), input(kDt));
#endif
#if FEATURE >= 8
  gWorld.addCustomForce(a, &gUserForce);
#endif
#if FEATURE >= 9
  gWorld.addRod(a, b, input(kRodLength));
#endif
#if FEATURE >= 10
  gWorld.addCable(b, vectorAt(kAnchor), input(kCableLength),
                  input(kRestitution));
#endif
#if FEATURE >= 11
  gWorld.addBox(vectorAt(kBoxLow), vectorAt(kBoxHigh), input(kRestitution));
#endif
#if FEATURE >= 12
  gWorld.addCollisions(input(kRestitution));
#endif
}

inline void step() {
  gWorld.step(input(kDt));
  gSink = measuredScalar::stored(gWorld.particleAt(0).position.y);
}

}  // namespace ladder
