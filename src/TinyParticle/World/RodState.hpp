// What the world keeps for its rods (Contacts/RodSolver.hpp): the solver,
// set by the first addRod() (so a world without rods links no solver code),
// and the solver's state bits. Only a world with constraint slots has it;
// without them it is an empty base class and takes no RAM.
#pragma once

#include <stdint.h>

namespace tinyparticle {
namespace detail {

template <typename Solve, bool kHasConstraints>
struct RodState {
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

template <typename Solve>
struct RodState<Solve, false> {
  constexpr RodState() {}
  uint8_t rodBits() const { return 0; }
  void setRodBits(uint8_t) {}
  void addRodBits(uint8_t) {}
  Solve rodSolver() const { return nullptr; }
  void setRodSolver(Solve) {}
};

}  // namespace detail
}  // namespace tinyparticle
