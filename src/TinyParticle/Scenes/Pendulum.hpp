// A simple pendulum: a bob of the given mass on a rod of length L from a
// pivot fixed at the origin, released at rest at angle theta0 (radians)
// from straight down. For small swings its period is
// 2 pi sqrt(L / g) (1 + theta0^2 / 16 + ...).
#pragma once

#include <stdint.h>

#include "../Core/Handle.hpp"
#include "../World/World.hpp"

namespace tinyparticle {

// 2 particles, gravity, the rod; no contact slot: rods take none, and a
// world without one links no resolver.
template <typename S, uint8_t Dim>
using PendulumWorld = World<S, Dim, 2, 0, 1, 0>;

struct PendulumScene {
  ParticleId pivot;
  ParticleId bob;
  ConstraintId rod;
  ForceId gravity;
};

template <class W>
PendulumScene buildPendulum(W& world, typename W::Scalar length,
                            typename W::Scalar theta0,
                            typename W::Scalar mass) {
  typedef typename W::Vec V;
  PendulumScene scene;
  scene.pivot = world.addFixedParticle(V());
  V bob;
  bob.x = length * sin(theta0);
  bob.y = -(length * cos(theta0));
  scene.bob = world.addParticle(bob, mass);
  // Hung from an anchor at the pivot's place, as the lever
  // (Scenes/Lever.hpp): the world links only the lone rods' solve.
  scene.rod = world.addRod(scene.bob, V(), length);
  scene.gravity = world.addGravity();  // the pivot is fixed: only the bob falls
  return scene;
}

}  // namespace tinyparticle
