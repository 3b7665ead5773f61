// The Nano half of `make verify-asm` (extras/scripts/verify-asm): compares
// the hand-written AVR routines with the portable reference, result and
// math flags, on one shard of inputs chosen at compile time:
//   -DVERIFY_ROUTINE=n  a tinyparticle::testing::AsmRoutine
//   -DVERIFY_KIND=k     0 structured (part VERIFY_FIRST of VERIFY_LAST),
//                       1 every argument in [VERIFY_FIRST, VERIFY_LAST),
//                       2 VERIFY_FIRST random inputs from seed VERIFY_LAST
// It prints up to 5 "MISMATCH a b fast fastFlags reference referenceFlags"
// lines, then "DONE <inputs> <checksum> <mismatches> <milliseconds>", and
// sleeps (simavr then exits). The checksum of the inputs lets the host
// check that it classified the very same inputs.
#include <TinyParticle.h>
#include <TinyParticle/Testing/AsmClasses.hpp>
#include <avr/interrupt.h>
#include <avr/sleep.h>

#ifndef VERIFY_ROUTINE
#define VERIFY_ROUTINE 0
#endif
#ifndef VERIFY_KIND
#define VERIFY_KIND 0
#endif
#ifndef VERIFY_FIRST
#define VERIFY_FIRST 0
#endif
#ifndef VERIFY_LAST
#define VERIFY_LAST 1
#endif

using namespace tinyparticle::testing;

struct TargetVisit {
  uint32_t count, checksum, mismatches;
  void operator()(int32_t a, int32_t b) {
    ++count;
    checksum = mixInput(checksum, a, b);
    const AsmOutcome o = runAsmRoutine(VERIFY_ROUTINE, a, b, false);
    if (!o.same() && ++mismatches <= 5) {
      Serial.print(F("MISMATCH "));
      Serial.print(a);
      Serial.print(' ');
      Serial.print(b);
      Serial.print(' ');
      Serial.print(o.fast);
      Serial.print(' ');
      Serial.print(o.fastFlags);
      Serial.print(' ');
      Serial.print(o.reference);
      Serial.print(' ');
      Serial.println(o.referenceFlags);
    }
  }
};

void setup() {
  Serial.begin(115200);
  Serial.println(F("VERIFY START"));
  const AsmShard shard = {VERIFY_ROUTINE, VERIFY_KIND, VERIFY_FIRST,
                          VERIFY_LAST};
  TargetVisit visit = {0, 2166136261ul, 0};
  const uint32_t start = millis();
  forEachShardInput(shard, visit);
  const uint32_t elapsed = millis() - start;
  Serial.print(F("DONE "));
  Serial.print(visit.count);
  Serial.print(' ');
  Serial.print(visit.checksum);
  Serial.print(' ');
  Serial.print(visit.mismatches);
  Serial.print(' ');
  Serial.println(elapsed);
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
}

void loop() {}
