// Particles with inverse mass 0 never move: not under gravity, not when a
// ball hits them, not when a rod pulls them, not when a force is applied.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S>
struct Checks {
  typedef World<S, 2, 3, 1, 2, 4> W;
  typedef typename W::Vec V;

  // An immovable particle under gravity, hit by a ball, held by a rod to
  // another particle and pushed by applyForce. Returns 1 if it never moved,
  // plus 2 if the ball did bounce off it.
  static int immovable() {
    W w;
    V where(0.5, 0.5), above(0.5, 0.9), aside(0.9, 0.5);
    ParticleId fixed = w.addFixedParticle(where, S(0.05));
    ParticleId ball = w.addParticle(above, S(1), S(0.05));
    ParticleId swing = w.addParticle(aside, S(2), S(0.01));
    w.particle(fixed)->velocity.x = S(1);  // ignored: it never moves
    w.addGravity();
    w.addCollisions(S(1));
    w.addRod(swing, fixed, S(0.4));
    bool bounced = false;
    for (uint16_t i = 0; i < 512; ++i) {
      V shove(3.0, -4.0);
      w.applyForce(fixed, shove);
      w.step(S(1.0 / 256));
      if (w.particle(ball)->velocity.y > S(0.5)) bounced = true;
      if (w.particle(fixed)->position != where) return 0;
    }
    return bounced ? 3 : 1;
  }
};

test(ImmovableNeverMoves_Q16_16) {
  assertEqual(Checks<Q16_16>::immovable(), 3);
}
test(ImmovableNeverMoves_Float) { assertEqual(Checks<Float>::immovable(), 3); }

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
