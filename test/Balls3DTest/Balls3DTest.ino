// The box of balls scene (Scenes/BouncingBalls.hpp) in 3D (a 1 m cube with
// six walls): the balls stay inside, and energy only goes (restitution 0.8).
// BallsTest does the same in 2D.
// (Q16.16 here; Balls3DFloatTest runs the same checks with Float: the two
// scalars together no longer fit in the Nano's 30 KB of flash.)
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S, uint8_t Dim>
struct Checks {
  // 8 balls and 16 contacts keep the world small enough for the Nano's
  // stack; the scene is the same as the 16-ball one.
  typedef BallsWorld<S, Dim, 8, 16> W;

  static float energy(const W& w) {
    float e = 0;
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const typename W::ParticleType& p = w.particleAt(i);
      e += 0.1f * (p.velocity.magnitudeSquared().toFloat() / 2 +
                   9.81f * p.position.y.toFloat());
    }
    return e;
  }

  // Runs 3 s at dt = 1/256. Returns how far any ball got beyond the walls
  // (its surface past a wall, m); `gain` gets the largest energy rise over
  // the start (J) and `loss` the energy lost by the end.
  static float run(float* gain, float* loss) {
    W w;
    buildBouncingBalls(w, 8);
    const float start = energy(w);
    float outside = 0;
    *gain = 0;
    for (uint16_t n = 0; n < 3 * 256; ++n) {
      w.step(S(1.0 / 256));
      for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
        const typename W::ParticleType& p = w.particleAt(i);
        for (uint8_t k = 0; k < Dim; ++k) {
          float x = p.position[k].toFloat();
          if (0.03f - x > outside) outside = 0.03f - x;
          if (x - 0.97f > outside) outside = x - 0.97f;
        }
      }
      float e = energy(w);
      if (e - start > *gain) *gain = e - start;
    }
    *loss = start - energy(w);
    return outside;
  }
};

// (Typedefs: a comma inside a macro argument would split it.)
typedef Checks<Q16_16, 3> Deep;

// A ball may overlap a wall by one step of travel before the contact pushes
// it out: at most 3 m/s * dt = 12 mm here. Energy: each correction of a
// penetration d lifts a ball by at most d, adding m g d = 0.1 * 9.81 * 0.012
// = 12 mJ; the bounces (restitution 0.8) take far more, so after 3 s the
// energy is lower than at the start.
test(BallsInBox3D_Q16_16) {
  TestRunner::setTimeout(0);
  float gain, loss;
  assertLessOrEqual(Deep::run(&gain, &loss), 0.012f);
  assertLessOrEqual(gain, 0.012f);
  assertMore(loss, 0.0f);
}


void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
