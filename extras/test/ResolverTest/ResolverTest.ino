// The contact resolver: the contact pool overflowing (counted, the most
// severe kept) and the iteration cap.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

template <typename S>
struct Checks {
  // 5 particles, 1 plane, and only 3 contacts, so that the pool overflows.
  typedef World<S, 2, 5, 0, 1, 3> W;
  typedef typename W::Vec V;

  // Five balls just touching a floor (restitution 0.5), falling at 1 to
  // 5 m/s, no gravity, one step. Returns the number of dropped contacts;
  // `kept` gets a bit per ball that bounced (its velocity turned upwards).
  static int overflow(int* kept, int* stored, bool* flagged) {
    W w;
    V up(0.0, 1.0);
    w.addPlane(up, S(0), S(0.5));
    for (uint8_t i = 0; i < 5; ++i) {
      V where(0.2 * i, 0.1);
      ParticleId id = w.addParticle(where, S(1), S(0.1));
      w.particle(id)->velocity.y = S(-1 - int(i));
    }
    w.step(S(1.0 / 256));
    *kept = 0;
    for (uint8_t i = 0; i < 5; ++i) {
      if (w.particleAt(i).velocity.y > S()) *kept |= 1 << i;
    }
    *stored = w.stats().contacts;
    *flagged = (w.error() & WorldError::kContactsDropped) != 0;
    return w.stats().dropped;
  }

  // The two-contact case with the iteration cap at 1: only one is resolved.
  static int capped() {
    W w;
    V up(0.0, 1.0);
    w.addPlane(up, S(0), S(0.5));
    for (uint8_t i = 0; i < 2; ++i) {
      V where(0.5 * i, 0.1);
      ParticleId id = w.addParticle(where, S(1), S(0.1));
      w.particle(id)->velocity.y = S(-1);
    }
    w.setIterationCap(1);
    w.step(S(1.0 / 256));
    int bounced = 0;
    for (uint8_t i = 0; i < 2; ++i) {
      if (w.particleAt(i).velocity.y > S()) ++bounced;
    }
    return bounced * 10 + w.stats().iterations;
  }

  // The peak: five balls on the floor ask for five contacts (three kept,
  // two dropped); a later step without contacts leaves the peak at five;
  // clear() starts it again from 0. Returns the three peaks, as digits.
  static int peaks() {
    W w;
    int contacts = 0;
    (void)overflowInto(w, &contacts);
    const int first = w.stats().peakContacts;
    for (uint8_t i = 0; i < 5; ++i) {
      w.particleAt(i).position.y = S(1);  // far above the floor, at rest
      w.particleAt(i).velocity = V();
    }
    w.step(S(1.0 / 256));
    const int later = w.stats().contacts == 0 ? w.stats().peakContacts : 9;
    w.clear();
    return first * 100 + later * 10 + w.stats().peakContacts;
  }

  static int overflowInto(W& w, int* stored) {
    V up(0.0, 1.0);
    w.addPlane(up, S(0), S(0.5));
    for (uint8_t i = 0; i < 5; ++i) {
      V where(0.2 * i, 0.1);
      ParticleId id = w.addParticle(where, S(1), S(0.1));
      w.particle(id)->velocity.y = S(-1 - int(i));
    }
    w.step(S(1.0 / 256));
    *stored = w.stats().contacts;
    return w.stats().dropped;
  }
};

// Five contacts, room for three: two dropped and counted, the error bit
// set, and the three kept are the most severe (the balls falling at 5, 4
// and 3 m/s: bits 4, 3 and 2), which alone bounce.
test(ContactOverflow_Q16_16) {
  int kept, stored;
  bool flagged;
  assertEqual(Checks<Q16_16>::overflow(&kept, &stored, &flagged), 2);
  assertEqual(stored, 3);
  assertEqual(kept, 0x1C);
  assertTrue(flagged);
}
test(ContactOverflow_Float) {
  int kept, stored;
  bool flagged;
  assertEqual(Checks<Float>::overflow(&kept, &stored, &flagged), 2);
  assertEqual(stored, 3);
  assertEqual(kept, 0x1C);
  assertTrue(flagged);
}

// stats().peakContacts: 5 (kept and dropped), still 5 after a step
// without contacts, 0 after clear().
test(PeakContacts_Q16_16) { assertEqual(Checks<Q16_16>::peaks(), 550); }
test(PeakContacts_Float) { assertEqual(Checks<Float>::peaks(), 550); }

// One iteration allowed, two contacts: one ball bounces (10), 1 iteration.
test(IterationCap_Q16_16) { assertEqual(Checks<Q16_16>::capped(), 11); }
test(IterationCap_Float) { assertEqual(Checks<Float>::capped(), 11); }

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
