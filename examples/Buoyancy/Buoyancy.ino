// Buoyancy: three bodies of the same size (1 litre) but different masses
// are dropped into water whose surface is at y = 0.5 m: a light one (0.3 kg)
// floats high, a heavier one (0.9 kg) floats low, and a stone (2.5 kg) sinks
// to the bottom. Water drag settles them. After 6 simulated seconds the
// sketch prints where each came to rest beside Archimedes' prediction: a
// floating body is submerged by the fraction mass / (density * volume).
//
// It shows buoyancy and drag for single particles, a floor plane, the
// ASCII renderer (the water line is drawn by the sketch), and Float as the
// scalar (Q16_16 works as well).
//
// Hardware: any Arduino (a Nano here), nothing wired; Serial Monitor at
// 115200 baud. On the PC: `make demo DEMO=examples/Buoyancy`.
//
// What you should see: a tank drawn every 1.5 s with the water line as
// '~', the three bodies falling in, bobbing and settling (the light one
// high, the heavier one low, the stone on the bottom), then a table of
// where each rests beside Archimedes' prediction, the two columns agreeing.
#include <TinyParticle.h>
#include <avr/sleep.h>

typedef Float S;
// 3 bodies; 3 buoyancy and 1 drag slots (gravity takes none); the floor;
// 4 contacts.
typedef World<S, 2, 3, 4, 1, 4> Tank;
Tank world;

const float kSurface = 0.5f;     // m
const float kHalfHeight = 0.05f; // m: each body is 0.1 m tall
const float kVolume = 0.001f;    // m^3
const float kMasses[3] = {0.3f, 0.9f, 2.5f};

AsciiRenderer<Tank, 30, 12> renderer(S(0), S(0), S(1.0 / 30), S(1.0 / 12));

void draw() {
  // The frame, with the water surface marked at the left and right.
  const uint8_t surfaceRow = uint8_t((1.0f - kSurface) * 12);  // from the top
  char line[31];
  Serial.println(F("+------------------------------+"));
  for (uint8_t row = 0; row < 12; ++row) {
    renderer.renderRow(world, row, line);
    line[30] = '\0';
    for (uint8_t c = 0; c < 30 && row == surfaceRow; ++c) {
      if (line[c] == ' ') line[c] = '~';
    }
    Serial.print('|');
    Serial.print(line);
    Serial.println('|');
  }
  Serial.println(F("+------------------------------+"));
}

void setup() {
  Serial.begin(115200);
  while (!Serial);
  Serial.println(F("Buoyancy: 1 litre bodies of 0.3, 0.9 and 2.5 kg in water"));
  for (uint8_t i = 0; i < 3; ++i) {
    Vec2<S> start(0.2 + 0.3 * i, 0.9);
    ParticleId body = world.addParticle(start, S(kMasses[i]), S(kHalfHeight));
    world.addBuoyancy(body, S(kSurface), S(kHalfHeight), S(kVolume), S(1000));
  }
  world.addGravity();
  world.addDrag(S(3), S(0));  // N s/m: slow enough to settle in a few seconds
  world.addPlane(Vec2<S>(0.0, 1.0), S(0), S(0.2));  // the bottom

  const uint16_t kStepsPerSecond = 256;
  const S dt(1.0 / kStepsPerSecond);  // exact: 1/256 s, folded at compile time
  for (uint16_t i = 0; i <= 6 * kStepsPerSecond; ++i) {
    if (i % (kStepsPerSecond * 3 / 2) == 0) {  // every 1.5 s
      Serial.print(F("t = "));
      Serial.print(float(i) / kStepsPerSecond, 1);
      Serial.println(F(" s"));
      draw();
    }
    world.step(dt);
  }

  Serial.println(F("body  mass (kg)  rests at y (m)  Archimedes (m)"));
  for (uint8_t i = 0; i < 3; ++i) {
    float fraction = kMasses[i] / (1000 * kVolume);
    // Submerged by `fraction` of its height, or on the bottom if it sinks.
    float expected = fraction < 1 ? kSurface + kHalfHeight - 2 * kHalfHeight * fraction
                                  : kHalfHeight;
    Serial.print(i + 1);
    Serial.print(F("     "));
    Serial.print(kMasses[i], 1);
    Serial.print(F("        "));
    Serial.print(world.particleAt(i).position.y.toFloat(), 4);
    Serial.print(F("          "));
    Serial.println(expected, 4);
  }
  Serial.flush();
  cli();
  sleep_enable();
  sleep_cpu();
}

void loop() {}
