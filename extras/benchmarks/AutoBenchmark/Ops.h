// The operations AutoBenchmark measures, and the operand pools they read.
//
// Every scalar operation works on the type's raw storage (int16_t, int32_t,
// int64_t or float), so that the timing loops read primitives from the
// volatile pools; converting a raw value to Q16_16 or Float and back costs
// nothing.
#pragma once

#include <TinyParticle.h>

#include "Harness.h"
#include "SeedFixed.h"

namespace bench {

// ---------------------------------------------------------------------------
// Raw<S>: the storage of scalar S and the conversions to and from it.

template <typename S>
struct Raw;

template <uint8_t I, uint8_t F>
struct Raw<Fixed<I, F> > {
  typedef Fixed<I, F> S;
  typedef typename S::Raw P;
  static const uint8_t kBits = I + F;
  static const uint8_t kFrac = F;
  static S from(P p) { return S::fromRaw(p); }
  static P to(S s) { return s.raw(); }
  // Values made on the target as float (angles).
  static P fromFloat(float v) { return S(double(v)).raw(); }
  // A raw operand drawn for this format.
  static P fromDraw(int64_t raw) { return P(raw); }
};

template <>
struct Raw<Float> {
  typedef Float S;
  typedef float P;
  // Float draws the Q16.16 operands (converted, rounded to 24 bits), so its
  // errors compare with the fixed types on the range the engine uses.
  static const uint8_t kBits = 32;
  static const uint8_t kFrac = 16;
  static S from(P p) { return S(double(p)); }
  static P to(S s) { return s.toFloat(); }
  static P fromFloat(float v) { return v; }
  static P fromDraw(int64_t raw) { return float(int32_t(raw)) * (1.0f / 65536.0f); }
};

// The integer types: their raw value is the value.
template <typename T, uint8_t Bits>
struct IntRaw {
  typedef T P;
  static const uint8_t kBits = Bits;
  static const uint8_t kFrac = 0;
  static P fromDraw(int64_t raw) { return P(raw); }
};
template <>
struct Raw<int16_t> : IntRaw<int16_t, 16> {};
template <>
struct Raw<int32_t> : IntRaw<int32_t, 32> {};
template <>
struct Raw<int64_t> : IntRaw<int64_t, 64> {};

// ---------------------------------------------------------------------------
// Operand pools. Bit lengths are of the raw value.

template <typename S>
struct Pools {
  typedef Raw<S> T;
  typedef typename T::P P;

