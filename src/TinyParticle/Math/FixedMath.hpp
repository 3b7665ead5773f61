// Square root and trigonometry for Fixed.
#pragma once

#include <stdint.h>

#include "Fixed.hpp"
#include "MathErrors.hpp"

namespace tinyparticle {

namespace detail {
// round(sqrt(n)) for an unsigned integer n, bit by bit. Portable reference.
template <typename U>
inline U roundedIntegerSqrt(U n) {
  U root = 0;
  U bit = U(1) << (sizeof(U) * 8 - 2);
  while (bit > n) bit >>= 2;
  while (bit != 0) {
    if (n >= root + bit) {
      n -= root + bit;
      root = (root >> 1) + bit;
    } else {
      root >>= 1;
    }
    bit >>= 2;
  }
  // Here n holds the remainder n - root^2; round up past root + 1/2.
  if (n > root) ++root;
  return root;
}
}  // namespace detail

// Correctly rounded square root. sqrt of a negative number returns 0 and
// raises MathError::kNegativeSqrt.
template <uint8_t I, uint8_t F>
inline Fixed<I, F> sqrt(Fixed<I, F> x) {
  typedef Fixed<I, F> T;
  if (x.raw() < 0) {
    detail::raiseMathError(MathError::kNegativeSqrt);
    return T();
  }
  typename T::UWide n = typename T::UWide(x.raw()) << F;
  return T::fromRaw(typename T::Raw(detail::roundedIntegerSqrt(n)));
}

}  // namespace tinyparticle
