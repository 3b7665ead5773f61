// What the world keeps besides its pools, as empty base classes where a
// world cannot use them (no RAM then).
//
// The world's gravity: the acceleration that every step applies to every
// movable particle alike (World::addGravity()), kept by the world rather
// than by a force slot or by each particle's accumulator. Every world has
// it, also one without force slots; it stays until it is changed
// (addGravity() adds to it, removeForce() of its id or clear() zeroes it).
#pragma once

#include <stdint.h>

#include "../Math/Float.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"

namespace tinyparticle {
namespace detail {

// sum += a. Float: component by component, zeros skipped, so that a
// constant zero (standard gravity's x) folds away: x + 0 is a library
// call the compiler must keep (-0 + 0 is +0). Fixed point folds it as is.
template <class V>
inline void addUniformTo(V& sum, const V& a) {
  sum += a;
}
inline void addUniformTo(Vec<Float, 2>& sum, const Vec<Float, 2>& a) {
  if (!isZero(a.x)) sum.x += a.x;
  if (!isZero(a.y)) sum.y += a.y;
}
inline void addUniformTo(Vec<Float, 3>& sum, const Vec<Float, 3>& a) {
  if (!isZero(a.x)) sum.x += a.x;
  if (!isZero(a.y)) sum.y += a.y;
  if (!isZero(a.z)) sum.z += a.z;
}

template <class V>
struct UniformAcceleration {
  V mUniform;

  constexpr UniformAcceleration() : mUniform() {}
  const V& uniform() const { return mUniform; }
  template <typename S>
  S uniformComponent(S V::*component) const { return mUniform.*component; }
  void clearUniform() { mUniform = V(); }
  void addUniform(const V& a) { addUniformTo(mUniform, a); }
};

// During a step, the step's Scaler (the multiply by dt) for the contact
// generators that need dt (rods and cables), and the rest of the uniform
// kick that the rods' solver adds after it moves the particles (V: the
// world's Vec; kept here, not on the step's stack: a frame for it cost the
// step about 20 bytes). Only worlds with constraints keep them.
template <class Scaler, class V, bool kUsed>
struct StepScaler {
  const Scaler* mByDt;
  V mRestKick;

  constexpr StepScaler() : mByDt(nullptr), mRestKick() {}
  void setStepScaler(const Scaler* byDt) { mByDt = byDt; }
  const Scaler& stepScaler() const { return *mByDt; }
  V& restKick() { return mRestKick; }
};

template <class Scaler, class V>
struct StepScaler<Scaler, V, false> {
  constexpr StepScaler() {}
  void setStepScaler(const Scaler*) {}
  // Never called (without constraints no generator runs), but a world
  // instantiates its generators' code when it names them (addRod()).
  const Scaler& stepScaler() const {
    static const Scaler kNone((typename Scaler::Scalar()));
    return kNone;
  }
  // Never written (without constraints the kick comes whole).
  V& restKick() {
    static V none;
    return none;
  }
};

}  // namespace detail
}  // namespace tinyparticle
