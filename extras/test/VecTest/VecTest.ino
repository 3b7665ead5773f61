// Vec2 and Vec3 over Q16_16 and Float: the arithmetic, dot and cross
// products, and the corner cases of magnitude() and normalize(): a zero
// vector stays zero and reports it, a vector of one step normalizes, the
// longest vectors do not overflow inside. (Random vectors of every length:
// VecLengthTest; Q24_8 and Q8_8: VecFormatsTest.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <TinyParticle/Testing/VecChecks.hpp>
#include <math.h>

using aunit::TestRunner;
// vec2() and vec3() check every operation on small values whose results
// are exact (src/TinyParticle/Testing/VecChecks.hpp).
using tinyparticle::testing::VecArithmetic;

test(arithmeticForQ16_16AndFloat) {
  assertTrue(VecArithmetic<Q16_16>::vec2());
  assertTrue(VecArithmetic<Q16_16>::vec3());
  assertTrue(VecArithmetic<Float>::vec2());
  assertTrue(VecArithmetic<Float>::vec3());
}

test(zeroTinyAndHugeVectors) {
  typedef Q16_16 T;
  const T e = T::epsilon();
  clearMathErrors();
  // Zero stays zero and reports it.
  Vec2<T> zero;
  assertFalse(zero.normalize());
  assertTrue(zero.isZero());
  assertTrue(zero.magnitudeAndNormalize() == T());
  Vec3<T> zero3;
  assertFalse(zero3.normalize());
  assertTrue(zero3.isZero() && zero3.magnitude() == T());
  // One step is a vector like any other.
  Vec2<T> tiny(e, T());
  assertTrue(tiny.magnitude() == e);
  assertTrue(tiny.normalize());
  assertTrue(tiny == Vec2<T>(T(1), T()));
  Vec3<T> tiny3(-e, e, -e);  // length sqrt(3) steps: rounds to 2
  assertTrue(tiny3.magnitude() == T::fromRaw(2));
  assertTrue(tiny3.normalize());
  assertNear(tiny3.x.toFloat(), -0.57735f, 0.0001f);
  // The largest vectors: no overflow inside, the result saturates.
  Vec2<T> big(T::largest(), T::largest());
  assertEqual(mathErrors(), (uint8_t) 0);
  assertTrue(big.magnitude() == T::largest());
  assertEqual(mathErrors(), (uint8_t) MathError::kOverflow);
  clearMathErrors();
  assertTrue(big.normalize());
  assertNear(big.x.toFloat(), 0.70711f, 0.0001f);
  Vec3<T> low(T::lowest(), T(), T());
  assertTrue(low.normalize());
  assertTrue(low == Vec3<T>(T(-1), T(), T()));
  Vec2<T> below(T(20000), T(-15000));  // 25000: fits
  assertTrue(below.magnitude() == T(25000));
  assertEqual(mathErrors(), (uint8_t) 0);
}

test(floatVectors) {
  Vec3<Float> zero;
  assertFalse(zero.normalize());
  Vec2<Float> v(Float(3), Float(-4));
  assertEqual(v.magnitude().toFloat(), 5.0f);
  assertEqual(v.magnitudeAndNormalize().toFloat(), 5.0f);
  assertNear(v.x.toFloat(), 0.6f, 1e-7f);
  // Squares that underflow: still normalized.
  Vec2<Float> tiny(Float(3e-30), Float(-4e-30));
  assertTrue(tiny.normalize());
  assertNear(tiny.x.toFloat(), 0.6f, 1e-6f);
  assertNear(tiny.y.toFloat(), -0.8f, 1e-6f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
