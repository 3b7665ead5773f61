// The measuring machinery of AutoBenchmark: a cycle counter, operand pools,
// timing loops and the lines sent over Serial. Included by AutoBenchmark.ino
// only (it defines globals, and CycleCounter.hpp an interrupt handler).
//
// How a figure is made (the method of the numeric issue):
//   cycles = (cycles of a loop of K calls to a non-inlined function that does
//             the operation on operands read from a volatile array
//           - cycles of the same loop calling an empty non-inlined function
//             of the same signature) / K
// and beside it the inlined cost: the same loop with the operation written in
// place, minus the loop that only reads the operands and stores one of them.
// K = BENCH_CHUNKS x 32 operand sets; the loops are timed one chunk of 32 at a
// time, so the pools fit in RAM, and the chunks are summed.
#pragma once

#include <Arduino.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/CycleCounter.hpp>
#include <TinyParticle/Testing/MathTestSupport.hpp>
#include <avr/interrupt.h>
#include <avr/sleep.h>

#ifndef BENCH_CHUNKS
#define BENCH_CHUNKS 8
#endif

#define BENCH_NOINLINE __attribute__((noinline, noclone))

namespace bench {

const uint8_t kChunk = 32;
const uint8_t kChunks = BENCH_CHUNKS;

// The cycle counter (Timer1 extended by its overflow interrupt, whose own
// cycles are taken out; src/TinyParticle/Testing/CycleCounter.hpp). Every
// other interrupt stays off while the benchmark runs: begin() stops Timer0's
// millis() tick.
namespace cycles = tinyparticle::testing::cycles;

// ---------------------------------------------------------------------------
// Output. Every value goes out as fixed-width hex of its bits, so the host
// decodes exactly what the target computed.

inline void printHex(uint64_t v, uint8_t digits) {
  Serial.write(' ');
  while (digits-- > 0) {
    uint8_t nibble = uint8_t(v >> (4 * digits)) & 0xF;
    Serial.write(nibble < 10 ? '0' + nibble : 'a' + nibble - 10);
  }
}
inline void printValue(int16_t v) { printHex(uint16_t(v), 4); }
inline void printValue(uint16_t v) { printHex(v, 4); }
inline void printValue(int32_t v) { printHex(uint32_t(v), 8); }
inline void printValue(int64_t v) { printHex(uint64_t(v), 16); }
inline void printValue(float v) {
  uint32_t bits;
  memcpy(&bits, &v, sizeof(bits));
  printHex(bits, 8);
}

// A count of tenths, e.g. 1234 -> "123.4".
inline void printTenths(int32_t tenths) {
  if (tenths < 0) {
    Serial.write('-');
    tenths = -tenths;
  }
  Serial.print(tenths / 10);
  Serial.write('.');
  Serial.print(int(tenths % 10));
}

// ---------------------------------------------------------------------------
// Operand pools: one volatile buffer shared by every type (a union, so each
// type reads the member it wrote). Binary operations read a[i] = p[i] and
// b[i] = p[kChunk + i]; vectors read component c of entry i at p[c * kChunk + i].

union Pool {
  int16_t i16[3 * kChunk];
  uint16_t u16[3 * kChunk];
  int32_t i32[3 * kChunk];
  float f32[3 * kChunk];
  int64_t i64[2 * kChunk];
};
volatile Pool gPool;

template <typename P> volatile P* pool();
template <> inline volatile int16_t* pool<int16_t>() { return gPool.i16; }
template <> inline volatile uint16_t* pool<uint16_t>() { return gPool.u16; }
template <> inline volatile int32_t* pool<int32_t>() { return gPool.i32; }
template <> inline volatile float* pool<float>() { return gPool.f32; }
template <> inline volatile int64_t* pool<int64_t>() { return gPool.i64; }

// Results land here, so the optimiser must compute them.
volatile int16_t gSink16;
volatile int32_t gSink32;
volatile int64_t gSink64;
volatile float gSinkF;
template <typename R> volatile R& sink();
template <> inline volatile int16_t& sink<int16_t>() { return gSink16; }
template <> inline volatile int32_t& sink<int32_t>() { return gSink32; }
template <> inline volatile int64_t& sink<int64_t>() { return gSink64; }
template <> inline volatile float& sink<float>() { return gSinkF; }

// ---------------------------------------------------------------------------
// A fixed-seed generator (xorshift32). Each operation reseeds it from its pool
// kind, so every type sees the same draws: int32, Q16.16 and Q24.8 get the
// same raw operands, and float gets the Q16.16 values.

tinyparticle::testing::XorShift32 gRandom(1);
inline void reseed(uint32_t seed) {
  gRandom = tinyparticle::testing::XorShift32(seed);
}
inline uint32_t random32() { return gRandom.next(); }
// Uniform in [0, 1).
inline float randomUnit() { return float(random32() >> 8) * (1.0f / 16777216.0f); }

// A raw magnitude whose bit length is uniform in [minBits, maxBits] and whose
// lower bits are random: magnitudes spread evenly on a log scale.
inline uint64_t randomMagnitude(uint8_t minBits, uint8_t maxBits) {
  uint8_t bits = minBits + uint8_t(random32() % (maxBits - minBits + 1));
  uint64_t top = uint64_t(1) << (bits - 1);
  uint64_t low = (uint64_t(random32()) << 32) | random32();
  return top | (low & (top - 1));
}
// The same with a random sign, as a signed value.
inline int64_t randomSigned(uint8_t minBits, uint8_t maxBits) {
  uint64_t m = randomMagnitude(minBits, maxBits);
  return (random32() & 1) ? -int64_t(m) : int64_t(m);
}

// ---------------------------------------------------------------------------
// Timing loops. f is called through a pointer, so the callee is never inlined
// into the loop; op and empty callee run through identical loop code.

template <typename P, typename R>
BENCH_NOINLINE R emptyBinary(P a, P b) {
  (void)b;
  __asm__ __volatile__("");
  return R(a);
}
template <typename P, typename R>
BENCH_NOINLINE R emptyUnary(P a) {
  __asm__ __volatile__("");
  return R(a);
}

template <typename P, typename R>
BENCH_NOINLINE uint32_t timeBinary(R (*f)(P, P)) {
  volatile P* p = pool<P>();
  cycles::start();
  for (uint8_t i = 0; i < kChunk; ++i) sink<R>() = f(p[i], p[kChunk + i]);
  return cycles::stop();
}

template <typename P, typename R>
BENCH_NOINLINE uint32_t timeUnary(R (*f)(P)) {
  volatile P* p = pool<P>();
  cycles::start();
  for (uint8_t i = 0; i < kChunk; ++i) sink<R>() = f(p[i]);
  return cycles::stop();
}

// The inlined loops: Op::apply is expanded in place.
template <typename Op>
BENCH_NOINLINE uint32_t timeBinaryInline() {
  typedef typename Op::P P;
  volatile P* p = pool<P>();
  cycles::start();
  for (uint8_t i = 0; i < kChunk; ++i) {
    sink<typename Op::R>() = Op::apply(p[i], p[kChunk + i]);
  }
  return cycles::stop();
}
template <typename Op>
BENCH_NOINLINE uint32_t timeUnaryInline() {
  typedef typename Op::P P;
  volatile P* p = pool<P>();
  cycles::start();
  for (uint8_t i = 0; i < kChunk; ++i) sink<typename Op::R>() = Op::apply(p[i]);
  return cycles::stop();
}

// The "operations" that do nothing but pass an operand on: inlined baselines.
template <typename PT, typename RT>
struct First {
  typedef PT P;
  typedef RT R;
  static R apply(P a, P) { return R(a); }
  static R apply(P a) { return R(a); }
};

template <typename Op>
BENCH_NOINLINE typename Op::R callBinary(typename Op::P a, typename Op::P b) {
  return Op::apply(a, b);
}
template <typename Op>
BENCH_NOINLINE typename Op::R callUnary(typename Op::P a) {
  return Op::apply(a);
}

// Sums over the chunks of one operation.
struct Totals {
  uint32_t call, empty, inlined, inlineBase;
  Totals() : call(0), empty(0), inlined(0), inlineBase(0) {}
};

inline int32_t tenthsPerOp(uint32_t total, uint32_t base, uint16_t count) {
  int32_t diff = int32_t(total - base);
  int32_t scaled = diff * 10;
  int32_t half = count / 2;
  return (scaled >= 0 ? scaled + half : scaled - half) / int32_t(count);
}

inline void printBegin(const __FlashStringHelper* type,
                       const __FlashStringHelper* op) {
  Serial.print(F("B "));
  Serial.print(type);
  Serial.write(' ');
  Serial.println(op);
}

// "C <type> <op> <cycles> <inlined cycles> <samples>"
inline void printCycles(const __FlashStringHelper* type,
                        const __FlashStringHelper* op, const Totals& t) {
  uint16_t count = uint16_t(kChunks) * kChunk;
  Serial.print(F("C "));
  Serial.print(type);
  Serial.write(' ');
  Serial.print(op);
  Serial.write(' ');
  printTenths(tenthsPerOp(t.call, t.empty, count));
  Serial.write(' ');
  printTenths(tenthsPerOp(t.inlined, t.inlineBase, count));
  Serial.write(' ');
  Serial.println(count);
}

// A pool filler: writes one chunk of operands for the given type.
typedef void (*Fill)();

// What every operation runs: for each chunk, fill the pool, time the four
// loops (Kind::time) and send a line per operand set (Kind::send); then the
// "C" line. Kind is BinaryKind, UnaryKind or VectorKind (below) of the Op.
template <class Kind>
void runOperation(const __FlashStringHelper* type,
                  const __FlashStringHelper* op, uint32_t seed, Fill fill) {
  printBegin(type, op);
  reseed(seed);
  Totals t;
  for (uint8_t c = 0; c < kChunks; ++c) {
    fill();
    Serial.flush();
    Kind::time(t);
    Kind::send();
  }
  printCycles(type, op, t);
}

// One binary operation: "S <a> <b> <result>" for each operand pair.
template <typename Op>
struct BinaryKind {
  typedef typename Op::P P;
  typedef typename Op::R R;
  static void time(Totals& t) {
    t.call += timeBinary<P, R>(callBinary<Op>);
    t.empty += timeBinary<P, R>(emptyBinary<P, R>);
    t.inlined += timeBinaryInline<Op>();
    t.inlineBase += timeBinaryInline<First<P, R> >();
  }
  static void send() {
    volatile P* p = pool<P>();
    for (uint8_t i = 0; i < kChunk; ++i) {
      P a = p[i];
      P b = p[kChunk + i];
      Serial.write('S');
      printValue(a);
      printValue(b);
      printValue(callBinary<Op>(a, b));
      Serial.println();
    }
  }
};

// One unary operation: "S <a> <result>".
template <typename Op>
struct UnaryKind {
  typedef typename Op::P P;
  typedef typename Op::R R;
  static void time(Totals& t) {
    t.call += timeUnary<P, R>(callUnary<Op>);
    t.empty += timeUnary<P, R>(emptyUnary<P, R>);
    t.inlined += timeUnaryInline<Op>();
    t.inlineBase += timeUnaryInline<First<P, R> >();
  }
  static void send() {
    volatile P* p = pool<P>();
    for (uint8_t i = 0; i < kChunk; ++i) {
      P a = p[i];
      Serial.write('S');
      printValue(a);
      printValue(callUnary<Op>(a));
      Serial.println();
    }
  }
};

template <typename Op>
void runBinary(const __FlashStringHelper* type, const __FlashStringHelper* op,
               uint32_t seed, Fill fill) {
  runOperation<BinaryKind<Op> >(type, op, seed, fill);
}

template <typename Op>
void runUnary(const __FlashStringHelper* type, const __FlashStringHelper* op,
              uint32_t seed, Fill fill) {
  runOperation<UnaryKind<Op> >(type, op, seed, fill);
}

// ---------------------------------------------------------------------------
// Vector operations take a vector by value (Op::V) and return Op::R (a raw
// scalar for a magnitude, a vector for normalize). Op provides load(i) from
// the pool, apply(v), empty(v) (passes its argument on), keep(r) (stores into
// the sinks) and print(r).

template <typename Op>
BENCH_NOINLINE typename Op::R callVector(typename Op::V v) {
  return Op::apply(v);
}
template <typename Op>
BENCH_NOINLINE typename Op::R emptyVector(typename Op::V v) {
  __asm__ __volatile__("");
  return Op::empty(v);
}

template <typename Op>
BENCH_NOINLINE uint32_t timeVector(typename Op::R (*f)(typename Op::V)) {
  cycles::start();
  for (uint8_t i = 0; i < kChunk; ++i) Op::keep(f(Op::load(i)));
  return cycles::stop();
}
template <typename Op>
BENCH_NOINLINE uint32_t timeVectorInline(bool inlined) {
  cycles::start();
  if (inlined) {
    for (uint8_t i = 0; i < kChunk; ++i) Op::keep(Op::apply(Op::load(i)));
  } else {
    for (uint8_t i = 0; i < kChunk; ++i) Op::keep(Op::empty(Op::load(i)));
  }
  return cycles::stop();
}

// One vector operation: "S <components...> <result...>".
template <typename Op>
struct VectorKind {
  typedef typename Op::P P;
  static void time(Totals& t) {
    t.call += timeVector<Op>(callVector<Op>);
    t.empty += timeVector<Op>(emptyVector<Op>);
    t.inlined += timeVectorInline<Op>(true);
    t.inlineBase += timeVectorInline<Op>(false);
  }
  static void send() {
    volatile P* p = pool<P>();
    for (uint8_t i = 0; i < kChunk; ++i) {
      Serial.write('S');
      for (uint8_t k = 0; k < Op::kDim; ++k) printValue(P(p[k * kChunk + i]));
      Op::print(callVector<Op>(Op::load(i)));
      Serial.println();
    }
  }
};

template <typename Op>
void runVector(const __FlashStringHelper* type, const __FlashStringHelper* op,
               uint32_t seed, Fill fill) {
  runOperation<VectorKind<Op> >(type, op, seed, fill);
}

// ---------------------------------------------------------------------------

inline void begin() {
  Serial.println(F("# TinyParticle AutoBenchmark"));
  Serial.print(F("# compiler avr-gcc "));
  Serial.println(F(__VERSION__));
  Serial.print(F("# F_CPU "));
  Serial.println(F_CPU);
  Serial.flush();
  cycles::begin();  // no millis() tick from here on: it would land in the loops
  Serial.print(F("# overflow-handler cycles "));
  Serial.println(cycles::handlerCycles());
  Serial.print(F("# samples per operation "));
  Serial.println(uint16_t(kChunks) * kChunk);
}

// "E" marks the end; then the CPU sleeps with interrupts off, which ends a
// simavr run.
inline void end() {
  Serial.println(F("E"));
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
}

}  // namespace bench
