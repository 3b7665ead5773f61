// Magnet: a steel ball hangs on a spring over a magnet that slides to and
// fro as a dial turns; the ball swings towards it and settles over it. The magnet's pull is
// a force generator written here, in the sketch (struct Magnet below), and
// added to the world with one call, world.addForce(magnet, ball): the
// library is not touched, and the world runs it each step as it runs its
// own springs. The sketch moves the magnet by changing the generator's
// field; the world holds a pointer to it.
//
// Hardware: a Nano with a dial (a 10 kOhm potentiometer: ends to 5 V and
// GND, wiper to A0); without one A0 floats and the magnet wanders. Serial
// Monitor at 115200 baud. On the PC: `make demo DEMO=examples/Magnet` (the
// simulated A0 reads 0: the magnet sits at the left end).
//
// What you should see: ASCII frames, five a second, of the pivot and the
// magnet ('+', the magnet below the ball), the spring ('.') and the ball
// ('O') swinging towards the magnet and settling over its side; under each
// frame the time, the dial, the magnet's x and the ball's. Turn the
// dial and the ball follows. After 8 s of simulated time it stops.
#include <TinyParticle.h>
#include <avr/sleep.h>

typedef Q16_16 S;
// 2D; 3 particles (pivot, ball, the magnet's marker), 2 forces (the
// spring, the magnet; gravity takes none), no constraint: a world without
// constraints links no contact code, and the sketch fits a Leonardo too.
typedef World<S, 2, 3, 2> MagnetWorld;
MagnetWorld world;

// An inverse-square attractor: a pull of strength / d^2 towards the pole,
// softened within `soft` of it (d^2 + soft^2), so that it stays finite.
struct Magnet {
  Vec2<S> pole;  // m
  S strength;    // N m^2
  S soft;        // m

  // Called by the world each step for the particle it was added for.
  void apply(MagnetWorld::ParticleType& p, S) {
    const Vec2<S> towards = pole - p.position;
    const S d2 = towards.magnitudeSquared() + soft * soft;
    // (strength / d^2) / d: two divisions keep Q16.16's precision where
    // d^3 would be a few units of it.
    const S perLength = strength / d2 / sqrt(d2);
    p.addForce(towards * perLength);
  }
};

Magnet magnet = {Vec2<S>(0.0, -0.15), S(0.01), S(0.05)};
ParticleId pivot, ball, marker;

// 41 x 10 characters over x from -0.41 m to 0.41 m, y from -0.2 m up.
AsciiRenderer<MagnetWorld, 41, 10> renderer(S(-0.41), S(-0.2), S(0.02),
                                            S(0.065));
RealTimeLoop timing(256, 5);  // dt = 1/256 s, 5 frames a second
const uint32_t kRunSteps = 8 * 256UL;
bool drawing = false;

// The dial (0 to 1023) as the magnet's x: -0.3 m to +0.3 m.
S magnetX() {
  const int dial = analogRead(A0);
  return S(long(dial) - 512) * S(0.3 / 512);
}

void setup() {
  Serial.begin(115200);
  while (!Serial);
  Serial.println(F("Magnet: a user force generator, dial on A0"));
  pivot = world.addFixedParticle(Vec2<S>(0.0, 0.4));
  ball = world.addParticle(Vec2<S>(0.0, -0.05), S(0.05), S(0.02));  // 50 g
  world.particle(ball)->setDampingRate(S(1.5));
  marker = world.addFixedParticle(magnet.pole);
  world.particle(marker)->setCollides(false);
  world.addSpring(ball, pivot, S(40), S(0.45));  // 40 N/m, 0.45 m at rest
  world.addGravity();
  world.addForce(magnet, ball);  // the sketch's own generator
}

void loop() {
  magnet.pole.x = magnetX();  // the generator reads it in the next step
  world.particle(marker)->position = magnet.pole;
  timing.runSteps(world);

  if (!drawing && timing.frameDue()) drawing = true;
  while (drawing && Serial.availableForWrite() >= renderer.lineLength()) {
    if (renderer.drawLine(world, Serial)) {
      drawing = false;
      // print() writes fixed point without float code (Text/Print.hpp).
      Serial.print(F("t="));
      print(Serial, S(long(timing.steps())) * S(1.0 / 256), 1);
      Serial.print(F(" s  dial "));
      Serial.print(analogRead(A0));
      Serial.print(F("  magnet x "));
      print(Serial, magnet.pole.x, 3);
      Serial.print(F(" m  ball x "));
      print(Serial, world.particle(ball)->position.x, 3);
      Serial.println(F(" m"));
    }
  }

  if (timing.steps() >= kRunSteps && !drawing) {
    Serial.println(F("Done."));
    Serial.flush();
    cli();
    sleep_enable();
    sleep_cpu();
  }
}
