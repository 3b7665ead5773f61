// Binary angles ("turns"): a uint16_t where 65536 is one full turn, so
// 16384 is a right angle and angles wrap around for free in unsigned
// arithmetic. For fixed point they are the cheap way to trigonometry: no
// multiply by 1 / (2 pi) and no range reduction.
//
//   S s = sinTurns<S>(angle);      // S = Q16_16, Q24_8, Q8_8, Float, ...
//   uint16_t a = radiansToTurns(x);
//
// The scalar cannot be deduced from a uint16_t, so it is named in angle
// brackets. Fixed and Float specialize detail::TurnsOf; any other scalar
// gets the generic version below, through its own sin() and cos().
#pragma once

#include <stdint.h>

namespace tinyparticle {

namespace detail {
template <typename S>
struct TurnsOf {
  // The angle as a signed fraction of a turn, in radians.
  static S angleOf(uint16_t turns) {
    int32_t s = turns < 32768u ? int32_t(turns) : int32_t(turns) - 65536;
    return S(double(s) * (6.283185307179586 / 65536.0));
  }
  static S sinTurns(uint16_t turns) { return sin(angleOf(turns)); }
  static S cosTurns(uint16_t turns) { return cos(angleOf(turns)); }
};
}  // namespace detail

template <typename S>
inline S sinTurns(uint16_t turns) {
  return detail::TurnsOf<S>::sinTurns(turns);
}
template <typename S>
inline S cosTurns(uint16_t turns) {
  return detail::TurnsOf<S>::cosTurns(turns);
}

}  // namespace tinyparticle
