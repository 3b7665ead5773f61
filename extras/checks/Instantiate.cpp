// Compile check of the library core without any Arduino core (see Makefile).
//
// Templates are only compiled when instantiated, so this file instantiates
// every public class template explicitly, for every scalar type, and calls the
// free function templates once. A warning anywhere in that code then fails
// the check on avr-g++, host g++ and arm-none-eabi-g++.
//
// CONTRIBUTORS: when you add a class template (or free function template) to
// the library, append its instantiations below, in the section for your area.
#include "TinyParticle.hpp"

namespace tinyparticle {

// ---- Math --------------------------------------------------------------
template class Fixed<16, 16>;
template class Fixed<24, 8>;
template class Fixed<8, 8>;

template struct Vec<Q16_16, 2>;
template struct Vec<Q16_16, 3>;
template struct Vec<Q24_8, 2>;
template struct Vec<Q24_8, 3>;
template struct Vec<Q8_8, 2>;
template struct Vec<Q8_8, 3>;
template struct Vec<Float, 2>;
template struct Vec<Float, 3>;
// Formats beyond the named ones: the widest fraction, a 16-bit one.
template class Fixed<2, 30>;
template class Fixed<4, 12>;
template struct Vec<Fixed<2, 30>, 3>;

// ---- World, Forces, Contacts, Render, Loop, Scenes ----------------------
// (append here)
// Every member of World, so every generator its add functions reference,
// for each scalar and dimension; and the empty-pool corner (capacity 0).
template struct Particle<Q16_16, 2>;
template struct Particle<Float, 3>;
template struct Particle<Q16_16, 2, false>;  // a world's without force slots
template struct Particle<Float, 3, false>;
template struct Contact<Q16_16, 2>;
template class World<Q16_16, 2, 4, 4, 4, 4>;
template class World<Q16_16, 3, 4, 4, 4, 4>;
template class World<Q24_8, 2, 4, 4, 4, 4>;
template class World<Q24_8, 3, 4, 4, 4, 4>;
template class World<Float, 2, 4, 4, 4, 4>;
template class World<Float, 3, 4, 4, 4, 4>;
template class AsciiRenderer<World<Q16_16, 2, 4, 4, 4, 4> >;
template class AsciiRenderer<World<Float, 3, 4, 4, 4, 4>, 80, 25>;
template class AsciiRenderer<World<Q16_16, 2, 1> >;
template class AsciiRenderer<World<Q16_16, 2, 4, 4, 4, 4>, 40, 20,
                             ParticleShape::kPoints>;
struct CheckClock {
  static uint32_t micros() { return 0; }
};
template class BasicRealTimeLoop<CheckClock>;

}  // namespace tinyparticle

// Free function templates: called once per scalar so that their bodies are
// compiled. Not meant to run.
template <typename S>
S checkVectorFunctions() {
  tinyparticle::Vec2<S> a(S(1), S(2));
  tinyparticle::Vec3<S> b(S(1), S(2), S(3));
  tinyparticle::Vec3<S> c = cross(b, b);
  return dot(a, a) + cross(a, a) + dot(b, c) + (S(2) * a).x;
}

template tinyparticle::Q16_16 checkVectorFunctions<tinyparticle::Q16_16>();
template tinyparticle::Q24_8 checkVectorFunctions<tinyparticle::Q24_8>();
template tinyparticle::Q8_8 checkVectorFunctions<tinyparticle::Q8_8>();
template tinyparticle::Float checkVectorFunctions<tinyparticle::Float>();

// A sketch's own generator of every shape (World::addForce, addConstraint).
template <class W>
struct CheckGenerator {
  typedef typename W::ParticleType P;
  typedef typename W::Scalar S;
  void apply(P& p, S) { p.addForce(typename W::Vec()); }
  void apply(P&, P&, S) {}
  bool contact(const P&, typename W::Vec&, S&) { return false; }
  bool contact(const P&, const P&, typename W::Vec&, S&) { return false; }
};

