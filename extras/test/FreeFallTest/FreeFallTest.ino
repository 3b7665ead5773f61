// Forces without contacts: free fall against its closed form, gravity with
// a multiplier, applyForce acting for one step, and the custom force that
// the HapticLever uses for the user's push. The world's gravity
// (addGravity() without a particle) is a setting of the world, not a force
// slot: it works in a world with no force slot, whose particles keep no
// force accumulator; removeForce() of its id switches it off; a second
// addGravity() adds to it.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

// One world type per scalar (each type instantiates the engine again).
template <typename S>
struct Checks {
  typedef World<S, 2, 2, 3> W;
  // No force slot: particles without the accumulator.
  typedef World<S, 2, 1> Slotless;
  typedef typename W::Vec V;

  // Drops a particle from rest at y0 = 10 m for n steps of dt = 1/256 s
  // (exact in both scalars) under `times` calls of addGravity(), in a world
  // of type Wt. Returns y - y_exact, where y_exact is the closed form
  // y0 - a t^2 / 2 corrected by the integrator's known first order term:
  // semi-implicit Euler gives exactly
  // y_n = y0 - a dt^2 n (n + 1) / 2 = y0 - a t^2 / 2 - a dt t / 2
  // (a = times * g). `speedError` gets v - (-a t).
  template <class Wt>
  static float fallError(uint16_t n, uint8_t times, float* speedError) {
    Wt w;
    ParticleId p = w.addParticle(V(0.0, 10.0), S(1));
    for (uint8_t i = 0; i < times; ++i) w.addGravity();
    const S dt(1.0 / 256);
    for (uint16_t i = 0; i < n; ++i) w.step(dt);
    const float t = n / 256.0f;
    const float a = 9.81f * times;
    const float exact = 10.0f - a * t * t / 2 - a * (1.0f / 256) * t / 2;
    *speedError = w.particle(p)->velocity.y.toFloat() + a * t;
    return w.particle(p)->position.y.toFloat() - exact;
  }

  // Falls for 64 steps in a world without force slots, then removeForce()
  // of the gravity's id: the next 64 steps keep the velocity to the bit
  // (nothing else acts). Returns a bit mask of what held (all: 15).
  static uint8_t removeSwitchesOff() {
    Slotless w;
    ParticleId p = w.addParticle(V(0.0, 10.0), S(1));
    const ForceId gravity = w.addGravity();
    uint8_t ok = 0;
    if (gravity.isValid() && w.error() == 0) ok |= 1;
    for (uint8_t i = 0; i < 64; ++i) w.step(S(1.0 / 256));
    const V falling = w.particle(p)->velocity;
    if (w.removeForce(gravity) && w.uniformAcceleration() == V()) ok |= 2;
    for (uint8_t i = 0; i < 64; ++i) w.step(S(1.0 / 256));
    if (falling.y < S() && w.particle(p)->velocity == falling) ok |= 4;
    // Removed already: refused, as a stale handle.
    if (!w.removeForce(gravity) && (w.error() & WorldError::kStaleHandle)) {
      ok |= 8;
    }
    return ok;
  }

  // Velocity after one second under gravity * 0.5 on that particle only,
  // and (in `other`) the velocity of a particle without gravity.
  static float halfGravity(float* other) {
    W w;
    V start;
    ParticleId p = w.addParticle(start, S(1));
    ParticleId q = w.addParticle(start, S(1));
    w.addGravity(p, S(0.5));
    for (uint16_t i = 0; i < 256; ++i) w.step(S(1.0 / 256));
    *other = w.particle(q)->velocity.y.toFloat();
    return w.particle(p)->velocity.y.toFloat();
  }

  // F = 4 N on 2 kg, applied once before a step of 1/256 s: v = 2/256 m/s
  // (exact in both scalars); the next step adds nothing, since the
  // accumulator is cleared at the end of a step.
  static float applyOnce(float* second) {
    W w;
    V origin, force(4.0, 0.0);
    ParticleId p = w.addParticle(origin, S(2));
    w.applyForce(p, force);
    w.step(S(1.0 / 256));
    float first = w.particle(p)->velocity.x.toFloat();
    w.step(S(1.0 / 256));
    *second = w.particle(p)->velocity.x.toFloat();
    return first;
  }

  // A custom force read through a pointer: 0.25 N on 0.125 kg for 128
  // steps (a = 2 m/s^2), then the sketch changes it to -0.5 N for 64 more.
  // Returns the final velocity: 2 * 0.5 - 4 * 0.25 = 0 m/s.
  static float customForce(float* halfway) {
    W w;
    V origin, push(0.25, 0.0);
    ParticleId p = w.addParticle(origin, S(0.125));
    w.addCustomForce(p, &push);
    for (uint16_t i = 0; i < 128; ++i) w.step(S(1.0 / 256));
    *halfway = w.particle(p)->velocity.x.toFloat();
    push.x = S(-0.5);
    for (uint16_t i = 0; i < 64; ++i) w.step(S(1.0 / 256));
    return w.particle(p)->velocity.x.toFloat();
  }
};

