// Compile-time settings. Each one has a documented default; define it before
// including <TinyParticle.h> to change it. The library is header-only, so a
// definition in the sketch really takes effect.
#pragma once

#include <stdint.h>

// TINYPARTICLE_AVR_ASM: 1 uses hand-written AVR code for fixed-point
// multiply, divide, square root and atan2 on chips with a hardware
// multiplier, and for saturating + and - on any AVR (Math/FixedAvr.hpp);
// 0 uses the portable C++ code everywhere (the reference in the tests).
// Default: 1 on AVR with MUL, 0 elsewhere.
#ifndef TINYPARTICLE_AVR_ASM
#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)
#define TINYPARTICLE_AVR_ASM 1
#else
#define TINYPARTICLE_AVR_ASM 0
#endif
#endif

// TINYPARTICLE_PROFILE: 1 turns on the profiling hooks in Debug/Profile.hpp;
// 0 (the default) compiles them to nothing.
#ifndef TINYPARTICLE_PROFILE
#define TINYPARTICLE_PROFILE 0
#endif

// TINYPARTICLE_DEBUG: 1 turns on the debug print hooks in Debug/Debug.hpp;
// 0 (the default) compiles them, and their strings, to nothing.
#ifndef TINYPARTICLE_DEBUG
#define TINYPARTICLE_DEBUG 0
#endif

// Places a function out of line. The benchmarks use it to measure a call.
#define TINYPARTICLE_NOINLINE __attribute__((noinline))

namespace tinyparticle {
namespace detail {

// p, hidden from the optimizer. In a pool of one slot the compiler knows
// every field's address and loads and stores each as a constant (lds and
// sts: 4 bytes each on AVR); through a pointer (ldd and std) they take 2
// bytes and as many cycles. The world's routines that place particles and
// step them (World/WorldCore.hpp) and the real-time loop's per-pass checks
// (Loop/RealTimeLoop.hpp) go through it. (In the step's integrator it once
// cost the spring scene 1 % of its cycles where the optimizer had found
// better code: use it where a measurement says so.)
template <typename T>
inline T* throughPointer(T* p) {
#if defined(__GNUC__)
  asm("" : "+r"(p));
#endif
  return p;
}

}  // namespace detail
}  // namespace tinyparticle
