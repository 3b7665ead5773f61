// The host half of `make verify-asm`: enumerates exactly the inputs of one
// shard (the same code as the Nano's VerifyAsm sketch), counts the classes
// they hit, checks the reference against its exact properties, and prints
//   INPUTS <count> <checksum>
//   PROPERTY <failures>   (then up to 5 "BADREF a b r flags" lines)
//   CLASS <family> <value> <count> <unreachable 0/1>   (one per class)
// Usage: VerifyHost <routine> <kind> <first> <last>   (see AsmShard)
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <TinyParticle.hpp>
#include <TinyParticle/Testing/AsmClasses.hpp>

using namespace tinyparticle;
using namespace tinyparticle::testing;

namespace {

ClassCounts<uint32_t>* gCounts;

struct HostVisit {
  uint8_t routine;
  uint32_t count, checksum, propertyFailures;
  void operator()(int32_t a, int32_t b) {
    ++count;
    checksum = mixInput(checksum, a, b);
    classify(routine, a, b, *gCounts);
    const AsmOutcome o = runAsmRoutine(routine, a, b, true);
    if (!o.property || !o.same()) {
      if (++propertyFailures <= 5) {
        std::printf("BADREF %ld %ld %ld %u\n", long(a), long(b),
                    long(o.reference), unsigned(o.referenceFlags));
      }
    }
  }
};

// Coverage of the subset (extras/test/AsmClassesTest) only.
struct CountOnly {
  uint8_t routine;
  void operator()(int32_t a, int32_t b) { classify(routine, a, b, *gCounts); }
};

// Finds, among `count` random inputs, one for each class that the subset
// misses, and prints it as a line of the witness table.
int findWitnesses(uint8_t routine, uint32_t count, uint32_t seed) {
  static ClassCounts<uint32_t> subset(routine);
  gCounts = &subset;
  CountOnly visit = {routine};
  enumerateStructured(routine, false, visit);
  AsmRandom random(seed);
  for (uint32_t i = 0; i < count; ++i) {
    int32_t a, b;
    randomInput(routine, random, &a, &b);
    static ClassCounts<uint32_t> one(routine);
    one.reset(routine);
    classify(routine, a, b, one);
    for (uint8_t f = 0; f < familyCount(routine); ++f) {
      for (uint16_t v = 0; v < familySize(routine, f); ++v) {
        if (one.count(f, v) != 0 && subset.count(f, v) == 0) {
          std::printf("    {%u, %ld, %ld},  // family %u value %u\n",
                      unsigned(routine), long(a), long(b), unsigned(f),
                      unsigned(v));
          classify(routine, a, b, subset);
        }
      }
    }
  }
  for (uint8_t f = 0; f < familyCount(routine); ++f) {
    for (uint16_t v = 0; v < familySize(routine, f); ++v) {
      if (subset.count(f, v) == 0) {
        std::printf("// missed: family %u value %u%s\n", unsigned(f),
                    unsigned(v),
                    isUnreachable(routine, f, v) ? " (unreachable)" : "");
      }
    }
  }
  return 0;
}

// Facts about the tables that the classification relies on, checked
// over every case: the interpolated reciprocal of the divide is within
// [-3, +1] of exact for every d1; the first root byte a (kSqrt, then one
// step) is floor(sqrt(top word)) for every top word.
int checkTables() {
  int failures = 0;
  int32_t lowest = 0, highest = 0;
  for (uint32_t d1 = 0x8000; d1 <= 0xffff; ++d1) {
    const uint8_t i = uint8_t((d1 >> 8) & 0x7f);
    const uint16_t e0 = recipEntry(i), e1 = recipEntry(uint8_t(i + 1));
    const uint16_t v0 = uint16_t(
        e0 - uint16_t((uint32_t(uint16_t(e0 - e1)) * uint8_t(d1)) >> 8));
    const int32_t fix = int32_t(0xffffffffu / d1 - 0x10000u) - int32_t(v0);
    if (fix < lowest) lowest = fix;
    if (fix > highest) highest = fix;
  }
  std::printf("TABLE recip-fix %ld %ld\n", long(lowest), long(highest));
  if (lowest < -3 || highest > 1) ++failures;
  for (uint32_t word = 0x4000; word <= 0xffff; ++word) {
    uint32_t a = platform::readFlashU8(
        &detail::TrigTables<void>::kSqrt[(word >> 8) - 64]);
    if (a != 255 && (a + 1) * (a + 1) <= word) ++a;
    if (a * a > word || (a + 1) * (a + 1) <= word) ++failures;
  }
  std::printf("TABLE sqrt-first-byte %s\n", failures ? "FAIL" : "ok");
  // The divide's reciprocal adjustments for d0 (after v is exact for d1):
  // which (first stage, second stage) decrement pairs occur, over every
  // normalized divisor D with d0 != 0 (2^31 - 2^15 of them).
  uint32_t seen[9] = {0};
  for (uint32_t d1 = 0x8000; d1 <= 0xffff; ++d1) {
    const uint16_t exact = uint16_t(0xffffffffu / d1 - 0x10000u);
    const uint16_t p0 = uint16_t(d1 * exact);
    for (uint32_t d0 = 1; d0 <= 0xffff; ++d0) {
      uint16_t v = exact, p = uint16_t(p0 + d0);
      uint8_t dec1 = 0, dec2 = 0;
      if (p < uint16_t(d0)) {
        v = uint16_t(v - 1);
        dec1 = 1;
        if (p >= d1) {
          v = uint16_t(v - 1);
          p = uint16_t(p - d1);
          dec1 = 2;
        }
        p = uint16_t(p - d1);
      }
      const uint32_t t = uint32_t(v) * d0;
      const uint16_t p2 = uint16_t(p + uint16_t(t >> 16));
      if (p2 < p) {
        dec2 = 1;
        if (((uint32_t(p2) << 16) | uint16_t(t)) >= ((d1 << 16) | d0)) dec2 = 2;
      }
      ++seen[dec1 * 3 + dec2];
    }
  }
  for (uint8_t k = 0; k < 9; ++k) {
    std::printf("TABLE divide-d0-steps %u %u %lu\n", unsigned(k / 3),
                unsigned(k % 3), (unsigned long)seen[k]);
  }
  return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && argv[1][0] == 't') return checkTables();
  if (argc == 5 && argv[1][0] == 'w') {
    return findWitnesses(uint8_t(std::strtoul(argv[2], 0, 0)),
                         uint32_t(std::strtoul(argv[3], 0, 0)),
                         uint32_t(std::strtoul(argv[4], 0, 0)));
  }
  if (argc != 5) {
    std::fprintf(stderr, "usage: VerifyHost routine kind first last\n");
    return 2;
  }
  AsmShard shard;
  shard.routine = uint8_t(std::strtoul(argv[1], 0, 0));
  shard.kind = uint8_t(std::strtoul(argv[2], 0, 0));
  shard.first = uint32_t(std::strtoul(argv[3], 0, 0));
  shard.last = uint32_t(std::strtoul(argv[4], 0, 0));
  static ClassCounts<uint32_t> counts(shard.routine);
  gCounts = &counts;
  HostVisit visit = {shard.routine, 0, 2166136261u, 0};
  forEachShardInput(shard, visit);
  std::printf("INPUTS %lu %lu\n", (unsigned long)visit.count,
              (unsigned long)visit.checksum);
  std::printf("PROPERTY %lu\n", (unsigned long)visit.propertyFailures);
  for (uint8_t f = 0; f < familyCount(shard.routine); ++f) {
    for (uint16_t v = 0; v < familySize(shard.routine, f); ++v) {
      std::printf("CLASS %u %u %lu %d\n", unsigned(f), unsigned(v),
                  (unsigned long)counts.count(f, v),
                  isUnreachable(shard.routine, f, v) ? 1 : 0);
    }
  }
  return 0;
}
