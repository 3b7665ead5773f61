// STAND-IN for the AUnit unit-test library (https://github.com/bxparks/AUnit).
//
// Used only where the real AUnit is not installed (these build machines).
// Written from AUnit's README, not from its code. It provides the subset of
// AUnit's documented API that TinyParticle's tests use and nothing more:
//
//   test(name) / test(suite, name) / testF(Fixture, name)   (aunit::TestOnce)
//   assertEqual, assertNotEqual, assertLess, assertMore,
//   assertLessOrEqual, assertMoreOrEqual, assertTrue, assertFalse,
//   assertNear(a, b, error)
//   aunit::TestRunner::run(), aunit::TestRunner::setTimeout(seconds)
//
// Behaviour kept identical to AUnit, so a sketch that passes here passes there:
// - assertXxx(a, b) only accepts the argument-type pairs AUnit documents
//   (bool, char, int, unsigned, long, unsigned long, long long,
//   unsigned long long, double, C and flash strings; any pointers for
//   assertEqual/assertNotEqual). Mixed types are ambiguous and do not compile.
//   (Arduino's String class is not supported here.)
// - assertXxx() are usable only inside a test body or a fixture's method;
//   a failed assertion prints a message and returns from that function.
// - Tests run one per TestRunner::run() call, sorted by name (byte order).
// - The timeout (default 10 s, setTimeout(0) = none) counts from the first
//   run() call: a test not started before it expires is "timed out".
// - Output lines: "TestRunner started on N test(s).", "Test X passed.",
//   "Test X failed.", "Test X timed out.",
//   "<file>:<line>: Assertion failed: (a) == (b).",
//   "TestRunner duration: S.mmm seconds.",
//   "TestRunner summary: P passed, F failed, S skipped, T timed out, out of N test(s)."
// - Under EpoxyDuino the program exits after the summary, with status 1 when
//   a test failed or timed out, 0 otherwise.
//
// It compiles for AVR too: names and the file name live in flash, and each
// test costs 7 bytes of RAM on the Nano.
#ifndef TINYPARTICLE_AUNIT_STANDIN_H
#define TINYPARTICLE_AUNIT_STANDIN_H

#include <Arduino.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define AUNIT_STANDIN 1

namespace aunit {

class TestRunner;

namespace internal {

enum : uint8_t { kEq, kNe, kLt, kGt, kLe, kGe };

// Flash string helpers: on AVR, names and file names are read with pgm_read_byte.
inline int compareFlash(const char* a, const char* b) {
  for (;;) {
    uint8_t ca = pgm_read_byte(a++);
    uint8_t cb = pgm_read_byte(b++);
    if (ca != cb) return ca < cb ? -1 : 1;
    if (ca == 0) return 0;
  }
}

// A string operand of an assertion, in RAM or in flash; null sorts first.
struct Text {
  const char* p;
  bool flash;
  uint8_t at(size_t i) const {
    return flash ? pgm_read_byte(p + i) : static_cast<uint8_t>(p[i]);
  }
};

inline int compareText(Text a, Text b) {
  if (a.p == nullptr || b.p == nullptr) {
    return (a.p == nullptr ? 0 : 1) - (b.p == nullptr ? 0 : 1);
  }
  for (size_t i = 0;; ++i) {
    uint8_t ca = a.at(i);
    uint8_t cb = b.at(i);
    if (ca != cb) return ca < cb ? -1 : 1;
    if (ca == 0) return 0;
  }
}

template <typename T>
bool holds(uint8_t op, const T& a, const T& b) {
  switch (op) {
    case kEq: return a == b;
    case kNe: return a != b;
    case kLt: return a < b;
    case kGt: return a > b;
    case kLe: return a <= b;
    default:  return a >= b;
  }
}

inline bool holdsOrder(uint8_t op, int c) { return holds<int>(op, c, 0); }

inline bool negative(int v) { return v < 0; }
inline bool negative(long v) { return v < 0; }
inline bool negative(unsigned int) { return false; }
inline bool negative(unsigned long) { return false; }

inline const __FlashStringHelper* opText(uint8_t op) {
  switch (op) {
    case kEq: return F("==");
    case kNe: return F("!=");
    case kLt: return F("<");
    case kGt: return F(">");
    case kLe: return F("<=");
    default:  return F(">=");
  }
}

// Printing of values in AUnit's message style.
inline void show(bool v) { Serial.print(v ? F("true") : F("false")); }
inline void show(char v) { Serial.print(v); }
inline void show(int v) { Serial.print(v); }
inline void show(unsigned int v) { Serial.print(v); }
inline void show(long v) { Serial.print(v); }
inline void show(unsigned long v) { Serial.print(v); }
inline void show(unsigned long long v) {
  char digits[21];
  uint8_t n = 0;
  do {
    digits[n++] = static_cast<char>('0' + static_cast<uint8_t>(v % 10u));
    v /= 10u;
  } while (v != 0);
  while (n > 0) Serial.print(digits[--n]);
}
inline void show(long long v) {
  if (v < 0) {
    Serial.print('-');
    // Negate in unsigned arithmetic: defined for the most negative value too.
    show(0ull - static_cast<unsigned long long>(v));
  } else {
    show(static_cast<unsigned long long>(v));
  }
}
inline void show(double v) { Serial.print(v); }
inline void show(Text v) {
  if (v.p == nullptr) {
    Serial.print(F("nullptr"));
  } else if (v.flash) {
    Serial.print(reinterpret_cast<const __FlashStringHelper*>(v.p));
  } else {
    Serial.print(v.p);
  }
}
inline void show(const void* v) {
  Serial.print(F("0x"));
  Serial.print(static_cast<unsigned long>(reinterpret_cast<uintptr_t>(v)), HEX);
}

}  // namespace internal

// Base of every test. Fixtures derive from TestOnce and may override
// setup() and teardown() (calling the base versions).
class Test {
 public:
  virtual void setup() {}
  virtual void teardown() {}

