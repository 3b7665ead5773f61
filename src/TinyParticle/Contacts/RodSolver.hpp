// The rod solver: every rod of a world, solved exactly each step.
//
// Rods are not contacts. A resolver that takes one contact at a time suits
// loose contacts, but rods that share particles (a chain, a rope, a double
// pendulum) undo each other's corrections, and a chain of eight stretched
// by a fifth while it lost all its energy. Here all rods are solved
// together, in two linear solves per step (the scheme of SHAKE and RATTLE,
// Andersen 1983, written in velocities):
//
//  1. Positions (SHAKE). The integrator has changed the velocities (half
//     of gravity's kick) but not yet the positions. Rod i between a and b
//     gets an impulse mu_i along its direction u_i (kept from the last
//     step), chosen so that the rod predicted at the end of the step,
//     d + dt w (d from b to a, w their relative velocity), has the rod's
//     length: with a = d.u and r = w.u, to second order in the rod's turn,
//       sum_j C_ij mu_j = -r - (dt / 2L) |speed across u|^2,
//     everything a speed, so that fixed point keeps its precision where the
//     correction of a position is a fraction of a unit (Q16.16 at 1 kHz).
//     The length error the rod has now, L - a, is solved for too but
//     mended by moving the ends alone. A rod of a chain that turns by more
//     than 1/16 rad in a step gets its exact length in closed form instead
//     (positionSpeed()); along a chain, further passes then take in what
//     its neighbours did. Where they converge slowly or not at all (a
//     whip's end turning by tens of degrees in a step), the step is undone
//     and taken as two halves (step()). Then every particle moves once,
//     x += dt v, and gets the rest of gravity's kick.
//  2. Velocities (RATTLE). The directions at the end of the step, u'_i,
//     and impulses along them that remove every rod's stretching speed:
//       sum_j C'_ij nu_j = -w . u'_i.
// The matrix C_ij is (w_a + w_b) on the diagonal and +-w_p (u_i . u_j)
// where rods i and j share a movable particle p. Along a chain it is
// tridiagonal: one elimination down the chain and one back solves it
// exactly, in time linear in its length (the Thomas algorithm; Baraff 1996
// makes the same point for any tree of constraints).
//
// Why it keeps the energy: for a particle turning at speed s around a
// fixed point, step 1 moves it along the chord of the circle and step 2
// keeps the chord velocity's component along the new tangent, which is s
// again exactly. What remains is the integrator's own bounded error of the
// forces, at any step rate.
//
// Topology: the rods are split into chains, each rod linked to the next
// one through a particle that belongs to these two rods only. A world
// whose rods form only chains (ropes, pendulums, levers) is solved in one
// pass. Where three or more rods meet at a particle, or rods close a loop,
// the chains are coupled through those particles: the velocity passes
// repeat (block Gauss-Seidel), kMaxPasses times at most, and the length
// errors are mended by one pass of moves per step. Rods still more than a
// millimetre off after all the passes (a loop whose lengths cannot all be
// met) raise WorldError::kRodsUnsatisfied and stay where the moves left
// them: moves pump no speed into the world. The chains are found again
// only when rods are added or removed.
//
// Lone rods: where every rod is alone with one end immovable (a pendulum,
// a lever, separate pendulums), there is nothing to eliminate and each
// rod is solved on its own in one pass (Contacts/LoneRod.hpp), with about
// 24 multiplies per step in 2D, no division and no square root while it
// turns slowly. A world whose rods can never share a particle links that
// solve alone, without this file's chains.
//
// Cost per rod of a chain and step, Q16.16 on AVR: about 45 multiplies and
// one division, no square root while the rod turns slowly (the new
// direction is normalised by one Newton step from 1 / L). The matrix
// depends on the directions and masses only, so it is factored once per
// step: the velocity solve factors it for the directions it leaves, the
// next step's position solve has those same directions, and its further
// passes reuse the factors too (kept per world type, see Factor). The
// measured cycles are in extras/benchmarks/scenes.csv (scene chain).
#pragma once

#include <stdint.h>

#include "../Math/Newton.hpp"
#include "../Math/Scaler.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "../Core/Handle.hpp"
#include "../Core/Particle.hpp"
#include "../Core/Access.hpp"

namespace tinyparticle {

// The step equations of one rod, shared by the chains' solve and the lone
// rods' (Contacts/LoneRod.hpp). A template over the scalar and dimension
// alone: every World<S, Dim, ...> of a sketch shares one copy (issue 12).
template <typename S, uint8_t Dim>
struct LinkParams;

template <typename S, uint8_t Dim>
struct RodEquations {
  typedef tinyparticle::Vec<S, Dim> V;
  typedef LinkParams<S, Dim> Link;

