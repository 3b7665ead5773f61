// A mass on a spring, on a frictionless table (no gravity): 1 kg on a
// spring of k = 100 N/m and rest length 0.5 m anchored at the origin,
// released at rest 0.1 m beyond its rest length. It oscillates along x with
// period 2 pi sqrt(m / k) = 0.628 s and amplitude 0.1 m.
#pragma once

#include <stdint.h>

#include "../Core/Handle.hpp"
#include "../World/World.hpp"

namespace tinyparticle {

template <typename S, uint8_t Dim>
using SpringWorld = World<S, Dim, 1, 1, 0, 0>;

struct SpringScene {
  ParticleId mass;
  ForceId spring;
};

template <class W>
SpringScene buildSpring(W& world) {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  SpringScene scene;
  V start;
  start.x = S(0.6);
  scene.mass = world.addParticle(start, S(1));
  scene.spring = world.addSpring(scene.mass, V(), S(100), S(0.5));
  return scene;
}

}  // namespace tinyparticle