// World, Forces, Contacts, Render, Loop, Scenes: stepping, drawing and the
// scene builders for each scalar and dimension. Not meant to run.
template <typename S, uint8_t D>
void checkEngine() {
  typedef tinyparticle::World<S, D, 4, 4, 4, 4> W;
  static W world;
  static typename W::Vec push;
  static CheckGenerator<W> mine;
  const tinyparticle::ParticleId a = world.idOf(0), b = world.idOf(1);
  world.addForce(mine);
  world.addForce(mine, a);
  world.addForce(mine, a, b);
  world.addConstraint(mine, S(0.5));
  world.addConstraint(mine, a, S(0.5));
  world.addConstraint(mine, a, b, S(0.5));
  world.template forceParams<tinyparticle::DragForce<S, D> >(
      tinyparticle::ForceId());
  world.template constraintParams<typename W::LinkParamsType>(
      tinyparticle::ConstraintId());
  world.step(S(1.0 / 256));
  world.step(S(1.0 / 256), 2);
  struct Sink {
    size_t write(uint8_t) { return 1; }
  } sink;
  tinyparticle::AsciiRenderer<W> renderer(S(0), S(0), S(0.1), S(0.2));
  renderer.draw(world, sink);
  static tinyparticle::LeverWorld<S, D> lever;
  buildLever(lever, &push);
  lever.step(S(1.0 / 256));
  static tinyparticle::PendulumWorld<S, D> pendulum;
  buildPendulum(pendulum, S(1), S(0.2), S(1));
  static tinyparticle::SpringWorld<S, D> spring;
  buildSpring(spring);
  static tinyparticle::BallsWorld<S, D, 4, 8> balls;
  buildBouncingBalls(balls, 4);
  balls.enableSleeping();
  balls.step(S(1.0 / 256));
  static tinyparticle::World<S, D, 1> bare;
  bare.step(S(1.0 / 256));
}

// Worlds with empty pools: every call that does not add to a missing pool
// (those do not compile, by design: extras/checks/fail/No*Slot.cpp; nor
// does applyForce() without a force slot: ApplyForceNoForceSlot.cpp), so no
// explicit instantiation of the whole class here.
template <typename W>
void checkEmptyPools() {
  static W world;
  typename W::Vec at;
  const tinyparticle::ParticleId id = world.idOf(0);
  world.particle(id);
  world.removeForce(world.addGravity(at));  // the world's: no slot
  world.removeParticle(id);
  world.removeForce(tinyparticle::ForceId());
  world.force(tinyparticle::ForceId());
  world.constraint(tinyparticle::ConstraintId());
  world.removeConstraint(tinyparticle::ConstraintId());
  world.setLength(tinyparticle::ConstraintId(), typename W::Scalar(1));
  world.step(typename W::Scalar(1.0 / 256));
  world.setIterationCap(uint8_t(world.particleCount() + world.contactCount() +
                                world.stats().peakContacts + world.error()));
  world.clearError();
  world.clear();
}

template void checkEmptyPools<tinyparticle::World<tinyparticle::Q16_16, 2, 1> >();
template void checkEmptyPools<tinyparticle::World<tinyparticle::Float, 3, 1> >();
template void checkEmptyPools<tinyparticle::World<tinyparticle::Q16_16, 2, 0, 0, 0, 0> >();

template void checkEngine<tinyparticle::Q16_16, 2>();
template void checkEngine<tinyparticle::Q16_16, 3>();
template void checkEngine<tinyparticle::Q24_8, 2>();
template void checkEngine<tinyparticle::Float, 2>();
template void checkEngine<tinyparticle::Float, 3>();

// Text: print() and println() for each scalar and its vectors, and the
// real-time loop's dt for each.
struct CheckSink {
  size_t write(uint8_t) { return 1; }
};
template <typename S>
S checkPrinting() {
  CheckSink sink;
  tinyparticle::print(sink, S(1));
  tinyparticle::print(sink, S(-1), 3);
  tinyparticle::println(sink, tinyparticle::Vec2<S>(S(1), S(2)));
  tinyparticle::println(sink, tinyparticle::Vec3<S>(S(1), S(2), S(3)), 2);
  return tinyparticle::BasicRealTimeLoop<tinyparticle::CheckClock>(256, 0)
      .dt<S>();
}
template tinyparticle::Q16_16 checkPrinting<tinyparticle::Q16_16>();
template tinyparticle::Q24_8 checkPrinting<tinyparticle::Q24_8>();
template tinyparticle::Q8_8 checkPrinting<tinyparticle::Q8_8>();
template tinyparticle::Fixed<2, 30> checkPrinting<tinyparticle::Fixed<2, 30> >();
template tinyparticle::Fixed<4, 12> checkPrinting<tinyparticle::Fixed<4, 12> >();
template tinyparticle::Float checkPrinting<tinyparticle::Float>();

