// The world's gravity (addGravity() without a particle): a setting of the
// world, not a force slot. It works in a world with no force slot, whose
// particles keep no force accumulator; removeForce() of its id switches it
// off; a second addGravity() adds to it.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S>
struct Checks {
  // No force slot: particles without the accumulator.
  typedef World<S, 2, 1> W;
  typedef typename W::Vec V;

  // Drops a particle from rest at y0 = 10 m for n steps of dt = 1/256 s
  // (exact in both scalars) under `times` calls of addGravity(). Returns
  // y - y_exact: semi-implicit Euler gives exactly
  // y_n = y0 - a dt^2 n (n + 1) / 2 = y0 - a t^2 / 2 - a dt t / 2
  // (a = times * g). `speedError` gets v - (-a t).
  static float fallError(uint16_t n, uint8_t times, float* speedError) {
    W w;
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

  // Falls for 64 steps, then removeForce() of the gravity's id: the next
  // 64 steps keep the velocity to the bit (nothing else acts). Returns a
  // bit mask of what held (all: 15).
  static uint8_t removeSwitchesOff() {
    W w;
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
};

// Rounding bound as in FreeFallTest: each step rounds the velocity and the
// position increments by at most half a unit u, so after n steps
// |dv| <= n u / 2 and |dy| <= u (n^2 dt / 2 + n) / 2. Q16.16: u = 2^-16;
// float: u = 2^-20, the spacing near 10 m and 10 m/s.
test(FreeFallWithoutForceSlot_Q16_16) {
  float speedError;
  const float error = Checks<Q16_16>::fallError(256, 1, &speedError);
  const float u = 1.0f / 65536, n = 256;
  assertNear(error, 0.0f, u * (n * n / 256 / 2 + n) / 2);
  assertNear(speedError, 0.0f, u * n / 2);
}
test(FreeFallWithoutForceSlot_Float) {
  float speedError;
  const float error = Checks<Float>::fallError(256, 1, &speedError);
  const float u = 1.0f / 1048576, n = 256;
  assertNear(error, 0.0f, u * (n * n / 256 / 2 + n) / 2);
  assertNear(speedError, 0.0f, u * n / 2);
}

// Two calls: 2 g, as two gravity slots summed before. The same bound
// (the fall takes a quarter second: y stays near 10 m).
test(SecondGravityAdds_Q16_16) {
  float speedError;
  const float error = Checks<Q16_16>::fallError(64, 2, &speedError);
  const float u = 1.0f / 65536, n = 64;
  assertNear(error, 0.0f, u * (n * n / 256 / 2 + n) / 2);
  assertNear(speedError, 0.0f, u * n / 2);
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
  assertEqual((int) sizeof(Checks<Q16_16>::W::ParticleType),
              (int) (sizeof(Particle<Q16_16, 2>) - sizeof(Vec2<Q16_16>)));
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
