// Bridge: a rope bridge of 7 small weights joined by cables between two
// fixed posts, with a heavy ball dropped onto it. The rope sags under its
// own weight, catches the ball, stretches taut and swings; drawn as ASCII
// frames on the Serial monitor (115200 baud) for 5 simulated seconds.
//
// It shows cables (they pull only when stretched to their length), fixed
// particles, collisions between particles of different sizes and masses,
// and the renderer's links ('.') between the particles.
//
// Hardware: any Arduino (a Nano here), nothing wired. On the PC:
// `make demo DEMO=examples/Bridge`.
//
// What you should see: the two '+' posts with a dotted rope between them
// that sags into a curve, a big 'O' that falls onto it, pushes it down,
// bounces and comes to rest in the dip; at the end whether any contact
// was dropped (the pool of 16 is sized so that none is).
#include <TinyParticle.h>
#include <avr/sleep.h>

const uint8_t kLinks = 7;  // weights between the posts
// 2 posts + 7 weights + the ball; no force slot (gravity takes none); 8
// cables and the collisions; 16 contacts.
typedef World<Q16_16, 2, kLinks + 3, 0, kLinks + 2, 16> BridgeWorld;
typedef Vec2<Q16_16> Point;
BridgeWorld world;

// Rods and no spring: only rods and cables are drawn (no code for the
// force slots linked).
AsciiRenderer<BridgeWorld, 40, 16, ParticleShape::kCircles,
              LinkShape::kRodsAndCables>
    renderer(Q16_16(0), Q16_16(0), Q16_16(0.025), Q16_16(0.0625));
RealTimeLoop timing(256, 8);

void setup() {
  Serial.begin(115200);
  while (!Serial);
  Serial.println(F("Bridge: 7 weights on cables, a 0.5 kg ball falls on them"));

  // The posts, 0.8 m apart, and the weights on a straight line between them,
  // 0.1 m apart. (Stepped in Q16.16: 0.1 + 0.1 * i would be float arithmetic
  // at run time, which links the float routines.)
  Point where(0.1, 0.6);
  ParticleId previous = world.addFixedParticle(where, Q16_16(0.02));
  for (uint8_t i = 1; i <= kLinks + 1; ++i) {
    where.x += Q16_16(0.1);
    ParticleId next = i <= kLinks
                          ? world.addParticle(where, Q16_16(0.05), Q16_16(0.02))
                          : world.addFixedParticle(where, Q16_16(0.02));
    // Each cable is 10 % longer than the gap: the rope sags.
    world.addCable(previous, next, Q16_16(0.11), Q16_16(0));
    previous = next;
  }
  world.addParticle(Point(0.42, 1.0), Q16_16(0.5), Q16_16(0.05));  // the ball
  world.addGravity();
  world.addCollisions(Q16_16(0.3));
}

bool drawing = false;

void loop() {
  timing.runSteps(world);  // dt = 1/256 s, from timing
  if (!drawing && timing.frameDue()) drawing = true;
  while (drawing && Serial.availableForWrite() >= renderer.lineLength()) {
    drawing = !renderer.drawLine(world, Serial);
  }
  if (timing.steps() >= 5 * 256UL && !drawing) {
    Serial.print(F("Contacts dropped: "));
    Serial.println((world.error() & WorldError::kContactsDropped) ? F("some")
                                                                  : F("none"));
    Serial.flush();
    cli();
    sleep_enable();
    sleep_cpu();
  }
}
