// Test support: contacts at rest and in motion, for any scalar. Elastic
// collisions of small balls (kinetic energy kept), sixteen elastic balls in
// a box, a pile at rest (sleeping), a ball dropped on a sleeping pile (it
// wakes, and reacts as an awake one), tunnelling at and past the speed limit
// of Contacts/Collisions.hpp, a contact pool too small for a pile,
// Newton's cradle, the bouncing balls falling asleep in coarse fixed
// point, swept contacts (fast pairs that pass through each other within a
// step), and a box against its planes.
//
// Used by extras/test/ContactsRestTest, ContactsMotionTest and CradleTest (Q16.16)
// and their Float twins, ContactsSleepQ24Test, and ContactsSwept*Test and
// ContactsBox*Test: every scene runs from here, the sketches assert on
// what it measures. Not included by TinyParticle.h: include
// <TinyParticle/Testing/ContactChecks.hpp> after it.
#pragma once

#include <math.h>
#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

template <typename S>
struct ContactChecks {
  // ---- Elastic collisions ----------------------------------------------

  typedef World<S, 2, 2, 0, 1, 2> PairWorld;
  typedef typename PairWorld::Vec PV;

  static float kineticEnergy2(const PairWorld& w) {
    float e = 0;
    for (uint8_t i = 0; i < 2; ++i) {
      const typename PairWorld::ParticleType& p = w.particleAt(i);
      const float vx = p.velocity.x.toFloat(), vy = p.velocity.y.toFloat();
      e += 0.5f / p.inverseMass.toFloat() * (vx * vx + vy * vy);
    }
    return e;
  }

  // Two balls of radius `radius` and 0.1 kg, restitution 1, no gravity: the
  // first at `speed` m/s along x towards the second at rest, whose centre
  // is `offset` m off the line of motion (0: head-on). Returns the kinetic
  // energy after 1 s over the energy before.
  static float elasticRatio(float radius, float speed, float offset) {
    PairWorld w;
    ParticleId a = w.addParticle(PV(0.3, 0.5), S(0.1), S(radius));
    w.addParticle(PV(0.5, 0.5 + offset), S(0.1), S(radius));
    w.particle(a)->velocity.x = S(speed);
    w.addCollisions(S(1));
    const float before = kineticEnergy2(w);
    for (uint16_t i = 0; i < 256; ++i) w.step(S(1.0 / 256));
    return kineticEnergy2(w) / before;
  }

  // ---- Sixteen balls ------------------------------------------------------

  // The row of 16 balls at rest (it needs 16 contacts while landing).
  typedef BallsWorld<S, 2, 16, 20> RowWorld;
  // The row and a ball dropped on it (25 contacts at most with 16 balls,
  // 18 with 12).
  // On the Nano a row of 12: the world and the test's record of the
  // positions must fit its RAM beside AUnit.
#if defined(__AVR__)
  static const uint8_t kDropRow = 12;
#else
  static const uint8_t kDropRow = 16;
#endif
  typedef BallsWorld<S, 2, kDropRow + 1, kDropRow + 12> DropWorld;
  typedef typename RowWorld::Vec BV;

  template <class Box>
  static float kineticEnergy(const Box& w) {
    float e = 0;
    for (uint8_t i = 0; i < Box::kParticleCapacity; ++i) {
      const typename Box::ParticleType& p = w.particleAt(i);
      if (!p.inUse()) continue;
      const float vx = p.velocity.x.toFloat(), vy = p.velocity.y.toFloat();
      e += 0.5f / p.inverseMass.toFloat() * (vx * vx + vy * vy);
    }
    return e;
  }