  // What a solve's pass over the rods shares (the lone rods' whole pass;
  // the chains' adds its own fields: RodSolver::Pass).
  struct Pass {
    Pass(const Scaler<S>& b, S i)
        : byDt(b), invDt(i), positions(true), turned(false) {}
    const Scaler<S>& byDt;
    S invDt;
    bool positions;  // the position solve (SHAKE), or the velocities
    bool turned;     // a rod turned by more than 1/16 rad
  };

  // d: the vector from particles[b] (link.anchor for kAnchorIndex) to
  // particles[a]. (P: the world's particle type, with or without the
  // accumulator. Into d, not returned: a vector returned in registers
  // cost the callers more code.)
  template <class P>
  TINYPARTICLE_NOINLINE static void span(const P* particles, uint8_t a,
                                         uint8_t b, const Link& link, V& d) {
    d = particles[a].position;
    // (A pivot is often at the origin: zeros are skipped. A Float lever
    // saves 30 B without the test, at 390 cycles a step.)
    detail::subtractNonZero(
        d, b == kAnchorIndex ? link.anchor : particles[b].position);
  }

  // A rod just added (RodSolver::start()): its length's inverse, no chain
  // links yet, and its first direction. Ends that coincide have no
  // direction: any will do (as for colliding balls), and the rod pushes
  // them apart along it. (With none, they stayed together, unflagged:
  // extras/stability.) Out of line and shared by every World type: the
  // set-up's frame stays small.
  template <class P>
  TINYPARTICLE_NOINLINE static void startRod(const P* particles, uint8_t a,
                                             uint8_t b, Link& link) {
    link.inverseLength = detail::reciprocalByMultiplies(link.length);
    link.next = link.prev = kNoIndex;
    V& d = link.direction;
    span(particles, a, b, link, d);
    if (!detail::unitBySteps(d)) d.y = S(1);  // d is 0
  }

  // A rod's direction from its span d. Near its length, d / L is nearly a
  // unit vector: with `unit`, one Newton step (1.5 - |d / L|^2 / 2) makes
  // it one to about 1e-7; without, d / L itself (lone rods, see
  // Contacts/LoneRod.hpp). Far off its length (just added, or moved by the
  // sketch) d is normalised in full.
  static void setDirection(const Vec<S, 2>& d,
                           Link& link, bool unit) {
    const S invL = link.inverseLength;
    V scaled(d.x * invL, d.y * invL);
    bool near;
    if (unit || !detail::nearUnitByMagnitudes(S())) {
      // |d / L|^2 within 1/256 of 1 (unit), or between 1/2 and 5/4
      // (lengths 0.71 to 1.12, from which the lone rods' half-error moves
      // converge: Contacts/LoneRod.hpp).
      const S q = detail::dotOutOfLine(scaled, scaled);
      near = detail::isAboveNonNegative(q, unit ? S(1 - 1.0 / 256) : S(0.5)) &&
             detail::isBelowNonNegative(q, unit ? S(1 + 1.0 / 256) : S(1.25));
      if (near && unit) {
        scaled *= detail::differenceOutOfLine(S(1.5), detail::half(q));
      }
    } else {
      // A bound without multiplies: |x|, |y| <= 1 and 1 <= |x| + |y| <=
      // 1.5 pass only lengths between 0.7 and 1.12 (as above).
      const S ax = fabs(scaled.x), ay = fabs(scaled.y);
      const S sum = detail::sumOutOfLine(ax, ay);
      near = detail::isBelowNonNegative(ax, S(1 + 1.0 / 64)) &&
             detail::isBelowNonNegative(ay, S(1 + 1.0 / 64)) &&
             detail::isAboveNonNegative(sum, S(1 - 1.0 / 64)) &&
             detail::isBelowNonNegative(sum, S(1.5));
    }
    if (near) {
      link.direction = scaled;
    } else {
      normalizeInto(d, link);
    }
  }
  static void setDirection(const Vec<S, 3>& d,
                           Link& link, bool unit) {
    V scaled = d * link.inverseLength;
    const S q = scaled.magnitudeSquared();
    if (detail::isAboveNonNegative(q, S(1 - 1.0 / 256)) &&
        detail::isBelowNonNegative(q, S(1 + 1.0 / 256))) {
      if (unit) {
        scaled *= detail::differenceOutOfLine(S(1.5), detail::half(q));
      }
      link.direction = scaled;
    } else {
      normalizeInto(d, link);
    }
  }
  // By multiplies (Math/Newton.hpp), as start() normalises: one unit
  // vector routine linked, and none that takes a square root or divides.
  static void normalizeInto(V d, Link& link) {
    if (detail::unitBySteps(d)) link.direction = d;
    // else the ends coincide: keep the old direction
  }

