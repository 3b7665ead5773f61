// The double-precision reference for the scene benchmark: the same scenes
// (SceneBenchmark/SceneRun.h) and the same engine templates, run on the PC
// with the Double scalar (Double.h).
//
//   SceneReference <scene> <n> <dim> <rate> [<seconds>]
//
// (n: the balls or the chain's beads; dt = 1 / rate s; 10 s by default)
// prints the state lines "P <t> <index> <inverse mass> <position...>
// <velocity...>" at t = 0, 1, 10 s and at the end in decimal, "M <largest
// link error> <largest energy error>", then "W <world error> <math errors>"
// and "E". Built and run by extras/benchmarks/tools/bench.py.
#include <stdio.h>
#include <stdlib.h>

#include "Double.h"
#include "SceneRun.h"

namespace {

using tinyparticle::Double;

struct HostReport {
  void beforeStep() {}
  void afterStep(uint32_t, uint16_t, uint8_t) {}

  void errors(double link, double energy) {
    printf("M %.17g %.17g\n", link, energy);
  }

  template <class W>
  void state(const W& world, uint8_t seconds) {
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const typename W::ParticleType& p = world.particleAt(i);
      if (!p.inUse()) continue;
      printf("P %u %u %.17g", unsigned(seconds), unsigned(i),
             p.inverseMass.toDouble());
      for (uint8_t k = 0; k < W::kDimensions; ++k) {
        printf(" %.17g", p.position[k].toDouble());
      }
      for (uint8_t k = 0; k < W::kDimensions; ++k) {
        printf(" %.17g", p.velocity[k].toDouble());
      }
      printf("\n");
    }
  }

  template <class W>
  void finish(const W& world) {
    printf("W %u %u\n", unsigned(world.error()),
           unsigned(tinyparticle::mathErrors()));
  }
};

template <uint8_t Dim, uint8_t Scene, uint8_t N>
int run(uint16_t rate, uint8_t seconds) {
  HostReport report;
  scenebench::runScene<scenebench::SceneSpec<Double, Dim, Scene, N>, double>(
      report, rate, seconds);
  printf("E\n");
  return 0;
}

int usage() {
  fprintf(stderr,
          "usage: SceneReference <scene 1-10> <balls 2|4|8|16 or beads "
          "2|4|8|16> <dim 2|3> <rate 1-4096> [<seconds 1-255>]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5 && argc != 6) return usage();
  const int scene = atoi(argv[1]);
  const int n = atoi(argv[2]);
  const int dim = atoi(argv[3]);
  const int rate = atoi(argv[4]);
  const int seconds = argc == 6 ? atoi(argv[5]) : 10;
  if (rate < 1 || rate > 4096 || seconds < 1 || seconds > 255) return usage();
  const uint16_t r = uint16_t(rate);
  const uint8_t s = uint8_t(seconds);
  using namespace scenebench;
  if (scene == kLever && dim == 2) return run<2, kLever, 2>(r, s);
  if (scene == kLever && dim == 3) return run<3, kLever, 2>(r, s);
  if (scene == kPendulum && dim == 2) return run<2, kPendulum, 2>(r, s);
  if (scene == kPendulum && dim == 3) return run<3, kPendulum, 2>(r, s);
  if (scene == kPendulumShort && dim == 2) {
    return run<2, kPendulumShort, 2>(r, s);
  }
  if (scene == kSpring && dim == 2) return run<2, kSpring, 1>(r, s);
  if (scene == kSpring && dim == 3) return run<3, kSpring, 1>(r, s);
  if (scene == kRope && dim == 2) return run<2, kRope, 7>(r, s);
  if (scene == kBalls && dim == 2) {
    switch (n) {
      case 2: return run<2, kBalls, 2>(r, s);
      case 4: return run<2, kBalls, 4>(r, s);
      case 8: return run<2, kBalls, 8>(r, s);
      case 16: return run<2, kBalls, 16>(r, s);
    }
  }
  if (scene == kPile && dim == 2 && n == 16) return run<2, kPile, 16>(r, s);
  if (scene == kElasticBox && dim == 2 && n == 16) {
    return run<2, kElasticBox, 16>(r, s);
  }
  if (scene == kCradle && dim == 2) return run<2, kCradle, 5>(r, s);
  if (scene == kChain && dim == 2) {
    switch (n) {
      case 2: return run<2, kChain, 2>(r, s);
      case 4: return run<2, kChain, 4>(r, s);
      case 8: return run<2, kChain, 8>(r, s);
      case 16: return run<2, kChain, 16>(r, s);
    }
  }
  return usage();
}