 protected:
  enum : uint8_t { kRunning, kPassed, kFailed, kExpired };

  Test() : mName(nullptr), mNext(nullptr), mStatus(kRunning) {}
  virtual void runBody() = 0;

  // Called by the constructor that test()/testF() generate.
  void init(const __FlashStringHelper* name) {
    mName = name;
    Test** link = &root();
    while (*link != nullptr &&
           internal::compareFlash(reinterpret_cast<const char*>((*link)->mName),
                                  reinterpret_cast<const char*>(name)) <= 0) {
      link = &(*link)->mNext;
    }
    mNext = *link;
    *link = this;
  }

  // The assertion back ends. Overloads mirror AUnit's documented set, so
  // argument pairs AUnit rejects are ambiguous here too.
#define AUNIT_STANDIN_ORDER(T)                                             \
  bool aunitOrder(uint16_t line, uint8_t op, T a, T b) {                  \
    if (internal::holds<T>(op, a, b)) return true;                        \
    failStart(line);                                                      \
    Serial.print('('); internal::show(a); failOp(op); internal::show(b);  \
    failEnd();                                                            \
    return false;                                                         \
  }                                                                       \
  bool aunitEquality(uint16_t line, uint8_t op, T a, T b) {               \
    return aunitOrder(line, op, a, b);                                    \
  }
  AUNIT_STANDIN_ORDER(bool)
  AUNIT_STANDIN_ORDER(char)
  AUNIT_STANDIN_ORDER(int)
  AUNIT_STANDIN_ORDER(unsigned int)
  AUNIT_STANDIN_ORDER(long)
  AUNIT_STANDIN_ORDER(unsigned long)
  AUNIT_STANDIN_ORDER(long long)
  AUNIT_STANDIN_ORDER(unsigned long long)
  AUNIT_STANDIN_ORDER(double)
#undef AUNIT_STANDIN_ORDER

#define AUNIT_STANDIN_TEXT(TA, FA, TB, FB)                                 \
  bool aunitOrder(uint16_t line, uint8_t op, TA a, TB b) {                \
    internal::Text ta = {reinterpret_cast<const char*>(a), FA};           \
    internal::Text tb = {reinterpret_cast<const char*>(b), FB};           \
    if (internal::holdsOrder(op, internal::compareText(ta, tb))) return true; \
    failStart(line);                                                      \
    Serial.print('('); internal::show(ta); failOp(op); internal::show(tb); \
    failEnd();                                                            \
    return false;                                                         \
  }                                                                       \
  bool aunitEquality(uint16_t line, uint8_t op, TA a, TB b) {             \
    return aunitOrder(line, op, a, b);                                    \
  }
  AUNIT_STANDIN_TEXT(const char*, false, const char*, false)
  AUNIT_STANDIN_TEXT(const char*, false, const __FlashStringHelper*, true)
  AUNIT_STANDIN_TEXT(const __FlashStringHelper*, true, const char*, false)
  AUNIT_STANDIN_TEXT(const __FlashStringHelper*, true, const __FlashStringHelper*, true)
#undef AUNIT_STANDIN_TEXT

  // Pointers: assertEqual and assertNotEqual only.
  bool aunitEquality(uint16_t line, uint8_t op, const void* a, const void* b) {
    if (internal::holds<const void*>(op, a, b)) return true;
    failStart(line);
    Serial.print('(');
    internal::show(a); failOp(op); internal::show(b); failEnd();
    return false;
  }