  // A rod seen along its direction u: the relative speed along u (given),
  // the span along u, and the square of the speed across u, (d - a u) / dt +
  // (w - r u) (in 2D by the dot kernel, detail::dotOutOfLine(): through
  // Vec operations that return vectors the lever's step cost 800 cycles
  // more; the kernel costs none measurable and saves code).
  struct Frame {
    S radial;   // w . u (the caller's: the lone rods' two solves share it)
    S along;    // d . u
    S across2;  // |(d - a u) / dt + (w - r u)|^2
  };
  TINYPARTICLE_ALWAYS_INLINE static void frameOf(const Vec<S, 2>& d,
                                                 const Vec<S, 2>& w,
                                                 const Vec<S, 2>& u, S invDt,
                                                 Frame& f) {
    f.along = detail::dotOutOfLine(d, u);
    // Across u: along its normal n = (-u.y, u.x), one kernel for all four
    // (n . d is u x d to the bit: a product rounds symmetrically). The
    // offset across u is rounding (the direction was set from this span)
    // unless something moved an end since: mostly zero.
    const V n(detail::negativeOutOfLine(u.y), u.x);
    const S offset = detail::dotOutOfLine(n, d);
    S across = detail::dotOutOfLine(n, w);
    // (Rare: the sum out of line.)
    if (!detail::isZero(offset)) {
      across = detail::sumOutOfLine(across, offset * invDt);
    }
    f.across2 = across * across;
  }
  TINYPARTICLE_ALWAYS_INLINE static void frameOf(const Vec<S, 3>& d,
                                                 const Vec<S, 3>& w,
                                                 const Vec<S, 3>& u, S invDt,
                                                 Frame& f) {
    f.along = dot(d, u);
    V q = d;
    q.addScaled(u, -f.along);
    q *= invDt;
    q += w;
    q.addScaled(u, -f.radial);
    f.across2 = q.magnitudeSquared();
  }

  // The speed along u that brings a rod to its length at the end of the
  // step. The positions have not moved yet (they move once, after this
  // solve, rounded once): the rod at the end of the step is predicted as
  // d + dt (w + speed u), d from b to a now and w their relative velocity.
  // With a = d.u, r = w.u and s the speed across u, (d - a u) / dt +
  // (w - r u), its length is L when
  //   speed = (L - a) / dt - r - dt s^2 / (L + sqrt(L^2 - (dt s)^2)),
  // to second order in the turn dt s / L
  //   speed = (L - a) / dt - r - dt s^2 / 2L.
  // Everything is a speed: in fixed point the drop dt s^2 / 2L, a fraction
  // of a unit at 1 kHz, keeps its precision.
  //
  // A rod that turns by less than 1/16 rad in the step takes the second
  // order form, and its error now, L - a (rounding of earlier steps, or
  // what the passes before left), is returned in `error` and mended by
  // moving the ends alone: mended through the speed, as (L - a) / dt, a
  // unit of rounding would be a large speed along the rod, and the
  // velocity solve would leave a little of it across the rod every step
  // (Q16.16 pendulums gained a few % a minute that way), and rods that
  // cannot all be held (a loop of impossible lengths) would pump speed
  // into the world. A chain's rod that turns faster takes the exact form,
  // error included (`error` becomes 0); a fast rod that is off its length
  // by more than L/16 is not one that turns but one that the others keep
  // from its length (or that the sketch moved): position only.
  //
  // The exact form's drop, dt s^2 / (L + sqrt(L^2 - (dt s)^2)), is
  // (dt s^2 / 2L) detail::turnDropFactor(h), h = (dt s / L)^2 / 2 the half
  // square of the turn that decides `turning`: no division, no square root.
  // `unit`: the directions are unit vectors (the chains'), else d / L
  // (lone rods: Contacts/LoneRod.hpp), whose error is half of L - a.
  //
  // Lone rods take, at a fast turn, the first two terms of the exact
  // drop's series in h, dt s^2 / 2L (1 + h / 2), not the exact form (issue
  // 12: 300 B of a Q16.16 lever's 5 KB); the error included is left to the
  // move, as at a slow turn. What the series' rest leaves, about L t^6 /
  // 16 of length a step at a turn of t rad, is 0.6 um at t = 0.2 (a 0.15 m
  // lever's bottom at 64 steps a second), mended the next step as any
  // length error. With the first term only it is L t^4 / 8, which the
  // move takes out of the speed across the rod (t^4 / 4 of the energy a
  // step: 0.3 % a second for a 0.2 m dumbbell at 0.12 rad a step), and
  // the lone rods' ends drifted 1.5 mm from the chains' in a second
  // (RodLone3DTest). The chains' solve keeps the exact form: a whip's end
  // turns by tens of degrees a step, where the series fails.
  static S positionSpeed(const V& d, const V& w, const V& u, S radial,
                         const Link& link, const Pass& pass, bool unit,
                         S& error, bool& turning) {
    const Scaler<S>& byDt = pass.byDt;
    const S invDt = pass.invDt;
    Frame f;
    f.radial = radial;
    frameOf(d, w, u, invDt, f);
    const S length = link.length;
    const S invL = link.inverseLength;
    error = detail::differenceOutOfLine(length, f.along);
    if (!unit) error = detail::half(error);  // u = d / L: lone rods
    S drop = detail::half(byDt(f.across2)) * invL;  // dt s^2 / 2L
    const S halfTurn2 = byDt(drop) * invL;  // (dt s / L)^2 / 2
    turning = detail::isAboveNonNegative(halfTurn2, S(1.0 / 512));
    if (turning) {
      // Far off: the offset across u is a move too, not a turn.
      if (!detail::isBelowNonNegative(fabs(error) * invL, S(1.0 / 16))) {
        return detail::negativeOutOfLine(f.radial);
      }
      if (unit) {
        const S speed = detail::differenceOutOfLine(
            detail::differenceOutOfLine(error * invDt, f.radial),
            drop * detail::turnDropFactor(halfTurn2));
        error = S();
        return speed;
      }
      drop = detail::sumOutOfLine(drop, detail::half(drop * halfTurn2));
    }  // (Lone rods: above.)
    // (Its sums out of line: Math/Newton.hpp.)
    return detail::differenceOutOfLine(detail::negativeOutOfLine(f.radial),
                                       drop);
  }

};

// Which ends of a world's lone rods may move, as far as the code must
// know: kAnchored, b is always an anchor (World::anchoredRodAdded());
// kOneMovable, one end of each rod is immovable, a or b (what the chains'
// solve hands over, LoneRods::allLone()); kTwoMovable, any (a world of one
// constraint slot whose rod joins two particles, World::rodAdded()).
struct LoneEnds {
  enum : uint8_t { kAnchored, kOneMovable, kTwoMovable };
};

template <class W>
struct LoneRods;

template <class W>
struct RodSolver {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef typename W::ParticleType P;
  typedef typename W::ConstraintSlot Slot;
  typedef typename W::LinkParamsType Link;  // a rod's parameters
  typedef RodEquations<S, W::kDimensions> Eq;  // shared by every W
  // A pass of the chains' solve: the lone rods' (RodEquations::Pass) and
  // what the chains' passes share.
  struct Pass : Eq::Pass {
    Pass(const Scaler<S>& b, S i)
        : Eq::Pass(b, i), first(true), coupled(false), factored(false),
          worst() {}
    bool first;      // the first pass of the position solve
    bool coupled;    // chains meet: passes repeat (Gauss-Seidel)
    bool factored;   // the rows' factors are set for these directions
    S worst;         // the largest correction of a length, m
  };