  // The elastic box (Scenes/BouncingBalls.hpp) for `seconds` at 1/256 s:
  // the largest |E(t) / E(0) - 1| of the kinetic energy.
  static float elasticBoxError(uint8_t seconds) {
    static BallsWorld<S, 2, 16, 8> w;  // two contacts at a time at most
    w.clear();
    buildElasticBox(w, 16);
    const float start = kineticEnergy(w);
    float worst = 0;
    for (uint16_t i = 0; i < uint16_t(seconds) * 256u; ++i) {
      w.step(S(1.0 / 256));
      const float e = ::fabs(kineticEnergy(w) / start - 1);
      if (e > worst) worst = e;
    }
    return worst;
  }

  // Sixteen balls (r = 0.03 m, 0.1 kg) released at rest 1 cm above the
  // floor of the 1 m box, side by side from the left wall (a row, as a
  // pile of them settles), with gravity and restitution 0.8; sleeping on
  // or off. The contact pool holds `contacts`.
  template <class Box>
  static void buildRow(Box& w, bool sleeping, uint8_t count = 16) {
    w.clear();
    BV low, high(1.0, 1.0);
    w.addBox(low, high, S(0.8));
    w.addGravity();
    w.addCollisions(S(0.8));
    if (sleeping) w.enableSleeping();
    for (uint8_t i = 0; i < count; ++i) {
      BV at(0.03 + 0.06 * i, 0.04);
      w.addParticle(at, S(0.1), S(0.03));
    }
  }

  // The deepest overlap (m) of two balls or of a ball and a wall.
  template <class Box>
  static float deepestOverlap(const Box& w) {
    float deepest = 0;
    for (uint8_t i = 0; i < Box::kParticleCapacity; ++i) {
      const typename Box::ParticleType& p = w.particleAt(i);
      if (!p.inUse()) continue;
      const float x = p.position.x.toFloat(), y = p.position.y.toFloat();
      const float r = p.radius.toFloat();
      const float walls[4] = {r - x, r - y, x + r - 1, y + r - 1};
      for (uint8_t k = 0; k < 4; ++k) {
        if (walls[k] > deepest) deepest = walls[k];
      }
      for (uint8_t j = i + 1; j < Box::kParticleCapacity; ++j) {
        const typename Box::ParticleType& q = w.particleAt(j);
        if (!q.inUse()) continue;
        const float dx = x - q.position.x.toFloat();
        const float dy = y - q.position.y.toFloat();
        const float o = r + q.radius.toFloat() - ::sqrt(dx * dx + dy * dy);
        if (o > deepest) deepest = o;
      }
    }
    return deepest;
  }

  template <class Box>
  static float fastest(const Box& w) {
    float v = 0;
    for (uint8_t i = 0; i < Box::kParticleCapacity; ++i) {
      const typename Box::ParticleType& p = w.particleAt(i);
      if (!p.inUse()) continue;
      const float vx = p.velocity.x.toFloat(), vy = p.velocity.y.toFloat();
      const float s = ::sqrt(vx * vx + vy * vy);
      if (s > v) v = s;
    }
    return v;
  }

  struct RestResult {
    float fastest;   // m/s, after the first 2 s
    float deepest;   // m, after the first 2 s
    uint8_t asleep;  // balls asleep at the end
    uint16_t error;  // world.error()
  };

  // The row for `seconds` at 1/256 s, looked at after every 8th step from
  // 2 s on (a look costs more than a step).
  static RestResult rest(uint8_t seconds, bool sleeping) {
    static RowWorld w;  // does not fit on the Nano's stack
    buildRow(w, sleeping);
    RestResult r = {0, 0, 0, 0};
    for (uint16_t i = 1; i <= uint16_t(seconds) * 256u; ++i) {
      w.step(S(1.0 / 256));
      if (i <= 2 * 256 || (i & 7) != 0) continue;
      const float v = fastest(w), d = deepestOverlap(w);
      if (v > r.fastest) r.fastest = v;
      if (d > r.deepest) r.deepest = d;
    }
    r.asleep = asleepCount(w);
    r.error = w.error();
    return r;
  }

