// Fixed<IntBits, FracBits>: a binary fixed-point number.
//
// The storage follows from the format: 16 bits in all -> int16_t,
// 32 bits in all -> int32_t. IntBits counts the sign bit, so Q16_16 holds
// [-32768, 32768) in steps of 2^-16.
//
// Rules every operation keeps:
// - + - * / round to nearest, ties away from zero, so that (-a) * b is
//   exactly -(a * b) and a mirror-symmetric scene stays symmetric.
// - A result that does not fit saturates: it becomes max() or lowest() and
//   raises MathError::kOverflow (see MathErrors.hpp). There is no signed
//   overflow and no shift of a negative value anywhere, so there is no
//   undefined behaviour, whatever the operands.
// - x / 0 returns max() or lowest() with x's sign (0 / 0 returns 0) and
//   raises MathError::kDivideByZero.
// - Construction from an integer or a decimal literal is constexpr, so
//   Q16_16(0.15) costs nothing at run time. A value out of range (or a
//   NaN) saturates (NaN gives 0) and raises MathError::kOverflow at run
//   time; in a constant expression (constexpr Q16_16 k(1e5);) the same
//   conversion does not compile (the error names conversionOutOfRange).
// - The same bits on every platform: a double is first rounded to float
//   (on AVR a double is a float anyway), then that float is rounded to the
//   format exactly (ties away from zero), with integer steps only. So
//   Q16_16(12345.6789) is 12345.6787109375 (raw 809086400) on the PC as on
//   the Nano, not the raw 809086412 that a 64-bit double would give. A
//   value with more than 24 significant bits needs fromRaw() or an integer.
//
// Speed: multiply, divide and square root go through detail::FixedFast,
// which uses hand-written AVR code where TINYPARTICLE_AVR_ASM is 1 (see
// FixedAvr.hpp) and the portable reference* functions everywhere else. The
// reference functions stay callable on every target so that tests can
// compare the two.
#pragma once

#include <stdint.h>
#include <string.h>

#include "../Configuration.hpp"
#include "MathErrors.hpp"

// The operators are one-line wrappers around the raw functions; at -Os
// avr-gcc would otherwise call them out of line and pass the object
// through memory, which costs more than the arithmetic itself.
#if defined(__GNUC__)
#define TINYPARTICLE_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define TINYPARTICLE_ALWAYS_INLINE inline
#endif

// The hand-written AVR code in use: the add/subtract below need any AVR,
// FixedAvr.hpp (multiply, divide, square root, atan2) one with MUL.
#if TINYPARTICLE_AVR_ASM && defined(__AVR__)
#define TINYPARTICLE_AVR_ASM_ADD 1
#else
#define TINYPARTICLE_AVR_ASM_ADD 0
#endif
#if TINYPARTICLE_AVR_ASM && defined(__AVR__) && defined(__AVR_HAVE_MUL__)
#define TINYPARTICLE_AVR_ASM_MUL 1
#else
#define TINYPARTICLE_AVR_ASM_MUL 0
#endif

// Whether the compiler knows a value (after inlining): constants take the
// inlined path that folds, other values a call. Without the builtin every
// value takes the inlined path.
#if defined(__GNUC__)
#define TINYPARTICLE_IS_CONSTANT(x) __builtin_constant_p(x)
#else
#define TINYPARTICLE_IS_CONSTANT(x) true
#endif

// __builtin_add_overflow and friends: GCC 5 and later, clang.
#if defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 5)
#define TINYPARTICLE_HAS_OVERFLOW_BUILTINS 1
#else
#define TINYPARTICLE_HAS_OVERFLOW_BUILTINS 0
#endif

