// Lone rods: rods that share no particle, each solved on its own.
//
// A pendulum, a lever, a Newton's cradle: no rod shares a particle with
// another, so there is nothing to eliminate, and each rod is solved in one
// pass with the step equations of the chains' solve (Contacts/RodSolver.hpp:
// positionSpeed(), with a term of the closed form's series at a fast turn),
// about 24 multiplies per rod and step in 2D, no division and no square
// root (not even when it turns fast, or at set-up: Math/Newton.hpp).
//
// The code is in two parts (issue 12): LoneRod<S, Dim, kEnds>, the
// solves of one rod, a template over the scalar and dimension alone, so
// that every World type of a sketch with the same S and Dim shares one
// copy; and LoneRods<W>, the world's walk over its slots, the only part
// that each World type links for itself. One path serves every rod: an
// immovable end (an anchor, or a particle of no inverse mass) is an end of
// inverse mass 0, and the ends share each change in the ratio of their
// inverse masses, so that a rod with two movable ends takes the same code
// as a pendulum's, with a reciprocal for the share. kEnds (LoneEnds)
// leaves out what a world's rods cannot need: the share where each rod has
// an immovable end, and all of b where b is always an anchor.
//
// Which solver a world links (World::rodAdded()): a world whose rods can
// never share a particle takes this one alone, and the chains' solve (the
// larger part of Contacts/RodSolver.hpp) is not linked. That is a world
// of one constraint slot, and a world whose rods all hang from anchors (addRod(particle, anchor,
// length)), where a particle takes one rod: a second anchored rod on the
// same particle is refused (WorldError::kBadArgument) while the world has
// no rod between two particles. The first rod between two particles, in a
// world of more slots, brings the chains' solve; it passes every lone
// world to solveAll() here at run time (Contacts/RodSolver.hpp).
//
// Two savings over the chains' solve make the lever's step about 40 %
// cheaper (measured):
// - no rows, passes or divisions (a rod with two movable ends takes a
//   reciprocal in each of the two solves, for its ends' shares);
// - the direction kept between steps is d / L, not normalised: the Newton
//   step costs four multiplies, and d / L serves as well. With |u| = 1 + e
//   (e a few units of rounding), the velocity solve leaves 2e of a speed
//   that is nearly zero anyway, and the next position solve sees a = d.u =
//   |d|^2 / L while the ends have not moved since: its length error L - |d|
//   is (L^2 - |d|^2) / 2L = (L - a) / 2, which is what it mends. (An end
//   moved along the rod by a contact is mended by half each step.) Short
//   rods in Q16.16 keep their energy better this way: the 5 cm pendulum's
//   error at dt = 1/256 s fell from 1.8 % to 0.6 % of its swing. A step in
//   which a rod turned by more than 1/16 rad ends with unit directions: at
//   such turns the drop's terms are large, and |u| = 1 + e would put
//   the end e of them off (a lever flung at 30 m/s by a move of the sketch
//   kept swinging 3 % off its length). Their error, halved all the same, is
//   mended by half a step: it converges.
#pragma once

#include <stdint.h>

#include "../Math/Newton.hpp"
#include "../Math/Scaler.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "../Core/Handle.hpp"
#include "RodSolver.hpp"
#include "../Core/Access.hpp"

namespace tinyparticle {

// One lone rod's two solves, on its ends a and b (b null for an anchor).
// A template over the scalar and dimension alone, out of line: every
// World<S, Dim, ...> of a sketch shares one copy (issue 12). One path for
// every rod: an immovable end (an anchor, or a particle of no inverse mass
// at the start of the step) is an end of inverse mass 0, so that the rod of
// a pendulum and a free dumbbell run the same code; kEnds (LoneEnds) leaves
// out what a world's rods cannot need. P: the world's particle type (with
// or without the force accumulator).
template <typename S, uint8_t Dim, uint8_t kEnds, class P = Particle<S, Dim> >
struct LoneRod {
  typedef RodEquations<S, Dim> Eq;
  typedef typename Eq::Pass Pass;
  typedef typename Eq::Link Link;
  typedef typename Eq::V V;
  static const bool kAnchored = kEnds == LoneEnds::kAnchored;

  // One of the two solves of the rod between particles[a] and particles[b]
  // (b kAnchorIndex: an anchor), one path for both, as the ends' share is
  // the same:
  // - pass.positions (SHAKE): the change of the ends' relative speed along
  //   u that brings the rod to its length at the end of the step, and the
  //   move that mends its length now (Eq::positionSpeed(); through the
  //   chains' rightSide() it cost 400 cycles more);
  // - else (RATTLE): the new direction (a unit vector after a fast turn,
  //   pass.turned), and the ends' relative speed along it, r, taken out as
  //   a change -r (a gets (-r) w, which is -(r w) to the bit, as a product
  //   rounds ties away from zero; b gets (-r) w - (-r) = r - r w; in fixed
  //   point all but r = S::lowest(), which -r saturates: a relative speed
  //   no step reaches).
  TINYPARTICLE_NOINLINE static void solve(P* particles, uint8_t a, uint8_t b,
                                          Link& link, Pass& pass) {
    const Ends ends(particles, a, b);
    if (ends.isFixed()) return;
    detail::Unset<V> span;  // written whole by Eq::span()
    V& d = span.value;
    Eq::span(particles, a, kAnchored ? kAnchorIndex : b, link, d);
    const V& u = link.direction;
    // (Taken once, before either solve: taken in each, it was linked twice.)
    V relative;
    const V& w = ends.relativeVelocity(relative);
    // The velocity solve's new direction first: then both solves take the
    // ends' relative speed along u, r, from one dot product.
    if (!pass.positions) Eq::setDirection(d, link, pass.turned);
    const S radial = detail::dotOutOfLine(w, u);
    S amount;
    S error = S();
    if (pass.positions) {
      bool turning;
      amount = Eq::positionSpeed(d, w, u, radial, link, pass, false, error,
                                 turning);
      if (turning) pass.turned = true;
    } else {
      amount = detail::negativeOutOfLine(radial);
    }
    const S share = ends.shareOfA();
    ends.pushApart(u, amount, error, share);
  }

