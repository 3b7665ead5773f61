// Handles to objects in the world's pools: a slot index and the slot's
// generation when the handle was made. Removing an object bumps its slot's
// generation, so an old handle no longer matches and lookups return null.
// (After 256 reuses of one slot an old handle would match again.)
#pragma once

#include <stdint.h>

namespace tinyparticle {

// Index values that are never a slot, so pools hold at most 253 objects.
static const uint8_t kNoIndex = 0xFF;      // no particle
static const uint8_t kAllIndex = 0xFE;     // every particle (e.g. gravity)
static const uint8_t kAnchorIndex = 0xFD;  // a fixed point held in the slot

template <typename Tag>
struct Handle {
  uint8_t index;
  uint8_t generation;

  constexpr Handle() : index(kNoIndex), generation(0) {}
  constexpr Handle(uint8_t i, uint8_t g) : index(i), generation(g) {}

  // True when the handle was returned by a successful add. It may still be
  // stale: the world's lookup functions tell.
  constexpr bool isValid() const { return index < kAnchorIndex; }
  constexpr bool operator==(Handle h) const {
    return index == h.index && generation == h.generation;
  }
  constexpr bool operator!=(Handle h) const { return !(*this == h); }
};

struct ParticleTag;
struct ForceTag;
struct ConstraintTag;

typedef Handle<ParticleTag> ParticleId;
typedef Handle<ForceTag> ForceId;
typedef Handle<ConstraintTag> ConstraintId;

// World::error() bits. They stay set until World::clearError().
namespace WorldError {
enum : uint16_t {
  kNone = 0,
  kParticlesFull = 1,    // addParticle on a full pool
  kForcesFull = 2,       // a force generator on a full pool
  kConstraintsFull = 4,  // a constraint on a full pool
  kContactsDropped = 8,  // the contact pool overflowed during a step
  kStaleHandle = 16,     // a stale or invalid handle was passed in
  kBadArgument = 32,     // e.g. a zero plane normal, a negative mass, dt <= 0
  kRodsUnsatisfied = 64, // rods that cannot all keep their lengths (a loop)
  kNonFinite = 128,      // a float state became inf or NaN (see World::step)
  // A colliding particle moved farther than its radius in a step, where
  // particle collisions may miss each other (Contacts/Collisions.hpp).
  kTunnelling = 256,
};
}

}  // namespace tinyparticle