namespace tinyparticle {

namespace detail {

template <uint8_t TotalBits>
struct FixedStorage;

template <>
struct FixedStorage<16> {
  typedef int16_t Raw;
  typedef uint16_t URaw;
  typedef uint32_t UWide;  // holds a product of two magnitudes
  static const Raw kMax = INT16_MAX;
};

template <>
struct FixedStorage<32> {
  typedef int32_t Raw;
  typedef uint32_t URaw;
  typedef uint64_t UWide;
  static const Raw kMax = INT32_MAX;
};

// Wrapping add and subtract that report signed overflow. On AVR the
// overflow flag of the last add/sub instruction says it directly; the
// compiler's builtins would compare the operands instead (about 3 times
// slower with avr-gcc 5.4).
#if TINYPARTICLE_AVR_ASM_ADD
// Saturating add and subtract in a few instructions and one call that is
// taken only on overflow: the wrapped result sits in fixed registers (r22
// for 32 bits, r24 for 16, the convention's return registers), so one
// routine saturates it for every site, raising MathError::kOverflow; it
// changes nothing else but the status flags. Inlined with a flag byte and a
// call to a C++ saturation instead, every site was 6 bytes and 3 cycles
// longer. The routines' results equal referenceAdd() and
// referenceSubtract() (AsmClassesTest, `make verify-asm`). The multiply and
// the divide saturate here too (FixedAvr.hpp).
//
// The low result byte, overwritten anyway, carries the flags byte (ori
// needs r16 or above; through r0 it took set and bld), and the high byte
// comes from the low one by subtracting 0x80: 0xFF - 0x80 = 0x7F,
// 0 - 0x80 = 0x80 (22 bytes where the first version took 34).
#define TINYPARTICLE_AVR_RAISE_OVERFLOW(reg)                          \
  "lds  " reg ", _ZN12tinyparticle6detail14MathErrorStoreIvE5flagsE\n\t" \
  "ori  " reg ", 4\n\t" /* MathError::kOverflow */                    \
  "sts  _ZN12tinyparticle6detail14MathErrorStoreIvE5flagsE, " reg "\n\t"
static_assert(uint8_t(MathError::kOverflow) == 4,
              "the saturation routines set bit 2 of the flags");
// r22..r25 wrapped, of sign s (bit 7 of r25): max() when s (the true sum
// was positive), else lowest().
extern "C" __attribute__((naked, noinline)) inline void
tinyparticle_saturate32() {
  asm volatile(TINYPARTICLE_AVR_RAISE_OVERFLOW("r22")
               "lsl  r25\n\t"       // C = s
               "sbc  r22, r22\n\t"  // 0xFF when s, else 0
               "mov  r23, r22\n\t"
               "movw r24, r22\n\t"
               "subi r25, 0x80\n\t" // 0x7F when s, else 0x80
               "ret");
}
// r24..r25 wrapped, likewise.
extern "C" __attribute__((naked, noinline)) inline void
tinyparticle_saturate16() {
  asm volatile(TINYPARTICLE_AVR_RAISE_OVERFLOW("r24")
               "lsl  r25\n\t"
               "sbc  r24, r24\n\t"
               "mov  r25, r24\n\t"
               "subi r25, 0x80\n\t"
               "ret");
}
#undef TINYPARTICLE_AVR_RAISE_OVERFLOW
// The flags byte is an operand ("+m"), so that reads of mathErrors() stay
// ordered with the adds that may raise it.
TINYPARTICLE_ALWAYS_INLINE int32_t addSaturating(int32_t a, int32_t b) {
  register int32_t sum asm("r22") = a;
  asm("add  %A0, %A2\n\t"
      "adc  %B0, %B2\n\t"
      "adc  %C0, %C2\n\t"
      "adc  %D0, %D2\n\t"
      "brvc 1f\n\t"
      "call %x3\n"
      "1:"
      : "+r"(sum), "+m"(MathErrorStore<void>::flags)
      : "r"(b), "i"(tinyparticle_saturate32)
      : "cc");
  return sum;
}
TINYPARTICLE_ALWAYS_INLINE int32_t subtractSaturating(int32_t a, int32_t b) {
  register int32_t difference asm("r22") = a;
  asm("sub  %A0, %A2\n\t"
      "sbc  %B0, %B2\n\t"
      "sbc  %C0, %C2\n\t"
      "sbc  %D0, %D2\n\t"
      "brvc 1f\n\t"
      "call %x3\n"
      "1:"
      : "+r"(difference), "+m"(MathErrorStore<void>::flags)
      : "r"(b), "i"(tinyparticle_saturate32)
      : "cc");
  return difference;
}
TINYPARTICLE_ALWAYS_INLINE int16_t addSaturating(int16_t a, int16_t b) {
  register int16_t sum asm("r24") = a;
  asm("add  %A0, %A2\n\t"
      "adc  %B0, %B2\n\t"
      "brvc 1f\n\t"
      "call %x3\n"
      "1:"
      : "+r"(sum), "+m"(MathErrorStore<void>::flags)
      : "r"(b), "i"(tinyparticle_saturate16)
      : "cc");
  return sum;
}
TINYPARTICLE_ALWAYS_INLINE int16_t subtractSaturating(int16_t a, int16_t b) {
  register int16_t difference asm("r24") = a;
  asm("sub  %A0, %A2\n\t"
      "sbc  %B0, %B2\n\t"
      "brvc 1f\n\t"
      "call %x3\n"
      "1:"
      : "+r"(difference), "+m"(MathErrorStore<void>::flags)
      : "r"(b), "i"(tinyparticle_saturate16)
      : "cc");
  return difference;
}
#elif TINYPARTICLE_HAS_OVERFLOW_BUILTINS
template <typename Raw>
TINYPARTICLE_ALWAYS_INLINE bool addOverflows(Raw& a, Raw b) {
  return __builtin_add_overflow(a, b, &a);
}
template <typename Raw>
TINYPARTICLE_ALWAYS_INLINE bool subtractOverflows(Raw& a, Raw b) {
  return __builtin_sub_overflow(a, b, &a);
}
#endif

// The raw multiply, divide and square root actually used. The primary
// template (after class Fixed) forwards to the portable reference code;
// FixedAvr.hpp specializes it for the formats it speeds up.
template <uint8_t IntBits, uint8_t FracBits>
struct FixedFast;

}  // namespace detail

template <uint8_t IntBits, uint8_t FracBits>
class Fixed {
  static_assert(IntBits + FracBits == 16 || IntBits + FracBits == 32,
                "Fixed needs 16 or 32 bits in all");
  static_assert(IntBits >= 2 && FracBits >= 1,
                "Fixed needs a sign bit, an integer bit and a fraction bit");
  typedef detail::FixedStorage<IntBits + FracBits> Storage;