  static Link& linkOf(Slot& s) { return s.params.template as<Link>(); }
  static const Link& linkOf(const Slot& s) {
    return s.params.template as<Link>();
  }

  static const uint8_t kMaxPasses = 8;
  // Whether a step may be taken as two halves (see step()): not in worlds
  // of one or two rods, which do not whip (a double pendulum's passes
  // converge at 256 steps a second), and so link none of its code.
  static const bool kHalves = W::kConstraintCapacity > 2;

  // A rod's slot makes no contacts: this marks it (World::isRod()).
  static void generate(W&, Slot&, uint8_t) {}

  // A rod just added, of a positive length (World::addRod() refuses
  // others): its length's inverse and its first direction. Newton's
  // reciprocal and unit vector (Math/Newton.hpp): a world whose step never
  // divides links no fast divide (nor, in float, the float divide).
  static void start(W& world, Slot& s) {
    Eq::startRod(&world.particleAt(0), s.a, s.b, linkOf(s));
  }

  // The step's two solves (World::step calls them after integrating).
  static void solve(W& world, const Scaler<S>& byDt, S dt) {
    if (WorldAccess::rodState(world) & W::kRodsChanged) findChains(world);
    const S invDt = WorldAccess::inverseDt(world, dt);
    if ((WorldAccess::rodState(world) & W::kRodsLone) &&
        LoneRods<W>::allLone(world)) {
      LoneRods<W>::template solveAll<LoneEnds::kOneMovable>(world, byDt,
                                                             invDt);
      return;
    }
    step(world, byDt, invDt, true);
  }

