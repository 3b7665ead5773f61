// The scenes of the scene benchmark and the run that both the Nano and the
// host reference perform, so that they step exactly the same scene.
//
// Scenes (the library's Scenes/ builders):
//   1 lever           the haptic lever (Scenes/Lever.hpp), 2D or 3D, no
//                     user force
//   2 pendulum        L = 1 m, theta0 = 0.5 rad, 1 kg (Scenes/Pendulum.hpp)
//   3 spring          1 kg, k = 100 N/m, 0.1 m beyond rest (Scenes/Spring.hpp)
//   4 balls           N balls in the 1 m box (Scenes/BouncingBalls.hpp),
//                     sleeping on
//   5 chain           the whip chain of N beads (Scenes/Chain.hpp)
//   6 rope            7 damped beads between two posts (Scenes/Chain.hpp)
//   7 pendulum_short  L = 0.05 m, theta0 = 0.5 rad, 0.1 kg
//   8 pile            16 balls released at rest 1 cm above the floor, side by
//                     side: a settled pile, without sleeping (what resting
//                     contacts cost in every step)
//   9 elastic_box     16 balls in the box, restitution 1, no gravity
//                     (Scenes/BouncingBalls.hpp, buildElasticBox)
//  10 cradle          Newton's cradle (Scenes/Cradle.hpp)
//
// A run: build the scene, report the state at t = 0, step it for `seconds`
// of scene time at dt = 1 / rate s (any rate; the step count is 32 bits),
// report the state after 1 s, 10 s and at the end. The reporter R is told
// about every step (the Nano times them) and gets the world to print at
// those instants. Between steps, outside the timed span, a Tracker follows
// the largest relative error of a rod's length and the largest |E(t) -
// E(0)| in the scene's reference energy (Spec::referenceEnergy(), 0 where
// the scene has none: the balls and the damped rope), computed in R's real
// type (float on the Nano, double on the PC).
#pragma once

#include <math.h>
#include <stdint.h>