 public:
  typedef typename Storage::Raw Raw;
  typedef typename Storage::URaw URaw;
  typedef typename Storage::UWide UWide;

  static const uint8_t kIntBits = IntBits;
  static const uint8_t kFracBits = FracBits;
  static const uint8_t kTotalBits = IntBits + FracBits;
  static const Raw kRawMax = Storage::kMax;
  static const Raw kRawMin = -Storage::kMax - 1;
  static const Raw kRawOne = Raw(1) << FracBits;

  constexpr Fixed() : mRaw(0) {}
  constexpr explicit Fixed(int v) : mRaw(fromSigned(v)) {}
  constexpr explicit Fixed(long v) : mRaw(fromSigned(v)) {}
  constexpr explicit Fixed(long long v) : mRaw(fromSigned(v)) {}
  constexpr explicit Fixed(unsigned v) : mRaw(fromUnsigned(v)) {}
  constexpr explicit Fixed(unsigned long v) : mRaw(fromUnsigned(v)) {}
  constexpr explicit Fixed(unsigned long long v) : mRaw(fromUnsigned(v)) {}
  // Inlined, so that a constant folds at every call site, also at -Os; a
  // value known only at run time calls the conversion out of line.
  TINYPARTICLE_ALWAYS_INLINE constexpr explicit Fixed(double v)
      : mRaw(TINYPARTICLE_IS_CONSTANT(v) ? fromDouble(v)
                                         : fromDoubleOutOfLine(v)) {}

  // The value whose representation is `raw`, i.e. raw / 2^FracBits.
  static constexpr Fixed fromRaw(Raw raw) { return Fixed(raw, RawTag()); }
  constexpr Raw raw() const { return mRaw; }

  constexpr float toFloat() const { return float(mRaw) * (1.0f / kScale); }
  // Rounds toward zero, like a cast from float to int.
  constexpr int32_t toInt() const {
    return mRaw >= 0 ? int32_t(mRaw >> FracBits)
                     : -int32_t(magnitude(mRaw) >> FracBits);
  }

  // The largest value. (Not max(): Arduino.h defines max(a, b) as a macro.)
  static constexpr Fixed largest() { return fromRaw(kRawMax); }
  // The most negative value.
  static constexpr Fixed lowest() { return fromRaw(kRawMin); }
  // The smallest positive value, one step of the format.
  static constexpr Fixed epsilon() { return fromRaw(1); }
  // pi rounded to the format (max() where pi does not fit).
  static constexpr Fixed pi() { return fromRaw(piRaw()); }