 private:
  // A rod's ends that move (null where the end is immovable: an anchor, or
  // a particle of no inverse mass). Only these are kept: what a solve
  // needs of an end is that it moves.
  struct Ends {
    TINYPARTICLE_ALWAYS_INLINE Ends(P* particles, uint8_t ia, uint8_t ib)
        : movingA(moving(&particles[ia])),
          movingB(kAnchored || ib == kAnchorIndex ? nullptr
                                                  : moving(&particles[ib])) {}
    static P* moving(P* p) { return p->isStatic() ? nullptr : p; }
    P* movingA;
    P* movingB;

    bool bMoves() const { return !kAnchored && movingB != nullptr; }
    // Whether both may move.
    bool bothMove() const {
      return kEnds == LoneEnds::kTwoMovable && movingA != nullptr &&
             movingB != nullptr;
    }
    bool isFixed() const { return movingA == nullptr && !bMoves(); }
    // va - vb, an immovable end at rest: a's velocity itself where b does
    // not move (a does then), else computed in w.
    TINYPARTICLE_ALWAYS_INLINE const V& relativeVelocity(V& w) const {
      if (!bMoves()) return movingA->velocity;
      if (movingA != nullptr) w = movingA->velocity;
      w -= movingB->velocity;
      return w;
    }
    // The part of a change of the ends' relative speed that a takes when
    // both move: its inverse mass over both ends'. Through the reciprocal
    // of Math/Newton.hpp (a unit or two at most), so that a world whose
    // step never divides elsewhere links no fast divide.
    S shareOfA() const {
      if (!bothMove()) return S();
      return movingA->inverseMass *
             detail::reciprocalByMultiplies(detail::sumOutOfLine(
                 movingA->inverseMass, movingB->inverseMass));
    }
    // A change `amount` of the ends' relative velocity along u, then one
    // `error` of their relative position (unless 0): all of each to the
    // one movable end, or `share` of it to a and the rest against u to b.
    // (Both in one call, a loop over the two fields: two calls cost rung 9
    // 46 B more, a Float lever 46 B, for 6 B of a Q16.16 lever.)
    void pushApart(const V& u, S amount, S error, S share) const {
      V P::*field = &P::velocity;
      do {
        S toA = amount;
        if (bMoves()) {
          toA = bothMove() ? amount * share : S();
          (movingB->*field).addScaled(u, toA - amount);
        }
        if (movingA != nullptr) (movingA->*field).addScaled(u, toA);
        amount = error;
        error = S();
        field = &P::position;
      } while (!detail::isZero(amount));
    }
  };
};

template <class W>
struct LoneRods {
  typedef typename W::Scalar S;
  typedef typename W::ConstraintSlot Slot;
  typedef RodSolver<W> Rods;
  typedef typename RodEquations<S, W::kDimensions>::Pass Pass;

  // The world's rod solve when its rods never share a particle (see the
  // top of this file): World::rodAdded() and anchoredRodAdded() set it.
  // kEnds: LoneEnds::kAnchored or kTwoMovable.
  template <uint8_t kEnds>
  static void solve(W& world, const Scaler<S>& byDt, S dt) {
    if (WorldAccess::rodState(world) & W::kRodsChanged) {
      WorldAccess::setRodState(world, W::kRodsLone);
    }
    solveAll<kEnds>(world, byDt, WorldAccess::inverseDt(world, dt));
  }

  // Whether rod slot `rod` may join a world solved here: its particle a is
  // on no other rod.
  static bool isAlone(W& world, uint8_t rod) {
    const uint8_t p = WorldAccess::constraint(world, rod).a;
    return Rods::otherRod(world, rod, p) == kNoIndex;
  }

  // Every rod alone, with exactly one immovable end (an anchor, or a
  // particle of no inverse mass at the start of this step): what the
  // chains' solve hands to solveAll().
  static bool allLone(W& world) {
    for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
      if (!Rods::isRodAt(world, i)) continue;
      const Slot& s = WorldAccess::constraint(world, i);
      if (isImmovable(world, s.a) == isImmovable(world, s.b)) return false;
    }
    return true;
  }

  // Both solves for rods that share no particle: positions (SHAKE), the
  // move, directions and velocities (RATTLE). The world's part is only
  // the walk over its slots: the solves are LoneRod's, shared.
  template <uint8_t kEnds>
  static void solveAll(W& world, const Scaler<S>& byDt, S invDt) {
    typedef LoneRod<S, W::kDimensions, kEnds, typename W::ParticleType> Rod;
    Pass pass(byDt, invDt);
    typename W::ParticleType* particles = &WorldAccess::particle(world, 0);
    for (;;) {
      for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
        if (Rods::isRodAt(world, i)) {
          Slot& s = WorldAccess::constraint(world, i);
          Rod::solve(particles, s.a, s.b, Rods::linkOf(s), pass);
        }
      }
      if (!pass.positions) break;
      // After a fast turn (pass.turned), unit directions (see above).
      // (byDt is the step's: the world kept the rest of its kick.)
      WorldAccess::movePositionsOfStep(world, byDt);
      pass.positions = false;
    }
  }

 private:
  static bool isImmovable(W& world, uint8_t p) {
    return p >= W::kParticleCapacity ||
           WorldAccess::particle(world, p).isStatic();
  }
};

}  // namespace tinyparticle
