// Springs (Hooke's law, F = -k (length - rest)) between two particles or
// from a particle to a fixed anchor, and bungees: springs that only pull,
// and only while stretched beyond their rest length.
//
// One square root and one division per spring and step. A mass m on a
// spring of stiffness k oscillates with period 2 pi sqrt(m / k). Stiff
// springs need a small dt (k dt^2 / m well below 1); see StiffSpring for
// one that stays stable at any stiffness.
#pragma once

#include <stdint.h>

#include "../Math/Vec.hpp"
#include "../World/Handle.hpp"

namespace tinyparticle {

template <typename S, uint8_t Dim>
struct SpringParams {
  Vec<S, Dim> anchor;  // used by the anchored kinds only
  S stiffness;         // k, N/m
  S restLength;        // m
};

template <class W, bool kAnchored, bool kBungee>
struct SpringForce {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;

  static void apply(W& world, typename W::ForceSlot& slot, S) {
    const SpringParams<S, W::kDimensions>& spring = slot.params.spring;
    typename W::ParticleType& a = world.particleAt(slot.a);
    V delta = a.position;
    if (kAnchored) {
      delta -= spring.anchor;
    } else {
      delta -= world.particleAt(slot.b).position;
    }
    S lengthSquared = delta.magnitudeSquared();
    if (lengthSquared == S()) return;  // no direction to push in
    S length = sqrt(lengthSquared);
    S extension = length - spring.restLength;
    if (kBungee && extension <= S()) return;  // slack
    // Force on a: -k * extension along delta / length.
    S perLength = -(spring.stiffness * extension) / length;
    a.acceleration.addScaled(delta, perLength * a.inverseMass);
    if (!kAnchored) {
      typename W::ParticleType& b = world.particleAt(slot.b);
      b.acceleration.addScaled(delta, -(perLength * b.inverseMass));
    }
  }
};

}  // namespace tinyparticle