  TINYPARTICLE_ALWAYS_INLINE Fixed operator+(Fixed b) const { return fromRaw(add(mRaw, b.mRaw)); }
  TINYPARTICLE_ALWAYS_INLINE Fixed operator-(Fixed b) const { return fromRaw(subtract(mRaw, b.mRaw)); }
  TINYPARTICLE_ALWAYS_INLINE Fixed operator*(Fixed b) const { return fromRaw(multiply(mRaw, b.mRaw)); }
  TINYPARTICLE_ALWAYS_INLINE Fixed operator/(Fixed b) const { return fromRaw(divide(mRaw, b.mRaw)); }
  TINYPARTICLE_ALWAYS_INLINE Fixed operator-() const { return fromRaw(subtract(0, mRaw)); }
  TINYPARTICLE_ALWAYS_INLINE Fixed& operator+=(Fixed b) { return *this = *this + b; }
  TINYPARTICLE_ALWAYS_INLINE Fixed& operator-=(Fixed b) { return *this = *this - b; }
  TINYPARTICLE_ALWAYS_INLINE Fixed& operator*=(Fixed b) { return *this = *this * b; }
  TINYPARTICLE_ALWAYS_INLINE Fixed& operator/=(Fixed b) { return *this = *this / b; }

  constexpr bool operator==(Fixed b) const { return mRaw == b.mRaw; }
  constexpr bool operator!=(Fixed b) const { return mRaw != b.mRaw; }
  constexpr bool operator<(Fixed b) const { return mRaw < b.mRaw; }
  constexpr bool operator<=(Fixed b) const { return mRaw <= b.mRaw; }
  constexpr bool operator>(Fixed b) const { return mRaw > b.mRaw; }
  constexpr bool operator>=(Fixed b) const { return mRaw >= b.mRaw; }

  // ---- Raw operations -----------------------------------------------------
  // On representations; they saturate and raise flags like the operators.

  TINYPARTICLE_ALWAYS_INLINE static Raw add(Raw a, Raw b) {
#if TINYPARTICLE_AVR_ASM_ADD
    return detail::addSaturating(a, b);
#elif TINYPARTICLE_HAS_OVERFLOW_BUILTINS
    // Defined for every input (no signed overflow in C++ terms).
    // After an overflow the wrapped sum has the wrong sign: saturate
    // toward the other one (a itself need not be kept).
    Raw sum = a;
    if (detail::addOverflows(sum, b)) return overflowAgainstSignOf(sum);
    return sum;
#else
    return referenceAdd(a, b);
#endif
  }

  TINYPARTICLE_ALWAYS_INLINE static Raw subtract(Raw a, Raw b) {
#if TINYPARTICLE_AVR_ASM_ADD
    return detail::subtractSaturating(a, b);
#elif TINYPARTICLE_HAS_OVERFLOW_BUILTINS
    Raw difference = a;
    if (detail::subtractOverflows(difference, b)) {
      return overflowAgainstSignOf(difference);
    }
    return difference;
#else
    return referenceSubtract(a, b);
#endif
  }

  // The fastest correct code for this target (FixedFast).
  TINYPARTICLE_ALWAYS_INLINE static Raw multiply(Raw a, Raw b) {
    return detail::FixedFast<IntBits, FracBits>::multiply(a, b);
  }
  TINYPARTICLE_ALWAYS_INLINE static Raw divide(Raw a, Raw b) {
    if (b == 0) return divideByZero(a);
    return detail::FixedFast<IntBits, FracBits>::divide(a, b);
  }
  // round(sqrt(x)); x < 0 gives 0 and raises MathError::kNegativeSqrt.
  TINYPARTICLE_ALWAYS_INLINE static Raw squareRoot(Raw x) {
    if (x < 0) return negativeSqrt();
    return detail::FixedFast<IntBits, FracBits>::squareRoot(x);
  }

  // The portable C++ versions: exact, simple, slow on 8-bit CPUs. They are
  // the reference in the tests, on every target.
  static Raw referenceAdd(Raw a, Raw b) {
    Raw sum = toSigned(URaw(URaw(a) + URaw(b)));
    // Overflow only when a and b share a sign that the sum lacks.
    if (((a ^ sum) & (b ^ sum)) < 0) return overflow(a < 0);
    return sum;
  }

