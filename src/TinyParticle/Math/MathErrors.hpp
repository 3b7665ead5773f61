// The sticky math error flags.
//
// Arithmetic that has no correct answer (division by zero, square root of a
// negative number) or whose answer does not fit (overflow) returns a defined,
// saturated value and sets a bit here. The bits stay set until the sketch
// clears them, so one check after a step covers every operation in it.
//
// Where it lives: one byte of RAM shared by every scalar type and world.
// Interrupts: reading it is a single byte load, safe from an interrupt. Setting
// a bit is a read-modify-write; if an interrupt handler also does fixed-point
// math, a bit it sets can be lost while the main program sets another.
// Clear it with interrupts off if that matters.
#pragma once

#include <stdint.h>

namespace tinyparticle {

namespace MathError {
enum : uint8_t {
  kNone = 0,
  kDivideByZero = 1,  // x / 0: saturated result with x's sign, 0 / 0 = 0
  kNegativeSqrt = 2,  // sqrt(x < 0): result 0
  kOverflow = 4,      // a result did not fit: saturated to max() or lowest()
};
}

// Marks a variable that hand-written AVR code (Math/FixedAvr.hpp) reads by
// its symbol name: link-time optimization must keep it, under that name.
#if defined(__AVR__) && defined(__GNUC__)
#define TINYPARTICLE_ASM_VISIBLE __attribute__((used, externally_visible))
// The same without `used`, for the tables (TrigTables.hpp), which must stay
// out of sketches that do not read them: each is kept by the C++ that reads
// it or that calls the assembly reading it (with `used`, a sketch calling
// only sin linked all four tables, 708 bytes more).
#define TINYPARTICLE_ASM_NAMED __attribute__((externally_visible))
#else
#define TINYPARTICLE_ASM_VISIBLE
#define TINYPARTICLE_ASM_NAMED
#endif

namespace detail {
// A template's static member may be defined in a header (C++11 has no
// inline variables), so every translation unit shares this one byte.
template <typename Tag>
struct MathErrorStore {
  static uint8_t flags;
};
template <typename Tag>
uint8_t MathErrorStore<Tag>::flags TINYPARTICLE_ASM_VISIBLE = 0;

inline void raiseMathError(uint8_t error) {
  MathErrorStore<void>::flags |= error;
}
}  // namespace detail

// The MathError bits raised since the last clearMathErrors().
inline uint8_t mathErrors() { return detail::MathErrorStore<void>::flags; }

inline void clearMathErrors() { detail::MathErrorStore<void>::flags = 0; }

}  // namespace tinyparticle
