// Test support: the rope of Scenes/Chain.hpp (buildRope) against the
// discrete catenary of the same links, for any scalar (extras/test/RopeTest,
// extras/test/RopeFloatTest).
//
// The catenary: seven equal point masses on eight rigid links of 0.1 m
// between posts 0.6 m apart at the same height, at rest; computed in double
// by extras/benchmarks/tools/catenary.py (its --cpp output is below).
// Not included by TinyParticle.h: include it after <TinyParticle.h>.
#pragma once

#include <math.h>
#include <stdint.h>

#include "../../TinyParticle.hpp"

namespace tinyparticle {
namespace testing {

// The beads, left to right (m). Made by extras/benchmarks/tools/catenary.py --links 8 --length 0.1 --span 0.6 --cpp
static const float kCatenarySag = 0.237591347f;  // m, depth of the lowest bead
static const float kCatenary[7][2] = {
    {0.053426880f, -0.084531465f},
    {0.119694107f, -0.159422416f},
    {0.202460526f, -0.215544781f},
    {0.300000000f, -0.237591347f},
    {0.397539474f, -0.215544781f},
    {0.480305893f, -0.159422416f},
    {0.546573120f, -0.084531465f},
};

struct RopeResult {
  float sagError;     // |sag / catenary sag - 1|
  float worstBead;    // largest distance of a bead from its catenary place, m
  float asymmetry;    // largest distance of bead k from bead 8 - k mirrored, m
  uint16_t error;     // world.error()
};

// The rope after 20 s at dt = 1/256 s, compared with the catenary.
template <typename S>
struct RopeChecks {
  static RopeResult settle() {
    typedef RopeWorld<S, 2> W;
    static W world;  // (static: keeps the Nano's stack small)
    world.clear();  // in place: W() would build a second world on the stack
    const RopeScene rope = buildRope(world);
    const S dt = S(1) / S(256);
    for (uint16_t n = 0; n < 20 * 256; ++n) world.step(dt);
    float x[RopeShape::kBeads], y[RopeShape::kBeads];
    for (uint8_t k = 0; k < RopeShape::kBeads; ++k) {
      const typename W::ParticleType* p = world.particle(rope.beads[k]);
      x[k] = p->position.x.toFloat();
      y[k] = p->position.y.toFloat();
    }
    RopeResult r = {0, 0, 0, world.error()};
    float lowest = 0;
    for (uint8_t k = 0; k < RopeShape::kBeads; ++k) {
      if (y[k] < lowest) lowest = y[k];
      const float dx = x[k] - kCatenary[k][0], dy = y[k] - kCatenary[k][1];
      const float off = ::sqrtf(dx * dx + dy * dy);
      if (off > r.worstBead) r.worstBead = off;
      const uint8_t m = RopeShape::kBeads - 1 - k;  // bead 8 - k, counting from 1
      const float mx = (0.6f - x[m]) - x[k], my = y[m] - y[k];
      const float skew = ::sqrtf(mx * mx + my * my);
      if (skew > r.asymmetry) r.asymmetry = skew;
    }
    r.sagError = ::fabsf(-lowest / kCatenarySag - 1);
    return r;
  }
};

}  // namespace testing
}  // namespace tinyparticle
