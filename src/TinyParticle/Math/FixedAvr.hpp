// Hand-written AVR code for Fixed, used when TINYPARTICLE_AVR_ASM is 1 (the
// default on AVR chips with MUL):
// - Q16.16 multiply, divide and square root, the core of atan2 for every
//   format, and Q16.16 sin and cos of radians (Q8.8 through them);
// - Q24.8 multiply, divide and square root and Q8.8 divide and square root
//   through the Q16.16 routines (exact rescalings).
// Each routine returns exactly what the portable code returns, flags
// included: multiply, divide and square root the reference* functions of
// Fixed.hpp, atan2 atan2UnitsPortable and sin sinUnitsOfRadians<16> in
// FixedMath.hpp (and the add and subtract in Fixed.hpp referenceAdd and
// referenceSubtract). `make
// verify-asm` proves it on the simulated ATmega328P, for every class of
// input that each routine's code tells apart (table entries, shifts,
// corrections, saturation edges, with +-3 neighbours) and 10^6 to 10^7
// random inputs per routine: see extras/verify-asm/README.md and
// results.csv. extras/test/AsmClassesTest runs a subset of it in `make test`.
//
// The routines are out-of-line naked functions, so that the engine's many
// multiplies share one copy of the code (a call costs a few cycles,
// inlining would cost hundreds of bytes of flash per use) and the rare
// paths can sit after a `ret`.
//
// Register use follows avr-gcc's calling convention: the first 32-bit
// argument arrives in r22..r25, the second in r18..r21 (a second 8-bit one
// in r20), the result leaves in r22..r25; r18..r27, r30, r31 and r0 may be
// clobbered, others are saved; r1 must be zero on return.
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "MathErrors.hpp"
#include "TrigTables.hpp"

#if defined(__AVR__) && defined(__AVR_HAVE_MUL__)

