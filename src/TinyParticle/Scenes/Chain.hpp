// Chains of rigid links (issue 9), solved by Contacts/RodSolver.hpp.
//
// The whip chain: a pivot fixed at the origin and N beads of 0.05 kg
// (radius 0) at (0.125 i, 0), i = 1..N, each tied to the one before by a
// rod of 0.125 m (the first to the pivot), gravity on all, released at rest
// from level. Falling to hanging it gives up
//   E_fall = m g 0.125 N (N + 1) / 2,
// the energy its errors are measured in.
//
//   ChainWorld<Q16_16, 2, 8> world;   // 9 particles, 8 rods
//   ChainScene chain = buildChain(world, 8);
//
// The rope: two posts fixed at (0, 0) and (0.6, 0), seven beads of 0.05 kg
// between them on eight rods of 0.1 m, started on a "V" close to the
// hanging shape (bead k at x = 0.075 k, y = -0.066144 min(k, 8 - k), which
// keeps every link at 0.1 m), gravity on all and a damping rate of 1/s on
// each bead, so it settles into the discrete catenary (extras/test/RopeTest).
//
//   RopeWorld<Q16_16, 2> world;       // 9 particles, 8 rods
//   RopeScene rope = buildRope(world);
#pragma once

#include <stdint.h>

#include "../Core/Handle.hpp"
#include "../World/World.hpp"

namespace tinyparticle {

// N beads and the pivot; one gravity slot serves every bead; no contacts.
template <typename S, uint8_t Dim, uint8_t N>
using ChainWorld = World<S, Dim, N + 1, 0, N, 0>;

struct ChainScene {
  ParticleId pivot;
  ParticleId last;  // the free end
  ForceId gravity;
  uint8_t beads;    // how many were added
};

// Adds the pivot, `beads` beads and their rods to an empty world (a world
// with fewer slots adds what fits and flags the rest in world.error()).
template <class W>
ChainScene buildChain(W& world, uint8_t beads) {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  ChainScene scene;
  scene.pivot = world.addFixedParticle(V());
  scene.beads = 0;
  ParticleId previous = scene.pivot;
  for (uint8_t i = 1; i <= beads; ++i) {
    V at;
    at.x = S(0.125) * S(long(i));
    const ParticleId bead = world.addParticle(at, S(0.05));
    if (!bead.isValid()) break;
    world.addRod(bead, previous, S(0.125));
    previous = bead;
    ++scene.beads;
  }
  scene.last = previous;
  scene.gravity = world.addGravity();
  return scene;
}

// The rope's shape: posts, beads and links.
struct RopeShape {
  static const uint8_t kBeads = 7;
  static const uint8_t kLinks = 8;
};

template <typename S, uint8_t Dim>
using RopeWorld = World<S, Dim, RopeShape::kBeads + 2, 0, RopeShape::kLinks, 0>;

struct RopeScene {
  ParticleId left;   // the post at (0, 0)
  ParticleId right;  // the post at (0.6, 0)
  ParticleId beads[RopeShape::kBeads];
  ForceId gravity;
};

template <class W>
RopeScene buildRope(W& world) {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  RopeScene scene;
  scene.left = world.addFixedParticle(V());
  V post;
  post.x = S(0.6);
  scene.right = world.addFixedParticle(post);
  ParticleId previous = scene.left;
  for (uint8_t k = 1; k <= RopeShape::kBeads; ++k) {
    const uint8_t fromPost = k < RopeShape::kLinks - k
                                 ? k : uint8_t(RopeShape::kLinks - k);
    V at;
    at.x = S(0.075) * S(long(k));
    at.y = -(S(0.066144) * S(long(fromPost)));
    const ParticleId bead = world.addParticle(at, S(0.05));
    scene.beads[k - 1] = bead;
    typename W::ParticleType* p = world.particle(bead);
    if (p != nullptr) p->setDampingRate(S(1));
    world.addRod(bead, previous, S(0.1));
    previous = bead;
  }
  world.addRod(previous, scene.right, S(0.1));
  scene.gravity = world.addGravity();
  return scene;
}

}  // namespace tinyparticle