// Math: every free function of the scalar interface, for each scalar.
template <typename S>
S checkScalarFunctions() {
  S a(0.5), b(-2);
  uint16_t t = radiansToTurns(a);
  S r = fabs(b) + fmin(a, b) + fmax(a, b) + clamp(a, b, S(1));
  r += sqrt(a) + atan2(a, b) + sin(a) + cos(b);
  r += tinyparticle::sinTurns<S>(t) + tinyparticle::cosTurns<S>(uint16_t(t + 1));
  r += S::pi() + S::epsilon() + S::largest() + S::lowest();
  tinyparticle::Vec3<S> v(a, b, r);
  tinyparticle::Vec2<S> w(a, b);
  r += v.magnitudeAndNormalize() + w.magnitudeAndNormalize();
  return r + S(v.normalize() && w.normalize() ? 1 : 0);
}

template tinyparticle::Q16_16 checkScalarFunctions<tinyparticle::Q16_16>();
template tinyparticle::Q24_8 checkScalarFunctions<tinyparticle::Q24_8>();
template tinyparticle::Q8_8 checkScalarFunctions<tinyparticle::Q8_8>();
template tinyparticle::Float checkScalarFunctions<tinyparticle::Float>();
template tinyparticle::Fixed<2, 30>
checkScalarFunctions<tinyparticle::Fixed<2, 30> >();
template tinyparticle::Fixed<4, 12>
checkScalarFunctions<tinyparticle::Fixed<4, 12> >();

// Math for the engine: the multiply by dt (Scaler) and the cheap tests and
// halving the engine's per-step paths use, for each scalar.
template class tinyparticle::Scaler<tinyparticle::Q16_16>;
template class tinyparticle::Scaler<tinyparticle::Float>;
template <typename S>
S checkEngineMath() {
  const tinyparticle::Scaler<S> byDt(S(1.0 / 256));
  const tinyparticle::Scaler<S> byOther(S(0.3));
  S r = byDt(S(2)) + byOther(S(-2)) + byDt.factor();
  r += tinyparticle::detail::half(r);
  tinyparticle::Vec2<S> v(r, S(1));
  tinyparticle::Vec3<S> w(S(1), r, S(0));
  tinyparticle::detail::subtractNonZero(v, v);
  tinyparticle::detail::subtractNonZero(w, w);
  const bool flags =
      tinyparticle::detail::isZero(r) || tinyparticle::detail::isNegative(r) ||
      tinyparticle::detail::isPositive(r) ||
      tinyparticle::detail::isZeroVector(v) ||
      tinyparticle::detail::isZeroVector(w);
  return r + S(flags ? 1 : 0);
}

template tinyparticle::Q16_16 checkEngineMath<tinyparticle::Q16_16>();
template tinyparticle::Q24_8 checkEngineMath<tinyparticle::Q24_8>();
template tinyparticle::Q8_8 checkEngineMath<tinyparticle::Q8_8>();
template tinyparticle::Float checkEngineMath<tinyparticle::Float>();
template tinyparticle::Fixed<2, 30>
checkEngineMath<tinyparticle::Fixed<2, 30> >();
template tinyparticle::Fixed<4, 12>
checkEngineMath<tinyparticle::Fixed<4, 12> >();

// Fixed only: the raw operations and binary-angle atan2.
template <uint8_t I, uint8_t F>
int32_t checkFixedFunctions() {
  typedef tinyparticle::Fixed<I, F> T;
  typename T::Raw x = T::referenceMultiply(1, 2) + T::referenceDivide(3, 4);
  x += T::referenceSquareRoot(5) + T::squareRoot(6) + T::multiply(7, 8);
  return x + T::divide(9, 10) + atan2Turns(T(1), T(-1)) + T(2).toInt();
}

template int32_t checkFixedFunctions<16, 16>();
template int32_t checkFixedFunctions<24, 8>();
template int32_t checkFixedFunctions<8, 8>();
template int32_t checkFixedFunctions<2, 30>();

