// Rope: a chain of 7 beads on 8 rigid links hangs between two posts; after
// 3 seconds (or as soon as you send any character) its middle link is cut,
// and the two halves swing down from their posts and settle. Drawn as ASCII
// frames on the Serial Monitor (115200 baud), 8 a second.
//
// It shows rods (links that keep their length exactly, solved together),
// removing a constraint at run time (removeConstraint), damping per
// particle, and the real-time loop at 64 steps a second (rods are exact at
// any step rate, and a Nano has time for about that many steps of a rope).
//
// Hardware: any Arduino (a Nano here), nothing wired. On the PC:
// `make demo DEMO=examples/Rope`.
//
// What you should see: the rope sags between the two '+' posts as a "V"
// that rounds into a hanging chain; at 3 s "cut" is printed and the two
// halves fall and swing, each hanging from its post. At the end the sketch
// prints how far the longest remaining link is from its 0.1 m (a few
// units of Q16.16) and stops.
#include <TinyParticle.h>
#include <avr/sleep.h>

typedef Q16_16 S;
typedef Vec2<S> V;
const uint8_t kBeads = 7;
const uint8_t kLinks = kBeads + 1;
// The posts and the beads; gravity (no force slot); the links; no contacts
// (rods take none).
typedef World<S, 2, kBeads + 2, 0, kLinks, 0> RopeWorld2;
RopeWorld2 world;
ParticleId chain[kBeads + 2];  // left post, beads, right post
ConstraintId links[kLinks];    // links[i] joins chain[i] and chain[i + 1]

// 40 x 20 characters over 1 m x 1 m.
// The beads (radius 1 cm) are smaller than half a cell: drawn as points,
// the same characters without the renderer's circle code.
// Its links are rods: only rods and cables are drawn (no code for the force
// slots linked).
AsciiRenderer<RopeWorld2, 40, 20, ParticleShape::kPoints,
              LinkShape::kRodsAndCables>
    renderer(S(0), S(0), S(0.025), S(0.05));
RealTimeLoop timing(64, 8);  // dt = 1/64 s, 8 frames a second
bool drawing = false;
bool cut = false;

void setup() {
  Serial.begin(115200);
  while (!Serial);
  Serial.println(F("Rope: 7 beads on 8 links; send a key (or wait 3 s) to cut"));
  // Posts 0.6 m apart; the beads on a "V" whose links are all 0.1 m long:
  // 0.075 m across and 0.066144 m down (0.075^2 + 0.066144^2 = 0.1^2).
  chain[0] = world.addFixedParticle(V(0.2, 0.8));
  for (uint8_t k = 1; k <= kBeads; ++k) {
    const uint8_t fromPost = k < kLinks - k ? k : uint8_t(kLinks - k);
    const V at(S(0.2) + S(0.075) * S(k), S(0.8) - S(0.066144) * S(fromPost));
    chain[k] = world.addParticle(at, S(0.05), S(0.01));  // 50 g beads
    world.particle(chain[k])->setDampingRate(S(1));       // settles in seconds
  }
  chain[kLinks] = world.addFixedParticle(V(0.8, 0.8));
  for (uint8_t i = 0; i < kLinks; ++i) {
    links[i] = world.addRod(chain[i], chain[i + 1], S(0.1));
  }
  world.addGravity();
}

// The largest |length - 0.1 m| of the links still in place.
S worstLink() {
  S worst;
  for (uint8_t i = 0; i < kLinks; ++i) {
    if (world.constraint(links[i]) == nullptr) continue;  // the cut one
    const V gap = world.particle(chain[i + 1])->position -
                  world.particle(chain[i])->position;
    const S error = fabs(gap.magnitude() - S(0.1));
    if (error > worst) worst = error;
  }
  return worst;
}

void loop() {
  timing.runSteps(world);
  if (!cut && (timing.steps() >= 3 * 64UL || Serial.available() > 0)) {
    world.removeConstraint(links[kLinks / 2]);
    cut = true;
    Serial.println(F("cut"));
  }
  if (!drawing && timing.frameDue()) drawing = true;
  while (drawing && Serial.availableForWrite() >= renderer.lineLength()) {
    drawing = !renderer.drawLine(world, Serial);
  }
  if (timing.steps() >= 8 * 64UL && !drawing) {
    Serial.print(F("Longest link error (m): "));
    println(Serial, worstLink());
    Serial.flush();
    cli();
    sleep_enable();
    sleep_cpu();
  }
}
