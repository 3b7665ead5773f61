// What the world keeps for the length of a step, as empty base classes
// where a world cannot use them (no RAM then).
//
// The acceleration that a step applies to every movable particle alike
// (gravity added for all particles), kept by the world instead of being
// written into each particle's accumulator. A world without force
// generators cannot have one.
#pragma once

#include <stdint.h>

namespace tinyparticle {
namespace detail {

template <class V, bool kUsed>
struct UniformAcceleration {
  V mUniform;

  constexpr UniformAcceleration() : mUniform() {}
  const V& uniform() const { return mUniform; }
  V* uniformPointer() { return &mUniform; }
  template <typename S>
  S uniformComponent(S V::*component) const { return mUniform.*component; }
  void clearUniform() { mUniform = V(); }
  void addUniform(const V& a) { mUniform += a; }
};

template <class V>
struct UniformAcceleration<V, false> {
  constexpr UniformAcceleration() {}
  V uniform() const { return V(); }
  V* uniformPointer() { return nullptr; }
  template <typename S>
  S uniformComponent(S V::*) const { return S(); }
  void clearUniform() {}
  void addUniform(const V&) {}
};

// During a step, the step's Scaler (the multiply by dt) for the contact
// generators that need dt (rods and cables). Only worlds with constraints
// keep the pointer.
template <class Scaler, bool kUsed>
struct StepScaler {
  const Scaler* mByDt;

  constexpr StepScaler() : mByDt(nullptr) {}
  void setStepScaler(const Scaler* byDt) { mByDt = byDt; }
  const Scaler& stepScaler() const { return *mByDt; }
};

template <class Scaler>
struct StepScaler<Scaler, false> {
  constexpr StepScaler() {}
  void setStepScaler(const Scaler*) {}
  // Never called (without constraints no generator runs), but a world
  // instantiates its generators' code when it names them (addRod()).
  const Scaler& stepScaler() const {
    static const Scaler kNone((typename Scaler::Scalar()));
    return kNone;
  }
};

}  // namespace detail
}  // namespace tinyparticle
