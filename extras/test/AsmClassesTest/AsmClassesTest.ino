// The hand-written AVR routines equal the portable reference bit for bit,
// flags included, on a subset of the classes of input that the full proof
// (`make verify-asm`) enumerates: every class each routine's code tells
// apart is hit at least once (counted here, branch by branch), with the
// +-3 neighbours of each table boundary, plus some random inputs. The
// shared code is src/TinyParticle/Testing/AsmClasses.hpp.
// On the Nano: fast (assembly) == reference, result and flags, exactly.
// On the host (no assembly there, so the first check is trivial): the
// reference has its exact property: correctly rounded
// product, quotient and root (exact integer inequalities), saturation and
// flags; atan2 within 6 units of 2^-16 rad of the exact angle, sin and
// cos within 3 units of 2^-16.
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/AsmClasses.hpp>

using aunit::TestRunner;
using namespace tinyparticle::testing;

#if defined(EPOXY_DUINO)
const uint16_t kRandomInputs = 20000;
typedef uint32_t Count;
const bool kProperty = true;
#else
const uint16_t kRandomInputs = 150;
typedef uint8_t Count;  // saturating: only "hit at least once" matters
// The reference's properties are checked on the host, on the same inputs
// (flash: the exact checks need 64-bit arithmetic and float atan2).
const bool kProperty = false;
#endif

static ClassCounts<Count> gCounts(0);

struct SubsetVisit {
  uint8_t routine;
  uint32_t inputs, failures;
  void operator()(int32_t a, int32_t b) {
    ++inputs;
    classify(routine, a, b, gCounts);
    const AsmOutcome o = runAsmRoutine(routine, a, b, kProperty);
    if (!o.same() || !o.property) {
      if (++failures <= 5) {
        Serial.print(F("routine "));
        Serial.print(routine);
        Serial.print(F(" a="));
        Serial.print(a);
        Serial.print(F(" b="));
        Serial.print(b);
        Serial.print(F(" fast "));
        Serial.print(o.fast);
        Serial.print('/');
        Serial.print(o.fastFlags);
        Serial.print(F(" reference "));
        Serial.print(o.reference);
        Serial.print('/');
        Serial.print(o.referenceFlags);
        Serial.println(o.property ? F("") : F(" (reference property fails)"));
      }
    }
  }
};

// Runs the subset of one routine; returns the failures (mismatches, bad
// reference results, classes never hit, unreachable classes hit).
static uint32_t checkRoutine(uint8_t routine, uint32_t seed) {
  const uint32_t start = millis();
  gCounts.reset(routine);
  SubsetVisit visit = {routine, 0, 0};
  enumerateStructured(routine, false, visit);
  AsmRandom random(seed);
  for (uint16_t i = 0; i < kRandomInputs; ++i) {
    int32_t a, b;
    randomInput(routine, random, &a, &b);
    visit(a, b);
  }
  uint16_t missed = 0, covered = 0;
  for (uint8_t f = 0; f < familyCount(routine); ++f) {
    for (uint16_t v = 0; v < familySize(routine, f); ++v) {
      const bool hit = gCounts.count(f, v) != 0;
      const bool unreachable = isUnreachable(routine, f, v);
      if (hit) ++covered;
      if (hit == unreachable && !(routineIsExhaustive(routine) && !hit)) {
        ++missed;
        Serial.print(F("routine "));
        Serial.print(routine);
        Serial.print(F(" family "));
        Serial.print(f);
        Serial.print(F(" value "));
        Serial.print(v);
        Serial.println(hit ? F(": an unreachable class was hit")
                           : F(": class never hit"));
      }
    }
  }
  Serial.print(F("routine "));
  Serial.print(routine);
  Serial.print(F(": "));
  Serial.print(visit.inputs);
  Serial.print(F(" inputs, "));
  Serial.print(covered);
  Serial.print(F(" classes hit, "));
  Serial.print(visit.failures);
  Serial.print(F(" failures, "));
  Serial.print(millis() - start);
  Serial.println(F(" ms"));
  return visit.failures + missed;
}

test(multiplyQ16) { assertEqual(checkRoutine(kAsmMulQ16, 11u), (uint32_t) 0); }
test(divideQ16) { assertEqual(checkRoutine(kAsmDivQ16, 12u), (uint32_t) 0); }
test(squareRootQ16) { assertEqual(checkRoutine(kAsmSqrtQ16, 13u), (uint32_t) 0); }
test(multiplyQ24) { assertEqual(checkRoutine(kAsmMulQ24, 14u), (uint32_t) 0); }
test(divideQ24) { assertEqual(checkRoutine(kAsmDivQ24, 15u), (uint32_t) 0); }
test(squareRootQ24) { assertEqual(checkRoutine(kAsmSqrtQ24, 16u), (uint32_t) 0); }
test(divideQ8) { assertEqual(checkRoutine(kAsmDivQ8, 17u), (uint32_t) 0); }
test(squareRootQ8) { assertEqual(checkRoutine(kAsmSqrtQ8, 18u), (uint32_t) 0); }
test(atan2Core) { assertEqual(checkRoutine(kAsmAtan2, 19u), (uint32_t) 0); }
test(addQ32) { assertEqual(checkRoutine(kAsmAddQ32, 20u), (uint32_t) 0); }
test(subtractQ32) { assertEqual(checkRoutine(kAsmSubQ32, 21u), (uint32_t) 0); }
test(addQ16) { assertEqual(checkRoutine(kAsmAddQ16, 22u), (uint32_t) 0); }
test(subtractQ16) { assertEqual(checkRoutine(kAsmSubQ16, 23u), (uint32_t) 0); }
test(sinCosQ16) { assertEqual(checkRoutine(kAsmSinQ16, 24u), (uint32_t) 0); }

// The inputs the square root once got wrong (issue 8), by value.
test(onceWrongSquareRoots) {
  assertEqual(Q16_16::squareRoot(66561), (int32_t) 66047);
  assertEqual(Q16_16::squareRoot(66562), (int32_t) 66047);
  assertEqual(Q16_16::squareRoot(266247), (int32_t) 132094);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);
}

void loop() { TestRunner::run(); }
