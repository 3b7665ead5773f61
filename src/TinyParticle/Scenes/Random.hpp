// A tiny deterministic random generator (16-bit xorshift) so that scenes
// start the same way on every board and on the host.
#pragma once

#include <stdint.h>

namespace tinyparticle {

class SceneRandom {
 public:
  explicit SceneRandom(uint16_t seed) : mState(seed == 0 ? 1 : seed) {}

  uint16_t next() {
    mState ^= uint16_t(mState << 7);
    mState ^= uint16_t(mState >> 9);
    mState ^= uint16_t(mState << 8);
    return mState;
  }

  // A whole number in [-limit, limit].
  int16_t symmetric(int16_t limit) {
    const uint16_t span = uint16_t(2 * limit + 1);
    return int16_t(int16_t(next() % span) - limit);
  }

 private:
  uint16_t mState;
};

}  // namespace tinyparticle
