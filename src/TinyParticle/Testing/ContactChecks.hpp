// Test support: contacts at rest and in motion, for any scalar. Elastic
// collisions of small balls (kinetic energy kept), sixteen elastic balls in
// a box, a pile at rest (sleeping), a ball dropped on a sleeping pile (it
// wakes, and reacts as an awake one), tunnelling at and past the speed limit
// of Contacts/Collisions.hpp, a contact pool too small for a pile, and
// Newton's cradle.
//
// Used by test/ContactsRestTest, ContactsMotionTest and CradleTest (Q16.16)
// and their Float twins: every scene runs from here, the sketches assert on
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

  typedef BallsWorld<S, 2, 17> BoxWorld;  // 16 balls and one to drop
  typedef typename BoxWorld::Vec BV;

  static BoxWorld& boxWorld() {
    static BoxWorld world;  // does not fit on the Nano's stack
    return world;
  }

  static float kineticEnergy(const BoxWorld& w) {
    float e = 0;
    for (uint8_t i = 0; i < BoxWorld::kParticleCapacity; ++i) {
      const typename BoxWorld::ParticleType& p = w.particleAt(i);
      if (!p.inUse()) continue;
      const float vx = p.velocity.x.toFloat(), vy = p.velocity.y.toFloat();
      e += 0.5f / p.inverseMass.toFloat() * (vx * vx + vy * vy);
    }
    return e;
  }

  // The elastic box (Scenes/BouncingBalls.hpp) for `seconds` at 1/256 s:
  // the largest |E(t) / E(0) - 1| of the kinetic energy.
  static float elasticBoxError(uint8_t seconds) {
    BoxWorld& w = boxWorld();
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
  static void buildRow(Box& w, bool sleeping) {
    w.clear();
    BV low, high(1.0, 1.0);
    w.addBox(low, high, S(0.8));
    w.addGravity();
    w.addCollisions(S(0.8));
    if (sleeping) w.enableSleeping();
    for (uint8_t i = 0; i < 16; ++i) {
      BV at(0.03 + 0.06 * i, 0.04);
      w.addParticle(at, S(0.1), S(0.03));
    }
  }

  // The deepest overlap (m) of two balls or of a ball and a wall.
  static float deepestOverlap(const BoxWorld& w) {
    float deepest = 0;
    for (uint8_t i = 0; i < BoxWorld::kParticleCapacity; ++i) {
      const typename BoxWorld::ParticleType& p = w.particleAt(i);
      if (!p.inUse()) continue;
      const float x = p.position.x.toFloat(), y = p.position.y.toFloat();
      const float r = p.radius.toFloat();
      const float walls[4] = {r - x, r - y, x + r - 1, y + r - 1};
      for (uint8_t k = 0; k < 4; ++k) {
        if (walls[k] > deepest) deepest = walls[k];
      }
      for (uint8_t j = i + 1; j < BoxWorld::kParticleCapacity; ++j) {
        const typename BoxWorld::ParticleType& q = w.particleAt(j);
        if (!q.inUse()) continue;
        const float dx = x - q.position.x.toFloat();
        const float dy = y - q.position.y.toFloat();
        const float o = r + q.radius.toFloat() - ::sqrt(dx * dx + dy * dy);
        if (o > deepest) deepest = o;
      }
    }
    return deepest;
  }

  static float fastest(const BoxWorld& w) {
    float v = 0;
    for (uint8_t i = 0; i < BoxWorld::kParticleCapacity; ++i) {
      const typename BoxWorld::ParticleType& p = w.particleAt(i);
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

  // The row for `seconds` at 1/256 s.
  static RestResult rest(uint8_t seconds, bool sleeping) {
    BoxWorld& w = boxWorld();
    buildRow(w, sleeping);
    RestResult r = {0, 0, 0, 0};
    for (uint16_t i = 1; i <= uint16_t(seconds) * 256u; ++i) {
      w.step(S(1.0 / 256));
      if (i <= 2 * 256) continue;
      const float v = fastest(w), d = deepestOverlap(w);
      if (v > r.fastest) r.fastest = v;
      if (d > r.deepest) r.deepest = d;
    }
    for (uint8_t i = 0; i < BoxWorld::kParticleCapacity; ++i) {
      if (w.particleAt(i).isAsleep()) ++r.asleep;
    }
    r.error = w.error();
    return r;
  }

  struct DropResult {
    uint8_t asleepBefore;  // balls asleep when the seventeenth is added
    uint8_t asleepAfter;   // 0.5 s later
    float positions[2 * 17];
  };

  // The row settles for 2 s, then a ball is released 0.3 m above the
  // fifth one's top, 1 cm off its centre; 2 s later the positions.
  static void drop(bool sleeping, DropResult* r) {
    BoxWorld& w = boxWorld();
    buildRow(w, sleeping);
    for (uint16_t i = 0; i < 2 * 256; ++i) w.step(S(1.0 / 256));
    r->asleepBefore = asleepCount(w);
    BV at(0.03 + 0.06 * 4 + 0.01, 0.06 + 0.33);
    w.addParticle(at, S(0.1), S(0.03));
    for (uint16_t i = 1; i <= 2 * 256; ++i) {
      w.step(S(1.0 / 256));
      if (i == 128) r->asleepAfter = asleepCount(w);
    }
    for (uint8_t i = 0; i < 17; ++i) {
      r->positions[2 * i] = w.particleAt(i).position.x.toFloat();
      r->positions[2 * i + 1] = w.particleAt(i).position.y.toFloat();
    }
  }

  static uint8_t asleepCount(const BoxWorld& w) {
    uint8_t n = 0;
    for (uint8_t i = 0; i < BoxWorld::kParticleCapacity; ++i) {
      if (w.particleAt(i).isAsleep()) ++n;
    }
    return n;
  }

  // The row with a contact pool of 8 (it needs about 30 while landing):
  // runs `seconds`; reports the drops and whether every ball is still in
  // the box.
  static bool overflow(uint8_t seconds, uint16_t* error, uint8_t* dropped) {
    static BallsWorld<S, 2, 17, 8> w;
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