namespace scenebench {

using namespace tinyparticle;

enum : uint8_t {
  kLever = 1,
  kPendulum = 2,
  kSpring = 3,
  kBalls = 4,
  kChain = 5,
  kRope = 6,
  kPendulumShort = 7,
  kPile = 8,
  kElasticBox = 9,
  kCradle = 10
};

// Standard gravity as the engine's scenes use it (m/s^2).
const double kG = 9.81;

template <typename S, uint8_t Dim, uint8_t Scene, uint8_t N>
struct SceneSpec;

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kLever, N> {
  typedef LeverWorld<S, Dim> WorldType;
  static typename WorldType::Vec userForce;  // stays zero
  static void build(WorldType& world) { buildLever(world, &userForce); }
  // Falling from level to straight down: m g L.
  static double referenceEnergy() { return 0.1 * kG * 0.15; }
  static const bool kGravity = true;
  static const bool kSpringEnergy = false;
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
  // The swing: m g L (1 - cos theta0).
  static double referenceEnergy() { return 1.0 * kG * 1.0 * (1 - ::cos(0.5)); }
  static const bool kGravity = true;
  static const bool kSpringEnergy = false;
};

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kPendulumShort, N> {
  typedef PendulumWorld<S, Dim> WorldType;
  static void build(WorldType& world) {
    buildPendulum(world, S(0.05), S(0.5), S(0.1));
  }
  static double referenceEnergy() { return 0.1 * kG * 0.05 * (1 - ::cos(0.5)); }
  static const bool kGravity = true;
  static const bool kSpringEnergy = false;
};

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kSpring, N> {
  typedef SpringWorld<S, Dim> WorldType;
  static void build(WorldType& world) { buildSpring(world); }
  // The spring's energy at release: k (0.1 m)^2 / 2.
  static double referenceEnergy() { return 0.5 * 100 * 0.1 * 0.1; }
  static const bool kGravity = false;
  static const bool kSpringEnergy = true;
};

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kBalls, N> {
  typedef BallsWorld<S, Dim, N> WorldType;
  static void build(WorldType& world) {
    buildBouncingBalls(world, N);
    world.enableSleeping();
  }
  static double referenceEnergy() { return 0; }  // bounces lose energy
  static const bool kGravity = true;
  static const bool kSpringEnergy = false;
};

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kChain, N> {
  typedef ChainWorld<S, Dim, N> WorldType;
  static void build(WorldType& world) { buildChain(world, N); }
  // Falling from level to hanging: E_fall = m g 0.125 N (N + 1) / 2.
  static double referenceEnergy() {
    return 0.05 * kG * 0.125 * N * (N + 1) / 2;
  }
  static const bool kGravity = true;
  static const bool kSpringEnergy = false;
};

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kRope, N> {
  typedef RopeWorld<S, Dim> WorldType;
  static void build(WorldType& world) { buildRope(world); }
  static double referenceEnergy() { return 0; }  // damped: it settles
  static const bool kGravity = true;
  static const bool kSpringEnergy = false;
};

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kPile, N> {
  typedef BallsWorld<S, Dim, N> WorldType;
  static void build(WorldType& world) {
    typedef typename WorldType::Vec V;
    V low, high;
    for (uint8_t k = 0; k < Dim; ++k) high[k] = S(1);
    world.addBox(low, high, S(0.8));
    world.addGravity();
    world.addCollisions(S(0.8));
    for (uint8_t i = 0; i < N; ++i) {
      V at;
      at.x = S(0.03) + S(0.06) * S(int(i));
      at.y = S(0.04);
      if (Dim == 3) at[2] = S(0.5);
      world.addParticle(at, S(0.1), S(0.03));
    }
  }
  static double referenceEnergy() { return 0; }  // it lands and rests
  static const bool kGravity = true;
  static const bool kSpringEnergy = false;
};

// The kinetic energy at the start (J), the elastic box's reference.
template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kElasticBox, N> {
  typedef BallsWorld<S, Dim, N, 8> WorldType;  // two contacts at a time
  static double start;
  static void build(WorldType& world) {
    buildElasticBox(world, N);
    start = 0;
    for (uint8_t i = 0; i < N; ++i) {
      const typename WorldType::ParticleType& p = world.particleAt(i);
      double v2 = 0;
      for (uint8_t k = 0; k < Dim; ++k) {
        const double v = p.velocity[k].toFloat();
        v2 += v * v;
      }
      start += 0.5 / p.inverseMass.toFloat() * v2;
    }
  }
  static double referenceEnergy() { return start; }
  static const bool kGravity = false;
  static const bool kSpringEnergy = false;
};
template <typename S, uint8_t Dim, uint8_t N>
double SceneSpec<S, Dim, kElasticBox, N>::start = 0;

template <typename S, uint8_t Dim, uint8_t N>
struct SceneSpec<S, Dim, kCradle, N> {
  typedef CradleWorld<S> WorldType;
  static void build(WorldType& world) { buildCradle(world); }
  // The first ball's drop: m g L (1 - cos 60 degrees), 0.1 kg, 0.5 m.
  static double referenceEnergy() { return 0.1 * kG * 0.25; }
  static const bool kGravity = true;
  static const bool kSpringEnergy = false;
};

// The world lives in static storage: a 16-ball world does not fit on the
// Nano's stack.
template <class Spec>
typename Spec::WorldType& sceneWorld() {
  static typename Spec::WorldType world;
  return world;
}

// The spring scene's energy beyond the motion: k (|x| - rest)^2 / 2 with
// its anchor at the origin (Scenes/Spring.hpp).
template <typename R, class W>
R springEnergy(const W& world, bool has) {
  if (!has) return R(0);
  const typename W::ParticleType& p = world.particleAt(0);
  R r2 = 0;
  for (uint8_t k = 0; k < W::kDimensions; ++k) {
    const R x = R(p.position[k].toFloat());
    r2 += x * x;
  }
  const R stretch = R(::sqrt(r2)) - R(0.5);
  return R(50) * stretch * stretch;
}

// Follows a run between steps: the largest relative error of a rod's length
// and the largest |E(t) - E(0)| over the reference energy, in the real type
// R.
template <class Spec, typename R>
class Tracker {
 public:
  typedef typename Spec::WorldType W;

