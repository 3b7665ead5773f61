// Printing scalars and vectors as decimal text:
//
//   print(Serial, x);          // 0.47943  (Q16_16: 5 decimals)
//   println(Serial, v);        // (0.47943, -0.87758)
//   print(Serial, x, 2);       // 0.48
//
// `out` is anything with write(uint8_t): Serial, any Print, a test buffer.
// (Serial.print(x) cannot take a scalar: that would need Printable and its
// virtual table in every scalar, 4 more bytes per coordinate.)
//
// Fixed point is printed from its raw integer with integer steps only, so a
// fixed-point sketch links no float routine for it. The text is the value
// raw / 2^FracBits rounded to `decimals` decimals, ties away from zero; a
// minus sign only when the rounded text is not zero. By default a format
// gets the fewest decimals that tell any two of its values apart
// (10^-decimals <= 2^-FracBits): 5 for Q16_16, 3 for Q24_8 and Q8_8.
//
// Float prints 5 decimals by default (as Q16_16, so the two read alike), in
// float arithmetic; "nan", "inf" and "-inf" for those; from 1e9 on, a
// mantissa and an exponent (1.50000e+12). At most 10 decimals either way.
//
// Anything else is a compile error that says what print() takes.
#pragma once

#include <stdint.h>

#include "../Math/Fixed.hpp"
#include "../Math/Float.hpp"
#include "../Math/Vec.hpp"

namespace tinyparticle {

namespace detail {

const uint8_t kMaxDecimals = 10;

template <class Out>
void writeText(Out& out, const char* text) {
  while (*text != '\0') out.write(uint8_t(*text++));
}

// A whole number in decimal. Below 65536 in 16-bit steps, several times
// faster than 32-bit division on an 8-bit AVR.
template <class Out>
void writeWhole(Out& out, uint32_t n) {
  char digits[10];
  uint8_t count = 0;
  while (n > 0xFFFFUL) {
    digits[count++] = char('0' + n % 10);
    n /= 10;
  }
  uint16_t small = uint16_t(n);
  do {
    digits[count++] = char('0' + small % 10);
    small = uint16_t(small / 10);
  } while (small > 0);
  while (count > 0) out.write(uint8_t(digits[--count]));
}

// Adds one unit in the last of `count` decimal digits; true if it carries
// out of the first one (all were 9).
inline bool roundUpDigits(uint8_t* digits, uint8_t count) {
  while (count > 0) {
    --count;
    if (digits[count] != 9) {
      ++digits[count];
      return false;
    }
    digits[count] = 0;
  }
  return true;
}

// sign, whole part, then a point and the decimals if there are any. The sign
// only for a text that is not zero.
template <class Out>
void writeDecimal(Out& out, bool negative, uint32_t whole,
                  const uint8_t* digits, uint8_t count) {
  bool zero = whole == 0;
  for (uint8_t i = 0; i < count; ++i) zero = zero && digits[i] == 0;
  if (negative && !zero) out.write(uint8_t('-'));
  writeWhole(out, whole);
  if (count == 0) return;
  out.write(uint8_t('.'));
  for (uint8_t i = 0; i < count; ++i) out.write(uint8_t('0' + digits[i]));
}

// The fraction's working integer: it must hold fraction * 10.
template <bool kNarrow>
struct FractionWord {
  typedef uint32_t Type;
};
template <>
struct FractionWord<false> {
  typedef uint64_t Type;
};

}  // namespace detail

// Printer<T>: how print() writes a T. Only the library's scalars and
// vectors have one.
template <typename T>
struct Printer {
  static_assert(sizeof(T) == 0,
                "print(out, x) prints a TinyParticle scalar (Q16_16, Q24_8, "
                "Q8_8, Float) or vector; print other values with "
                "Serial.print(x)");
};

template <uint8_t IntBits, uint8_t FracBits>
struct Printer<Fixed<IntBits, FracBits> > {
  typedef Fixed<IntBits, FracBits> S;
  // ceil(FracBits * log10(2)), log10(2) = 0.30103.
  static const uint8_t kDecimals =
      uint8_t((FracBits * 30103UL + 99999UL) / 100000UL);

