// Debug printing. With TINYPARTICLE_DEBUG 0 (the default) the macros expand
// to nothing, and their strings never reach flash (the seed report found that
// strings passed to a disabled debug function still took memory).
//
// With TINYPARTICLE_DEBUG 1 on an Arduino, call
// tinyparticle::debug::setOutput(&Serial) in setup(); then
//   TINYPARTICLE_DEBUG_PRINT("text")          prints the text (from flash)
//   TINYPARTICLE_DEBUG_VALUE("label", value)  prints "label=value" for a scalar
// each on its own line. The engine reports dropped contacts and stale
// handles this way.
#pragma once

#include "../Configuration.hpp"
#include "../Platform/Arduino.hpp"

#if TINYPARTICLE_DEBUG && TINYPARTICLE_HAS_ARDUINO

namespace tinyparticle {
namespace debug {

namespace detail {
template <typename Tag>
struct Store {
  static Print* output;
};
template <typename Tag>
Print* Store<Tag>::output = nullptr;
}  // namespace detail

inline void setOutput(Print* output) { detail::Store<void>::output = output; }
inline Print* output() { return detail::Store<void>::output; }

}  // namespace debug
}  // namespace tinyparticle

#define TINYPARTICLE_DEBUG_PRINT(text)                                  \
  do {                                                                  \
    Print* tinyparticleOut = ::tinyparticle::debug::output();           \
    if (tinyparticleOut != nullptr) tinyparticleOut->println(F(text)); \
  } while (0)

#define TINYPARTICLE_DEBUG_VALUE(label, value)                        \
  do {                                                                \
    Print* tinyparticleOut = ::tinyparticle::debug::output();         \
    if (tinyparticleOut != nullptr) {                                 \
      tinyparticleOut->print(F(label "="));                           \
      tinyparticleOut->println((value).toFloat(), 5);                 \
    }                                                                 \
  } while (0)

#else

#define TINYPARTICLE_DEBUG_PRINT(text) ((void)0)
#define TINYPARTICLE_DEBUG_VALUE(label, value) ((void)0)

#endif