  bool aunitTruth(uint16_t line, bool value, bool expected) {
    if (value == expected) return true;
    failStart(line);
    Serial.print('(');
    internal::show(value);
    Serial.print(expected ? F(") is true.") : F(") is false."));
    Serial.println();
    return false;
  }

#define AUNIT_STANDIN_NEAR(T, U)                                           \
  bool aunitNear(uint16_t line, T a, T b, T error) {                      \
    /* distance in the unsigned type: defined for any pair of values */   \
    U d = a > b ? static_cast<U>(static_cast<U>(a) - static_cast<U>(b))   \
                : static_cast<U>(static_cast<U>(b) - static_cast<U>(a));  \
    if (!internal::negative(error) && d <= static_cast<U>(error)) return true;          \
    return nearFailed(line, a, b, error);                                 \
  }
  AUNIT_STANDIN_NEAR(int, unsigned int)
  AUNIT_STANDIN_NEAR(unsigned int, unsigned int)
  AUNIT_STANDIN_NEAR(long, unsigned long)
  AUNIT_STANDIN_NEAR(unsigned long, unsigned long)
#undef AUNIT_STANDIN_NEAR
  bool aunitNear(uint16_t line, double a, double b, double error) {
    if (fabs(a - b) <= error) return true;  // false for NaN: fails
    return nearFailed(line, a, b, error);
  }

 private:
  friend class TestRunner;

  static Test*& root() {
    static Test* first = nullptr;
    return first;
  }

  void failStart(uint16_t line);
  void failOp(uint8_t op) {
    Serial.print(F(") "));
    Serial.print(internal::opText(op));
    Serial.print(F(" ("));
  }
  void failEnd() { Serial.println(F(").")); }
  template <typename T>
  bool nearFailed(uint16_t line, T a, T b, T error) {
    failStart(line);
    Serial.print(F("|("));
    internal::show(a);
    Serial.print(F(") - ("));
    internal::show(b);
    Serial.print(F(")| <= ("));
    internal::show(error);
    Serial.println(F(")."));
    return false;
  }

  const __FlashStringHelper* mName;
  Test* mNext;
  uint8_t mStatus;
};

// A test whose body runs once: test() and testF() (fixtures derive from it).
class TestOnce : public Test {
 protected:
  virtual void once() = 0;
  void runBody() override { once(); }
};

class TestRunner {
 public:
  // Runs the next test; after the last one prints the summary (and exits
  // under EpoxyDuino). Call it from loop().
  static void run() { state().step(); }

  // Seconds allowed for the whole run, counted from the first run() call;
  // 0 means no limit. Default 10.
  static void setTimeout(uint16_t seconds) { state().mTimeout = seconds; }

 private:
  TestRunner() : mNext(nullptr), mStart(0), mTimeout(10), mCount(0),
      mPassed(0), mFailed(0), mExpired(0), mStarted(false), mDone(false) {}

  static TestRunner& state() {
    static TestRunner runner;
    return runner;
  }

  void step() {
    if (!mStarted) {
      mStarted = true;
      mNext = Test::root();
      for (Test* t = mNext; t != nullptr; t = t->mNext) ++mCount;
      Serial.print(F("TestRunner started on "));
      Serial.print(mCount);
      Serial.println(F(" test(s)."));
      mStart = millis();
      return;
    }
    if (mNext == nullptr) {
      if (!mDone) finish();
      return;
    }
    Test* t = mNext;
    mNext = t->mNext;
    if (mTimeout != 0 && millis() - mStart >= 1000ul * mTimeout) {
      t->mStatus = Test::kExpired;
    } else {
      t->setup();
      if (t->mStatus == Test::kRunning) t->runBody();
      t->teardown();
      if (t->mStatus == Test::kRunning) t->mStatus = Test::kPassed;
    }
    Serial.print(F("Test "));
    Serial.print(t->mName);
    switch (t->mStatus) {
      case Test::kPassed: ++mPassed; Serial.println(F(" passed.")); break;
      case Test::kFailed: ++mFailed; Serial.println(F(" failed.")); break;
      default: ++mExpired; Serial.println(F(" timed out.")); break;
    }
  }

