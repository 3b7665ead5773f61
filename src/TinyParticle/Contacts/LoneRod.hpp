// Lone rods: rods that share no particle, each solved on its own.
//
// A pendulum, a lever, a Newton's cradle: no rod shares a particle with
// another, so there is nothing to eliminate, and each rod is solved in one
// pass with the step equations of the chains' solve (Contacts/RodSolver.hpp:
// positionSpeed(), exact at any turn), about 24 multiplies per rod and step
// in 2D, no division and no square root (in fixed point not even when it
// turns fast, or at set-up: Math/Newton.hpp).
//
// Which solver a world links (World::rodAdded()): a world whose rods can
// never share a particle takes this one alone, and the chains' solve (the
// larger part of Contacts/RodSolver.hpp) is not linked. That is a world of one constraint slot,
// and a world whose rods all hang from anchors (addRod(particle, anchor,
// length)), where a particle takes one rod: a second anchored rod on the
// same particle is refused (WorldError::kBadArgument) while the world has
// no rod between two particles. The first rod between two particles, in a
// world of more slots, brings the chains' solve; it passes every lone
// world to solveAll() here at run time (Contacts/RodSolver.hpp).
//
// Two savings over the chains' solve make the lever's step about 40 %
// cheaper (measured):
// - no rows, passes or divisions (a rod with two movable ends divides
//   once in each of the two solves, for its ends' shares);
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
//   such turns the closed form's terms are large, and |u| = 1 + e would put
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

template <class W>
struct LoneRods {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef typename W::ParticleType P;
  typedef typename W::ConstraintSlot Slot;
  typedef RodSolver<W> Rods;
  typedef typename Rods::Pass Pass;