// ---- Testing (src/TinyParticle/Testing/) ---------------------------------
// The helpers that the test and benchmark sketches share. TinyParticle.hpp
// does not include them, so they are included here on their own, and every
// template is instantiated for the scalars its sketches use. Not meant to
// run. CycleCounter.hpp is AVR-only (Timer1): the avr and macros checks
// compile it, with its interrupt handler.
#include "TinyParticle/Testing/AsmClasses.hpp"
#include "TinyParticle/Testing/BallChecks.hpp"
#include "TinyParticle/Testing/CollisionChecks.hpp"
#include "TinyParticle/Testing/ImmovableChecks.hpp"
#include "TinyParticle/Testing/MathTestSupport.hpp"
#include "TinyParticle/Testing/PendulumChecks.hpp"
#include "TinyParticle/Testing/RodEnergyChecks.hpp"
#include "TinyParticle/Testing/StackChecks.hpp"
#include "TinyParticle/Testing/VecChecks.hpp"
#include "TinyParticle/Testing/WorldChecks.hpp"
#if defined(__AVR__)
#include "TinyParticle/Testing/CycleCounter.hpp"
#endif

namespace tinyparticle {
namespace testing {

template struct WorldChecks<Q16_16>;
template struct WorldChecks<Float>;
template struct CollisionChecks<Q16_16>;
template struct CollisionChecks<Float>;
template struct StackChecks<Q16_16>;
template struct StackChecks<Float>;
template struct PendulumChecks<Q16_16>;
template struct PendulumChecks<Float>;
template struct RodEnergyChecks<Q16_16>;
template struct RodEnergyChecks<Float>;
template struct ImmovableChecks<Q16_16>;
template struct ImmovableChecks<Float>;
template struct BallChecks<Q16_16, 2>;
template struct BallChecks<Q16_16, 3>;
template struct BallChecks<Float, 2>;
template struct BallChecks<Float, 3>;
template struct VecArithmetic<Q16_16>;
template struct VecArithmetic<Q24_8>;
template struct VecArithmetic<Q8_8>;
template struct VecArithmetic<Float>;
template struct VecLengths<Q16_16, double>;
template struct VecLengths<Q24_8, float>;
template struct VecLengths<Q8_8, double>;

}  // namespace testing
}  // namespace tinyparticle

// The free helpers, with a stand-in for Serial (any type with print() and
// println() serves).
struct CheckPrint {
  void print(const char*) {}
  void print(long) {}
  void println(long) {}
};

long checkTestingHelpers() {
  using namespace tinyparticle;
  testing::XorShift32 random(1);
  CheckPrint out;
  testing::printFailure(out, "check", 1, 2, 3);
  long r = long(random.next() & 0xff);
  r += testing::randomRaw<int16_t>(random, 15);
  r += testing::randomRawOfLength<int32_t>(random, 31);
  r += long(testing::magnitude64(-5));
  r += long(testing::exactValue<double>(Q24_8(2)));
  r += long(testing::exactValue<float>(Q8_8(1)));
#if defined(__AVR__)
  testing::cycles::begin();
  testing::cycles::start();
  r += long(testing::cycles::stop()) + testing::cycles::handlerCycles();
#endif
  return r;
}

// The input classes of the assembly proof (AsmClasses.hpp): one shard of
// each kind, classified and compared.
struct CheckAsmVisit {
  tinyparticle::testing::ClassCounts<uint8_t>* counts;
  long sum;
  void operator()(int32_t a, int32_t b) {
    using namespace tinyparticle::testing;
    classify(counts->routine(), a, b, *counts);
    const AsmOutcome o = runAsmRoutine(counts->routine(), a, b, true);
    sum += o.same() ? 0 : 1;
  }
};

long checkAsmClasses() {
  using namespace tinyparticle::testing;
  static ClassCounts<uint8_t> counts(kAsmMulQ16);
  CheckAsmVisit visit = {&counts, 0};
  for (uint8_t r = 0; r < kAsmRoutineCount; ++r) {
    counts.reset(r);
    for (uint8_t kind = 0; kind < 3; ++kind) {
      const AsmShard shard = {r, kind, 0, 1};
      forEachShardInput(shard, visit);
    }
    enumerateStructured(r, false, visit);
    visit.sum += isUnreachable(r, 0, 0) + routineIsExhaustive(r) +
                 familyCount(r) + long(counts.count(0, 0));
  }
  return visit.sum;
}
