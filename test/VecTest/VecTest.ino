// Vec2 and Vec3 over Q16_16 and Float: the arithmetic, dot and cross
// products, and the corner cases of magnitude() and normalize(): a zero
// vector stays zero and reports it, a vector of one step normalizes, the
// longest vectors do not overflow inside. (Random vectors of every length:
// VecLengthTest; Q24_8 and Q8_8: VecFormatsTest.)
#include <AUnit.h>
#include <TinyParticle.h>
#include <math.h>

using aunit::TestRunner;

template <typename S>
struct Arithmetic {
  static bool vec2() {
    Vec2<S> a(S(1), S(-2)), b(S(0.5), S(3));
    bool ok = a + b == Vec2<S>(S(1.5), S(1)) && a - b == Vec2<S>(S(0.5), S(-5));
    ok = ok && a * S(2) == Vec2<S>(S(2), S(-4)) && S(2) * a == a * S(2);
    ok = ok && -a == Vec2<S>(S(-1), S(2));
    ok = ok && dot(a, b) == S(-5.5) && cross(a, b) == S(4);  // 1*3 - (-2)*0.5
    ok = ok && a.componentProduct(b) == Vec2<S>(S(0.5), S(-6));
    Vec2<S> c = a;
    c.addScaled(b, S(2));  // a + 2b
    ok = ok && c == Vec2<S>(S(2), S(4));
    c += a;
    c -= b;
    c *= S(0.5);
    ok = ok && c == Vec2<S>(S(1.25), S(-0.5));
    ok = ok && a[0] == S(1) && a[1] == S(-2);
    c[1] = S(7);
    ok = ok && c.y == S(7) && a.magnitudeSquared() == S(5);
    ok = ok && Vec2<S>().isZero() && !a.isZero() && a != b;
    return ok;
  }
  static bool vec3() {
    Vec3<S> a(S(1), S(2), S(3)), b(S(-1), S(0.5), S(2));
    bool ok = a + b == Vec3<S>(S(0), S(2.5), S(5));
    ok = ok && a - b == Vec3<S>(S(2), S(1.5), S(1));
    ok = ok && dot(a, b) == S(6);  // -1 + 1 + 6
    // a x b = (2*2 - 3*0.5, 3*(-1) - 1*2, 1*0.5 - 2*(-1))
    ok = ok && cross(a, b) == Vec3<S>(S(2.5), S(-5), S(2.5));
    ok = ok && dot(cross(a, b), a) == S(0) && dot(cross(a, b), b) == S(0);
    Vec3<S> c = a;
    c.addScaled(b, S(-1));
    ok = ok && c == a - b && a.componentProduct(b) == Vec3<S>(S(-1), S(1), S(6));
    ok = ok && a[2] == S(3) && a.magnitudeSquared() == S(14) && !a.isZero();
    c *= S(2);
    ok = ok && c == Vec3<S>(S(4), S(3), S(2));
    return ok;
  }
};

test(arithmeticForQ16_16AndFloat) {
  assertTrue(Arithmetic<Q16_16>::vec2());
  assertTrue(Arithmetic<Q16_16>::vec3());
  assertTrue(Arithmetic<Float>::vec2());
  assertTrue(Arithmetic<Float>::vec3());
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
