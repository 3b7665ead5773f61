// Scaler<S>: multiplies by one factor many times, faster when the factor is
// a power of two. The world makes one per step for dt: the integrator's
// x += v dt and v += a dt, a multiply each per component, are then shifts.
//
//   Scaler<S> byDt(dt);   // looks at dt once
//   S dx = byDt(v);       // == v * dt, to the last bit
//
// The result is always exactly x * factor as the scalar's own multiply
// rounds it, flags included, so a scene gives the same bits either way:
// - Fixed, factor 2^-8 or 2^-16: a rounding shift by whole bytes, ties away
//   from zero like the multiply. Any other factor: the multiply.
// - Float, factor 2^-k: the exponent field goes down by k when x and the
//   result are normal numbers (the product is then exact, and so is this);
//   zero, subnormal, infinite or NaN operands take the multiply.
// - Any other scalar: the multiply.
#pragma once

#include <stdint.h>
#include <string.h>

#include "Fixed.hpp"
#include "Float.hpp"

namespace tinyparticle {

template <typename S>
class Scaler {
 public:
  typedef S Scalar;
  explicit Scaler(S factor) : mFactor(factor) {}
  S operator()(S x) const { return x * mFactor; }
  S factor() const { return mFactor; }

 private:
  S mFactor;
};

template <uint8_t I, uint8_t F>
class Scaler<Fixed<I, F> > {
  typedef Fixed<I, F> T;
  typedef typename T::Raw Raw;
  typedef typename T::URaw URaw;

 public:
  typedef T Scalar;
  // Only shifts by whole bytes are worth it on AVR (1/256 s in Q16.16 and
  // Q24.8, 1/65536 in Q16.16): a byte moves as a whole, where other shifts
  // would loop bit by bit and cost about what the multiply costs.
  explicit Scaler(T factor) : mFactor(factor), mBytes(0) {
    const Raw raw = factor.raw();
    if (F >= 8 && raw == Raw(T::kRawOne >> (F >= 8 ? 8 : 0))) {
      mBytes = 1;
    } else if (F >= 16 && raw == Raw(T::kRawOne >> (F >= 16 ? 16 : 0))) {
      mBytes = 2;
    }
  }

  T operator()(T x) const {
    if (mBytes == 0) return x * mFactor;
    // round(|x| 2^-k) = (|x| + 2^(k-1)) >> k: the multiply's rounding of
    // |x| 2^(F-k) / 2^F (ties away from zero). |x| + 2^(k-1) fits URaw
    // (|x| <= 2^(bits-1), k <= bits - 2), and the shifted magnitude fits
    // Raw, so the negation is safe.
    const Raw raw = x.raw();
    URaw m = T::magnitude(raw);
    if (mBytes == 1) {
      m = URaw(URaw(m + 0x80u) >> 8);
    } else {  // two bytes: only where F >= 16
      m = URaw(URaw(m + (URaw(1) << (kTwo - 1))) >> kTwo);
    }
    return T::fromRaw(raw < 0 ? Raw(-Raw(m)) : Raw(m));
  }

  T factor() const { return mFactor; }

 private:
  static const uint8_t kTwo = F >= 16 ? 16 : 8;  // (8: never used)

  T mFactor;
  uint8_t mBytes;  // factor = 2^(-8 mBytes); 0: any other, multiply
};

template <>
class Scaler<Float> {
 public:
  typedef Float Scalar;
  explicit Scaler(Float factor) : mFactor(factor), mShift(0), mStep(0) {
    const uint32_t bits = bitsOf(factor.toFloat());
    const uint8_t exponent = exponentOf(uint16_t(bits >> 16));
    // A positive normal power of two below 1: no mantissa bits.
    if ((bits & 0x807FFFFFul) == 0 && exponent != 0 && exponent < 127) {
      mShift = uint8_t(127 - exponent);  // factor = 2^-shift
      mStep = uint16_t(uint16_t(mShift) << 7);
    }
  }

  Float operator()(Float x) const {
    if (mShift != 0) {
      uint32_t bits = bitsOf(x.toFloat());
      // The exponent field is in the high half: bytes, not a 23-bit shift
      // (a loop of 23 steps on AVR).
      const uint16_t high = uint16_t(bits >> 16);
      const uint8_t exponent = exponentOf(high);
      // Normal (not zero, subnormal, infinite or NaN), and the result is
      // normal too: then x 2^-shift only lowers the exponent.
      if (exponent > mShift && exponent != 0xFF) {
        bits -= uint32_t(mStep) << 16;
        float f;
        memcpy(&f, &bits, sizeof(f));
        return Float(f);
      }
    }
    return x * mFactor;
  }

  Float factor() const { return mFactor; }

 private:
  static uint32_t bitsOf(float f) {
    uint32_t bits;
    memcpy(&bits, &f, sizeof(bits));
    return bits;
  }
  // Bits 14..7 of the high half (bits 30..23 of the float).
  static uint8_t exponentOf(uint16_t high) {
    return uint8_t(uint8_t(uint8_t(high >> 8) << 1) |
                   uint8_t(uint8_t(high) >> 7));
  }

  Float mFactor;
  uint8_t mShift;  // 0: not a power of two below 1, multiply
  uint16_t mStep;  // shift << 7: the exponent step in the high half
};

namespace detail {

// x / 2, exactly as x * S(0.5) rounds it: a rounding shift in fixed point
// (ties away from zero, like the multiply), one less in the exponent of a
// normal float (exact), a multiply otherwise.
template <typename S>
inline S half(S x) {
  return x * S(0.5);
}
template <uint8_t I, uint8_t F>
inline Fixed<I, F> half(Fixed<I, F> x) {
  typedef Fixed<I, F> T;
  typedef typename T::Raw Raw;
  // round(x / 2), ties away from zero: (x + 1) >> 1 for x >= 0 (in
  // URaw, where it cannot overflow), floor(x / 2) for x < 0 (-2k - 1 gives
  // -k - 1), an arithmetic shift written as ~(~x >> 1) so that no negative
  // value is shifted. Half the code of negating to the magnitude and back.
  const Raw r = x.raw();
  if (r < 0) return T::fromRaw(Raw(~Raw(Raw(~r) >> 1)));
  return T::fromRaw(Raw(typename T::URaw(typename T::URaw(r) + 1u) >> 1));
}
inline Float half(Float x) {
  float f = x.toFloat();
  uint32_t bits;
  memcpy(&bits, &f, sizeof(bits));
  const uint8_t exponent = uint8_t(uint8_t(uint8_t(bits >> 24) << 1) |
                                   uint8_t(uint8_t(bits >> 16) >> 7));
  // Above the smallest normal exponent and below infinity and NaN.
  if (exponent > 1 && exponent != 0xFF) {
    bits -= 0x00800000ul;
    memcpy(&f, &bits, sizeof(f));
    return Float(f);
  }
  return x * Float(0.5);
}

}  // namespace detail

}  // namespace tinyparticle