// Rounding bound for the fall: each step rounds the velocity increment and
// the position increment by at most half a unit of the scalar's resolution
// u, so after n steps |dv| <= n u / 2 and
// |dy| <= u (n^2 dt / 2 + n) / 2. For Q16.16, u = 2^-16. For float, u is
// the spacing of floats near 10 m (2^-20) and near 10 m/s.
const float kUnitQ16 = 1.0f / 65536, kUnitFloat = 1.0f / 1048576;
float positionBound(float u, float n) { return u * (n * n / 256 / 2 + n) / 2; }
float speedBound(float u, float n) { return u * n / 2; }

test(FreeFall_Q16_16) {
  float speedError;
  const float error =
      Checks<Q16_16>::fallError<Checks<Q16_16>::W>(256, 1, &speedError);
  assertNear(error, 0.0f, positionBound(kUnitQ16, 256));
  assertNear(speedError, 0.0f, speedBound(kUnitQ16, 256));
}
test(FreeFall_Float) {
  float speedError;
  const float error =
      Checks<Float>::fallError<Checks<Float>::W>(256, 1, &speedError);
  assertNear(error, 0.0f, positionBound(kUnitFloat, 256));
  assertNear(speedError, 0.0f, speedBound(kUnitFloat, 256));
}

// The same fall and bound in a world without force slots (gravity is the
// world's, its particles keep no accumulator).
test(FreeFallWithoutForceSlot_Q16_16) {
  float speedError;
  const float error =
      Checks<Q16_16>::fallError<Checks<Q16_16>::Slotless>(256, 1, &speedError);
  assertNear(error, 0.0f, positionBound(kUnitQ16, 256));
  assertNear(speedError, 0.0f, speedBound(kUnitQ16, 256));
}
test(FreeFallWithoutForceSlot_Float) {
  float speedError;
  const float error =
      Checks<Float>::fallError<Checks<Float>::Slotless>(256, 1, &speedError);
  assertNear(error, 0.0f, positionBound(kUnitFloat, 256));
  assertNear(speedError, 0.0f, speedBound(kUnitFloat, 256));
}

// Two calls: 2 g, as two gravity slots summed before. The same bound
// (the fall takes a quarter second: y stays near 10 m).
test(SecondGravityAdds_Q16_16) {
  float speedError;
  const float error =
      Checks<Q16_16>::fallError<Checks<Q16_16>::Slotless>(64, 2, &speedError);
  assertNear(error, 0.0f, positionBound(kUnitQ16, 64));
  assertNear(speedError, 0.0f, speedBound(kUnitQ16, 64));
}

test(RemoveForceSwitchesGravityOff_Q16_16) {
  assertEqual((int) Checks<Q16_16>::removeSwitchesOff(), 15);
}
test(RemoveForceSwitchesGravityOff_Float) {
  assertEqual((int) Checks<Float>::removeSwitchesOff(), 15);
}

// Without a force slot a particle keeps no accumulator: 8 bytes less in
// 2D Q16.16 (one Vec), the RAM that BouncingBalls' 16 balls save.
test(ParticleWithoutAccumulator_Q16_16) {
  assertEqual((int) sizeof(Checks<Q16_16>::Slotless::ParticleType),
              (int) (sizeof(Particle<Q16_16, 2>) - sizeof(Vec2<Q16_16>)));
}

// v = -g/2 * 1 s; the particle without a gravity slot stays at rest.
test(GravityMultiplier_Q16_16) {
  float other;
  float v = Checks<Q16_16>::halfGravity(&other);
  assertNear(v, -4.905f, 256.0f / 65536 / 2);
  assertEqual(other, 0.0f);
}
test(GravityMultiplier_Float) {
  float other;
  float v = Checks<Float>::halfGravity(&other);
  assertNear(v, -4.905f, 1e-4f);
  assertEqual(other, 0.0f);
}

test(ApplyForceActsOnce_Q16_16) {
  float second;
  float first = Checks<Q16_16>::applyOnce(&second);
  assertEqual(first, 2.0f / 256);
  assertEqual(second, first);
}
test(ApplyForceActsOnce_Float) {
  float second;
  float first = Checks<Float>::applyOnce(&second);
  assertEqual(first, 2.0f / 256);
  assertEqual(second, first);
}

// All quantities are powers of two times small integers: exact in both.
test(CustomForce_Q16_16) {
  float halfway;
  float end = Checks<Q16_16>::customForce(&halfway);
  assertEqual(halfway, 1.0f);
  assertEqual(end, 0.0f);
}
test(CustomForce_Float) {
  float halfway;
  float end = Checks<Float>::customForce(&halfway);
  assertEqual(halfway, 1.0f);
  assertEqual(end, 0.0f);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