  // The two solves of a step of dt (byDt, invDt); `mayHalve`: see below.
  static void step(W& world, const Scaler<S>& byDt, S invDt, bool mayHalve) {
    const bool coupled = (WorldAccess::rodState(world) & W::kRodsCoupled) != 0;
    Pass pass(byDt, invDt);
    pass.coupled = coupled;
    Row rows[W::kConstraintCapacity > 0 ? W::kConstraintCapacity : 1];
    // The directions are the ones the last velocity solve factored.
    pass.factored = factorsHold(world);
    // The position solve is exact to second order in each rod's turn: a
    // rod that turned by more than 1/16 rad in the step, or coupled chains,
    // take further passes (Newton's iterations, or Gauss-Seidel) until
    // every rod is within tolerance() of its length. Along chains a pass
    // whose corrections all stay below four tolerances is the last: the
    // passes converge as Newton's do, and the corrections it applies leave
    // every rod within one (whip chains of 4 to 16 beads, Q16.16 and
    // float, 10 s: a further pass found one off in 2 of 4,677 such
    // cases). Coupled chains' Gauss-Seidel passes converge slowly: they
    // stop only within one tolerance.
    pass.positions = true;
    // A step in which a chain turns so fast that its passes converge
    // slowly or not at all (a whip's end at a coarse step: the directions
    // the rows were factored with are far from the rods' new ones) is
    // undone and taken as two steps of dt / 2, once: when a rod is still
    // more than 8 tolerances off after the second pass, or off at all
    // after the last. The integrator's half kick of gravity for dt is then
    // the first half step's whole kick, and each half step's
    // movePositions() gives a quarter: the sum is right. Coupled chains
    // converge slowly anyway: they take their passes.
    // A whip's fast turns last a few steps: the step after a halved one is
    // halved at once (on whip chains of 8 to 16 beads, 58 to 78 % of those
    // steps were halved anyway), which saves the two passes that would find
    // it out and halves more of the steps that turn fast, for a smaller
    // energy error. Once only: the step after that tries the whole dt.
    const bool kept = kHalves && !coupled && mayHalve;
    if (kept && sHalvedWorld == &world) {
      sHalvedWorld = nullptr;
      halve(world, byDt, invDt);
      return;
    }
    static V saved[W::kParticleCapacity];  // (on the stack: +180 B of code)
    if (kept) keepVelocities(world, saved, false);
    const S held = tolerance();
    S enough = held;
    if (!coupled) {
      enough += enough;
      enough += enough;
    }
    uint8_t n = 0;
    for (;;) {
      pass.worst = S();
      pass.turned = false;
      sweep(world, rows, pass);
      pass.first = false;
      if (++n == kMaxPasses) break;
      if (!coupled && !pass.turned) break;
      if (n > 1 && pass.worst < enough) break;
      if (kHalves && n == 2 && kept && pass.worst > held * S(8)) {
        n = kMaxPasses;  // as if out of passes: halved below
        break;
      }
    }
    if (kHalves && n == kMaxPasses && kept && !(pass.worst < held)) {
      keepVelocities(world, saved, true);
      sHalvedWorld = &world;
      halve(world, byDt, invDt);
      return;
    }
    // Rounding leaves a few units of a fixed-point scalar; a rod off by a
    // millimetre after all the passes is one that cannot be held.
    if (n == kMaxPasses && pass.worst > S(1.0 / 1024)) {
      WorldAccess::raiseError(world, WorldError::kRodsUnsatisfied);
    }
    // The first pass's moves of the ends, unless further passes along
    // chains took the errors into the speed (a fast rod's exact length).
    if (n == 1 || coupled) {
      for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
        if (isRodAt(world, i)) {
          move(world, WorldAccess::constraint(world, i), rows[i].moved, pass);
        }
      }
    }
    WorldAccess::movePositions(world, pass.byDt);
    newDirections(world);
    pass.positions = false;
    pass.factored = false;
    for (n = 0; n < kMaxPasses; ++n) {
      sweep(world, rows, pass);
      if (!coupled) break;
    }
    sFactoredWorld = &world;
  }

  // A step of dt (byDt, invDt) taken as two steps of dt / 2.
  static void halve(W& world, const Scaler<S>& byDt, S invDt) {
    const Scaler<S> byHalf(detail::half(byDt.factor()));
    const S invHalf = invDt + invDt;
    step(world, byHalf, invHalf, false);
    step(world, byHalf, invHalf, false);
  }

  // Within this of their length (m) the rods count as held: 61 um, or
  // four units of a coarse scalar.
  static S tolerance() {
    return fmax(S(1.0 / 16384), S::epsilon() * S(4));
  }

 private:
  friend struct LoneRods<W>;  // reads the rod slots (isRodAt(), otherRod())

