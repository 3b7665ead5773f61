// Silent failures of issue 13, in Q16.16 (StabilityFloatTest has the Float
// ones): conversions out of range, a stiff spring the scalar cannot hold,
// steps of dt <= 0 and results that must not depend on the platform
// (StabilityClearTest: World::clear()). (The constexpr side of the conversion rule is a compile
// check: extras/checks/fail/.)
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

typedef World<Q16_16, 2, 2, 2, 2, 2> W;
typedef W::Vec V;

// A double out of range saturates and raises MathError::kOverflow at run
// time; in range, nothing is raised. (volatile: a value the compiler cannot
// see, as from a sensor.)
test(ConversionOutOfRangeRaisesOverflow) {
  volatile double big = 1e5;
  volatile double fits = -32768.0;
  volatile long bigInt = 40000L;
  clearMathErrors();
  assertEqual(Q16_16(double(fits)).raw(), (int32_t) INT32_MIN);
  assertEqual(Q16_16(0.5).raw(), (int32_t) 32768);
  assertEqual(Q8_8(-128).raw(), (int16_t) INT16_MIN);
  assertEqual((int) mathErrors(), 0);
  assertEqual(Q16_16(double(big)).raw(), (int32_t) INT32_MAX);
  assertEqual((int) mathErrors(), (int) MathError::kOverflow);
  clearMathErrors();
  assertEqual(Q16_16(-double(big)).raw(), (int32_t) INT32_MIN);
  assertEqual((int) mathErrors(), (int) MathError::kOverflow);
  clearMathErrors();
  assertEqual(Q16_16(long(bigInt)).raw(), (int32_t) INT32_MAX);
  assertEqual((int) mathErrors(), (int) MathError::kOverflow);
  clearMathErrors();
  assertEqual(Q8_8(1000).raw(), (int16_t) INT16_MAX);  // a literal, at run time
  assertEqual((int) mathErrors(), (int) MathError::kOverflow);
  clearMathErrors();
}

// A constant folds to the same bits on every platform: the double is
// rounded to float first (AVR's double), then to the format. 12345.6789
// is the float 12345.6787109375, 809086400 / 2^16 exactly; through a 64-bit
// double it would be 809086412.
test(ConstantsSameOnEveryPlatform) {
  assertEqual(Q16_16(12345.6789).raw(), (int32_t) 809086400L);
  volatile double v = 12345.6789;
  assertEqual(Q16_16(double(v)).raw(), (int32_t) 809086400L);
  assertEqual(Q16_16(-0.15).raw(), (int32_t) -9830);
  assertEqual(Q24_8(2.5).raw(), (int32_t) 640);
}

// The stiff spring's gains are computed in float on every platform, so a
// fixed-point world gets the same bits everywhere: these are the Nano's
// (computed in double, the PC's position gain was -129470531, 5 units off).
test(StiffSpringGainsSameOnEveryPlatform) {
  W w;
  ParticleId p = w.addParticle(V(0.1, 0.0), Q16_16(1));
  ForceId f = w.addStiffSpring(p, V(), Q16_16(2000), Q16_16(5), Q16_16(1.0 / 256));
  assertTrue(f.isValid());
  const StiffSpringForce<Q16_16, 2>& s =
      *w.forceParams<StiffSpringForce<Q16_16, 2> >(f);
  assertEqual(s.positionGain.raw(), (int32_t) -129470536L);
  assertEqual(s.velocityGain.raw(), (int32_t) -324501L);
}

// k = 1e5 N/m does not fit Q16.16 (its conversion raises kOverflow), and
// 20000 N/m on 0.1 kg needs a position gain beyond 32767 at dt = 1/256 s:
// both are refused with kBadArgument instead of running a softer spring.
// A spring that fits is taken.
test(StiffSpringThatDoesNotFitIsRefused) {
  W w;
  ParticleId heavy = w.addParticle(V(0.1, 0.0), Q16_16(1));
  ParticleId light = w.addParticle(V(0.1, 0.0), Q16_16(0.1));
  clearMathErrors();
  ForceId f = w.addStiffSpring(heavy, V(), Q16_16(1e5), Q16_16(0), Q16_16(1.0 / 256));
  assertFalse(f.isValid());
  assertEqual((int) w.error(), (int) WorldError::kBadArgument);
  assertEqual((int) mathErrors(), (int) MathError::kOverflow);
  clearMathErrors();
  w.clearError();
  f = w.addStiffSpring(light, V(), Q16_16(20000), Q16_16(0), Q16_16(1.0 / 256));
  assertFalse(f.isValid());
  assertEqual((int) w.error(), (int) WorldError::kBadArgument);
  w.clearError();
  f = w.addStiffSpring(heavy, V(), Q16_16(20000), Q16_16(0), Q16_16(1.0 / 256));
  assertTrue(f.isValid());
  assertEqual((int) w.error(), 0);
  assertEqual((int) mathErrors(), 0);
}

// step(dt <= 0) does nothing and raises kBadArgument.
test(NonPositiveDtIsRefused) {
  W w;
  ParticleId p = w.addParticle(V(1.0, 2.0), Q16_16(1));
  w.addGravity();
  w.particle(p)->velocity = V(0.5, 0.0);
  w.step(Q16_16(-1.0 / 256));
  w.step(Q16_16(0));
  assertEqual((int) w.error(), (int) WorldError::kBadArgument);
  assertTrue(w.particle(p)->position == V(1.0, 2.0));
  assertTrue(w.particle(p)->velocity == V(0.5, 0.0));
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
