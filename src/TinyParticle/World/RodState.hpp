// What the world keeps for its rods (Contacts/RodSolver.hpp): the solver,
// set by the first addRod() (so a world without rods links no solver code),
// the solver's state bits, and 1 / dt for the last dt. Only a world with constraint slots has it;
// without them it is an empty base class and takes no RAM.
#pragma once

#include <stdint.h>

#include "../Math/Newton.hpp"

namespace tinyparticle {
namespace detail {

// 1 / dt for the last dt, apart from the solver's pointer (which names the
// World type): two World types of one scalar share inverseOf(), which the
// compiler may keep out of line (62 bytes a copy in Q16.16).
template <typename S>
struct InverseDt {
  constexpr InverseDt() : mDt(), mInverseDt() {}
  // 1 / dt, computed again only when dt changes: rarely, so a reciprocal
  // without the fast divide does it (Math/Newton.hpp). dt > 0: the step
  // refuses others.
  S inverseOf(S dt) {
    if (!detail::isEqualPositive(dt, mDt)) {
      mDt = dt;
      mInverseDt = detail::reciprocalByMultiplies(dt);
    }
    return mInverseDt;
  }

 private:
  S mDt;
  S mInverseDt;
};

template <typename Solve, typename S, bool kHasConstraints>
struct RodState : InverseDt<S> {
  constexpr RodState() : mRodBits(0), mSolveRods(nullptr) {}
  uint8_t rodBits() const { return mRodBits; }
  void setRodBits(uint8_t bits) { mRodBits = bits; }
  void addRodBits(uint8_t bits) { mRodBits |= bits; }
  Solve rodSolver() const { return mSolveRods; }
  void setRodSolver(Solve solve) { mSolveRods = solve; }

 private:
  uint8_t mRodBits;
  Solve mSolveRods;
};

template <typename Solve, typename S>
struct RodState<Solve, S, false> {
  constexpr RodState() {}
  uint8_t rodBits() const { return 0; }
  void setRodBits(uint8_t) {}
  void addRodBits(uint8_t) {}
  Solve rodSolver() const { return nullptr; }
  void setRodSolver(Solve) {}
  S inverseOf(S dt) { return detail::reciprocalByMultiplies(dt); }
};

}  // namespace detail
}  // namespace tinyparticle