  struct DropResult {
    uint8_t asleepBefore;  // balls asleep when the seventeenth is added
    uint8_t asleepAfter;   // 0.5 s later
    float farthest;        // m, the largest distance from `positions`
  };
  // The x, y of every ball in units of 2^-14 m (61 um; half the RAM of
  // floats).
  typedef int16_t DropPositions[2 * (kDropRow + 1)];

  // The row settles for 2 s, then a ball is released 0.3 m above the
  // fifth one's top, 1 cm off its centre; 2 s later the positions are
  // written to `positions`, or, when `compare`, compared with those there.
  static DropResult drop(bool sleeping, DropPositions& positions,
                         bool compare) {
    static DropWorld w;  // does not fit on the Nano's stack
    buildRow(w, sleeping, kDropRow);
    for (uint16_t i = 0; i < 2 * 256; ++i) w.step(S(1.0 / 256));
    DropResult r = {asleepCount(w), 0, 0};
    BV at(0.03 + 0.06 * 4 + 0.01, 0.06 + 0.33);
    w.addParticle(at, S(0.1), S(0.03));
    for (uint16_t i = 1; i <= 2 * 256; ++i) {
      w.step(S(1.0 / 256));
      if (i == 128) r.asleepAfter = asleepCount(w);
    }
    const float unit = 1.0f / 16384;
    for (uint8_t i = 0; i < kDropRow + 1; ++i) {
      const float x = w.particleAt(i).position.x.toFloat();
      const float y = w.particleAt(i).position.y.toFloat();
      if (compare) {
        const float dx = x - positions[2 * i] * unit;
        const float dy = y - positions[2 * i + 1] * unit;
        const float d = ::sqrt(dx * dx + dy * dy);
        if (d > r.farthest) r.farthest = d;
      } else {
        positions[2 * i] = int16_t(::floor(x / unit + 0.5f));
        positions[2 * i + 1] = int16_t(::floor(y / unit + 0.5f));
      }
    }
    return r;
  }

  template <class Box>
  static uint8_t asleepCount(const Box& w) {
    uint8_t n = 0;
    for (uint8_t i = 0; i < Box::kParticleCapacity; ++i) {
      if (w.particleAt(i).isAsleep()) ++n;
    }
    return n;
  }

  // The row with a contact pool of 8 (it needs about 30 while landing):
  // runs `seconds`; reports the drops and whether every ball is still in
  // the box.
  static bool overflow(uint8_t seconds, uint16_t* error, uint8_t* dropped) {
    static BallsWorld<S, 2, 16, 8> w;
    buildRow(w, false);
    *dropped = 0;
    for (uint16_t i = 0; i < uint16_t(seconds) * 256u; ++i) {
      w.step(S(1.0 / 256));
      if (w.stats().dropped > *dropped) *dropped = w.stats().dropped;
    }
    *error = w.error();
    for (uint8_t i = 0; i < 16; ++i) {
      const float x = w.particleAt(i).position.x.toFloat();
      const float y = w.particleAt(i).position.y.toFloat();
      if (!(x > -0.001f && x < 1.001f && y > -0.001f && y < 1.001f)) {
        return false;
      }
    }
    return true;
  }

  // ---- Sleeping in coarse fixed point -------------------------------------

  struct SettleResult {
    uint16_t steps;   // steps until every ball slept (0: not within the run)
    float hanging;    // m, the largest gap under a sleeping ball
    float deepest;    // m, the deepest overlap once all sleep
    uint16_t error;   // world.error()
  };