namespace tinyparticle {
namespace detail {

// The flags byte by its symbol name: a naked function may hold nothing but
// assembly, so the name is spelled out.
// The compiler does not read assembly, so it does not know that the flags
// byte changes there; with link-time optimization it would then keep the
// byte in a register across a call, or drop a store before it. Callers put
// flagsTouched() around each call: an empty statement that claims to read
// and write the byte (it also makes sure the byte is defined).
TINYPARTICLE_ALWAYS_INLINE void flagsTouched() {
  asm volatile("" : "+m"(MathErrorStore<void>::flags));
}

// The same for the multiply and the divide, which saturate in
// tinyparticle_saturate32 (TINYPARTICLE_AVR_SATURATE): the "i" operand also
// makes the compiler emit that routine, named only in assembly text there.
TINYPARTICLE_ALWAYS_INLINE void flagsTouchedSaturating() {
  asm volatile("" : "+m"(MathErrorStore<void>::flags)
               : "i"(tinyparticle_saturate32));
}

#define TINYPARTICLE_AVR_FLAGS \
  "_ZN12tinyparticle6detail14MathErrorStoreIvE5flagsE"
// TrigTables<>::kRecip, kSqrt, kAtan and kSin, likewise.
#define TINYPARTICLE_AVR_RECIP \
  "_ZN12tinyparticle6detail10TrigTablesIvE6kRecipE"
#define TINYPARTICLE_AVR_SQRT \
  "_ZN12tinyparticle6detail10TrigTablesIvE5kSqrtE"
#define TINYPARTICLE_AVR_ATAN \
  "_ZN12tinyparticle6detail10TrigTablesIvE5kAtanE"
#define TINYPARTICLE_AVR_SIN \
  "_ZN12tinyparticle6detail10TrigTablesIvE4kSinE"

// Pieces of assembly text that several routines share, as string macros:
// they expand to the very same instructions in each routine (no call, no
// cycle added). Register names are passed as strings, high byte first;
// a label is a number, free in the routine that uses the piece. Comments
// inside the macros are C comments (a // comment would swallow the line
// continuations).

// x = -x for the 32-bit value in b3:b2:b1:b0: ~x + 1.
#define TINYPARTICLE_AVR_NEGATE32(b3, b2, b1, b0) \
  "    com  " b3 "\n"                             \
  "    com  " b2 "\n"                             \
  "    com  " b1 "\n"                             \
  "    neg  " b0 "\n"                             \
  "    sbci " b1 ", 0xff\n"                       \
  "    sbci " b2 ", 0xff\n"                       \
  "    sbci " b3 ", 0xff\n"

// x = |x| (the most negative value stays 0x80000000, its magnitude as
// unsigned).
#define TINYPARTICLE_AVR_MAGNITUDE32(b3, b2, b1, b0, label) \
  "    sbrs " b3 ", 7\n"                                     \
  "    rjmp " label "f\n"                                    \
  TINYPARTICLE_AVR_NEGATE32(b3, b2, b1, b0)                  \
  label ":\n"

// Multiply and divide: T = sign of the result; a (r25..r22) and b
// (r21..r18) become magnitudes. Uses labels 1 and 2.
#define TINYPARTICLE_AVR_SIGN_AND_MAGNITUDES                    \
  "    mov  r30, r25\n"                                         \
  "    eor  r30, r21\n"                                         \
  "    bst  r30, 7\n"                                           \
  TINYPARTICLE_AVR_MAGNITUDE32("r25", "r24", "r23", "r22", "1") \
  TINYPARTICLE_AVR_MAGNITUDE32("r21", "r20", "r19", "r18", "2")

// Too big: saturate with the sign of the result (T), raise kOverflow, in
// the saturation routine of the adds (Fixed.hpp), which takes the sign
// from bit 7 of r25, set for max(): 4 words where the inline copy was 13.
// `branch` is call (more follows) or jmp (its ret ends the routine). The
// routine changes r22..r25 and the status flags only. A routine that
// uses this must odr-use tinyparticle_saturate32 from C++
// (flagsTouchedSaturating()), so that it is emitted.
#define TINYPARTICLE_AVR_SATURATE(branch)                   \
  "    bld  r25, 7\n"                                       \
  "    com  r25\n"                    /* bit 7: not T */    \
  "    " branch " tinyparticle_saturate32\n"

// ---------------------------------------------------------------------------
// Q16.16 multiply: round(a * b / 2^16), ties away from zero, saturated.
//
// Method: multiply the magnitudes, then give the result its sign. The
// 64-bit product of the magnitudes is summed column by column (all partial
// products of one byte weight together, "product scanning"), so only three
// accumulator bytes are live at a time and no carry has to travel far.
// The accumulator is kept complemented (~sum): adding a partial product
// becomes subtracting it, and the carry into the third byte becomes
// `sbci x, 0`, so no register has to hold zero (MUL overwrites r1). The
// rounding constant 2^15 is preloaded; byte 0 of the sum never carries
// (nothing but the low byte of a0*b0 lands there), so it is not kept.
// Nine MULs when both magnitudes fit three bytes (|x| < 256, the usual case
// in a physics scene), twelve when one of them does; when neither does,
// the product cannot fit and saturates at once.
// ---------------------------------------------------------------------------
// Columns 0 to 2 of the multiply (the partial products of a0..a2 and
// b0..b2 whose weights are 2^0..2^16), into the complemented sum: byte 1 in
// r30, then bytes 2..4 in r26, r27, r30 (r30 reused once byte 1 is out).
// Both paths of avrMultiplyQ16 start with them.
#define TINYPARTICLE_AVR_MUL_COLUMNS_0_TO_2                         \
  "    ldi  r30, 0x7f\n" /* ~0x80: the rounding constant 2^15 */    \
  "    ldi  r26, 0xff\n"                                            \
  "    mul  r22, r18\n"  /* column 0: only the high byte matters */ \
  "    sub  r30, r1\n"                                              \
  "    sbci r26, 0\n"                                               \
  "    ldi  r27, 0xff\n" /* column 1 */                             \
  "    mul  r22, r19\n"                                             \
  "    sub  r30, r0\n"                                              \
  "    sbc  r26, r1\n"                                              \
  "    sbci r27, 0\n"                                               \
  "    mul  r23, r18\n"                                             \
  "    sub  r30, r0\n"                                              \
  "    sbc  r26, r1\n"                                              \
  "    sbci r27, 0\n"                                               \
  "    ldi  r30, 0xff\n" /* column 2 */                             \
  "    mul  r22, r20\n"                                             \
  "    sub  r26, r0\n"                                              \
  "    sbc  r27, r1\n"                                              \
  "    sbci r30, 0\n"                                               \
  "    mul  r23, r19\n"                                             \
  "    sub  r26, r0\n"                                              \
  "    sbc  r27, r1\n"                                              \
  "    sbci r30, 0\n"                                               \
  "    mul  r24, r18\n"                                             \
  "    sub  r26, r0\n"                                              \
  "    sbc  r27, r1\n"                                              \
  "    sbci r30, 0\n"

__attribute__((naked, noinline)) inline int32_t avrMultiplyQ16(int32_t,
                                                                int32_t) {
  asm volatile(
      // T = sign of the result; a and b become magnitudes.
      TINYPARTICLE_AVR_SIGN_AND_MAGNITUDES
      // a3 != 0: swap or saturate at 4 (r1 is still zero here).
      "    cpse r25, r1\n"
      "    rjmp 4f\n"
      "6:\n"
      // a3 == 0 now. Columns 0 to 2 take no byte 3, so both paths share
      // them (56 bytes once, not twice); b3 picks the path after them, with
      // tst as MUL has overwritten r1: the same 2 cycles as the cpse it
      // replaces when b3 == 0. Complemented sum: byte 1 in r30, bytes 2..5
      // in r26, r27, r30, r31 (r30 is reused once the carries of byte 1 are
      // out).
      TINYPARTICLE_AVR_MUL_COLUMNS_0_TO_2
      "    tst  r21\n"
      "    brne 5f\n"
      // ---- b3 == 0 too (|a|, |b| < 256): nine MULs.
      "    ldi  r31, 0xff\n"          // column 3
      "    mul  r23, r20\n"
      "    sub  r27, r0\n"
      "    sbc  r30, r1\n"
      "    sbci r31, 0\n"
      "    mul  r24, r19\n"
      "    sub  r27, r0\n"
      "    sbc  r30, r1\n"
      "    sbci r31, 0\n"
      // column 4: the sum stays below 2^48, so no byte 6
      "    mul  r24, r20\n"
      "    sub  r30, r0\n"
      "    sbc  r31, r1\n"
      "7:\n"
      // Complemented bytes 2..5 in r26, r27, r30, r31, bytes 6 and 7 zero. The
      // magnitude R may be at most 2^31 - 1, or 2^31 if negative.
      "    clr  r1\n"
      "    brts 9f\n"
      "    sbrs r31, 7\n"             // R >= 2^31: too big
      "    rjmp 8f\n"
      "    com  r26\n"
      "    com  r27\n"
      "    com  r30\n"
      "    com  r31\n"
      "    movw r22, r26\n"
      "    movw r24, r30\n"
      "    ret\n"
      "9:\n"
      // Negative: -R = ~R + 1, the complemented bytes plus one.
      "    subi r26, 0xff\n"
      "    sbci r27, 0xff\n"
      "    sbci r30, 0xff\n"
      "    sbci r31, 0xff\n"
      "    brmi 10f\n"                // -R in [-2^31, -1]
      "    breq 10f\n"                // R == 0
      "    rjmp 8f\n"
      "10:\n"
      "    movw r22, r26\n"
      "    movw r24, r30\n"
      "    ret\n"
      "4:\n"
      // a3 != 0: too big if b3 != 0 too (the product is at least 2^48), else
      // swap a and b so that a3 == 0 in the path below.
      "    cpse r21, r1\n"
      "    rjmp 8f\n"
      "    movw r26, r22\n"
      "    movw r30, r24\n"
      "    movw r22, r18\n"
      "    movw r24, r20\n"
      "    movw r18, r26\n"
      "    movw r20, r30\n"
      "    rjmp 6b\n"
      "5:\n"
      // ---- a3 == 0, b3 != 0: twelve MULs; byte 6 goes to r22 once a0 is
      // no longer needed.
      "    ldi  r31, 0xff\n"          // column 3
      "    mul  r22, r21\n"
      "    sub  r27, r0\n"
      "    sbc  r30, r1\n"
      "    sbci r31, 0\n"
      "    mul  r23, r20\n"
      "    sub  r27, r0\n"
      "    sbc  r30, r1\n"
      "    sbci r31, 0\n"
      "    mul  r24, r19\n"
      "    sub  r27, r0\n"
      "    sbc  r30, r1\n"
      "    sbci r31, 0\n"
      "    ldi  r22, 0xff\n"          // column 4
      "    mul  r23, r21\n"
      "    sub  r30, r0\n"
      "    sbc  r31, r1\n"
      "    sbci r22, 0\n"
      "    mul  r24, r20\n"
      "    sub  r30, r0\n"
      "    sbc  r31, r1\n"
      "    sbci r22, 0\n"
      // column 5: the sum is below 2^56, so byte 6 takes no carry out
      "    mul  r24, r21\n"
      "    sub  r31, r0\n"
      "    sbc  r22, r1\n"
      "    cpi  r22, 0xff\n"          // byte 6 must be zero (complemented: 0xff)
      "    brne 8f\n"
      "    rjmp 7b\n"
      "8:\n"
      // Too big: saturate with the sign of the result, raise kOverflow.
      "    clr  r1\n"
      TINYPARTICLE_AVR_SATURATE("jmp")
      // It writes the flags byte, so callers must not keep it in a register.
      ::: "memory");
}

// ---------------------------------------------------------------------------
// Q16.16 divide: round(a * 2^16 / b), ties away from zero, saturated;
// b != 0 (Fixed::divide handles zero).
//
// Method: long division in 16-bit words with multiplies instead of trial
// subtractions. D = |b| shifted until its top bit is set; the numerator
// |a| * 2^16 is shifted along and split into words. A reciprocal
// v = floor((2^48 - 1) / D) - 2^16 is computed once (table kRecip, then
// made exact) and each quotient word costs eleven MULs and at most two
// corrections (the 3-by-2 step of Moller and Granlund, "Improved division by
// invariant integers", IEEE Trans. Computers 60(2), 2011). A quotient below
// 1.0 needs one word instead of two. Rounding compares twice the remainder
// with D.
// ---------------------------------------------------------------------------
// One quotient word of the long division (the 3-by-2 step of Moller and
// Granlund): q = floor((u2, u1, u0) / D), given (u2, u1) < D, with v and D
// as set up below. q ends in r31:r30 and the remainder in (u1, u0), each
// argument naming a register pair (high, low). setU0 is placed once u2 is
// no longer read: the second word clears u0 there, as it reuses u2's
// registers. Uses r28, r29, r0, r1 and labels 1, 2 and 3.
#define TINYPARTICLE_AVR_DIVIDE_WORD(u2h, u2l, u1h, u1l, u0h, u0l, setU0) \
  /* (q1 q0) = v * u2 + (u2, u1) in r31:r30, r29:r28 */                   \
  "    mul  r16, " u2l "\n"                                               \
  "    movw r28, r0\n"                                                    \
  "    mul  r17, " u2h "\n"                                               \
  "    movw r30, r0\n"                                                    \
  "    mul  r16, " u2h "\n"                                               \
  "    add  r29, r0\n"                                                    \
  "    adc  r30, r1\n"                                                    \
  "    adc  r31, r15\n"                                                   \
  "    mul  r17, " u2l "\n"                                               \
  "    add  r29, r0\n"                                                    \
  "    adc  r30, r1\n"                                                    \
  "    adc  r31, r15\n"                                                   \
  "    add  r28, " u1l "\n"                                               \
  "    adc  r29, " u1h "\n"                                               \
  "    adc  r30, " u2l "\n"                                               \
  "    adc  r31, " u2h "\n"                                               \
  /* r1w = u1 - q1 * d1 (mod 2^16) */                                     \
  "    mul  r30, r20\n"                                                   \
  "    sub  " u1l ", r0\n"                                                \
  "    sbc  " u1h ", r1\n"                                                \
  "    mul  r30, r21\n"                                                   \
  "    sub  " u1h ", r0\n"                                                \
  "    mul  r31, r20\n"                                                   \
  "    sub  " u1h ", r0\n"                                                \
  /* (the second word: u0 = 0) */                                         \
  setU0                                                                   \
  /* (r1w, u0) -= q1 * d0 (when d0 != 0), then -= D */                    \
  "    cp   r18, r15\n"                                                   \
  "    cpc  r19, r15\n"                                                   \
  "    breq 3f\n"                                                         \
  "    mul  r30, r18\n"                                                   \
  "    sub  " u0l ", r0\n"                                                \
  "    sbc  " u0h ", r1\n"                                                \
  "    sbci " u1l ", 0\n"                                                 \
  "    sbci " u1h ", 0\n"                                                 \
  "    mul  r31, r19\n"                                                   \
  "    sub  " u1l ", r0\n"                                                \
  "    sbc  " u1h ", r1\n"                                                \
  "    mul  r30, r19\n"                                                   \
  "    sub  " u0h ", r0\n"                                                \
  "    sbc  " u1l ", r1\n"                                                \
  "    sbci " u1h ", 0\n"                                                 \
  "    mul  r31, r18\n"                                                   \
  "    sub  " u0h ", r0\n"                                                \
  "    sbc  " u1l ", r1\n"                                                \
  "    sbci " u1h ", 0\n"                                                 \
  "3:\n"                                                                  \
  "    sub  " u0l ", r18\n"                                               \
  "    sbc  " u0h ", r19\n"                                               \
  "    sbc  " u1l ", r20\n"                                               \
  "    sbc  " u1h ", r21\n"                                               \
  /* q1 + 1 */                                                            \
  "    subi r30, 0xff\n"                                                  \
  "    sbci r31, 0xff\n"                                                  \
  /* r1w >= q0: one less, add D back */                                   \
  "    cp   " u1l ", r28\n"                                               \
  "    cpc  " u1h ", r29\n"                                               \
  "    brcs 1f\n"                                                         \
  "    subi r30, 1\n"                                                     \
  "    sbci r31, 0\n"                                                     \
  "    add  " u0l ", r18\n"                                               \
  "    adc  " u0h ", r19\n"                                               \
  "    adc  " u1l ", r20\n"                                               \
  "    adc  " u1h ", r21\n"                                               \
  "1:\n"                                                                  \
  /* remainder >= D (rare): one more */                                   \
  "    cp   " u0l ", r18\n"                                               \
  "    cpc  " u0h ", r19\n"                                               \
  "    cpc  " u1l ", r20\n"                                               \
  "    cpc  " u1h ", r21\n"                                               \
  "    brcs 2f\n"                                                         \
  "    subi r30, 0xff\n"                                                  \
  "    sbci r31, 0xff\n"                                                  \
  "    sub  " u0l ", r18\n"                                               \
  "    sbc  " u0h ", r19\n"                                               \
  "    sbc  " u1l ", r20\n"                                               \
  "    sbc  " u1h ", r21\n"                                               \
  "2:\n"

__attribute__((naked, noinline)) inline int32_t avrDivideQ16(int32_t,
                                                              int32_t) {
  asm volatile(
      // Registers: T = sign of the result; r15 = 0; D = |b| normalized in
      // r21:r20 (d1) and r19:r18 (d0); W = |a| << (16 + s) as three words n3
      // r27:r26, n2 r25:r24, n1 r23:r22; v in r17:r16.
      "    push r14\n"
      "    push r15\n"
      "    push r16\n"
      "    push r17\n"
      "    push r28\n"
      "    push r29\n"
      "    clr  r15\n"
      // Sign and magnitudes.
      TINYPARTICLE_AVR_SIGN_AND_MAGNITUDES
      "    clr  r26\n"
      "    clr  r27\n"
      // Normalize D (top bit set), shifting W along: whole bytes first.
      "3:\n"
      "    cpse r21, r15\n"
      "    rjmp 4f\n"
      "    cpse r27, r15\n"               // a nonzero byte would leave W: quotient >= 2^32
      "    rjmp 30f\n"
      "    mov  r21, r20\n"
      "    mov  r20, r19\n"
      "    mov  r19, r18\n"
      "    clr  r18\n"
      "    mov  r27, r26\n"
      "    mov  r26, r25\n"
      "    mov  r25, r24\n"
      "    mov  r24, r23\n"
      "    mov  r23, r22\n"
      "    clr  r22\n"
      "    rjmp 3b\n"
      "4:\n"
      "    sbrc r21, 7\n"
      "    rjmp 5f\n"
      "    lsl  r18\n"
      "    rol  r19\n"
      "    rol  r20\n"
      "    rol  r21\n"
      "    lsl  r22\n"
      "    rol  r23\n"
      "    rol  r24\n"
      "    rol  r25\n"
      "    rol  r26\n"
      "    rol  r27\n"
      "    brcc 4b\n"
      "    rjmp 30f\n"
      "5:\n"
      // The quotient fits 32 bits only if n3:n2 < D.
      "    cp   r24, r18\n"
      "    cpc  r25, r19\n"
      "    cpc  r26, r20\n"
      "    cpc  r27, r21\n"
      "    brcs 6f\n"
      "    rjmp 30f\n"
      "6:\n"
      // v = floor((2^48 - 1) / D) - 2^16, after Moller and Granlund,
      // "Improved division by invariant integers" (2011). First the word
      // reciprocal floor((2^32 - 1) / d1) - 2^16: interpolated in kRecip
      // (index: the 7 bits below the top bit of d1) ...
      "    mov  r30, r21\n"
      "    andi r30, 0x7f\n"
      "    lsl  r30\n"
      "    clr  r31\n"
      "    subi r30, lo8(-(" TINYPARTICLE_AVR_RECIP "))\n"
      "    sbci r31, hi8(-(" TINYPARTICLE_AVR_RECIP "))\n"
      "    lpm  r16, Z+\n"
      "    lpm  r17, Z+\n"
      "    lpm  r28, Z+\n"
      "    lpm  r29, Z\n"
      "    sub  r28, r16\n"               // r29:r28 = entry[i] - entry[i + 1]
      "    sbc  r29, r17\n"
      "    com  r29\n"
      "    neg  r28\n"
      "    sbci r29, 0xff\n"
      "    mul  r28, r20\n"               // minus (difference * (d1 & 0xff)) >> 8
      "    mov  r30, r1\n"
      "    mul  r29, r20\n"
      "    add  r30, r0\n"
      "    mov  r31, r1\n"
      "    adc  r31, r15\n"
      "    sub  r16, r30\n"
      "    sbc  r17, r31\n"
      // ... then made exact: S = (2^16 + v) * d1 must lie in (2^32 - 1 - d1,
      // 2^32 - 1]; S in (carry, r31, r30, r29, r28).
      "    mul  r16, r20\n"
      "    movw r28, r0\n"
      "    mul  r17, r21\n"
      "    movw r30, r0\n"
      "    mul  r16, r21\n"
      "    add  r29, r0\n"
      "    adc  r30, r1\n"
      "    adc  r31, r15\n"
      "    mul  r17, r20\n"
      "    add  r29, r0\n"
      "    adc  r30, r1\n"
      "    adc  r31, r15\n"
      "    add  r30, r20\n"
      "    adc  r31, r21\n"
      "    brcc 8f\n"
      "7:\n"
      "    subi r16, 1\n"                 // S >= 2^32: v too big
      "    sbci r17, 0\n"
      "    sub  r28, r20\n"
      "    sbc  r29, r21\n"
      "    sbc  r30, r15\n"
      "    sbc  r31, r15\n"
      "    brcc 7b\n"
      "    rjmp 9f\n"
      "8:\n"
      "    add  r28, r20\n"               // S + d1 < 2^32: v too small
      "    adc  r29, r21\n"
      "    adc  r30, r15\n"
      "    adc  r31, r15\n"
      "    brcs 10f\n"
      "    subi r16, 0xff\n"
      "    sbci r17, 0xff\n"
      "    rjmp 8b\n"
      "10:\n"
      "    sub  r28, r20\n"               // undo the last step (low word only)
      "    sbc  r29, r21\n"
      "9:\n"
      // The low word of S is p = d1 * v mod 2^16. Now account for d0,
      // unless it is zero (|b| had at most 16 significant bits).
      "    cp   r18, r15\n"
      "    cpc  r19, r15\n"
      "    breq 13f\n"
      "    add  r28, r18\n"
      "    adc  r29, r19\n"
      "    brcc 11f\n"
      "    subi r16, 1\n"
      "    sbci r17, 0\n"
      "    cp   r28, r20\n"
      "    cpc  r29, r21\n"
      "    brcs 12f\n"
      "    subi r16, 1\n"
      "    sbci r17, 0\n"
      "    sub  r28, r20\n"
      "    sbc  r29, r21\n"
      "12:\n"
      "    sub  r28, r20\n"
      "    sbc  r29, r21\n"
      "11:\n"
      // t = v * d0: high word in r31:r30, low word in r1:r0.
      "    mul  r17, r19\n"
      "    movw r30, r0\n"
      "    mul  r16, r19\n"
      "    mov  r14, r0\n"
      "    add  r30, r1\n"
      "    adc  r31, r15\n"
      "    mul  r17, r18\n"
      "    add  r14, r0\n"
      "    adc  r30, r1\n"
      "    adc  r31, r15\n"
      "    mul  r16, r18\n"
      "    add  r1, r14\n"
      "    adc  r30, r15\n"
      "    adc  r31, r15\n"
      "    add  r28, r30\n"
      "    adc  r29, r31\n"
      "    brcc 13f\n"
      "    subi r16, 1\n"
      "    sbci r17, 0\n"
      "    cp   r0, r18\n"
      "    cpc  r1, r19\n"
      "    cpc  r28, r20\n"
      "    cpc  r29, r21\n"
      "    brcs 13f\n"
      "    subi r16, 1\n"
      "    sbci r17, 0\n"
      "13:\n"
      // First quotient word q1 from (n3, n2, n1); it is 0, and the step is
      // skipped, when (n3, n2, n1) < D: the usual case for a result below 1.
      "    cp   r26, r15\n"
      "    cpc  r27, r15\n"
      "    brne 14f\n"
      "    cp   r22, r18\n"
      "    cpc  r23, r19\n"
      "    cpc  r24, r20\n"
      "    cpc  r25, r21\n"
      "    brcc 14f\n"
      "    rjmp 15f\n"
      "14:\n"
      TINYPARTICLE_AVR_DIVIDE_WORD("r27", "r26", "r25", "r24", "r23", "r22", "")
      "    movw r26, r30\n"               // q1
      "15:\n"
      // Second word q0 from (r1, r0, 0): the remainder is then in
      // r23:r22:r25:r24.
      // u0 = 0 goes into r25:r24, free once u2 is read.
      TINYPARTICLE_AVR_DIVIDE_WORD("r25", "r24", "r23", "r22", "r25", "r24",
                                   "    clr  r24\n"
                                   "    clr  r25\n")
      // Round: one more when twice the remainder reaches D.
      "    lsl  r24\n"
      "    rol  r25\n"
      "    rol  r22\n"
      "    rol  r23\n"
      "    brcs 16f\n"
      "    cp   r24, r18\n"
      "    cpc  r25, r19\n"
      "    cpc  r22, r20\n"
      "    cpc  r23, r21\n"
      "    brcs 17f\n"
      "16:\n"
      "    subi r30, 0xff\n"
      "    sbci r31, 0xff\n"
      "    sbci r26, 0xff\n"
      "    sbci r27, 0xff\n"
      "    breq 30f\n"                    // 2^32: too big
      "17:\n"
      // Quotient magnitude Q in r27:r26:r31:r30: at most 2^31 - 1, or 2^31
      // when negative.
      "    movw r22, r30\n"
      "    movw r24, r26\n"
      "    brts 18f\n"
      "    sbrc r25, 7\n"
      "    rjmp 30f\n"
      "    rjmp 31f\n"
      "18:\n"
      TINYPARTICLE_AVR_NEGATE32("r25", "r24", "r23", "r22")
      "    brmi 31f\n"
      "    breq 31f\n"
      "30:\n"
      // Too big: saturate with the sign of the result, raise kOverflow.
      TINYPARTICLE_AVR_SATURATE("call")
      "31:\n"
      "    clr  r1\n"
      "    pop  r29\n"
      "    pop  r28\n"
      "    pop  r17\n"
      "    pop  r16\n"
      "    pop  r15\n"
      "    pop  r14\n"
      "    ret\n"

      ::: "memory");
}

// ---------------------------------------------------------------------------
// Square root: round(sqrt(x * 2^16) / 2^e0) for x >= 0 (Fixed::squareRoot
// handles x < 0): e0 = 0 for Q16.16, e0 = 4 for formats with 8 fraction
// bits (Q24.8: x < 2^31; Q8.8: x < 2^15).
//
// Method: digit by digit, one root byte at a time, instead of one bit. x is
// shifted left by an even number of bits; the first root byte comes from a
// table of square roots of the top byte (kSqrt, then at most one step), and
// each further byte is estimated from the remainder with a reciprocal
// (kRecip) and fixed with at most one step, the remainder being updated
// exactly. Small arguments (x < 0.25) need two root bytes, not three.
// Proven equal to referenceSquareRoot on the simulated Nano by `make
// verify-asm` (e0 = 0 and e0 = 4): every argument below 2^22, each kSqrt
// entry's first and last argument at each normalization shift, each first
// byte's remainder edges (R1 = 0, 255, 256, 2a), each 16-bit root's square,
// all with +-3 neighbours, plus random arguments; every branch below is
// counted (extras/verify-asm/classes.csv). Since the normalized top byte is
// at least 64, a >= 128 always: the "a < 128" paths are never taken.
// ---------------------------------------------------------------------------
__attribute__((naked, noinline)) inline int32_t avrSquareRoot(int32_t,
                                                             uint8_t) {
  asm volatile(
      // x in r25:r22, x >= 0 (the caller handles x < 0); r20 = e0, the
      // extra halvings of the result: 0 for Q16.16 (the root of x * 2^16),
      // 4 for 8 fraction bits (the root of x * 2^8 = that / 16). sqrt(0) = 0.
      "    cp   r22, r1\n"
      "    cpc  r23, r1\n"
      "    cpc  r24, r1\n"
      "    cpc  r25, r1\n"
      "    brne 1f\n"
      "    ret\n"
      "1:\n"
      // Normalize: x <<= 2e until its top two bits are not both zero; e in
      // r18 (from e0). The root of x * 2^16 * 4^(e - e0) is computed, then
      // shifted back by e.
      "    mov  r18, r20\n"
      "2:\n"
      "    tst  r25\n"
      "    brne 3f\n"
      "    mov  r25, r24\n"
      "    mov  r24, r23\n"
      "    mov  r23, r22\n"
      "    clr  r22\n"
      "    subi r18, -4\n"
      "    rjmp 2b\n"
      "3:\n"
      "    cpi  r25, 0x40\n"
      "    brcc 4f\n"
      "    lsl  r22\n"
      "    rol  r23\n"
      "    rol  r24\n"
      "    rol  r25\n"
      "    lsl  r22\n"
      "    rol  r23\n"
      "    rol  r24\n"
      "    rol  r25\n"
      "    inc  r18\n"
      "    rjmp 3b\n"
      "4:\n"
      // Root byte a (r19) = floor(sqrt(top word)): kSqrt gives it for the top
      // byte, or one less; R1 = top word - a^2 (at most 2a) in r21:r20.
      "    mov  r30, r25\n"
      "    clr  r31\n"
      "    subi r30, lo8(-(" TINYPARTICLE_AVR_SQRT " - 64))\n"
      "    sbci r31, hi8(-(" TINYPARTICLE_AVR_SQRT " - 64))\n"
      "    lpm  r19, Z\n"
      "    cpi  r19, 0xff\n"
      "    breq 5f\n"
      "    mov  r20, r19\n"
      "    inc  r20\n"
      "    mul  r20, r20\n"
      "    cp   r24, r0\n"
      "    cpc  r25, r1\n"
      "    brcs 5f\n"
      "    mov  r19, r20\n"
      "5:\n"
      "    mul  r19, r19\n"
      "    movw r20, r24\n"
      "    sub  r20, r0\n"
      "    sbc  r21, r1\n"
      // Root byte b ~ X / 512a, X = R1:x1:x0 (25 bits): with v = kRecip entry
      // for 256a (a >= 128) or 512a, about 2^32 / that - 2^16, from the top
      // 17 bits Xh = R1:x1 as (Xh + Xh * v / 2^16) >> 9 (or 8).
      "    mov  r30, r19\n"
      "    sbrs r19, 7\n"
      "    lsl  r30\n"
      "    andi r30, 0x7f\n"
      "    lsl  r30\n"
      "    clr  r31\n"
      "    subi r30, lo8(-(" TINYPARTICLE_AVR_RECIP "))\n"
      "    sbci r31, hi8(-(" TINYPARTICLE_AVR_RECIP "))\n"
      "    lpm  r24, Z+\n"
      "    lpm  r25, Z\n"
      "    clr  r31\n"
      "    mul  r23, r24\n"               // floor(Xh * v / 2^16) in r30:r27 (r31 = 0)
      "    mov  r26, r1\n"
      "    clr  r27\n"
      "    clr  r30\n"
      "    mul  r23, r25\n"
      "    add  r26, r0\n"
      "    adc  r27, r1\n"
      "    adc  r30, r31\n"
      "    mul  r20, r24\n"
      "    add  r26, r0\n"
      "    adc  r27, r1\n"
      "    adc  r30, r31\n"
      "    mul  r20, r25\n"
      "    add  r27, r0\n"
      "    adc  r30, r1\n"
      // Bit 16 of Xh (R1 >= 256, only when a is small) adds v * 2^16. The
      // sum r26:r30:r27 needs its third byte here already: for a = 128,
      // v = 65535 and this add carries whenever x1 >= 2.
      "    mov  r26, r21\n"
      "    sbrs r21, 0\n"
      "    rjmp 6f\n"
      "    add  r27, r24\n"
      "    adc  r30, r25\n"
      "    adc  r26, r31\n"
      "6:\n"
      "    add  r27, r23\n"               // + Xh, then >> 8: r26:r30
      "    adc  r30, r20\n"
      "    adc  r26, r31\n"
      "    sbrs r19, 7\n"
      "    rjmp 7f\n"
      "    lsr  r26\n"
      "    ror  r30\n"
      "7:\n"
      "    tst  r26\n"                    // at most 255
      "    breq 8f\n"
      "    ldi  r30, 0xff\n"
      "8:\n"
      // R2 = X - b * (512a + b) in r21:r20:r23:r22; one correction at most.
      "    mul  r30, r19\n"
      "    movw r26, r0\n"
      "    lsl  r26\n"
      "    rol  r27\n"
      "    clr  r24\n"
      "    rol  r24\n"
      "    mul  r30, r30\n"
      "    add  r26, r1\n"
      "    clr  r1\n"
      "    adc  r27, r1\n"
      "    adc  r24, r1\n"
      "    sub  r22, r0\n"
      "    sbc  r23, r26\n"
      "    sbc  r20, r27\n"
      "    sbc  r21, r24\n"
      // t = 2 (256a + b) + 1 in r27:r26:r25 (b is 255 at most ... )
      "    brcc 9f\n"
      "    dec  r30\n"                    // negative: b - 1, R2 + t(b - 1)
      "    mov  r25, r30\n"
      "    mov  r26, r19\n"
      "    clr  r27\n"
      "    sec\n"
      "    rol  r25\n"
      "    rol  r26\n"
      "    rol  r27\n"
      "    add  r22, r25\n"
      "    adc  r23, r26\n"
      "    adc  r20, r27\n"
      "    rjmp 10f\n"
      "9:\n"
      "    mov  r25, r30\n"
      "    mov  r26, r19\n"
      "    clr  r27\n"
      "    sec\n"
      "    rol  r25\n"
      "    rol  r26\n"
      "    rol  r27\n"
      "    cp   r22, r25\n"
      "    cpc  r23, r26\n"
      "    cpc  r20, r27\n"
      "    cpc  r21, r1\n"
      "    brcs 10f\n"
      "    cpi  r30, 0xff\n"
      "    breq 10f\n"
      "    inc  r30\n"
      "    sub  r22, r25\n"
      "    sbc  r23, r26\n"
      "    sbc  r20, r27\n"
      "10:\n"
      "    mov  r21, r30\n"               // b
      // (a:b) is the root to 16 bits. When e >= 9 that is enough: round it
      // shifted right by e - 8.
      "    cpi  r18, 9\n"
      "    brcs 12f\n"
      "    subi r18, 8\n"
      "11:\n"
      "    lsr  r19\n"
      "    ror  r21\n"
      "    dec  r18\n"
      "    brne 11b\n"
      "    mov  r22, r21\n"
      "    mov  r23, r19\n"
      "    clr  r24\n"
      "    clr  r25\n"
      "    adc  r22, r24\n"
      "    adc  r23, r24\n"
      "    ret\n"
      "12:\n"
      // Root byte c ~ 128 R2 / (a:b), R2 (17 bits) in r20:r23:r22. d3 = a:b,
      // doubled when a < 128, and its interpolated reciprocal v3 (r27:r26).
      "    mov  r25, r19\n"
      "    mov  r24, r21\n"
      "    sbrc r25, 7\n"
      "    rjmp 13f\n"
      "    lsl  r24\n"
      "    rol  r25\n"
      "13:\n"
      "    mov  r30, r25\n"
      "    andi r30, 0x7f\n"
      "    lsl  r30\n"
      "    clr  r31\n"
      "    subi r30, lo8(-(" TINYPARTICLE_AVR_RECIP "))\n"
      "    sbci r31, hi8(-(" TINYPARTICLE_AVR_RECIP "))\n"
      "    lpm  r26, Z+\n"
      "    lpm  r27, Z+\n"
      "    lpm  r0, Z+\n"
      "    lpm  r1, Z\n"
      "    movw r30, r26\n"
      "    sub  r30, r0\n"
      "    sbc  r31, r1\n"
      "    mul  r30, r24\n"
      "    mov  r25, r1\n"
      "    mul  r31, r24\n"
      "    sub  r26, r0\n"
      "    sbc  r27, r1\n"
      "    sub  r26, r25\n"
      "    sbci r27, 0\n"
      // q = R2 * (2^16 + v3): bytes 4:3 in r25:r31 (bytes 2, 1 in r30, r24).
      "    mov  r30, r22\n"
      "    mov  r31, r23\n"
      "    mov  r25, r20\n"
      "    mul  r22, r26\n"
      "    mov  r24, r1\n"
      "    mul  r22, r27\n"
      "    add  r24, r0\n"
      "    adc  r30, r1\n"
      "    clr  r1\n"
      "    adc  r31, r1\n"
      "    adc  r25, r1\n"
      "    mul  r23, r26\n"
      "    add  r24, r0\n"
      "    adc  r30, r1\n"
      "    clr  r1\n"
      "    adc  r31, r1\n"
      "    adc  r25, r1\n"
      "    mul  r23, r27\n"
      "    add  r30, r0\n"
      "    adc  r31, r1\n"
      "    clr  r1\n"
      "    adc  r25, r1\n"
      "    sbrs r20, 0\n"
      "    rjmp 14f\n"
      "    add  r30, r26\n"
      "    adc  r31, r27\n"
      "    adc  r25, r1\n"
      "14:\n"
      "    sbrs r19, 7\n"                 // c = q >> 25 (a >= 128) or q >> 24, at most 255
      "    rjmp 15f\n"
      "    lsr  r25\n"
      "    ror  r31\n"
      "15:\n"
      "    tst  r25\n"
      "    breq 16f\n"
      "    ldi  r31, 0xff\n"
      "16:\n"
      // R3 = R2 * 2^16 - c * (512 (a:b) + c) in r20:r23:r22:r1:r30.
      "    mul  r31, r21\n"
      "    movw r26, r0\n"
      "    mul  r31, r19\n"
      "    add  r27, r0\n"
      "    clr  r24\n"
      "    adc  r24, r1\n"
      "    lsl  r26\n"
      "    rol  r27\n"
      "    rol  r24\n"
      "    clr  r25\n"
      "    rol  r25\n"
      "    mul  r31, r31\n"
      "    add  r26, r1\n"
      "    clr  r1\n"
      "    adc  r27, r1\n"
      "    adc  r24, r1\n"
      "    adc  r25, r1\n"
      "    clr  r30\n"
      "    sub  r30, r0\n"
      "    sbc  r1, r26\n"
      "    sbc  r22, r27\n"
      "    sbc  r23, r24\n"
      "    sbc  r20, r25\n"
      // t = 2 (a:b:c) + 1 in r25:r24:r27:r26; one correction at most.
      "    brcc 17f\n"
      "    dec  r31\n"                    // negative: c - 1, R3 + t(c - 1)
      "    mov  r26, r31\n"
      "    mov  r27, r21\n"
      "    mov  r24, r19\n"
      "    clr  r25\n"
      "    sec\n"
      "    rol  r26\n"
      "    rol  r27\n"
      "    rol  r24\n"
      "    rol  r25\n"
      "    add  r30, r26\n"
      "    adc  r1, r27\n"
      "    adc  r22, r24\n"
      "    adc  r23, r25\n"
      "    rjmp 18f\n"
      "17:\n"
      "    mov  r26, r31\n"
      "    mov  r27, r21\n"
      "    mov  r24, r19\n"
      "    clr  r25\n"
      "    sec\n"
      "    rol  r26\n"
      "    rol  r27\n"
      "    rol  r24\n"
      "    rol  r25\n"
      "    cp   r30, r26\n"
      "    cpc  r1, r27\n"
      "    cpc  r22, r24\n"
      "    cpc  r23, r25\n"
      "    brcs 18f\n"
      "    cpi  r31, 0xff\n"
      "    breq 18f\n"
      "    inc  r31\n"
      "    sub  r30, r26\n"
      "    sbc  r1, r27\n"
      "    sbc  r22, r24\n"
      "    sbc  r23, r25\n"
      "18:\n"
      // r = a:b:c (r19:r21:r31). e == 0: round up when R3 > r; else shift
      // right by e, rounding with the last bit out.
      "    tst  r18\n"
      "    brne 19f\n"
      "    clr  r24\n"
      "    cp   r31, r30\n"
      "    cpc  r21, r1\n"
      "    cpc  r19, r22\n"
      "    cpc  r24, r23\n"
      "    rjmp 20f\n"
      "19:\n"
      "    lsr  r19\n"
      "    ror  r21\n"
      "    ror  r31\n"
      "    dec  r18\n"
      "    brne 19b\n"
      "20:\n"
      "    mov  r22, r31\n"
      "    mov  r23, r21\n"
      "    mov  r24, r19\n"
      "    clr  r25\n"
      "    clr  r1\n"
      "    adc  r22, r1\n"
      "    adc  r23, r1\n"
      "    adc  r24, r1\n"
      "    ret\n"

      ::: "memory");
}

// ---------------------------------------------------------------------------
// atan2(y, x) in units of 2^-16 rad, in [-pi, pi], atan2(0, 0) = 0: the
// steps of FixedMath.hpp's atan2UnitsPortable in assembly (the same result
// bit for bit, proven by `make verify-asm`), with the normalizing shifts
// done as multiplies and no 32-bit loops.
// ---------------------------------------------------------------------------
__attribute__((naked, noinline)) inline int32_t avrAtan2Units(int32_t,
                                                               int32_t) {
  asm volatile(
      // y in r25:r22, x in r21:r18 (signed). T keeps x < 0; r17 keeps y < 0
      // in bit 7 and, below, whether the larger magnitude was |x| in bit 0.
      // (T and r17 rather than two bits of r17: fewer cycles to set and test.)
      "    push r17\n"
      "    mov  r17, r25\n"
      "    andi r17, 0x80\n"
      "    bst  r21, 7\n"
      TINYPARTICLE_AVR_MAGNITUDE32("r25", "r24", "r23", "r22", "13")
      TINYPARTICLE_AVR_MAGNITUDE32("r21", "r20", "r19", "r18", "14")
      // |y| in r25:r22, |x| in r21:r18: the larger goes to r25:r22; bit 0 of
      // r17 set when that was |x| (the angle is below pi / 4).
      "    cp   r22, r18\n"
      "    cpc  r23, r19\n"
      "    cpc  r24, r20\n"
      "    cpc  r25, r21\n"
      "    brcc 1f\n"
      "    ori  r17, 0x01\n"
      "    movw r26, r22\n"
      "    movw r30, r24\n"
      "    movw r22, r18\n"
      "    movw r24, r20\n"
      "    movw r18, r26\n"
      "    movw r20, r30\n"
      "1:\n"
      // big in r25:r22, small in r21:r18. Window of three bytes from the top
      // nonzero byte of big: big in r25:r24:r23, small in r21:r20:r19.
      "    tst  r25\n"
      "    brne 3f\n"
      "    mov  r25, r24\n"
      "    mov  r24, r23\n"
      "    mov  r23, r22\n"
      "    mov  r21, r20\n"
      "    mov  r20, r19\n"
      "    mov  r19, r18\n"
      "    tst  r25\n"
      "    brne 3f\n"
      "    mov  r25, r24\n"
      "    mov  r24, r23\n"
      "    clr  r23\n"
      "    mov  r21, r20\n"
      "    mov  r20, r19\n"
      "    clr  r19\n"
      "    tst  r25\n"
      "    brne 3f\n"
      "    mov  r25, r24\n"
      "    clr  r24\n"
      "    mov  r21, r20\n"
      "    clr  r20\n"
      "    tst  r25\n"
      "    brne 3f\n"
      // Both zero: atan2(0, 0) = 0 (r25:r22 is zero here).
      "    pop  r17\n"
      "    ret\n"
      "3:\n"
      // m = 2^(leading zeros of the top byte) in r30: 4, 2, 1 bits.
      "    ldi  r30, 1\n"
      "    mov  r31, r25\n"
      "    cpi  r31, 0x10\n"
      "    brcc 4f\n"
      "    swap r31\n"
      "    ldi  r30, 16\n"
      "4:\n"
      "    cpi  r31, 0x40\n"
      "    brcc 5f\n"
      "    lsl  r31\n"
      "    lsl  r31\n"
      "    lsl  r30\n"
      "    lsl  r30\n"
      "5:\n"
      "    sbrs r31, 7\n"
      "    lsl  r30\n"
      // big16 = (window * m) >> 8 in r27:r26 (truncated: the ratio moves by
      // at most 2^-15 of itself); small16 likewise in r25:r24, at most big16.
      // r31 = 0.
      "    clr  r31\n"
      "    mul  r23, r30\n"
      "    mov  r26, r1\n"
      "    mul  r24, r30\n"
      "    add  r26, r0\n"
      "    mov  r27, r1\n"
      "    adc  r27, r31\n"
      "    mul  r25, r30\n"
      "    add  r27, r0\n"
      "    brcc 6f\n"
      "    ldi  r26, 0xff\n"
      "    ldi  r27, 0xff\n"
      "6:\n"
      "    mul  r19, r30\n"
      "    mov  r24, r1\n"
      "    mul  r20, r30\n"
      "    add  r24, r0\n"
      "    mov  r25, r1\n"
      "    adc  r25, r31\n"
      "    mul  r21, r30\n"
      "    add  r25, r0\n"
      "    brcs 7f\n"
      "    cp   r26, r24\n"
      "    cpc  r27, r25\n"
      "    brcc 8f\n"
      "7:\n"
      "    movw r24, r26\n"
      "8:\n"
      // r = 2^32 / big16 - 2^16 (about), kRecip interpolated: r19:r18.
      "    mov  r30, r27\n"
      "    andi r30, 0x7f\n"
      "    lsl  r30\n"
      "    clr  r31\n"
      "    subi r30, lo8(-(" TINYPARTICLE_AVR_RECIP "))\n"
      "    sbci r31, hi8(-(" TINYPARTICLE_AVR_RECIP "))\n"
      "    lpm  r18, Z+\n"
      "    lpm  r19, Z+\n"
      "    lpm  r20, Z+\n"
      "    lpm  r21, Z\n"
      "    clr  r31\n"
      "    sub  r20, r18\n"
      "    sbc  r21, r19\n"
      "    com  r21\n"
      "    neg  r20\n"
      "    sbci r21, 0xff\n"
      "    mul  r20, r26\n"
      "    mov  r30, r1\n"
      "    mul  r21, r26\n"
      "    add  r30, r0\n"
      "    clr  r27\n"
      "    adc  r27, r1\n"
      "    sub  r18, r30\n"
      "    sbc  r19, r27\n"
      // t = small16 + (small16 * r + 2^15) >> 16 = small / big * 2^16 in
      // r30:r21 (without the low product: at most one unit less); from 2^16
      // on, atan is pi / 4.
      "    ldi  r20, 0x80\n"
      "    clr  r21\n"
      "    clr  r30\n"
      "    mul  r24, r19\n"
      "    add  r20, r0\n"
      "    adc  r21, r1\n"
      "    adc  r30, r31\n"
      "    mul  r25, r18\n"
      "    add  r20, r0\n"
      "    adc  r21, r1\n"
      "    adc  r30, r31\n"
      "    mul  r25, r19\n"
      "    add  r21, r0\n"
      "    adc  r30, r1\n"
      "    add  r21, r24\n"
      "    adc  r30, r25\n"
      "    brcc 9f\n"
      "    ldi  r18, lo8(51472)\n"
      "    ldi  r19, hi8(51472)\n"
      "    rjmp 11f\n"
      "9:\n"
      // atan(t / 2^16) from kAtan: entry t >> 9, fraction bits 1..8 of t
      // (the lowest bit moves the result by at most half a unit).
      "    mov  r27, r30\n"
      "    lsr  r30\n"
      "    lsl  r30\n"
      "    clr  r31\n"
      "    subi r30, lo8(-(" TINYPARTICLE_AVR_ATAN "))\n"
      "    sbci r31, hi8(-(" TINYPARTICLE_AVR_ATAN "))\n"
      "    lpm  r18, Z+\n"
      "    lpm  r19, Z+\n"
      "    lpm  r22, Z+\n"
      "    lpm  r23, Z\n"
      "    sub  r22, r18\n"
      "    sbc  r23, r19\n"
      "    lsr  r27\n"
      "    ror  r21\n"
      "    mul  r22, r21\n"
      "    mov  r24, r1\n"
      "    sbrc r0, 7\n"
      "    inc  r24\n"
      "    mul  r23, r21\n"
      "    add  r24, r0\n"
      "    clr  r25\n"
      "    adc  r25, r1\n"
      "    add  r18, r24\n"
      "    adc  r19, r25\n"
      "11:\n"
      // a = atan in r19:r18. The larger was |y| (bit 0 of r17 clear):
      // pi / 2 - a, 102944 = round(pi / 2 * 2^16). Result in r24:r23:r22.
      "    clr  r1\n"
      "    clr  r24\n"
      "    movw r22, r18\n"
      "    sbrc r17, 0\n"
      "    rjmp 12f\n"
      "    ldi  r22, 0x20\n"
      "    ldi  r23, 0x92\n"
      "    ldi  r24, 0x01\n"
      "    sub  r22, r18\n"
      "    sbc  r23, r19\n"
      "    sbci r24, 0\n"
      "12:\n"
      // x < 0: pi - a (205887 = 0x3243f); y < 0: -a.
      "    clr  r25\n"
      "    brtc 15f\n"
      "    ldi  r18, 0x3f\n"
      "    ldi  r19, 0x24\n"
      "    ldi  r20, 0x03\n"
      "    sub  r18, r22\n"
      "    sbc  r19, r23\n"
      "    sbc  r20, r24\n"
      "    movw r22, r18\n"
      "    mov  r24, r20\n"
      "15:\n"
      "    sbrs r17, 7\n"
      "    rjmp 16f\n"
      TINYPARTICLE_AVR_NEGATE32("r25", "r24", "r23", "r22")
      "16:\n"
      "    pop  r17\n"
      "    ret\n"

      ::: "memory");
}

// ---------------------------------------------------------------------------
// sin of a Q16.16 angle in radians, in units of 2^-16 (cos: quarter =
// 0x40, a quarter turn added): the steps of FixedMath.hpp's
// sinUnitsOfRadians<16> in assembly (the same result bit for bit, proven by
// `make verify-asm`).
// 1. |x| (r25:r22 = m3..m0) times C = 0x28BE60DB93 (floor(2^64 / (2 pi))
//    >> 24), bytes 4..6 of the product, summed column by column as in
//    turns24FromRadians: the high bytes of column 3 with the carry estimate
//    3, columns 4 and 5, the low bytes of column 6; thirteen MULs, grouped
//    by byte of C. Negated for x < 0; a quarter turn added for cos.
// 2. The quadrant's angle p, mirrored in the 2nd and 4th; entry p >> 15 of
//    kSin and its 15-bit fraction; the top (p = 2^22) is exactly one.
// 3. kSin[i] + (rise f + 2^14) >> 15 from four MULs; negated in the
//    lower half turn.
// ---------------------------------------------------------------------------
__attribute__((naked, noinline)) inline int32_t avrSinUnitsQ16(int32_t,
                                                                uint8_t) {
  asm volatile(
      // T = x < 0; r25:r22 = |x|; r19 = 0; the sum of bytes 4..6 in
      // r30:r27:r26.
      "    bst  r25, 7\n"
      TINYPARTICLE_AVR_MAGNITUDE32("r25", "r24", "r23", "r22", "1")
      "    clr  r19\n"
      "    ldi  r26, 3\n"
      "    clr  r27\n"
      "    clr  r30\n"
      "    ldi  r18, 0xbe\n"          // c3
      "    mul  r22, r18\n"           // m0 c3: column 3
      "    add  r26, r1\n"
      "    adc  r27, r19\n"
      "    adc  r30, r19\n"
      "    mul  r23, r18\n"           // m1 c3: column 4
      "    add  r26, r0\n"
      "    adc  r27, r1\n"
      "    adc  r30, r19\n"
      "    mul  r24, r18\n"           // m2 c3: column 5
      "    add  r27, r0\n"
      "    adc  r30, r1\n"
      "    mul  r25, r18\n"           // m3 c3: column 6
      "    add  r30, r0\n"
      "    ldi  r18, 0x60\n"          // c2
      "    mul  r23, r18\n"           // m1 c2: column 3
      "    add  r26, r1\n"
      "    adc  r27, r19\n"
      "    adc  r30, r19\n"
      "    mul  r24, r18\n"           // m2 c2: column 4
      "    add  r26, r0\n"
      "    adc  r27, r1\n"
      "    adc  r30, r19\n"
      "    mul  r25, r18\n"           // m3 c2: column 5
      "    add  r27, r0\n"
      "    adc  r30, r1\n"
      "    ldi  r18, 0xdb\n"          // c1
      "    mul  r24, r18\n"           // m2 c1: column 3
      "    add  r26, r1\n"
      "    adc  r27, r19\n"
      "    adc  r30, r19\n"
      "    mul  r25, r18\n"           // m3 c1: column 4
      "    add  r26, r0\n"
      "    adc  r27, r1\n"
      "    adc  r30, r19\n"
      "    ldi  r18, 0x93\n"          // c0
      "    mul  r25, r18\n"           // m3 c0: column 3
      "    add  r26, r1\n"
      "    adc  r27, r19\n"
      "    adc  r30, r19\n"
      "    ldi  r18, 0x28\n"          // c4
      "    mul  r22, r18\n"           // m0 c4: column 4
      "    add  r26, r0\n"
      "    adc  r27, r1\n"
      "    adc  r30, r19\n"
      "    mul  r23, r18\n"           // m1 c4: column 5
      "    add  r27, r0\n"
      "    adc  r30, r1\n"
      "    mul  r24, r18\n"           // m2 c4: column 6
      "    add  r30, r0\n"
      // The turns t in r30:r27:r26: negated for x < 0 (24 bits), plus the
      // quarter turn; the top byte kept in r20 for the quadrant and sign.
      "    brtc 2f\n"
      "    com  r30\n"
      "    com  r27\n"
      "    neg  r26\n"
      "    sbci r27, 0xff\n"
      "    sbci r30, 0xff\n"
      "2:\n"
      "    add  r20, r30\n"
      // p = (r30 & 0x3f, r27, r26); 2nd and 4th quadrants: 2^22 - p.
      "    mov  r30, r20\n"
      "    andi r30, 0x3f\n"
      "    sbrs r20, 6\n"
      "    rjmp 3f\n"
      "    com  r30\n"
      "    com  r27\n"
      "    neg  r26\n"
      "    sbci r27, 0xff\n"
      "    sbci r30, 0xff\n"
      "    subi r30, 0xc0\n"           // + 0x40
      "    cpi  r30, 0x40\n"
      "    breq 5f\n"                  // p = 2^22: exactly one
      "3:\n"
      // i = p >> 15 in r30, f1 = bits 8..14 of p in r27, f0 in r26.
      "    lsl  r27\n"
      "    rol  r30\n"
      "    lsr  r27\n"
      "    lsl  r30\n"
      "    clr  r31\n"
      "    subi r30, lo8(-(" TINYPARTICLE_AVR_SIN "))\n"
      "    sbci r31, hi8(-(" TINYPARTICLE_AVR_SIN "))\n"
      "    lpm  r22, Z+\n"             // y0 in r23:r22
      "    lpm  r23, Z+\n"
      "    lpm  r24, Z+\n"
      "    lpm  r25, Z\n"
      "    sub  r24, r22\n"            // rise in r25:r24 (r25 < 4)
      "    sbc  r25, r23\n"
      // m = r0 f1 + r1 f0 + (r0 f0 >> 8) + 0x40 in r21:r18 (below 2^16).
      "    mul  r24, r26\n"
      "    mov  r18, r1\n"
      "    clr  r21\n"
      "    subi r18, 0xc0\n"           // + 0x40 (16 bits)
      "    sbci r21, 0xff\n"
      "    mul  r24, r27\n"
      "    add  r18, r0\n"
      "    adc  r21, r1\n"
      "    mul  r25, r26\n"
      "    add  r18, r0\n"
      "    adc  r21, r1\n"
      // m >> 7 in r18:r21 (r18 the high byte).
      "    lsl  r18\n"
      "    rol  r21\n"
      "    ldi  r18, 0\n"
      "    adc  r18, r18\n"
      // + 2 r1 f1, then y0 + that in r25:r22.
      "    mul  r25, r27\n"
      "    lsl  r0\n"
      "    rol  r1\n"
      "    add  r21, r0\n"
      "    adc  r18, r1\n"
      "    clr  r1\n"
      "    add  r22, r21\n"
      "    adc  r23, r18\n"
      "    ldi  r24, 0\n"
      "    adc  r24, r24\n"
      "    clr  r25\n"
      "4:\n"
      // Lower half turn: negative.
      "    sbrs r20, 7\n"
      "    ret\n"
      TINYPARTICLE_AVR_NEGATE32("r25", "r24", "r23", "r22")
      "    ret\n"
      "5:\n"
      "    clr  r1\n"
      "    ldi  r22, 0\n"
      "    ldi  r23, 0\n"
      "    ldi  r24, 1\n"
      "    ldi  r25, 0\n"
      "    rjmp 4b\n"
      ::: "memory");
}

template <>
struct FixedFast<16, 16> {
  typedef int32_t Raw;
  TINYPARTICLE_ALWAYS_INLINE static Raw multiply(Raw a, Raw b) {
    flagsTouchedSaturating();
    Raw r = avrMultiplyQ16(a, b);
    flagsTouched();
    return r;
  }
  // Member templates (U is always void): the tables are then instantiated,
  // and linked, only by a sketch that divides or takes a square root.
  template <typename U = void>
  TINYPARTICLE_ALWAYS_INLINE static Raw divide(Raw a, Raw b) {
    // Tell the compiler that the assembly reads kRecip, so that it keeps
    // the table (it cannot see the reference by name either).
    asm volatile("" : : "m"(TrigTables<U>::kRecip[0]));
    flagsTouchedSaturating();
    Raw r = avrDivideQ16(a, b);
    flagsTouched();
    return r;
  }
  template <typename U = void>
  TINYPARTICLE_ALWAYS_INLINE static Raw squareRoot(Raw x) {
    asm volatile("" : : "m"(TrigTables<U>::kRecip[0]), "m"(TrigTables<U>::kSqrt[0]));
    return avrSquareRoot(x, 0);  // raises no flag
  }
};

// Q24.8 on the Q16.16 routines: a * b / 2^8 = a * (b * 2^8) / 2^16 and
// a * 2^8 / b = a * 2^16 / (b * 2^8) exactly, so rounding, saturation and
// flags are the same as the reference's whenever b * 2^8 fits (|b| below
// 2^23 steps, i.e. 32768.0); else the other operand is scaled, or the
// reference code runs (division by 32768.0 or more).
template <>
struct FixedFast<24, 8> {
  typedef int32_t Raw;
  static bool small(Raw x) { return x >= -0x800000l && x < 0x800000l; }
  TINYPARTICLE_ALWAYS_INLINE static Raw multiply(Raw a, Raw b) {
    if (small(b)) return FixedFast<16, 16>::multiply(a, b * 256);
    if (small(a)) return FixedFast<16, 16>::multiply(b, a * 256);
    // Both at least 2^23 steps: the product is at least 2^38 steps.
    return Q24_8::overflow((a < 0) != (b < 0));
  }
  template <typename U = void>
  TINYPARTICLE_ALWAYS_INLINE static Raw divide(Raw a, Raw b) {
    if (small(b)) return FixedFast<16, 16>::divide<U>(a, b * 256);
    return Q24_8::referenceDivide(a, b);
  }
  template <typename U = void>
  TINYPARTICLE_ALWAYS_INLINE static Raw squareRoot(Raw x) {
    asm volatile("" : : "m"(TrigTables<U>::kRecip[0]), "m"(TrigTables<U>::kSqrt[0]));
    return avrSquareRoot(x, 4);  // sqrt(x * 2^16) / 16 = sqrt(x * 2^8)
  }
};

// Q8.8 divide and square root likewise (b * 2^8 always fits 32 bits); the
// 32-bit result is then saturated to 16 bits.
template <>
struct FixedFast<8, 8> {
  typedef int16_t Raw;
  static Raw narrow(int32_t r) {
    if (r > INT16_MAX) return Q8_8::overflow(false);
    if (r < INT16_MIN) return Q8_8::overflow(true);
    return Raw(r);
  }
  // A 16 x 16 product: the portable code is already a 32-bit multiply
  // (a library routine of four MULs), faster than the Q16.16 path here.
  static Raw multiply(Raw a, Raw b) { return Q8_8::referenceMultiply(a, b); }
  template <typename U = void>
  TINYPARTICLE_ALWAYS_INLINE static Raw divide(Raw a, Raw b) {
    return narrow(FixedFast<16, 16>::divide<U>(a, int32_t(b) * 256));
  }
  template <typename U = void>
  TINYPARTICLE_ALWAYS_INLINE static Raw squareRoot(Raw x) {
    asm volatile("" : : "m"(TrigTables<U>::kRecip[0]), "m"(TrigTables<U>::kSqrt[0]));
    return Raw(avrSquareRoot(x, 4));  // at most 2^11.5: fits
  }
};

}  // namespace detail

}  // namespace tinyparticle

#endif  // __AVR__ && __AVR_HAVE_MUL__
