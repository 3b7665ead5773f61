// The double-precision reference for the scene benchmark: the same scenes
// (SceneBenchmark/SceneRun.h) and the same engine templates, run on the PC
// with the Double scalar (Double.h).
//
//   SceneReference <scene> <balls> <dim> <shift>
//
// prints the state lines "P <t> <index> <inverse mass> <position...>
// <velocity...>" at t = 0, 1 and 10 s in decimal, then "W <world error>
// <math errors>" and "E". Built and run by extras/benchmarks/tools/bench.py.
#include <stdio.h>
#include <stdlib.h>

#include "Double.h"
#include "SceneRun.h"

namespace {

using tinyparticle::Double;

struct HostReport {
  void beforeStep() {}
  void afterStep(uint16_t, uint16_t) {}

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
int run(uint8_t shift) {
  HostReport report;
  scenebench::runScene<scenebench::SceneSpec<Double, Dim, Scene, N> >(report,
                                                                      shift);
  printf("E\n");
  return 0;
}

int usage() {
  fprintf(stderr,
          "usage: SceneReference <scene 1-4> <balls 2|4|8|16> <dim 2|3> "
          "<shift 0-12>\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) return usage();
  const int scene = atoi(argv[1]);
  const int balls = atoi(argv[2]);
  const int dim = atoi(argv[3]);
  const int shift = atoi(argv[4]);
  if (shift < 0 || shift > 12) return usage();
  const uint8_t s = uint8_t(shift);
  using namespace scenebench;
  if (scene == kLever && dim == 2) return run<2, kLever, 2>(s);
  if (scene == kLever && dim == 3) return run<3, kLever, 2>(s);
  if (scene == kPendulum && dim == 2) return run<2, kPendulum, 2>(s);
  if (scene == kPendulum && dim == 3) return run<3, kPendulum, 2>(s);
  if (scene == kSpring && dim == 2) return run<2, kSpring, 1>(s);
  if (scene == kSpring && dim == 3) return run<3, kSpring, 1>(s);
  if (scene == kBalls && dim == 2) {
    switch (balls) {
      case 2: return run<2, kBalls, 2>(s);
      case 4: return run<2, kBalls, 4>(s);
      case 8: return run<2, kBalls, 8>(s);
      case 16: return run<2, kBalls, 16>(s);
    }
  }
  return usage();
}
