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
#include "../Core/Generator.hpp"
#include "../Core/Particle.hpp"

namespace tinyparticle {

// Generator classes (Core/Generator.hpp): a spring (or bungee) between two
// particles, and one from a particle to a fixed anchor.
template <typename S, uint8_t Dim, bool kBungee = false>
struct SpringForce {
  static const uint8_t kShape = SlotShape::kPair;
  S stiffness;   // k, N/m
  S restLength;  // m

  static SpringForce make(S stiffness, S restLength) {
    SpringForce spring;
    spring.stiffness = stiffness;
    spring.restLength = restLength;
    return spring;
  }

  void apply(Particle<S, Dim>& a, Particle<S, Dim>& b, S) const {
    Vec<S, Dim> delta = a.position;
    delta -= b.position;
    S perLength;
    if (!forcePerLength(delta, stiffness, restLength, perLength)) return;
    a.acceleration.addScaled(delta, perLength * a.inverseMass);
    b.acceleration.addScaled(delta, -(perLength * b.inverseMass));
  }

  // -k (length - rest) / length for the span delta; false when there is
  // no force (no direction, or a slack bungee). Shared with the anchored
  // kind, and inlined in both.
  TINYPARTICLE_ALWAYS_INLINE static bool forcePerLength(
      const Vec<S, Dim>& delta, S k, S rest, S& perLength) {
    S lengthSquared = delta.magnitudeSquared();
    if (lengthSquared == S()) return false;  // no direction to push in
    S length = sqrt(lengthSquared);
    S extension = length - rest;
    if (kBungee && extension <= S()) return false;  // slack
    // Force on a: -k * extension along delta / length.
    perLength = -(k * extension) / length;
    return true;
  }
};

template <typename S, uint8_t Dim, bool kBungee = false>
struct AnchoredSpringForce {
  static const uint8_t kShape = SlotShape::kAnchorable;
  Vec<S, Dim> anchor;  // m
  S stiffness;         // k, N/m
  S restLength;        // m

  static AnchoredSpringForce make(const Vec<S, Dim>& anchor, S stiffness,
                                  S restLength) {
    AnchoredSpringForce spring;
    spring.anchor = anchor;
    spring.stiffness = stiffness;
    spring.restLength = restLength;
    return spring;
  }

  void apply(Particle<S, Dim>& p, S) const {
    Vec<S, Dim> delta = p.position;
    delta -= anchor;
    S perLength;
    if (!SpringForce<S, Dim, kBungee>::forcePerLength(delta, stiffness,
                                                      restLength, perLength)) {
      return;
    }
    p.acceleration.addScaled(delta, perLength * p.inverseMass);
  }
};

}  // namespace tinyparticle