  // Scenes/BouncingBalls.hpp (16 balls, sleeping on) at 1/256 s for up to
  // `seconds`, until every ball sleeps. Then, for each ball, the gap to
  // what holds it up: the floor, or the nearest ball whose centre is
  // lower; the largest of those gaps, and the deepest overlap.
  static SettleResult settleBalls(uint8_t seconds) {
    // 24 contacts: the most it asks for is below that (a drop would be
    // flagged), and the sketch keeps RAM for the stack.
    static BallsWorld<S, 2, 16, 24> w;  // does not fit on the Nano's stack
    w.clear();
    buildBouncingBalls(w, 16);
    w.enableSleeping();
    SettleResult r = {0, 0, 0, 0};
    for (uint16_t i = 1; i <= uint16_t(seconds) * 256u; ++i) {
      w.step(S(1.0 / 256));
      if (asleepCount(w) == 16) {
        r.steps = i;
        break;
      }
    }
    for (uint8_t i = 0; i < 16; ++i) {
      const typename RowWorld::ParticleType& p = w.particleAt(i);
      const float x = p.position.x.toFloat(), y = p.position.y.toFloat();
      const float r1 = p.radius.toFloat();
      float gap = y - r1;  // above the floor
      for (uint8_t j = 0; j < 16; ++j) {
        const typename RowWorld::ParticleType& q = w.particleAt(j);
        const float qy = q.position.y.toFloat();
        if (j == i || !(qy < y)) continue;
        const float dx = x - q.position.x.toFloat(), dy = y - qy;
        const float g = ::sqrt(dx * dx + dy * dy) - r1 - q.radius.toFloat();
        if (g < gap) gap = g;
      }
      if (gap > r.hanging) r.hanging = gap;
    }
    r.deepest = deepestOverlap(w);
    r.error = w.error();
    return r;
  }

  // ---- Tunnelling ---------------------------------------------------------

  // Two balls of radius 2 cm meet head-on, each at `factor` times the
  // speed limit r / dt (dt = 1/256 s: 5.12 m/s). Returns whether they kept
  // their order along x (they bounced), and the world's error bits.
  static bool tunnel(float factor, uint16_t* error) {
    PairWorld w;
    const float speed = factor * 0.02f * 256;
    ParticleId a = w.addParticle(PV(0.1, 0.5), S(0.1), S(0.02));
    ParticleId b = w.addParticle(PV(0.9037, 0.5), S(0.1), S(0.02));
    w.particle(a)->velocity.x = S(speed);
    w.particle(b)->velocity.x = S(-speed);
    w.addCollisions(S(1));
    for (uint16_t i = 0; i < 64; ++i) w.step(S(1.0 / 256));
    *error = w.error();
    return w.particle(a)->position.x < w.particle(b)->position.x;
  }

  // The same along the diagonal: each ball moves along (1, 1), with
  // |vx| = |vy| = u at `factor` times the limit of the speed bound
  // (u + u/2 = r / dt; |v| = 0.94 r / dt, while |vx| + |vy| is 1.33 r / dt).
  // Returns whether they kept their order along the diagonal.
  static bool tunnelDiagonal(float factor, uint16_t* error) {
    PairWorld w;
    const float u = factor * 0.02f * 256 / 1.5f;
    ParticleId a = w.addParticle(PV(0.1, 0.1), S(0.1), S(0.02));
    ParticleId b = w.addParticle(PV(0.6037, 0.6037), S(0.1), S(0.02));
    w.particle(a)->velocity = PV(S(u), S(u));
    w.particle(b)->velocity = PV(S(-u), S(-u));
    w.addCollisions(S(1));
    for (uint16_t i = 0; i < 32; ++i) w.step(S(1.0 / 256));
    *error = w.error();
    return w.particle(a)->position.x + w.particle(a)->position.y <
           w.particle(b)->position.x + w.particle(b)->position.y;
  }

  // ---- Swept contacts -----------------------------------------------------

  struct SweptResult {
    bool ordered;      // the first ball is still left of the second
    float energy;      // kinetic energy after over before
    float struckSpeed; // m/s, the second ball's speed after
    float struckAngle; // degrees, its direction from the x axis
    uint16_t error;    // world.error()
  };