  static Raw referenceSubtract(Raw a, Raw b) {
    Raw difference = toSigned(URaw(URaw(a) - URaw(b)));
    if (((a ^ b) & (a ^ difference)) < 0) return overflow(a < 0);
    return difference;
  }

  // fromDouble() by float steps: what the constructor folds a constant to,
  // and the reference of the bits' steps for a value known only at run
  // time (fromDoubleOutOfLine()).
  static Raw referenceFromDouble(double v) { return fromDouble(v); }

  static Raw referenceMultiply(Raw a, Raw b) {
    UWide product = UWide(magnitude(a)) * magnitude(b);
    UWide rounded = (product + (UWide(1) << (FracBits - 1))) >> FracBits;
    return fromMagnitude(rounded, (a < 0) != (b < 0));
  }

  static Raw referenceDivide(Raw a, Raw b) {
    if (b == 0) return divideByZero(a);
    UWide numerator = UWide(magnitude(a)) << FracBits;
    UWide divisor = magnitude(b);
    // Rounds up when twice the remainder reaches the divisor.
    UWide quotient = (numerator + divisor / 2) / divisor;
    return fromMagnitude(quotient, (a < 0) != (b < 0));
  }

  // 1 / b, exactly as divide(kRawOne, b) gives it (rounding, saturation,
  // flags; b = 0 as in divide()), from a bit-by-bit long division: 128
  // bytes of code on AVR in Q16.16 where the fast divide and its table take
  // about 1 KB, but several times its cycles. For set-up (an inverse mass,
  // an inverse length): a sketch that never divides while stepping then
  // links neither the fast divide nor its table. Portable, the same code
  // on every target. Inlined, so that what the caller knows of b (a mass
  // is positive) drops the tests it makes unnecessary; the loop is out of
  // line.
  TINYPARTICLE_ALWAYS_INLINE static Raw compactReciprocal(Raw b) {
    if (b == 0) return divideByZero(kRawOne);
    if (b > 0) return Raw(reciprocalOfPositive(URaw(b)));
    const URaw d = magnitude(b);
    // Below kLowestDivisor the quotient is out of range, at it exactly
    // lowest(); above, its magnitude fits kRawMax.
    if (d <= kLowestDivisor) {
      return d == kLowestDivisor ? kRawMin : overflow(true);
    }
    return Raw(-Raw(positiveReciprocal(d)));
  }
  // positiveReciprocal(d), folded where d is a constant the compiler
  // knows (a mass given as a literal): the wide division is then done at
  // compile time, and the call and its argument moves go.
  TINYPARTICLE_ALWAYS_INLINE static URaw reciprocalOfPositive(URaw d) {
    if (TINYPARTICLE_IS_CONSTANT(d) && d > kLowestDivisor) {
      return URaw(((UWide(1) << (2 * FracBits)) + d / 2) / d);
    }
    return positiveReciprocal(d);
  }
  // 1 / d for d > 0: round(2^(2 FracBits) / d), ties up, or kRawMax and
  // kOverflow when that does not fit (d <= kLowestDivisor). Long
  // division: r is the partial remainder, doubled for the next digit (the
  // numerator's single 1 is its start, the digits after it are zeros); r <
  // 2d <= 2^bits, so it fits URaw, and the quotient is below 2^(bits-1).
  TINYPARTICLE_NOINLINE static URaw positiveReciprocal(URaw d) {
    if (d <= kLowestDivisor) {
      detail::raiseMathError(MathError::kOverflow);
      return URaw(kRawMax);
    }
    URaw q = 0;
    URaw r = 1;
    for (uint8_t i = 0; i <= 2 * FracBits; ++i) {
      q = URaw(q << 1);
      if (r >= d) {
        r = URaw(r - d);
        q = URaw(q | 1u);
      }
      r = URaw(r << 1);
    }
    // r is now twice the remainder: round up when it reaches d, as the
    // divide does (the result stays within kRawMax: see kLowestDivisor).
    return r >= d ? URaw(q + 1u) : q;
  }

