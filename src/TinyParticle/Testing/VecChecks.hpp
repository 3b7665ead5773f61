// Test support for the vector sketches: the arithmetic every scalar must get
// exactly right (VecTest: Q16.16 and Float; VecFormatsTest: Q24.8 and Q8.8),
// and the accuracy of magnitude() and normalize() for random fixed-point
// vectors of every length (VecLengthTest: Q16.16; VecFormatsTest: Q24.8 and
// Q8.8). The sketches are split by format to fit the Nano's flash; the
// checks live here once.
//
// Not included by TinyParticle.h: include
// <TinyParticle/Testing/VecChecks.hpp> after it.
#pragma once

#include <math.h>
#include <stdint.h>

#include "../../TinyParticle.hpp"
#include "MathTestSupport.hpp"

namespace tinyparticle {
namespace testing {

// Small values whose every result is exact in each scalar: each function
// returns true when all of them came out right.
template <typename S>
struct VecArithmetic {
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

// Lengths of random vectors of the fixed-point type T, measured against
// Exact (double on the host, float on the Nano). `vectors` random vectors
// are drawn from `random` per call; components have random bit lengths up
// to maxBits, all lengths equally often.
template <typename T, typename Exact>
struct VecLengths {
  typedef typename T::Raw Raw;

  static Exact value(T x) { return exactValue<Exact>(x); }

  static T randomComponent(XorShift32& random, uint8_t maxBits) {
    return T::fromRaw(randomRaw<Raw>(random, maxBits));
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
  static Exact magnitudeError(XorShift32& random, uint32_t vectors,
                              uint8_t maxBits) {
    Exact worst = 0;
    const Exact step = Exact(1) / Exact(int32_t(1) << T::kFracBits);
    const Exact relative = relativeError();
    for (uint32_t i = 0; i < vectors; ++i) {
      const uint8_t bits = uint8_t(random.next() % (maxBits + 1));
      Vec3<T> v(randomComponent(random, bits), randomComponent(random, bits),
                randomComponent(random, bits));
      const Exact x = value(v.x), y = value(v.y), z = value(v.z);
      // ::sqrt, ::fabs: the C functions on Exact (tinyparticle's take
      // scalars).
      const Exact exact = ::sqrt(x * x + y * y + z * z);
      // Near the top the result may saturate (VecTest checks that).
      if (exact * (1 + relative) + 2 * step >= value(T::largest())) continue;
      clearMathErrors();
      const T m = v.magnitude();
      if (mathErrors() != 0) return Exact(1e9);
      Exact e = ::fabs(value(m) - exact) - exact * relative;
      e /= step;
      if (e > worst) worst = e;
      // 2D as well.
      Vec2<T> w(v.x, v.y);
      const Exact exact2 = ::sqrt(x * x + y * y);
      e = (::fabs(value(w.magnitude()) - exact2) - exact2 * relative) / step;
      if (e > worst) worst = e;
    }
    return worst;
  }

  // Worst | |normalize(v)| - 1 | in steps, for random vectors of every
  // length, and whether any raised a flag or pointed elsewhere (the
  // normalized vector must be parallel: cross product with v tiny).
  // Expected: about 2.1 steps (length error 1.3 relative to a length >= 1,
  // plus each quotient's rounding); allowed: 4.
  static Exact unitError(XorShift32& random, uint32_t vectors, uint8_t maxBits,
                         bool* bad) {
    Exact worst = 0;
    *bad = false;
    const Exact step = Exact(1) / Exact(int32_t(1) << T::kFracBits);
    for (uint32_t i = 0; i < vectors; ++i) {
      const uint8_t bits = uint8_t(1 + random.next() % maxBits);
      Vec3<T> v(randomComponent(random, bits), randomComponent(random, bits),
                randomComponent(random, bits));
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
      const Exact e = ::fabs(::sqrt(ux * ux + uy * uy + uz * uz) - 1) / step;
      if (e > worst) worst = e;
      // Parallel: |u x (v / |v|)| within a few steps.
      const Exact ox = value(original.x), oy = value(original.y),
                  oz = value(original.z);
      const Exact n = ::sqrt(ox * ox + oy * oy + oz * oz);
      const Exact cx = uy * oz - uz * oy, cy = uz * ox - ux * oz,
                  cz = ux * oy - uy * ox;
      if (::sqrt(cx * cx + cy * cy + cz * cz) / n > 6 * step) *bad = true;
    }
    return worst;
  }
};

}  // namespace testing
}  // namespace tinyparticle
