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
  int16_t symmetric(int16_t limit) { return fromDraw(next(), limit); }

  // A draw x as a whole number in [-limit, limit]: x % (2 limit + 1) -
  // limit. A span of 257 (every scene's limit of 128) is reduced without
  // the division routine: 256 = -1 (mod 257), so x = 256 h + l leaves
  // l - h, in (-256, 256), brought into [0, 257) by one add. (The same
  // value as x % 257 for every x: extras/test/SceneRandomTest.)
  static int16_t fromDraw(uint16_t x, int16_t limit) {
    const uint16_t span = uint16_t(2 * limit + 1);
    if (span == 257) {
      int16_t r = int16_t(int16_t(x & 0xFF) - int16_t(x >> 8));
      if (r < 0) r = int16_t(r + 257);
      return int16_t(r - limit);
    }
    return int16_t(int16_t(x % span) - limit);
  }

 private:
  uint16_t mState;
};

}  // namespace tinyparticle