  static Raw referenceSquareRoot(Raw x) {
    if (x < 0) return negativeSqrt();
    // sqrt(raw / 2^F) * 2^F = sqrt(raw * 2^F): an integer square root.
    UWide n = UWide(URaw(x)) << FracBits;
    UWide root = 0;
    UWide bit = UWide(1) << (sizeof(UWide) * 8 - 2);
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
    // n is now the remainder x * 2^F - root^2; past root + 1/2 round up.
    if (n > root) ++root;
    return Raw(root);  // at most sqrt(2^(kTotalBits - 1 + F)): it fits
  }

  // |raw| as an unsigned number; exact for kRawMin too.
  static constexpr URaw magnitude(Raw raw) {
    return raw < 0 ? URaw(URaw(0) - URaw(raw)) : URaw(raw);
  }

  // The value with magnitude `m` and the given sign, saturated.
  static Raw fromMagnitude(UWide m, bool negative) {
    if (negative) {
      if (m > UWide(kRawMax) + 1) return overflow(true);
      return toSigned(URaw(URaw(0) - URaw(m)));
    }
    if (m > UWide(kRawMax)) return overflow(false);
    return Raw(m);
  }

  // Saturated result of an overflow; raises MathError::kOverflow.
  static Raw overflow(bool negative) {
    detail::raiseMathError(MathError::kOverflow);
    return negative ? kRawMin : kRawMax;
  }
  // The same, out of line (the rare path of + and - then costs no
  // registers at the call site): max() for wrapped < 0, else lowest().
  TINYPARTICLE_NOINLINE static Raw overflowAgainstSignOf(Raw wrapped) {
    return overflow(wrapped >= 0);
  }

  // Two's-complement reinterpretation without implementation-defined casts.
  static constexpr Raw toSigned(URaw u) {
    return u <= URaw(kRawMax) ? Raw(u) : Raw(-Raw(URaw(~u)) - 1);
  }

 private:
  struct RawTag {};
  constexpr Fixed(Raw raw, RawTag) : mRaw(raw) {}

  static constexpr double kScale = double(uint32_t(1) << FracBits);
  static constexpr float kScaleFloat = float(uint32_t(1) << FracBits);
  // long is 32 bits on AVR, so these compares stay cheap there.
  static constexpr long kIntMax = long(kRawMax >> FracBits);
  static constexpr long kIntMin = -kIntMax - 1;
  // compactReciprocal(): the divisor d = 2^(2 FracBits - bits + 1) whose
  // reciprocal is exactly 2^(bits-1) steps, |lowest()|; a smaller one gives
  // more, a larger one at most kRawMax (rounding cannot reach 2^(bits-1)
  // from below, as FracBits <= bits - 2). 0 where no divisor reaches it
  // (Q24.8).
  static constexpr URaw kLowestDivisor =
      2 * FracBits + 1 >= kTotalBits
          ? URaw(URaw(1) << (2 * FracBits + 1 >= kTotalBits
                                 ? 2 * FracBits + 1 - kTotalBits
                                 : 0))
          : URaw(0);

  static Raw divideByZero(Raw a) {
    detail::raiseMathError(MathError::kDivideByZero);
    return a > 0 ? kRawMax : (a < 0 ? kRawMin : Raw(0));
  }
  static Raw negativeSqrt() {
    detail::raiseMathError(MathError::kNegativeSqrt);
    return 0;
  }

  // Out of range: the saturated value (0 for a NaN) and the flag. Not
  // constexpr, so a conversion that gets here in a constant expression
  // fails to compile.
  static Raw conversionOutOfRange(Raw saturated) {
    detail::raiseMathError(MathError::kOverflow);
    return saturated;
  }

