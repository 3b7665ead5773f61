// Profiling hooks. With TINYPARTICLE_PROFILE 0 (the default) every macro here
// expands to nothing: no code, no RAM.
//
//   TINYPARTICLE_PROFILE 1: each section accumulates Timer1 cycles (call
//       tinyparticle::profile::start() in setup(); each timed span must be
//       shorter than 65,536 cycles, about 4 ms). Read them with
//       profile::cycles(section) and profile::count(section).
//   TINYPARTICLE_PROFILE 2: each section drives a pin high while it runs
//       (pin TINYPARTICLE_PROFILE_FIRST_PIN + section), for a logic analyser,
//       as in the seed report's Appendix B.
//
// Sections: step, forces, integrate, contacts, resolve, render.
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"

namespace tinyparticle {

enum ProfileSection : uint8_t {
  kProfileStep = 0,
  kProfileForces,
  kProfileIntegrate,
  kProfileContacts,
  kProfileResolve,
  kProfileRender,
  kProfileRods,
  kProfileSections
};

}  // namespace tinyparticle

#if TINYPARTICLE_PROFILE

#include "../Platform/Cycles.hpp"

#ifndef TINYPARTICLE_PROFILE_FIRST_PIN
#define TINYPARTICLE_PROFILE_FIRST_PIN 2
#endif

namespace tinyparticle {
namespace profile {

namespace detail {
template <typename Tag>
struct Store {
  static uint32_t cycles[kProfileSections];
  static uint16_t started[kProfileSections];
  static uint16_t count[kProfileSections];
};
template <typename Tag>
uint32_t Store<Tag>::cycles[kProfileSections];
template <typename Tag>
uint16_t Store<Tag>::started[kProfileSections];
template <typename Tag>
uint16_t Store<Tag>::count[kProfileSections];
typedef Store<void> S;
}  // namespace detail

inline void start() {
#if TINYPARTICLE_PROFILE == 2
  for (uint8_t i = 0; i < kProfileSections; ++i) {
    platform::setupPin(uint8_t(TINYPARTICLE_PROFILE_FIRST_PIN + i));
  }
#else
  platform::startCycleCounter();
#endif
}

inline void reset() {
  for (uint8_t i = 0; i < kProfileSections; ++i) {
    detail::S::cycles[i] = 0;
    detail::S::count[i] = 0;
  }
}

inline void begin(uint8_t section) {
#if TINYPARTICLE_PROFILE == 2
  platform::writePin(uint8_t(TINYPARTICLE_PROFILE_FIRST_PIN + section), true);
#else
  detail::S::started[section] = platform::cycleCount();
#endif
}

inline void end(uint8_t section) {
#if TINYPARTICLE_PROFILE == 2
  platform::writePin(uint8_t(TINYPARTICLE_PROFILE_FIRST_PIN + section), false);
#else
  detail::S::cycles[section] +=
      uint16_t(platform::cycleCount() - detail::S::started[section]);
  ++detail::S::count[section];
#endif
}

inline uint32_t cycles(uint8_t section) { return detail::S::cycles[section]; }
inline uint16_t count(uint8_t section) { return detail::S::count[section]; }

}  // namespace profile
}  // namespace tinyparticle

#define TINYPARTICLE_PROFILE_BEGIN(section) \
  ::tinyparticle::profile::begin(::tinyparticle::section)
#define TINYPARTICLE_PROFILE_END(section) \
  ::tinyparticle::profile::end(::tinyparticle::section)

#else

#define TINYPARTICLE_PROFILE_BEGIN(section) ((void)0)
#define TINYPARTICLE_PROFILE_END(section) ((void)0)

#endif
