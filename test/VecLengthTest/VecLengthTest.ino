// Q16_16 vectors of every length: magnitude() within 2 steps plus the
// relative error of scaling a long vector down (see relativeError()), for
// random 2D and 3D vectors whose components have any bit length;
// normalize() to unit length within 4 steps, parallel to the original,
// raising no flag; magnitudeAndNormalize() returns magnitude().
#include <AUnit.h>
#include <TinyParticle.h>
#include <math.h>

using aunit::TestRunner;

#if defined(EPOXY_DUINO)
const uint32_t kRandomVectors = 200000;
typedef double Exact;
#else
const uint32_t kRandomVectors = 600;
typedef float Exact;
#endif

static uint32_t gState = 521288629ul;
static uint32_t nextRandom() {
  uint32_t x = gState;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  return gState = x;
}

template <typename T>
struct Lengths {
  typedef typename T::Raw Raw;
  static Exact value(T x) {
    return Exact(x.raw()) / Exact(int32_t(1) << T::kFracBits);
  }
  // A component with a random bit length (all lengths equally often).
  static T randomComponent(uint8_t maxBits) {
    const uint8_t bits = uint8_t(nextRandom() % (maxBits + 1));
    const uint32_t m = bits == 0 ? 0 : nextRandom() >> (32 - bits);
    return T::fromRaw((nextRandom() & 1) ? Raw(-int32_t(m)) : Raw(m));
  }

  // The squared sum is formed with the largest component below 2^W steps,
  // W = (bits + F - 3) / 2 (Vec.hpp); a longer vector is scaled down to at
  // least 2^(W - 1) steps first, so its length carries a relative error of
  // about 1.3 / 2^(W - 1). Allowed: twice that.
  static Exact relativeError() {
    const uint8_t w = (T::kTotalBits + T::kFracBits - 3) / 2;
    return Exact(1) / Exact(int32_t(1) << (w - 2));
  }

  // Worst magnitude error in steps, beyond relativeError(), for random 3D
  // and 2D vectors of every length that fits the format. Expected: about
  // 1.3 steps (three squares rounded, the square root rounded); allowed: 2.
  static Exact magnitudeError(uint8_t maxBits) {
    Exact worst = 0;
    const Exact step = Exact(1) / Exact(int32_t(1) << T::kFracBits);
    const Exact relative = relativeError();
    for (uint32_t i = 0; i < kRandomVectors; ++i) {
      const uint8_t bits = uint8_t(nextRandom() % (maxBits + 1));
      Vec3<T> v(randomComponent(bits), randomComponent(bits),
                randomComponent(bits));
      const Exact x = value(v.x), y = value(v.y), z = value(v.z);
      const Exact exact = sqrt(x * x + y * y + z * z);
      // Near the top the result may saturate (VecTest checks that).
      if (exact * (1 + relative) + 2 * step >= value(T::largest())) continue;
      clearMathErrors();
      const T m = v.magnitude();
      if (mathErrors() != 0) return Exact(1e9);
      Exact e = fabs(value(m) - exact) - exact * relative;
      e /= step;
      if (e > worst) worst = e;
      // 2D as well.
      Vec2<T> w(v.x, v.y);
      const Exact exact2 = sqrt(x * x + y * y);
      e = (fabs(value(w.magnitude()) - exact2) - exact2 * relative) / step;
      if (e > worst) worst = e;
    }
    return worst;
  }

  // Worst | |normalize(v)| - 1 | in steps, for random vectors of every
  // length, and whether any raised a flag or pointed elsewhere (the
  // normalized vector must be parallel: cross product with v tiny).
  // Expected: about 2.1 steps (length error 1.3 relative to a length >= 1,
  // plus each quotient's rounding); allowed: 4.
  static Exact unitError(uint8_t maxBits, bool* bad) {
    Exact worst = 0;
    *bad = false;
    const Exact step = Exact(1) / Exact(int32_t(1) << T::kFracBits);
    for (uint32_t i = 0; i < kRandomVectors; ++i) {
      const uint8_t bits = uint8_t(1 + nextRandom() % maxBits);
      Vec3<T> v(randomComponent(bits), randomComponent(bits),
                randomComponent(bits));
      if (v.isZero()) continue;
      const Vec3<T> original = v;
      // magnitudeAndNormalize() returns magnitude(), with the same flag (a
      // length that does not fit saturates); normalize() raises nothing.
      clearMathErrors();
      const T m = v.magnitude();
      const uint8_t flags = mathErrors();
      clearMathErrors();
      Vec3<T> copy = v;
      const T returned = v.magnitudeAndNormalize();
      if (mathErrors() != flags || returned != m) *bad = true;
      clearMathErrors();
      if (!copy.normalize() || copy != v || mathErrors() != 0) *bad = true;
      const Exact ux = value(v.x), uy = value(v.y), uz = value(v.z);
      const Exact e = fabs(sqrt(ux * ux + uy * uy + uz * uz) - 1) / step;
      if (e > worst) worst = e;
      // Parallel: |u x (v / |v|)| within a few steps.
      const Exact ox = value(original.x), oy = value(original.y),
                  oz = value(original.z);
      const Exact n = sqrt(ox * ox + oy * oy + oz * oz);
      const Exact cx = uy * oz - uz * oy, cy = uz * ox - ux * oz,
                  cz = ux * oy - uy * ox;
      if (sqrt(cx * cx + cy * cy + cz * cz) / n > 6 * step) *bad = true;
    }
    return worst;
  }
};

test(q16_16MagnitudeOfAnyVector) {
  assertLess(Lengths<Q16_16>::magnitudeError(31), Exact(2));
}
test(q16_16NormalizeOfAnyVector) {
  bool bad;
  assertLess(Lengths<Q16_16>::unitError(31, &bad), Exact(4));
  assertFalse(bad);
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