  // In range, v * 2^FracBits fits Raw, so the product cannot overflow.
  template <typename T>
  static constexpr Raw fromSigned(T v) {
    return v > kIntMax ? conversionOutOfRange(kRawMax)
         : v < kIntMin ? conversionOutOfRange(kRawMin)
                       : Raw(Raw(v) * kRawOne);
  }
  template <typename T>
  static constexpr Raw fromUnsigned(T v) {
    return v > (unsigned long)kIntMax ? conversionOutOfRange(kRawMax)
                                      : Raw(Raw(v) * kRawOne);
  }
  // A value known only at run time: fromDouble()'s result, by integer
  // steps on the float's bits, so that the conversion itself calls no
  // float routine (on AVR the float steps were 408 B and called float
  // compares and both conversions between float and uint32_t: the Spring
  // example is 56 B smaller this way, the stiff spring's ladder rung 150
  // B). Checked against fromDouble() at every exponent and at each
  // rounding and overflow edge (extras/test/FixedTest).
  TINYPARTICLE_NOINLINE static Raw fromDoubleOutOfLine(double v) {
    if (sizeof(double) > sizeof(float)) {  // beyond float's range: caught first
      if (v >= 4294967296.0) return conversionOutOfRange(kRawMax);
      if (v <= -4294967296.0) return conversionOutOfRange(kRawMin);
    }
    const float f = float(v);
    uint32_t bits;
    memcpy(&bits, &f, sizeof(bits));
    return fromFloatBits(bits);
  }
  // |f| = m 2^(e - 150) with m the significand (the hidden bit set unless
  // subnormal, where e counts as 1), so |f| 2^FracBits = m 2^shift.
  static Raw fromFloatBits(uint32_t bits) {
    const bool negative = (bits >> 31) != 0;
    const uint8_t exponent = uint8_t(bits >> 23);
    uint32_t m = bits & 0x7FFFFFul;
    if (exponent == 0xFF) {  // NaN gives 0, an infinity saturates
      return conversionOutOfRange(m != 0   ? Raw(0)
                                  : negative ? kRawMin
                                             : kRawMax);
    }
    if (exponent != 0) m |= 0x800000ul;
    const int16_t shift =
        int16_t(exponent != 0 ? exponent : 1) - 150 + FracBits;
    if (shift >= 0) {
      // m < 2^24: m 2^shift reaches 2^32 only for shift > 8.
      if (shift > 8 && (shift > 31 || (m >> (32 - shift)) != 0)) {
        return conversionOutOfRange(negative ? kRawMin : kRawMax);
      }
      return fromRoundedMagnitude(m << shift, negative);
    }
    // Ties away from zero: add half a unit of the result, then drop the
    // bits below it. Below half a unit (shift < -24: m < 2^24) it is 0.
    const uint8_t down = uint8_t(-shift);
    return fromRoundedMagnitude(
        down > 24 ? 0 : (m + (uint32_t(1) << (down - 1))) >> down, negative);
  }
  // Through float on every platform (see the top of the file). Beyond
  // 2^32 the double is out of every format, and its conversion to float
  // could overflow, so it is caught first.
  TINYPARTICLE_ALWAYS_INLINE static constexpr Raw fromDouble(double v) {
    return v != v ? conversionOutOfRange(Raw(0))
         : v >= 4294967296.0 ? conversionOutOfRange(kRawMax)
         : v <= -4294967296.0 ? conversionOutOfRange(kRawMin)
         : fromFloat(float(v));
  }
  // |f| * 2^FracBits is exact (a power of two), and so are its whole part
  // (a uint32_t below 2^32) and the fraction left: the rounding is exact
  // and the same wherever it is done.
  TINYPARTICLE_ALWAYS_INLINE static constexpr Raw fromFloat(float f) {
    return f < 0.0f ? fromScaledMagnitude(-f * kScaleFloat, true)
                    : fromScaledMagnitude(f * kScaleFloat, false);
  }
  TINYPARTICLE_ALWAYS_INLINE static constexpr Raw fromScaledMagnitude(float m, bool negative) {
    return m >= 4294967296.0f
               ? conversionOutOfRange(negative ? kRawMin : kRawMax)
               : fromRoundedMagnitude(
                     uint32_t(m) + (m - float(uint32_t(m)) >= 0.5f ? 1u : 0u),
                     negative);
  }
  TINYPARTICLE_ALWAYS_INLINE static constexpr Raw fromRoundedMagnitude(uint32_t m, bool negative) {
    return negative
               ? (m > uint32_t(kRawMax) + 1u
                      ? conversionOutOfRange(kRawMin)
                      : toSigned(URaw(URaw(0) - URaw(m))))
               : (m > uint32_t(kRawMax) ? conversionOutOfRange(kRawMax)
                                        : Raw(m));
  }