  Tracker() : mStart(0), mLinkError(0), mEnergyError(0) {}

  void begin(const W& world) { mStart = energy(world); }

  void update(const W& world) {
    for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
      const typename W::ConstraintSlot& c = WorldAccess::constraint(world, i);
      if (!c.inUse() || !WorldAccess::isRod(world, c)) continue;
      const typename W::LinkParamsType& link =
          c.params.template as<typename W::LinkParamsType>();
      const typename W::ParticleType& a = world.particleAt(c.a);
      R d2 = 0;
      for (uint8_t k = 0; k < W::kDimensions; ++k) {
        const R other = c.b == kAnchorIndex
                            ? R(link.anchor[k].toFloat())
                            : R(world.particleAt(c.b).position[k].toFloat());
        const R d = R(a.position[k].toFloat()) - other;
        d2 += d * d;
      }
      const R length = R(link.length.toFloat());
      R e = R(::sqrt(d2)) / length - R(1);
      if (e < 0) e = -e;
      if (e > mLinkError) mLinkError = e;
    }
    if (Spec::referenceEnergy() > 0) {
      R e = (energy(world) - mStart) / R(Spec::referenceEnergy());
      if (e < 0) e = -e;
      if (e > mEnergyError) mEnergyError = e;
    }
  }

  R linkError() const { return mLinkError; }
  // Negative where the scene has no reference energy.
  R energyError() const {
    return Spec::referenceEnergy() > 0 ? mEnergyError : R(-1);
  }

 private:
  // Kinetic plus potential energy of the movable particles (J), heights
  // from y = 0.
  static R energy(const W& world) {
    if (!(Spec::referenceEnergy() > 0)) return R(0);
    R e = 0;
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const typename W::ParticleType& p = world.particleAt(i);
      if (!p.inUse() || p.isImmovable()) continue;
      const R m = R(1) / R(p.inverseMass.toFloat());
      R v2 = 0;
      for (uint8_t k = 0; k < W::kDimensions; ++k) {
        const R v = R(p.velocity[k].toFloat());
        v2 += v * v;
      }
      e += m * (v2 / 2 + (Spec::kGravity ? R(kG) * R(p.position.y.toFloat())
                                         : R(0)));
    }
    return e + springEnergy<R>(world, Spec::kSpringEnergy);
  }

  R mStart;
  R mLinkError;
  R mEnergyError;
};

template <class Spec, typename R, class Reporter>
void runScene(Reporter& reporter, uint16_t rate, uint8_t seconds) {
  typedef typename Spec::WorldType W;
  typedef typename W::Scalar S;
  W& world = sceneWorld<Spec>();
  Spec::build(world);
  // 1/rate is exact in every scalar for the powers of two it can represent;
  // other rates get the nearest step the scalar has.
  const S dt = S(1) / S(long(rate));
  const uint32_t steps = uint32_t(rate) * seconds;
  Tracker<Spec, R> tracker;
  tracker.begin(world);
  reporter.state(world, 0);
  for (uint32_t step = 1; step <= steps; ++step) {
    reporter.beforeStep();
    world.step(dt);
    reporter.afterStep(step, rate, seconds);
    tracker.update(world);
    if (step == rate) reporter.state(world, 1);
    if (step == 10 * uint32_t(rate)) reporter.state(world, 10);
  }
  if (seconds != 1 && seconds != 10) reporter.state(world, seconds);
  reporter.errors(tracker.linkError(), tracker.energyError());
  reporter.finish(world);
}

}  // namespace scenebench
