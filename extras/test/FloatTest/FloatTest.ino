// Float, the floating-point scalar: the same interface as Fixed, and the
// same defined results where plain float would give inf or NaN (x / 0,
// sqrt of a negative number), with the same flags. Its trigonometry is the
// C library's, so it must agree with it to float precision.
#include <AUnit.h>
#include <TinyParticle.h>
#include <float.h>
#include <math.h>

using aunit::TestRunner;

static_assert(Float(0.5).toFloat() == 0.5f, "constexpr");

test(arithmeticAndConversions) {
  const Float a(1.5), b(-0.25);
  assertEqual((a + b).toFloat(), 1.25f);
  assertEqual((a - b).toFloat(), 1.75f);
  assertEqual((a * b).toFloat(), -0.375f);
  assertEqual((a / b).toFloat(), -6.0f);
  assertEqual((-a).toFloat(), -1.5f);
  Float c(2);
  c += a;
  c *= Float(2);
  c -= Float(1);
  c /= Float(3);
  assertEqual(c.toFloat(), 2.0f);
  assertTrue(b < a && b <= a && a > b && a >= b && a != b && !(a == b));
  // toInt rounds toward zero and saturates; NaN gives 0.
  assertEqual(Float(2.75).toInt(), (int32_t) 2);
  assertEqual(Float(-2.75).toInt(), (int32_t) -2);
  assertEqual(Float(1e20).toInt(), (int32_t) INT32_MAX);
  assertEqual(Float(-1e20).toInt(), (int32_t) INT32_MIN);
  assertEqual(Float(NAN).toInt(), (int32_t) 0);
  assertTrue(Float(3) == Float(3L) && Float(3) == Float(3u) &&
             Float(3) == Float(3ul) && Float(3) == Float(3.0));
}

test(constantsAndHelpers) {
  assertEqual(Float::largest().toFloat(), FLT_MAX);
  assertEqual(Float::lowest().toFloat(), -FLT_MAX);
  assertEqual(Float::epsilon().toFloat(), FLT_MIN);
  assertNear(Float::pi().toFloat(), 3.14159265f, 1e-6f);
  assertEqual(fabs(Float(-2)).toFloat(), 2.0f);
  assertEqual(fmin(Float(1), Float(2)).toFloat(), 1.0f);
  assertEqual(fmax(Float(1), Float(2)).toFloat(), 2.0f);
  assertEqual(clamp(Float(5), Float(-1), Float(1)).toFloat(), 1.0f);
  assertEqual(clamp(Float(-5), Float(-1), Float(1)).toFloat(), -1.0f);
  assertEqual(clamp(Float(0.5), Float(-1), Float(1)).toFloat(), 0.5f);
}

test(divisionByZeroAndNegativeSqrt) {
  clearMathErrors();
  assertEqual((Float(2) / Float(0)).toFloat(), FLT_MAX);
  assertEqual(mathErrors(), (uint8_t) MathError::kDivideByZero);
  assertEqual((Float(-2) / Float(0)).toFloat(), -FLT_MAX);
  assertEqual((Float(0) / Float(0)).toFloat(), 0.0f);
  clearMathErrors();
  assertEqual(sqrt(Float(-4)).toFloat(), 0.0f);
  assertEqual(mathErrors(), (uint8_t) MathError::kNegativeSqrt);
  clearMathErrors();
  assertEqual(sqrt(Float(6.25)).toFloat(), 2.5f);
  assertEqual(mathErrors(), (uint8_t) 0);
}

test(trigonometryFollowsTheCLibrary) {
  // Radian functions are the C library's own.
  assertEqual(sin(Float(0.7)).toFloat(), sinf(0.7f));
  assertEqual(cos(Float(0.7)).toFloat(), cosf(0.7f));
  assertEqual(atan2(Float(-1), Float(2)).toFloat(), atan2f(-1.0f, 2.0f));
  // Binary angles: within 6e-7. The angle a 2 pi / 65536 (|angle| <= pi)
  // is rounded twice in float, 2 * 2^-24 * pi = 3.7e-7 at worst, sinf and
  // cosf and the reference's conversion to float add a step (6e-8) each.
  float worst = 0;
  for (uint32_t a = 0; a < 65536ul; a += 255) {
    const double angle = double(a) * 6.283185307179586 / 65536.0;
    const float es = fabsf(sinTurns<Float>(uint16_t(a)).toFloat() - float(sin(angle)));
    const float ec = fabsf(cosTurns<Float>(uint16_t(a)).toFloat() - float(cos(angle)));
    if (es > worst) worst = es;
    if (ec > worst) worst = ec;
  }
  assertLess(worst, 6e-7f);
  assertEqual(sinTurns<Float>(16384).toFloat(), 1.0f);
  assertEqual(cosTurns<Float>(0).toFloat(), 1.0f);
}

test(radiansToTurnsWraps) {
  assertEqual(radiansToTurns(Float(0)), (uint16_t) 0);
  assertEqual(radiansToTurns(Float::pi()), (uint16_t) 32768);
  assertEqual(radiansToTurns(-Float::pi() / Float(2)), (uint16_t) 49152);
  assertEqual(radiansToTurns(Float(2) * Float::pi()), (uint16_t) 0);
  // 100 rad = 15.915494 turns: 0.915494 * 65536 = 59997.8.
  assertEqual(radiansToTurns(Float(100)), (uint16_t) 59998);
  assertEqual(radiansToTurns(Float(-100)), (uint16_t) (65536u - 59998u));
  assertEqual(radiansToTurns(Float(INFINITY)), (uint16_t) 0);
  assertEqual(radiansToTurns(Float(NAN)), (uint16_t) 0);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