  // round(pi * 2^30), exact in integers, so pi() is right on AVR too where
  // a double literal has only 24 bits.
  static constexpr uint32_t kPiQ30 = 0xC90FDAA2ul;
  static constexpr uint8_t kPiShift = FracBits < 30 ? 30 - FracBits : 1;
  static constexpr uint32_t kPiRounded =
      (kPiQ30 >> kPiShift) + ((kPiQ30 >> (kPiShift - 1)) & 1u);
  static constexpr Raw piRaw() {
    return FracBits >= 30 || kPiRounded > uint32_t(kRawMax) ? kRawMax
                                                             : Raw(kPiRounded);
  }

  Raw mRaw;
};

template <uint8_t I, uint8_t F>
constexpr double Fixed<I, F>::kScale;
template <uint8_t I, uint8_t F>
constexpr float Fixed<I, F>::kScaleFloat;

namespace detail {
// Portable: the reference code is the fast path.
template <uint8_t IntBits, uint8_t FracBits>
struct FixedFast {
  typedef Fixed<IntBits, FracBits> T;
  typedef typename T::Raw Raw;
  static Raw multiply(Raw a, Raw b) { return T::referenceMultiply(a, b); }
  // b != 0 (Fixed::divide handled it).
  static Raw divide(Raw a, Raw b) { return T::referenceDivide(a, b); }
  // x >= 0 (Fixed::squareRoot handled it).
  static Raw squareRoot(Raw x) { return T::referenceSquareRoot(x); }
};

// 1 / x, the same value and flags as S(1) / x, from code that is small
// rather than fast (Fixed::compactReciprocal): for set-up, where a divide
// would link the fast divide into a sketch that never divides in a step.
// Other scalars divide.
template <typename S>
inline S compactReciprocal(S x) {
  return S(1) / x;
}
template <uint8_t I, uint8_t F>
TINYPARTICLE_ALWAYS_INLINE Fixed<I, F> compactReciprocal(Fixed<I, F> x) {
  return Fixed<I, F>::fromRaw(Fixed<I, F>::compactReciprocal(x.raw()));
}
// The same for an x the caller knows to be positive (a step's dt): a
// fixed-point format then skips the zero and sign cases. (x <= 0 breaks
// the promise: the result is then meaningless.)
template <typename S>
inline S compactReciprocalOfPositive(S x) {
  return S(1) / x;
}
template <uint8_t I, uint8_t F>
TINYPARTICLE_ALWAYS_INLINE Fixed<I, F> compactReciprocalOfPositive(
    Fixed<I, F> x) {
  typedef Fixed<I, F> T;
  // Through reciprocalOfPositive(): a constant x folds. (With the plain
  // call the two-World-types scene took 46 B more and BouncingBalls 14 B;
  // the inverse of dt, kept out of line, is InverseDt<S>'s, shared by
  // every World type: the shared-engine check.)
  return T::fromRaw(typename T::Raw(
      T::reciprocalOfPositive(typename T::URaw(x.raw()))));
}
}  // namespace detail

// The formats the library names. Q16_16 is the default fixed type.
typedef Fixed<16, 16> Q16_16;
typedef Fixed<24, 8> Q24_8;
typedef Fixed<8, 8> Q8_8;

// abs, min and max are macros in Arduino.h, so these take the C library's
// floating-point names, which are functions there.
// fabs(lowest()) saturates to max() and raises MathError::kOverflow.
template <uint8_t I, uint8_t F>
inline Fixed<I, F> fabs(Fixed<I, F> x) {
  return x < Fixed<I, F>() ? -x : x;
}
template <uint8_t I, uint8_t F>
inline Fixed<I, F> fmin(Fixed<I, F> a, Fixed<I, F> b) {
  return b < a ? b : a;
}
template <uint8_t I, uint8_t F>
inline Fixed<I, F> fmax(Fixed<I, F> a, Fixed<I, F> b) {
  return a < b ? b : a;
}

// x limited to [lo, hi] (lo <= hi).
template <uint8_t I, uint8_t F>
inline Fixed<I, F> clamp(Fixed<I, F> x, Fixed<I, F> lo, Fixed<I, F> hi) {
  return x < lo ? lo : (hi < x ? hi : x);
}

}  // namespace tinyparticle

#if TINYPARTICLE_AVR_ASM_MUL
#include "FixedAvr.hpp"
#endif