  void finish() {
    mDone = true;
    unsigned long ms = millis() - mStart;
    Serial.print(F("TestRunner duration: "));
    Serial.print(ms / 1000ul);
    Serial.print('.');
    unsigned int frac = static_cast<unsigned int>(ms % 1000ul);
    if (frac < 100) Serial.print('0');
    if (frac < 10) Serial.print('0');
    Serial.print(frac);
    Serial.println(F(" seconds."));
    Serial.print(F("TestRunner summary: "));
    Serial.print(mPassed);
    Serial.print(F(" passed, "));
    Serial.print(mFailed);
    Serial.print(F(" failed, 0 skipped, "));
    Serial.print(mExpired);
    Serial.print(F(" timed out, out of "));
    Serial.print(mCount);
    Serial.println(F(" test(s)."));
#if defined(EPOXY_DUINO)
    Serial.flush();
    exit((mFailed != 0 || mExpired != 0) ? 1 : 0);
#endif
  }

  Test* mNext;
  unsigned long mStart;
  uint16_t mTimeout;
  uint16_t mCount;
  uint16_t mPassed;
  uint16_t mFailed;
  uint16_t mExpired;
  bool mStarted;
  bool mDone;
};

namespace internal {
// The sketch's file name, stored once per translation unit (not once per
// assertion, which would cost flash on the Nano).
static const char kFileName[] PROGMEM = __BASE_FILE__;
}  // namespace internal

inline void Test::failStart(uint16_t line) {
  if (mStatus == kRunning) mStatus = kFailed;
  // Print the base name; arduino-cli compiles Name.ino as Name.ino.cpp.
  const char* name = internal::kFileName;
  size_t n = 0;
  for (size_t i = 0; pgm_read_byte(internal::kFileName + i) != 0; ++i) {
    if (pgm_read_byte(internal::kFileName + i) == '/') name = internal::kFileName + i + 1;
  }
  while (pgm_read_byte(name + n) != 0) ++n;
  if (n > 8 && internal::compareFlash(name + n - 8, PSTR(".ino.cpp")) == 0) n -= 4;
  for (size_t i = 0; i < n; ++i) Serial.print(static_cast<char>(pgm_read_byte(name + i)));
  Serial.print(':');
  Serial.print(line);
  Serial.print(F(": Assertion failed: "));
}

}  // namespace aunit

// ---- test definitions ----------------------------------------------------

#define AUNIT_STANDIN_DEFINE(BASE, CLASS, NAME)                            \
  class CLASS : public BASE {                                              \
   public:                                                                 \
    CLASS() { init(F(NAME)); }                                             \
   protected:                                                              \
    void once() override;                                                  \
  } CLASS##_instance;                                                      \
  void CLASS::once()

#define AUNIT_STANDIN_TEST1(name) \
  AUNIT_STANDIN_DEFINE(aunit::TestOnce, test_##name, #name)
#define AUNIT_STANDIN_TEST2(suite, name) \
  AUNIT_STANDIN_DEFINE(aunit::TestOnce, suite##_##name, #suite "_" #name)
#define AUNIT_STANDIN_PICK(_1, _2, chosen, ...) chosen

#define test(...) \
  AUNIT_STANDIN_PICK(__VA_ARGS__, AUNIT_STANDIN_TEST2, AUNIT_STANDIN_TEST1, _)(__VA_ARGS__)
#define testF(fixture, name) \
  AUNIT_STANDIN_DEFINE(fixture, fixture##_##name, #fixture "_" #name)

// ---- assertions ------------------------------------------------------------

#define AUNIT_STANDIN_CHECK(call) \
  do { if (!(call)) return; } while (false)

#define assertEqual(a, b) \
  AUNIT_STANDIN_CHECK(this->aunitEquality(__LINE__, aunit::internal::kEq, (a), (b)))
#define assertNotEqual(a, b) \
  AUNIT_STANDIN_CHECK(this->aunitEquality(__LINE__, aunit::internal::kNe, (a), (b)))
#define assertLess(a, b) \
  AUNIT_STANDIN_CHECK(this->aunitOrder(__LINE__, aunit::internal::kLt, (a), (b)))
#define assertMore(a, b) \
  AUNIT_STANDIN_CHECK(this->aunitOrder(__LINE__, aunit::internal::kGt, (a), (b)))
#define assertLessOrEqual(a, b) \
  AUNIT_STANDIN_CHECK(this->aunitOrder(__LINE__, aunit::internal::kLe, (a), (b)))
#define assertMoreOrEqual(a, b) \
  AUNIT_STANDIN_CHECK(this->aunitOrder(__LINE__, aunit::internal::kGe, (a), (b)))
#define assertTrue(c) AUNIT_STANDIN_CHECK(this->aunitTruth(__LINE__, (c), true))
#define assertFalse(c) AUNIT_STANDIN_CHECK(this->aunitTruth(__LINE__, (c), false))
#define assertNear(a, b, error) \
  AUNIT_STANDIN_CHECK(this->aunitNear(__LINE__, (a), (b), (error)))

#endif  // TINYPARTICLE_AUNIT_STANDIN_H