  template <class Out>
  static void print(Out& out, S x, uint8_t decimals) {
    typedef typename detail::FractionWord<(FracBits <= 27)>::Type Word;
    if (decimals > detail::kMaxDecimals) decimals = detail::kMaxDecimals;
    const int32_t raw = x.raw();
    // The magnitude, in modular unsigned arithmetic (no signed overflow for
    // the lowest value).
    const uint32_t magnitude = raw < 0 ? uint32_t(0) - uint32_t(raw)
                                       : uint32_t(raw);
    const uint32_t mask = (uint32_t(1) << FracBits) - 1;
    uint32_t whole = magnitude >> FracBits;
    // The exact decimal expansion of the fraction, one digit at a time.
    Word fraction = magnitude & mask;
    uint8_t digits[detail::kMaxDecimals];
    for (uint8_t i = 0; i < decimals; ++i) {
      fraction *= 10;
      digits[i] = uint8_t(fraction >> FracBits);
      fraction &= mask;
    }
    // What is left is below one unit of the last digit: round it, ties up.
    if (fraction >= (Word(1) << (FracBits - 1)) &&
        detail::roundUpDigits(digits, decimals)) {
      ++whole;
    }
    detail::writeDecimal(out, raw < 0, whole, digits, decimals);
  }
};

template <>
struct Printer<Float> {
  static const uint8_t kDecimals = 5;

  template <class Out>
  static void print(Out& out, Float x, uint8_t decimals) {
    if (decimals > detail::kMaxDecimals) decimals = detail::kMaxDecimals;
    float v = x.toFloat();
    if (v != v) {
      detail::writeText(out, "nan");
      return;
    }
    const bool negative = v < 0.0f;
    if (negative) v = -v;
    if (v > 3.4028235e38f) {
      detail::writeText(out, negative ? "-inf" : "inf");
      return;
    }
    // From 1e9 on, a mantissa in [1, 10) and a power of ten.
    int8_t exponent = 0;
    if (v >= 1e9f) {
      while (v >= 10.0f) {
        v /= 10.0f;
        ++exponent;
      }
    }
    uint32_t whole = uint32_t(v);
    float fraction = v - float(whole);  // exact for a float
    uint8_t digits[detail::kMaxDecimals];
    for (uint8_t i = 0; i < decimals; ++i) {
      fraction *= 10.0f;
      const uint8_t digit = uint8_t(fraction);
      digits[i] = digit > 9 ? 9 : digit;
      fraction -= float(digits[i]);
    }
    if (fraction >= 0.5f && detail::roundUpDigits(digits, decimals)) ++whole;
    if (exponent != 0 && whole == 10) {  // 9.99...95 rounded up to 10
      whole = 1;
      ++exponent;
    }
    detail::writeDecimal(out, negative, whole, digits, decimals);
    if (exponent == 0) return;
    detail::writeText(out, "e+");
    if (exponent < 10) out.write(uint8_t('0'));
    detail::writeWhole(out, uint8_t(exponent));
  }
};

template <typename S, uint8_t Dim>
struct Printer<Vec<S, Dim> > {
  static const uint8_t kDecimals = Printer<S>::kDecimals;

  // (x, y) or (x, y, z)
  template <class Out>
  static void print(Out& out, const Vec<S, Dim>& v, uint8_t decimals) {
    out.write(uint8_t('('));
    for (uint8_t k = 0; k < Dim; ++k) {
      if (k > 0) detail::writeText(out, ", ");
      Printer<S>::print(out, v[k], decimals);
    }
    out.write(uint8_t(')'));
  }
};

// Writes `value` (a scalar or a vector) to `out` with its format's number of
// decimals (see the top of this file).
template <class Out, typename T>
void print(Out& out, const T& value) {
  Printer<T>::print(out, value, Printer<T>::kDecimals);
}
// The same with `decimals` decimals (at most 10).
template <class Out, typename T>
void print(Out& out, const T& value, uint8_t decimals) {
  Printer<T>::print(out, value, decimals);
}
// print(), then a line end ("\r\n", as Serial.println()).
template <class Out, typename T>
void println(Out& out, const T& value) {
  print(out, value);
  detail::writeText(out, "\r\n");
}
template <class Out, typename T>
void println(Out& out, const T& value, uint8_t decimals) {
  print(out, value, decimals);
  detail::writeText(out, "\r\n");
}

}  // namespace tinyparticle
