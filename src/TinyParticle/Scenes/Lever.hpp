// The haptic lever of the seed report (Code Block 2.1): a pivot fixed at the
// origin, a 0.1 kg rod end at (length, 0), a rod between them, gravity on the
// rod end, and a custom force through which the user pushes it.
//
//   LeverWorld<Q16_16, 2> world;   // 2 particles, 1 force, 1 rod
//   Vec2<Q16_16> push;             // the user's force, N (zero: it falls)
//   LeverScene lever = buildLever(world, &push);
#pragma once

#include <stdint.h>

#include "../Core/Handle.hpp"
#include "../World/World.hpp"

namespace tinyparticle {

// No contact slot: rods take none, and a world without one links no
// resolver.
template <typename S, uint8_t Dim>
using LeverWorld = World<S, Dim, 2, 1, 1, 0>;

struct LeverScene {
  ParticleId pivot;
  ParticleId end;
  ConstraintId rod;
  ForceId gravity;
  ForceId user;
};

// The rod end has mass 0.1 kg and radius 0.01 m; length defaults to 0.15 m.
// The rod hangs from an anchor at the pivot's place, so that the world's
// rods are all anchored and it links only the lone rods' solve
// (Contacts/LoneRod.hpp); the pivot particle marks the place (the renderer
// draws it) and takes no part in the motion.
template <class W>
LeverScene buildLever(W& world, const typename W::Vec* userForce,
                      typename W::Scalar length = typename W::Scalar(0.15)) {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  LeverScene scene;
  scene.pivot = world.addFixedParticle(V());
  V end;
  end.x = length;
  scene.end = world.addParticle(end, S(0.1), S(0.01));
  scene.rod = world.addRod(scene.end, V(), length);
  scene.gravity = world.addGravity();  // the pivot is fixed: only the end falls
  scene.user = world.addCustomForce(scene.end, userForce);
  return scene;
}

}  // namespace tinyparticle