  // Saves every particle's velocity in `saved`, or with `back` puts it
  // back (a step undone).
  TINYPARTICLE_NOINLINE static void keepVelocities(W& world, V* saved,
                                                  bool back) {
    P* p = &world.particleAt(0);  // (the particles are one array)
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
      if (back) {
        p->velocity = saved[i];
      } else {
        saved[i] = p->velocity;
      }
    }
  }

  // A row of the solve, for one step.
  struct Row {
    S y;             // the row's right side, eliminated and divided
    S yMove;         // the same for the length errors (position solve)
    S moved;         // the first pass's position impulse, applied after all
  };

  // A row's factors, kept from step to step: the velocity solve factors
  // the matrix of the directions it leaves, and the next step's position
  // solve has the same directions. They hold while the rods, the world
  // and the masses of the rods' ends stay the same (factorsHold()). One
  // set per world type: a second world of the type factors afresh.
  struct Factor {
    S multiplier;    // the elimination's factor for this row
    S inversePivot;  // 1 / the row's pivot, after the elimination
    S inverseMassA;  // the masses it was factored with (0: immovable)
    S inverseMassB;
    S sharedBefore;  // sharedMass() with the rod before it in its chain
  };
  static Factor sFactors[W::kConstraintCapacity > 0 ? W::kConstraintCapacity
                                                    : 1];
  static const W* sFactoredWorld;  // whose directions sFactors has, or null
  static const W* sHalvedWorld;    // whose last step was halved, or null

  // The factors of the last velocity solve serve this world's position
  // solve: the same world, no rod added or removed since (findChains()
  // forgets them), and every end's inverse mass as it was.
  static bool factorsHold(W& world) {
    if (sFactoredWorld != &world) return false;
    for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
      if (!isRodAt(world, i)) continue;
      const Slot& s = WorldAccess::constraint(world, i);
      const Factor& f = sFactors[i];
      if (!(inverseMassOf(world, s.a) == f.inverseMassA) ||
          !(inverseMassOf(world, s.b) == f.inverseMassB)) {
        return false;
      }
    }
    return true;
  }

  static bool isRodAt(W& world, uint8_t i) {
    return WorldAccess::isRod(world, WorldAccess::constraint(world, i));
  }

  // The inverse mass of an end (0 for an anchor or a fixed particle).
  static S inverseMassOf(W& world, uint8_t p) {
    if (p >= W::kParticleCapacity) return S();
    const P& particle = world.particleAt(p);
    return particle.isStatic() ? S() : particle.inverseMass;
  }

  // The sign of rod slot's impulse on particle p: +1 at a, -1 at b.
  static bool pushesA(const Slot& s, uint8_t p) { return s.a == p; }

  // ---- Topology ---------------------------------------------------------

  // How many rods end at particle p (anchors are not particles).
  static uint8_t degree(W& world, uint8_t p) {
    if (p >= W::kParticleCapacity) return 0;
    uint8_t n = 0;
    for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
      if (!isRodAt(world, i)) continue;
      const Slot& s = WorldAccess::constraint(world, i);
      if (s.a == p) ++n;
      if (s.b == p) ++n;
    }
    return n;
  }

  // The other rod at particle p (of degree 2), or kNoIndex; also what
  // LoneRods asks when a rod is added (none: it is alone).
  static uint8_t otherRod(W& world, uint8_t rod, uint8_t p) {
    for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
      if (i == rod || !isRodAt(world, i)) continue;
      const Slot& s = WorldAccess::constraint(world, i);
      if (s.a == p || s.b == p) return i;
    }
    return kNoIndex;
  }

  // Splits the rods into chains (next / prev in each rod's parameters).
  // Chains start at a rod with an end that no other rod shares, so that
  // a chain is as long as it can be; rods left over lie on loops.
  static void findChains(W& world) {
    sFactoredWorld = nullptr;
    bool coupled = false;
    for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
      if (!isRodAt(world, i)) continue;
      linkParamsOf(world, i).next = kNoIndex;
      linkParamsOf(world, i).prev = kAllIndex;  // not placed yet
      const Slot& s = WorldAccess::constraint(world, i);
      if (degree(world, s.a) > 2 || degree(world, s.b) > 2) coupled = true;
    }
    for (uint8_t round = 0; round < 2; ++round) {
      for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
        if (!isRodAt(world, i) || linkParamsOf(world, i).prev != kAllIndex) {
          continue;
        }
        const Slot& s = WorldAccess::constraint(world, i);
        // Enter at an end through which the chain cannot continue.
        uint8_t from;
        if (degree(world, s.a) != 2) {
          from = s.a;
        } else if (degree(world, s.b) != 2) {
          from = s.b;
        } else if (round == 1) {
          from = s.a;  // a loop: start anywhere
          coupled = true;
        } else {
          continue;
        }
        uint8_t rod = i;
        uint8_t prev = kNoIndex;
        for (;;) {
          linkParamsOf(world, rod).prev = prev;
          if (prev != kNoIndex) linkParamsOf(world, prev).next = rod;
          const Slot& r = WorldAccess::constraint(world, rod);
          const uint8_t far = r.a == from ? r.b : r.a;
          if (degree(world, far) != 2) break;
          const uint8_t next = otherRod(world, rod, far);
          if (next == kNoIndex || linkParamsOf(world, next).prev != kAllIndex) {
            break;  // back at the start of a loop
          }
          prev = rod;
          rod = next;
          from = far;
        }
      }
    }
    uint8_t state = coupled ? W::kRodsCoupled : W::kRodsLone;
    for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
      if (!isRodAt(world, i)) continue;
      const typename W::LinkParamsType& link = linkParamsOf(world, i);
      if (link.next != kNoIndex || link.prev != kNoIndex) {
        state &= uint8_t(~W::kRodsLone);
      }
    }
    WorldAccess::setRodState(world, state);
  }

  static typename W::LinkParamsType& linkParamsOf(W& world, uint8_t i) {
    return linkOf(WorldAccess::constraint(world, i));
  }

  // ---- The solves ---------------------------------------------------------

  // The vector from b to a.
  TINYPARTICLE_NOINLINE static V span(W& world, const Slot& s) {
    V d;
    Eq::span(&world.particleAt(0), s.a, s.b, linkOf(s), d);
    return d;
  }

  // va - vb (b at rest when it is an anchor or fixed).
  static V relativeVelocity(W& world, const Slot& s) {
    V w = world.particleAt(s.a).velocity;
    if (s.b != kAnchorIndex && !world.particleAt(s.b).isStatic()) {
      w -= world.particleAt(s.b).velocity;
    }
    return w;
  }

  // Every rod's direction at the end of the step.
  static void newDirections(W& world) {
    for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
      if (!isRodAt(world, i)) continue;
      Slot& s = WorldAccess::constraint(world, i);
      Eq::setDirection(span(world, s), linkOf(s), true);
    }
  }
  // The right side of rod s's row: for the velocity solve, minus the
  // stretching speed; for the position solve, positionSpeed(), the speed
  // along u that brings the rod to its length at the end of the step, and
  // in `error` the move (m) that mends its length now.
  static S rightSide(W& world, const Slot& s, Pass& pass, S& error) {
    const V& u = linkOf(s).direction;
    const V w = relativeVelocity(world, s);
    const S radial = dot(w, u);
    if (!pass.positions) return -radial;
    bool turning;
    S right = Eq::positionSpeed(span(world, s), w, u, radial, linkOf(s), pass,
                                true, error, turning);
    if (turning && detail::isZero(error)) pass.turned = true;
    if (!pass.first && !turning && !pass.coupled) {
      // Along a chain, what a further pass finds is the motion that a
      // fast neighbour's correction caused: speed too.
      right += error * pass.invDt;
      error = S();
    }
    if (pass.coupled || pass.turned || !pass.first) {
      const S correction = fabs(error + pass.byDt(right));
      if (correction > pass.worst) pass.worst = correction;
    }
    return right;
  }

  // Applies rod s's impulse mu (per unit mass along u) to the velocities.
  // Ends of the same mass (a chain of equal beads) change by the same
  // vector, written out: two multiplies saved, and the same bits (the
  // multiply rounds symmetrically).
  static void apply(W& world, const Slot& s, S mu, const Pass&) {
    if (detail::isZero(mu)) return;
    const V& u = linkOf(s).direction;
    P& a = world.particleAt(s.a);
    P* b = nullptr;
    if (s.b != kAnchorIndex && !world.particleAt(s.b).isStatic()) {
      b = &world.particleAt(s.b);
    }
    if (!a.isStatic()) {
      const S k = a.inverseMass * mu;
      if (b != nullptr && b->inverseMass == a.inverseMass) {
        pushPair(a.velocity, b->velocity, u, k);
        return;
      }
      a.velocity.addScaled(u, k);
    }
    if (b != nullptr) b->velocity.addScaled(u, -(b->inverseMass * mu));
  }
  TINYPARTICLE_ALWAYS_INLINE static void pushPair(Vec<S, 2>& x, Vec<S, 2>& y,
                                                  const Vec<S, 2>& u, S k) {
    const S cx = u.x * k, cy = u.y * k;
    x.x += cx;
    x.y += cy;
    y.x -= cx;
    y.y -= cy;
  }
  TINYPARTICLE_ALWAYS_INLINE static void pushPair(Vec<S, 3>& x, Vec<S, 3>& y,
                                                  const Vec<S, 3>& u, S k) {
    const S cx = u.x * k, cy = u.y * k, cz = u.z * k;
    x.x += cx;
    x.y += cy;
    x.z += cz;
    y.x -= cx;
    y.y -= cy;
    y.z -= cz;
  }

  // Moves rod s's ends along u by dt times `speed` per unit mass: the
  // first pass's correction of the length error, without a velocity.
  static void move(W& world, const Slot& s, S speed, const Pass& pass) {
    if (detail::isZero(speed)) return;
    const V& u = linkOf(s).direction;
    P& a = world.particleAt(s.a);
    if (!a.isStatic()) shift(a.position, u, a.inverseMass * speed, pass);
    if (s.b != kAnchorIndex) {
      P& b = world.particleAt(s.b);
      if (!b.isStatic()) shift(b.position, u, -(b.inverseMass * speed), pass);
    }
  }
  static void shift(V& x, const V& u, S speed, const Pass& pass) {
    x.addScaled(u, pass.byDt(speed));
  }

  // How rod `other`'s impulse changes rod r's stretching speed, per unit
  // of impulse and along other's direction: +-w_p for the particle p
  // they share (0 for none).
  static S sharedMass(W& world, const Slot& r, const Slot& other) {
    S c = S();
    const uint8_t ends[2] = {r.a, r.b};
    for (uint8_t k = 0; k < 2; ++k) {
      const uint8_t p = ends[k];
      if (p >= W::kParticleCapacity || (other.a != p && other.b != p)) {
        continue;
      }
      const S w = inverseMassOf(world, p);
      // + when p is the same end (a or b) of both rods, - otherwise.
      c += pushesA(r, p) == pushesA(other, p) ? w : -w;
    }
    return c;
  }

  // The elimination's factor and inverse pivot of row i (rod s), the row
  // before it factored already.
  // The masses are read afresh in the position solve (when the factors of
  // the last step did not hold), and kept for the velocity solve.
  static void factor(W& world, const Slot& s, uint8_t i, bool fresh) {
    Factor& f = sFactors[i];
    const uint8_t prev = linkOf(s).prev;
    if (fresh) {
      f.inverseMassA = inverseMassOf(world, s.a);
      f.inverseMassB = inverseMassOf(world, s.b);
      f.sharedBefore = prev != kNoIndex
                           ? sharedMass(world, s, WorldAccess::constraint(world, prev))
                           : S();
    }
    S pivot = f.inverseMassA + f.inverseMassB;
    S multiplier = S();
    if (!detail::isZero(f.sharedBefore)) {
      const S c = f.sharedBefore *
                  dot(linkOf(s).direction,
                      linkOf(WorldAccess::constraint(world, prev)).direction);
      if (!detail::isZero(c)) {
        multiplier = c * sFactors[prev].inversePivot;
        pivot -= multiplier * c;
      }
    }
    f.multiplier = multiplier;
    // Both ends immovable: no impulse.
    f.inversePivot = detail::isPositive(pivot) ? S(1) / pivot : S();
  }

  // One pass over all chains.
  static void sweep(W& world, Row* rows, Pass& pass) {
    // The length errors are solved for in the first pass of the positions
    // only (their impulses are applied from it alone).
    const bool moves = pass.positions && pass.first;
    for (uint8_t head = 0; head < W::kConstraintCapacity; ++head) {
      if (!isRodAt(world, head) ||
          linkOf(WorldAccess::constraint(world, head)).prev != kNoIndex) {
        continue;
      }
      // Down the chain: eliminate the coupling with the rod before.
      uint8_t last = head;
      S previousRight = S(), previousMove = S();
      for (uint8_t i = head; i != kNoIndex;
           i = linkOf(WorldAccess::constraint(world, i)).next) {
        const Slot& s = WorldAccess::constraint(world, i);
        S move = S();
        S right = rightSide(world, s, pass, move);
        // An error of one unit of a fine scalar (Q16.16: 15 um) is left
        // for later steps: most rows of a chain have 0 or 1, mending costs
        // a solve, and the error stays bounded. (A float's errors, and a
        // coarse scalar's, are mended.)
        if (fabs(move) <= S::epsilon() && S::epsilon() < S(1.0 / 16384)) {
          move = S();
        }
        if (!detail::isZero(move)) move *= pass.invDt;  // a speed
        // The matrix depends on the directions and masses only: factored
        // in the first pass of each solve, reused by the further passes.
        if (!pass.factored) factor(world, s, i, pass.positions);
        const Factor& f = sFactors[i];
        const S multiplier = f.multiplier;
        if (!detail::isZero(multiplier)) right -= multiplier * previousRight;
        const S inversePivot = f.inversePivot;
        rows[i].y = right * inversePivot;
        previousRight = right;
        if (moves) {
          // Most length errors are 0 in fixed point (see above): products
          // of zeros are skipped.
          if (!detail::isZero(previousMove)) move -= multiplier * previousMove;
          rows[i].yMove = detail::isZero(move) ? S() : move * inversePivot;
          previousMove = move;
        }
        last = i;
      }
      // Back up the chain: mu_i = y_i - m_(i+1) mu_(i+1), applied at once.
      S mu = S(), muMove = S();
      S nextMultiplier = S();
      for (uint8_t i = last; i != kNoIndex;
           i = linkOf(WorldAccess::constraint(world, i)).prev) {
        mu = rows[i].y - nextMultiplier * mu;
        if (moves) {
          muMove = detail::isZero(muMove)
                       ? rows[i].yMove
                       : rows[i].yMove - nextMultiplier * muMove;
          rows[i].moved = muMove;
        }
        nextMultiplier = sFactors[i].multiplier;
        apply(world, WorldAccess::constraint(world, i), mu, pass);
      }
    }
    pass.factored = true;
  }
};

template <class W>
typename RodSolver<W>::Factor RodSolver<W>::sFactors[
    W::kConstraintCapacity > 0 ? W::kConstraintCapacity : 1];
template <class W>
const W* RodSolver<W>::sFactoredWorld = nullptr;
template <class W>
const W* RodSolver<W>::sHalvedWorld = nullptr;

}  // namespace tinyparticle
