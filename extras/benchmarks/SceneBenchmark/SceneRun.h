// The scenes of the scene benchmark and the run that both the Nano and the
// host reference perform, so that they step exactly the same scene.
//
// Scenes (the library's Scenes/ builders):
//   1 lever     the haptic lever (Scenes/Lever.hpp), 2D or 3D, no user force
//   2 pendulum  L = 1 m, theta0 = 0.5 rad, 1 kg (Scenes/Pendulum.hpp)
//   3 spring    1 kg, k = 100 N/m, 0.1 m beyond rest (Scenes/Spring.hpp)
//   4 balls     N balls in the 1 m box (Scenes/BouncingBalls.hpp)
//
// A run: build the scene, report the state at t = 0, step it for 10 s of
// scene time at dt = 2^-shift s, report the state after 1 s and after 10 s.
// The reporter R is told about every step (the Nano times them) and gets the
// world to print at the three instants.
#pragma once

#include <stdint.h>

namespace scenebench {

using namespace tinyparticle;

enum : uint8_t { kLever = 1, kPendulum = 2, kSpring = 3, kBalls = 4 };

template <typename S, uint8_t Dim, uint8_t Scene, uint8_t N>
struct SceneSpec;

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kLever, N> {
  typedef LeverWorld<S, Dim> WorldType;
  static typename WorldType::Vec userForce;  // stays zero
  static void build(WorldType& world) { buildLever(world, &userForce); }
};
template <typename S, uint8_t Dim, uint8_t N>
typename SceneSpec<S, Dim, kLever, N>::WorldType::Vec
    SceneSpec<S, Dim, kLever, N>::userForce;

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kPendulum, N> {
  typedef PendulumWorld<S, Dim> WorldType;
  static void build(WorldType& world) {
    buildPendulum(world, S(1.0), S(0.5), S(1.0));
  }
};

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kSpring, N> {
  typedef SpringWorld<S, Dim> WorldType;
  static void build(WorldType& world) { buildSpring(world); }
};

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kBalls, N> {
  typedef BallsWorld<S, Dim, N> WorldType;
  static void build(WorldType& world) { buildBouncingBalls(world, N); }
};

// The world lives in static storage: a 16-ball world does not fit on the
// Nano's stack.
template <class Spec>
typename Spec::WorldType& sceneWorld() {
  static typename Spec::WorldType world;
  return world;
}

template <class Spec, class Reporter>
void runScene(Reporter& reporter, uint8_t shift) {
  typedef typename Spec::WorldType W;
  typedef typename W::Scalar S;
  W& world = sceneWorld<Spec>();
  Spec::build(world);
  // 2^-shift is exact in every scalar that can represent it at all.
  const S dt = S(1) / S(long(1) << shift);
  const uint16_t perSecond = uint16_t(1) << shift;
  reporter.state(world, 0);
  for (uint16_t step = 1; step <= 10 * perSecond; ++step) {
    reporter.beforeStep();
    world.step(dt);
    reporter.afterStep(step, perSecond);
    if (step == perSecond) reporter.state(world, 1);
  }
  reporter.state(world, 10);
  reporter.finish(world);
}

}  // namespace scenebench