  // The world's rod solve when its rods never share a particle (see the
  // top of this file). kTwoMovable: a rod may have two movable ends (a
  // rod between particles); without, every rod hangs from an anchor
  // (World::anchoredRodAdded() sets this solve only then), and neither the
  // code for two movable ends nor that for a rod between particles is
  // linked.
  template <bool kTwoMovable>
  static void solve(W& world, const Scaler<S>& byDt, S dt) {
    if (WorldAccess::rodState(world) & W::kRodsChanged) {
      WorldAccess::setRodState(world, W::kRodsLone);
    }
    solveAll<kTwoMovable, !kTwoMovable>(world, byDt,
                                        WorldAccess::inverseDt(world, dt));
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
  // move, directions and velocities (RATTLE). kAnchored: every rod hangs
  // from an anchor (b), and a is its moving end unless it is immovable.
  template <bool kTwoMovable, bool kAnchored = false>
  static void solveAll(W& world, const Scaler<S>& byDt, S invDt) {
    Pass pass(byDt, invDt);
    pass.unit = false;
    for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
      if (Rods::isRodAt(world, i)) {
        shake<kTwoMovable, kAnchored>(world, WorldAccess::constraint(world, i),
                                      pass);
      }
    }
    // After a fast turn, unit directions (see above).
    const bool unit = pass.turned;
    WorldAccess::movePositions(world, byDt);
    for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
      if (Rods::isRodAt(world, i)) {
        rattle<kTwoMovable, kAnchored>(world, WorldAccess::constraint(world, i),
                                       unit);
      }
    }
  }

 private:
  static bool isImmovable(W& world, uint8_t p) {
    return p >= W::kParticleCapacity || world.particleAt(p).isStatic();
  }

  // The moving end of a rod with one immovable end; fromB when that is b
  // (the rod's direction then points away from it). A rod on an anchor
  // moves at a.
  template <bool kAnchored>
  static P& movingEnd(W& world, const Slot& s, bool& fromB) {
    P& a = world.particleAt(s.a);
    fromB = !kAnchored && a.isStatic();
    return fromB ? world.particleAt(s.b) : a;
  }

  // The position solve of one rod: with one immovable end, the moving
  // end's change of speed along u. (Through the chains' rightSide() it
  // cost 400 cycles more.) With two movable ends, the same for their
  // relative motion, shared between them (shareBoth()).
  template <bool kTwoMovable, bool kAnchored>
  static void shake(W& world, const Slot& s, Pass& pass) {
    const uint8_t moving = movingEnds<kTwoMovable, kAnchored>(world, s);
    if (moving == 0) return;
    const bool both = kTwoMovable && moving == 2;
    bool fromB;
    P& end = movingEnd<kAnchored>(world, s, fromB);  // a when both move
    const V& u = Rods::linkOf(s).direction;
    const V d = Rods::span(world, s);  // from b to a: the same as rattle()'s
    const V* w = &end.velocity;
    V relative;
    if (both) {
      relative = end.velocity;
      relative -= world.particleAt(s.b).velocity;
      w = &relative;
    } else if (fromB) {
      // Seen from b, the rod is -d along -u. Every product of the solve
      // then changes sign twice or not at all, except those with the
      // velocity: negating it instead gives the same speed and error to
      // the bit (a product rounds symmetrically), and the change along -u
      // is minus that along u. (Two scalars negated here rather than two
      // vectors through Vec's operator-: 128 B less where b may move.)
      for (uint8_t i = 0; i < V::kDimensions; ++i) relative[i] = -end.velocity[i];
      w = &relative;
    }
    S error;
    bool turning;
    S speed = Rods::positionSpeed(d, *w, u, Rods::linkOf(s), pass, error,
                                  turning);
    if (turning) pass.turned = true;
    if (both) {
      shareBoth(world, s, speed, error);
      return;
    }
    if (fromB) {
      speed = -speed;
      error = -error;
    }
    end.velocity.addScaled(u, speed);
    if (!detail::isZero(error)) end.position.addScaled(u, error);
  }

  // The new direction, and the velocity solve: no speed along the rod.
  template <bool kTwoMovable, bool kAnchored>
  static void rattle(W& world, Slot& s, bool unit) {
    const uint8_t moving = movingEnds<kTwoMovable, kAnchored>(world, s);
    if (moving == 0) return;
    Rods::setDirection(Rods::span(world, s), Rods::linkOf(s), unit);
    if (kTwoMovable && moving == 2) {
      rattleBoth(world, s);
      return;
    }
    bool fromB;
    P& end = movingEnd<kAnchored>(world, s, fromB);
    detail::removeAlong(end.velocity, Rods::linkOf(s).direction);
  }


  // How many ends of the rod move: 0, 1 or 2 (at most 1 without
  // kTwoMovable: b is an anchor, or the world's rods each have one
  // immovable end, LoneRods::allLone()).
  template <bool kTwoMovable, bool kAnchored>
  static uint8_t movingEnds(W& world, const Slot& s) {
    if (kAnchored) return uint8_t(!isImmovable(world, s.a));
    if (!kTwoMovable) {
      return uint8_t(!isImmovable(world, s.a) || !isImmovable(world, s.b));
    }
    return uint8_t(!isImmovable(world, s.a)) +
           uint8_t(!isImmovable(world, s.b));
  }

  // A rod with two movable ends (a free dumbbell, or a world of one
  // constraint slot whose rod joins two movable particles): the change of
  // their relative speed is shared in the ratio of the inverse masses, a's
  // share w_a / (w_a + w_b) and b's the rest. Out of line: rare. Through
  // the compact reciprocal (rounded twice: a unit at most), so that a world
  // whose step never divides elsewhere (the lever) links no fast divide.
  static S shareOfA(const P& a, const P& b) {
    return a.inverseMass *
           detail::compactReciprocalOfPositive(a.inverseMass + b.inverseMass);
  }
  // The change `speed` of the relative speed along u, and the move
  // `error` along it, shared between the two ends.
  TINYPARTICLE_NOINLINE static void shareBoth(W& world, const Slot& s,
                                              S speed, S error) {
    P& a = world.particleAt(s.a);
    P& b = world.particleAt(s.b);
    const V& u = Rods::linkOf(s).direction;
    const S share = shareOfA(a, b);
    pushApart(a.velocity, b.velocity, u, speed, share);
    if (!detail::isZero(error)) {
      pushApart(a.position, b.position, u, error, share);
    }
  }
  // x gets `amount` times `share` along u, y the rest against it.
  TINYPARTICLE_NOINLINE static void pushApart(V& x, V& y, const V& u,
                                              S amount, S share) {
    const S toX = amount * share;
    x.addScaled(u, toX);
    y.addScaled(u, toX - amount);
  }
  // RATTLE for two moving ends: their relative speed along u, r, is taken
  // out as a change -r shared as above (shareBoth(): a gets (-r) w, which
  // is -(r w) to the bit, as a product rounds ties away from zero; b gets
  // (-r) w - (-r) = r - r w; in fixed point all but r = S::lowest(),
  // which -r saturates: a relative speed no step reaches).
  TINYPARTICLE_NOINLINE static void rattleBoth(W& world, const Slot& s) {
    const V& u = Rods::linkOf(s).direction;
    V relative = world.particleAt(s.a).velocity;
    relative -= world.particleAt(s.b).velocity;
    const S radial = detail::dotOutOfLine(relative, u);
    shareBoth(world, s, -radial, S());
  }
};

}  // namespace tinyparticle
