// A world of one constraint slot is solved by the lone rods alone
// (Contacts/LoneRod.hpp), without the chains' solve, also when its rod
// joins two movable particles (a thrown dumbbell), Q16.16 2D: the rod keeps
// its length, the momentum and the energy, and the ends follow the chains'
// solve of the same rod. (RodAnchoredTest: a world of anchored rods.)
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

typedef Q16_16 S;
typedef Vec2<S> V;
typedef World<S, 2, 2, 0, 1, 0> OneSlot;    // lone rods only
typedef World<S, 2, 5, 0, 3, 0> WithChain;  // the chains' solve

// The dumbbell: 0.1 kg at the origin, 0.3 kg 0.2 m to its right, turning
// at 7.5 rad/s (relative speed 1.5 m/s across the rod) and drifting.
const float kMassA = 0.1f, kMassB = 0.3f, kLength = 0.2f;

template <class W>
void buildDumbbell(W& w) {
  w.clear();
  const ParticleId a = w.addParticle(V(0.0, 0.0), S(kMassA));
  const ParticleId b = w.addParticle(V(0.2, 0.0), S(kMassB));
  w.addRod(a, b, S(kLength));
  w.particle(a)->velocity = V(0.3, 1.0);
  w.particle(b)->velocity = V(0.3, -0.5);
}

float momentumX(const OneSlot& w) {
  return kMassA * w.particleAt(0).velocity.x.toFloat() +
         kMassB * w.particleAt(1).velocity.x.toFloat();
}
float momentumY(const OneSlot& w) {
  return kMassA * w.particleAt(0).velocity.y.toFloat() +
         kMassB * w.particleAt(1).velocity.y.toFloat();
}
float energyOf(const OneSlot& w) {
  const float a = w.particleAt(0).velocity.magnitudeSquared().toFloat();
  const float b = w.particleAt(1).velocity.magnitudeSquared().toFloat();
  return 0.5f * (kMassA * a + kMassB * b);
}

OneSlot gOne;
WithChain gChain;

// What a run of the dumbbell shows.
struct Run {
  uint16_t error;
  bool lone;       // solved as lone rods
  float length;    // largest |length - 0.2 m|
  float momentum;  // largest change of a momentum component, kg m/s
  float energy;    // change of the energy, J
  float start;     // the energy at the start, J
  float apart;     // largest distance of an end from the chains' solve's, m

  // `steps` steps of dt, from the same start in both worlds. (A member:
  // the Arduino builder declares free functions above this type.)
  static Run of(S dt, uint16_t steps);
};

Run Run::of(S dt, uint16_t steps) {
  buildDumbbell(gOne);
  buildDumbbell(gChain);
  // A free chain of two rods besides: every rod takes the chains' solve.
  const ParticleId c = gChain.addParticle(V(1.0, 1.0), S(0.1));
  const ParticleId d = gChain.addParticle(V(1.1, 1.0), S(0.1));
  gChain.addRod(c, d, S(0.1));
  gChain.addRod(d, gChain.addParticle(V(1.2, 1.0), S(0.1)), S(0.1));
  const float px = momentumX(gOne), py = momentumY(gOne);
  Run run;
  run.start = energyOf(gOne);
  run.length = run.apart = 0;
  for (uint16_t k = 0; k < steps; ++k) {
    gOne.step(dt);
    gChain.step(dt);
    const V span = gOne.particleAt(1).position - gOne.particleAt(0).position;
    const float l = ::fabsf(span.magnitude().toFloat() - kLength);
    if (l > run.length) run.length = l;
    for (uint8_t i = 0; i < 2; ++i) {
      const V gap = gOne.particleAt(i).position - gChain.particleAt(i).position;
      const float g = gap.magnitude().toFloat();
      if (g > run.apart) run.apart = g;
    }
  }
  run.error = gOne.error();
  run.lone = (tinyparticle::WorldAccess::rodState(gOne) & OneSlot::kRodsLone) != 0;
  const float mx = ::fabsf(momentumX(gOne) - px);
  const float my = ::fabsf(momentumY(gOne) - py);
  run.momentum = mx > my ? mx : my;
  run.energy = ::fabsf(energyOf(gOne) - run.start);
  return run;
}

// Slow turns at 1/256 s (0.03 rad a step: second order), fast ones at
// 1/64 s (0.12 rad: the closed form's series), 1 s each.
test(oneSlotDumbbell) {
  const S dts[2] = {S(1.0 / 256), S(1.0 / 64)};
  const uint16_t counts[2] = {256, 64};
  for (uint8_t i = 0; i < 2; ++i) {
    const uint16_t steps = counts[i];
    const Run run = Run::of(dts[i], steps);
    assertEqual(run.error, (uint16_t)0);
    assertTrue(run.lone);
    // Held as the chains' solve holds rods: within tolerance() (61 um).
    assertLess(run.length, RodSolver<OneSlot>::tolerance().toFloat());
    // Each step's impulses are equal and opposite up to rounding: a few
    // units (2^-16 m/s) of velocity per particle and step, times the
    // masses.
    assertLess(run.momentum, steps * 4.0f / 65536 * (kMassA + kMassB));
    // The step keeps a rigid turn's energy (RATTLE): within 1 %.
    assertLess(run.energy, 0.01f * run.start);
    // The two solves differ by rounding, and the lone one mends half of a
    // length error at a time: a unit (2^-16 m) a step at most.
    assertLess(run.apart, steps / 65536.0f);
  }
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
  TestRunner::setTimeout(0);
}

void loop() { TestRunner::run(); }