  // Both operands over the whole representable range, random signs.
  static void arithmetic() {
    volatile P* p = pool<P>();
    for (uint8_t i = 0; i < 2 * kChunk; ++i) {
      p[i] = T::fromDraw(randomSigned(1, T::kBits - 1));
    }
  }
  // Positive values over the whole range (square root).
  static void positive() {
    volatile P* p = pool<P>();
    for (uint8_t i = 0; i < kChunk; ++i) {
      p[i] = T::fromDraw(int64_t(randomMagnitude(1, T::kBits - 1)));
    }
  }
  // Angles uniform in [-pi, pi).
  static void angles() {
    volatile P* p = pool<P>();
    for (uint8_t i = 0; i < kChunk; ++i) {
      p[i] = T::fromFloat((randomUnit() * 2.0f - 1.0f) * float(M_PI));
    }
  }
  // Vector components whose squares and sum of squares are representable:
  // from 2^-(F/2) up to below sqrt(max / N).
  template <uint8_t N>
  static void vectors() {
    const uint8_t minBits = T::kFrac / 2 + 1;
    const uint8_t maxBits =
        T::kFrac + (T::kBits - T::kFrac - 1 - (N > 2 ? 2 : 1)) / 2 - 1;
    volatile P* p = pool<P>();
    for (uint8_t i = 0; i < N * kChunk; ++i) {
      p[i] = T::fromDraw(randomSigned(minBits, maxBits));
    }
  }
};

// Binary angles: uniform over the whole turn.
inline void fillTurns() {
  volatile uint16_t* p = pool<uint16_t>();
  for (uint8_t i = 0; i < kChunk; ++i) p[i] = uint16_t(random32());
}

// Seeds per pool kind, shared by all types.
const uint32_t kSeedArithmetic = 0x2545F491UL;
const uint32_t kSeedPositive = 0x9E3779B9UL;
const uint32_t kSeedAngles = 0x6A09E667UL;
const uint32_t kSeedTurns = 0x3C6EF372UL;
const uint32_t kSeedVec2 = 0xA54FF53AUL;
const uint32_t kSeedVec3 = 0x510E527FUL;

// ---------------------------------------------------------------------------
// Integer operations. Sums and products wrap (done on the unsigned type, the
// same instructions), so an overflowing operand pair is defined behaviour; the
// host leaves out-of-range results out of the error figures.

template <typename T, typename U>
struct IntAdd {
  typedef T P;
  typedef T R;
  static R apply(P a, P b) { return R(U(a) + U(b)); }
};
template <typename T, typename U>
struct IntSub {
  typedef T P;
  typedef T R;
  static R apply(P a, P b) { return R(U(a) - U(b)); }
};
template <typename T, typename U>
struct IntMul {
  typedef T P;
  typedef T R;
  static R apply(P a, P b) { return R(U(a) * U(b)); }
};
// The pools never hold 0 or the most negative value, so a / b is defined.
template <typename T>
struct IntDiv {
  typedef T P;
  typedef T R;
  static R apply(P a, P b) { return R(a / b); }
};

// ---------------------------------------------------------------------------
// Scalar operations through the library.

template <typename S>
struct Add {
  typedef typename Raw<S>::P P;
  typedef P R;
  static R apply(P a, P b) { return Raw<S>::to(Raw<S>::from(a) + Raw<S>::from(b)); }
};
template <typename S>
struct Sub {
  typedef typename Raw<S>::P P;
  typedef P R;
  static R apply(P a, P b) { return Raw<S>::to(Raw<S>::from(a) - Raw<S>::from(b)); }
};
template <typename S>
struct Mul {
  typedef typename Raw<S>::P P;
  typedef P R;
  static R apply(P a, P b) { return Raw<S>::to(Raw<S>::from(a) * Raw<S>::from(b)); }
};
template <typename S>
struct Div {
  typedef typename Raw<S>::P P;
  typedef P R;
  static R apply(P a, P b) { return Raw<S>::to(Raw<S>::from(a) / Raw<S>::from(b)); }
};
template <typename S>
struct Sqrt {
  typedef typename Raw<S>::P P;
  typedef P R;
  static R apply(P a) { return Raw<S>::to(sqrt(Raw<S>::from(a))); }
};
// atan2(y, x) with y = a, x = b.
template <typename S>
struct Atan2 {
  typedef typename Raw<S>::P P;
  typedef P R;
  static R apply(P y, P x) {
    return Raw<S>::to(atan2(Raw<S>::from(y), Raw<S>::from(x)));
  }
};
template <typename S>
struct Sin {
  typedef typename Raw<S>::P P;
  typedef P R;
  static R apply(P a) { return Raw<S>::to(sin(Raw<S>::from(a))); }
};
template <typename S>
struct Cos {
  typedef typename Raw<S>::P P;
  typedef P R;
  static R apply(P a) { return Raw<S>::to(cos(Raw<S>::from(a))); }
};
template <typename S>
struct SinTurns {
  typedef uint16_t P;
  typedef typename Raw<S>::P R;
  static R apply(P a) { return Raw<S>::to(sinTurns<S>(a)); }
};
template <typename S>
struct CosTurns {
  typedef uint16_t P;
  typedef typename Raw<S>::P R;
  static R apply(P a) { return Raw<S>::to(cosTurns<S>(a)); }
};

// Vectors: N components of S.
template <typename S, uint8_t N>
struct VecBase {
  typedef typename Raw<S>::P P;
  typedef Vec<S, N> V;
  static const uint8_t kDim = N;
  static V load(uint8_t i) {
    volatile P* p = pool<P>();
    V v;
    for (uint8_t k = 0; k < N; ++k) v[k] = Raw<S>::from(p[k * kChunk + i]);
    return v;
  }
};

template <typename S, uint8_t N>
struct Magnitude : VecBase<S, N> {
  typedef VecBase<S, N> Base;
  typedef typename Base::P P;
  typedef typename Base::V V;
  typedef P R;
  static R apply(V v) { return Raw<S>::to(v.magnitude()); }
  static R empty(V v) { return Raw<S>::to(v.x); }
  static void keep(R r) { sink<R>() = r; }
  static void print(R r) { printValue(r); }
};

template <typename S, uint8_t N>
struct Normalize : VecBase<S, N> {
  typedef VecBase<S, N> Base;
  typedef typename Base::P P;
  typedef typename Base::V V;
  typedef V R;
  static R apply(V v) {
    v.normalize();
    return v;
  }
  static R empty(V v) { return v; }
  static void keep(const R& r) {
    for (uint8_t k = 0; k < N; ++k) sink<P>() = Raw<S>::to(r[k]);
  }
  static void print(const R& r) {
    for (uint8_t k = 0; k < N; ++k) printValue(Raw<S>::to(r[k]));
  }
};

// ---------------------------------------------------------------------------
// The seed engine's operations (SeedFixed.h), on Q16.16 raw values.

struct SeedAdd {
  typedef int32_t P;
  typedef int32_t R;
  static R apply(P a, P b) { return seed::add(a, b); }
};
struct SeedSub {
  typedef int32_t P;
  typedef int32_t R;
  static R apply(P a, P b) { return seed::subtract(a, b); }
};
struct SeedMul {
  typedef int32_t P;
  typedef int32_t R;
  static R apply(P a, P b) { return seed::multiply(a, b); }
};
struct SeedDiv {
  typedef int32_t P;
  typedef int32_t R;
  static R apply(P a, P b) { return seed::divide(a, b); }
};
struct SeedSqrt {
  typedef int32_t P;
  typedef int32_t R;
  static R apply(P a) { return seed::squareRoot(a); }
};
struct SeedAtan2 {
  typedef int32_t P;
  typedef int32_t R;
  static R apply(P y, P x) { return seed::atan2(y, x); }
};

struct SeedVecBase {
  typedef int32_t P;
  typedef seed::Vector3 V;
  static const uint8_t kDim = 3;
  static V load(uint8_t i) {
    volatile P* p = pool<P>();
    V v;
    v.x = p[i];
    v.y = p[kChunk + i];
    v.z = p[2 * kChunk + i];
    return v;
  }
};
struct SeedMagnitude : SeedVecBase {
  typedef int32_t R;
  static R apply(V v) { return seed::magnitude3(v.x, v.y, v.z); }
  static R empty(V v) { return v.x; }
  static void keep(R r) { sink<R>() = r; }
  static void print(R r) { printValue(r); }
};
struct SeedNormalize : SeedVecBase {
  typedef V R;
  static R apply(V v) { return seed::normalize3(v); }
  static R empty(V v) { return v; }
  static void keep(const R& r) {
    sink<P>() = r.x;
    sink<P>() = r.y;
    sink<P>() = r.z;
  }
  static void print(const R& r) {
    printValue(r.x);
    printValue(r.y);
    printValue(r.z);
  }
};

}  // namespace bench