  // Two balls of radius 2 cm and 0.1 kg, restitution 1, swept collisions
  // (World::addSweptCollisions), no gravity: the first from (0.1, 0.5) at
  // `speedA` m/s along x, the second from (0.9037, 0.5 + offset) at
  // `speedB` m/s against it; 64 steps of 1/256 s.
  static SweptResult swept(float speedA, float speedB, float offset) {
    PairWorld w;
    ParticleId a = w.addParticle(PV(0.1, 0.5), S(0.1), S(0.02));
    ParticleId b = w.addParticle(PV(0.9037, 0.5 + offset), S(0.1), S(0.02));
    w.particle(a)->velocity.x = S(speedA);
    w.particle(b)->velocity.x = S(-speedB);
    w.addSweptCollisions(S(1));
    const float before = kineticEnergy2(w);
    for (uint16_t i = 0; i < 64; ++i) w.step(S(1.0 / 256));
    SweptResult r;
    r.ordered = w.particle(a)->position.x < w.particle(b)->position.x;
    r.energy = kineticEnergy2(w) / before;
    const float vx = w.particle(b)->velocity.x.toFloat();
    const float vy = w.particle(b)->velocity.y.toFloat();
    r.struckSpeed = ::sqrt(vx * vx + vy * vy);
    r.struckAngle = float(::atan2(vy, vx) * (180.0 / 3.14159265358979));
    r.error = w.error();
    return r;
  }

  // The bouncing balls (8 of them, Scenes/BouncingBalls.hpp) for 2 s at
  // 1/256 s, all slower than the speed limit: the x + y of every ball at
  // the end, summed, with plain or swept collisions.
  static float ballsChecksum(bool swept) {
    static BallsWorld<S, 2, 8> w;  // does not fit on the Nano's stack
    w.clear();
    typename RowWorld::Vec low, high(1.0, 1.0);
    w.addBox(low, high, S(0.8));
    w.addGravity();
    if (swept) {
      w.addSweptCollisions(S(0.8));
    } else {
      w.addCollisions(S(0.8));
    }
    SceneRandom random(2024);
    for (uint8_t i = 0; i < 8; ++i) {
      typename RowWorld::Vec at(0.25 * (i % 3 + 1), 0.25 * (i / 3 + 1));
      ParticleId id = w.addParticle(at, S(0.1), S(0.03));
      w.particle(id)->velocity.x = S(0.7 / 128) * S(int(random.symmetric(128)));
      w.particle(id)->velocity.y = S(0.7 / 128) * S(int(random.symmetric(128)));
    }
    for (uint16_t i = 0; i < 2 * 256; ++i) w.step(S(1.0 / 256));
    float sum = 0;
    for (uint8_t i = 0; i < 8; ++i) {
      sum += w.particleAt(i).position.x.toFloat() +
             w.particleAt(i).position.y.toFloat();
    }
    return sum;
  }

  // ---- A box against its planes -------------------------------------------

  // Eight balls (r = 3 cm, 0.1 kg) thrown about a 1 m box under gravity
  // for 2 s at 1/256 s, restitution 0.8, in 2D or 3D: the box as addBox
  // (one pass for all walls) or as its 2 Dim axis planes, added in the
  // box's order (x low, x high, y low, ...). Returns the x + y (+ z) of
  // every ball at the end, summed, and in `touched` the walls that made a
  // contact at some step (bit 2k: the low wall of axis k, 2k + 1: the
  // high one), whether two walls of one ball made contacts in one step (a
  // corner) in bit 7, and in bit 6 whether the contact pool ran full.
  template <uint8_t Dim>
  static float boxChecksum(bool asBox, uint8_t* touched) {
    typedef World<S, Dim, 8, 1, 2 * Dim + 1, 16> BoxWorld;
    typedef typename BoxWorld::Vec V;
    static BoxWorld w;  // does not fit on the Nano's stack
    w.clear();
    V low, high;
    for (uint8_t k = 0; k < Dim; ++k) high[k] = S(1);
    if (asBox) {
      w.addBox(low, high, S(0.8));
    } else {
      for (uint8_t k = 0; k < Dim; ++k) {
        V normal;
        normal[k] = S(1);
        w.addPlane(normal, S(), S(0.8));  // x_k >= 0
        normal[k] = S(-1);
        w.addPlane(normal, S(-1), S(0.8));  // x_k <= 1
      }
    }
    w.addGravity();
    w.addCollisions(S(0.8));
    SceneRandom random(7);
    for (uint8_t i = 0; i < 8; ++i) {
      V at;
      at.x = S(0.2 + 0.2 * (i % 4));
      at.y = S(0.3 + 0.4 * (i / 4));
      if (Dim == 3) at[2] = S(0.5);
      // The first one flies into the corner at the origin (two or three
      // walls at once).
      if (i == 0) at = V();
      for (uint8_t k = 0; i == 0 && k < Dim; ++k) at[k] = S(0.04);
      ParticleId id = w.addParticle(at, S(0.1), S(0.03));
      for (uint8_t k = 0; k < Dim; ++k) {
        w.particle(id)->velocity[k] =
            i == 0 ? S(-1) : S(4.0 / 128) * S(int(random.symmetric(128)));
      }
    }
    *touched = 0;
    for (uint16_t i = 0; i < 2 * 256; ++i) {
      w.step(S(1.0 / 256));
      uint8_t wallsOf[8] = {0, 0, 0, 0, 0, 0, 0, 0};
      for (uint8_t c = 0; c < w.contactCount(); ++c) {
        const typename BoxWorld::ContactType& contact = WorldAccess::contact(w, c);
        if (contact.b != kNoIndex) continue;  // a ball, not a wall
        for (uint8_t k = 0; k < Dim; ++k) {
          const uint8_t lowWall = uint8_t(1u << (2 * k));
          if (contact.normal[k] == S(1)) wallsOf[contact.a] |= lowWall;
          if (contact.normal[k] == S(-1)) {
            wallsOf[contact.a] |= uint8_t(lowWall << 1);
          }
        }
      }
      for (uint8_t b = 0; b < 8; ++b) {
        *touched |= wallsOf[b];
        if (wallsOf[b] & (wallsOf[b] - 1)) *touched |= 0x80;  // two bits
      }
    }
    // A full contact pool would drop contacts: flagged as bit 6.
    if (w.error() & WorldError::kContactsDropped) *touched |= 0x40;
    float sum = 0;
    for (uint8_t i = 0; i < 8; ++i) {
      for (uint8_t k = 0; k < Dim; ++k) {
        sum += w.particleAt(i).position[k].toFloat();
      }
    }
    return sum;
  }

  // ---- Newton's cradle ----------------------------------------------------

  typedef World<S, 2, 5, 1, 6, 8> CradleWorld;

  struct CradleResult {
    float rise;       // the last ball's highest rise over its first's, 1 = all
    float middle;     // the largest move of the three middle balls, m
    uint16_t error;
  };

  // Scenes/Cradle.hpp at dt = 1/256 s, for 1.1 s: the first ball falls,
  // and the last one rises (a quarter period each, about 0.38 s).
  static CradleResult cradle() {
    CradleWorld w;
    buildCradle(w);
    const float start = w.particleAt(0).position.y.toFloat() - kCradleLow;
    CradleResult r = {0, 0, 0};
    float highest = 0;
    for (uint16_t i = 0; i < 282; ++i) {
      w.step(S(1.0 / 256));
      const float h = w.particleAt(4).position.y.toFloat() - kCradleLow;
      if (h > highest) highest = h;
      for (uint8_t k = 1; k < 4; ++k) {
        const float dx = w.particleAt(k).position.x.toFloat() - cradlePost(k);
        const float dy = w.particleAt(k).position.y.toFloat() - kCradleLow;
        const float d = ::sqrt(dx * dx + dy * dy);
        if (d > r.middle) r.middle = d;
      }
    }
    r.rise = highest / start;
    r.error = w.error();
    return r;
  }
  static constexpr float kCradleLow = 0.8f - 0.5f;  // the balls' rest height
  static float cradlePost(uint8_t k) { return 0.3f + 0.1f * k; }
};

}  // namespace testing
}  // namespace tinyparticle
