// Particle-particle collisions between spheres, as a contact generator: a
// scene that never calls World::addCollisions() (or addSweptCollisions())
// links none of this code and pays nothing per step.
//
// Sort and sweep along x. The colliding particles are sorted by the x of
// their centres, and each one is paired only with those after it whose
// centre is within its radius plus the largest radius (plus the contact
// margin) along x: the inner loop stops at the first one that is not, so a
// step costs about one compare per particle plus one per pair that overlaps
// along x, instead of one per pair. The order is kept from one step to the
// next (particles move little in a step), so the insertion sort that
// restores it costs about one compare per particle. The pairs that pass are
// tested on the other axes (|d| > r1 + r2 rejects) in the same loop, then
// squared, and only touching pairs pay for a normal (by multiplies: no
// square root or divide is linked for collisions in fixed point).
// Touching counts, and so does a gap below World::contactMargin(), as for
// planes: a resting ball must still lose the closing velocity that gravity
// gives it in each step.
//
// The speed limit (tunnelling). Contacts are found from the positions after
// each step's move, so two balls that cross each other within one step are
// never seen. While every moving particle goes at most the smallest radius
// in a step (|v| dt <= r_min, with |v| bounded from above by the largest
// axis's speed plus half the others': within 12 % of |v| in 2D, 22 % in
// 3D, and no square root), two particles close by at most the sum of their
// radii per step: their centres cannot pass each other between two
// looks, so a collision is found, and resolved on the right side. (What a
// step can still miss: a glancing touch, shallower than 13 % of the radii's
// sum, of two particles that are apart again by the step's end.) Beyond
// that speed a pair may pass through each other unseen, and the step raises
// WorldError::kTunnelling. Planes need no limit: they are half-spaces, and
// whatever has crossed one is behind it and is pushed back. (r = 3 cm at
// dt = 1/256 s: 7.7 m/s; halving dt doubles it.)
//
// Swept contacts (World::addSweptCollisions()) lift the limit for pairs. A
// step below it is exactly the plain one. A step past it sweeps: each
// particle moved in a straight line, so a pair's difference went from
// p0 = delta - d to delta (d, the difference of their moves); the sweep
// takes in the moves along x and y, and a pair that was apart at the start
// and whose path came within reach gets the contact of its first touch
// (sweptPair()), however fast, also when it ends the step overlapping or
// past each other. No flag is raised. What a swept step can still get
// wrong: a particle that also meets a plane or a third particle in the
// same step (its path was not straight), or one that the resolver pushes
// back out of a deep contact through a third one it did not touch. The
// sweep costs more cycles, and more stack (sweptPair()'s frame, on top of
// the sort list's), only in the steps past the limit.
//
// Memory: the sort order lives in a static array of one byte per particle
// slot, linked only with this generator. Worlds of one type share
// it; any starting order gives the same contacts, a shared one is only less
// sorted. The sweep list is on the stack (5 bytes per colliding particle in
// Q16.16 and float).
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "../Math/Fixed.hpp"
#include "../Math/Float.hpp"
#include "../Math/Newton.hpp"
#include "../Math/Scaler.hpp"
#include "../Math/ScalarTraits.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "../Core/Handle.hpp"
#include "../Core/Access.hpp"

namespace tinyparticle {
namespace detail {

// (Magnitudes compare by isAboveNonNegative(), Math/Zero.hpp: for floats
// their bit patterns as unsigned integers, a compare of four bytes instead
// of a call to the float compare; the bound then costs the survey a few
// cycles per particle more than |vx| + |vy| did.)

// A bound on the speed |v| for the speed limit, without a square root: the
// largest axis's |v_k| plus half of the others' (a >= b >= c >= 0:
// (a + b/2)^2 >= a^2 + b^2 as ab >= b^2, and (a + (b + c)/2)^2 >=
// a^2 + b^2 + c^2 as a(b + c) >= b^2 + c^2). It is at most 1.12 |v| in 2D
// (at b = a/2; |vx| + |vy| is up to 1.41 |v|), 1.22 |v| in 3D (1.73).
// In any scalar: a bound that cannot overflow (Sum) and its value as the
// scalar (toScalar); along() is one axis's share.
template <typename S>
struct AxisSpeed {
  typedef S Sum;
  static S of(const Vec<S, 2>& v) {
    const S a = fabs(v.x), b = fabs(v.y);
    return isAboveNonNegative(a, b) ? a + half(b) : b + half(a);
  }
  static S of(const Vec<S, 3>& v) {
    S a = fabs(v.x), b = fabs(v.y), c = fabs(v.z);
    if (isAboveNonNegative(b, a)) {
      const S t = a; a = b; b = t;
    }
    if (isAboveNonNegative(c, a)) {
      const S t = a; a = c; c = t;
    }
    return a + half(b + c);
  }
  static S along(S v) { return fabs(v); }
  static S toScalar(S sum) { return sum; }
};

// Fixed point: the magnitudes of the raw values, unsigned; a bound past the
// unsigned range is held at its top (3D: up to 2^31 + 2^31).
template <uint8_t I, uint8_t F>
struct AxisSpeed<Fixed<I, F> > {
  typedef Fixed<I, F> T;
  typedef typename T::URaw Sum;
  // (2D: at most 2^31 + 2^30, no overflow.)
  static Sum of(const Vec<T, 2>& v) {
    const Sum a = along(v.x), b = along(v.y);
    return a > b ? Sum(a + (b >> 1)) : Sum(b + (a >> 1));
  }
  static Sum of(const Vec<T, 3>& v) {
    Sum a = along(v.x), b = along(v.y), c = along(v.z);
    if (b > a) {
      const Sum t = a; a = b; b = t;
    }
    if (c > a) {
      const Sum t = a; a = c; c = t;
    }
    return plus(a, Sum((b >> 1) + (c >> 1)));
  }
  static Sum along(T v) { return T::magnitude(v.raw()); }
  static T toScalar(Sum sum) {
    return sum > Sum(T::kRawMax) ? T::largest()
                                 : T::fromRaw(typename T::Raw(sum));
  }

 private:
  static Sum plus(Sum a, Sum b) {
    const Sum sum = Sum(a + b);
    return sum < a ? Sum(~Sum(0)) : sum;
  }
};

// A difference of centres along x only (balls side by side on the floor:
// its contacts leave them at exactly the same height) normalises to x, +1
// or -1, and its length is that component's magnitude: the exact answer,
// what Vec::magnitudeAndNormalize() gives for it while the magnitude is
// below 2^kTop, where that normalisation scales nothing down (checked for
// every such value by extras/test/CollisionAxisTest). The general way
// (Newton's multiplies) comes within a few units of it, for a dozen
// multiplies. Fixed point only; false (nothing done) for any other vector
// or scalar.
template <typename S>
struct AxisDifference {
  template <class V>
  static bool normalize(V&, S&) {
    return false;
  }
};

template <uint8_t I, uint8_t F>
struct AxisDifference<Fixed<I, F> > {
  typedef Fixed<I, F> T;
  typedef typename T::Raw Raw;
  typedef typename T::URaw URaw;
  // Vec's normalisation keeps the largest magnitude below 2^kTop.
  static const uint8_t kTop = (sizeof(Raw) * 8 + F - 3) / 2;

  static bool normalize(Vec<T, 2>& v, T& length) {
    return v.y.raw() == 0 && unit(v.x, length);
  }
  static bool normalize(Vec<T, 3>& v, T& length) {
    return v.y.raw() == 0 && v.z.raw() == 0 && unit(v.x, length);
  }

 private:
  static bool unit(T& c, T& length) {
    const Raw raw = c.raw();
    const URaw m = T::magnitude(raw);
    if (m == 0 || m >= (URaw(1) << kTop)) return false;
    length = T::fromRaw(Raw(m));
    c = T::fromRaw(raw < 0 ? Raw(-T::kRawOne) : Raw(T::kRawOne));
    return true;
  }
};

}  // namespace detail

template <class W>
struct CollisionConstraint {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef typename W::ParticleType P;

  // World::addCollisions(): contacts of touching pairs, and the speed limit.
  static void generate(W& world, typename W::ConstraintSlot&, uint8_t source) {
    generateWith<false>(world, source);
  }
  // World::addSweptCollisions(): also the pairs whose paths in the step
  // met, at any speed (top of this file).
  static void generateSwept(W& world, typename W::ConstraintSlot&,
                            uint8_t source) {
    generateWith<true>(world, source);
  }

 private:
  template <bool kSwept>
  static void generateWith(W& world, uint8_t source) {
    const uint8_t both = P::kInUse | P::kCollides;
    // At least one entry: ISO C++ has no zero-size arrays.
    static const uint8_t kSize =
        W::kParticleCapacity > 0 ? W::kParticleCapacity : 1;
    uint8_t* order = sortOrder();

    // The colliding particles in last step's order, by their centre's x,
    // each inserted at its place (insertion sort: a nearly sorted list
    // costs one compare per particle). The centre, not the start of the
    // extent: the loop then does no arithmetic, and the sweep allows for
    // the largest radius instead.
    // (Left unconstructed: each entry is written before it is read, and
    // zeroing the list cost a store per byte and step.)
    union List {
      List() {}
      Entry at[kSize];
    } list;
    Entry* const entries = list.at;
    Entry* end = entries;
    for (uint8_t k = 0; k < W::kParticleCapacity; ++k) {
      const uint8_t i = uint8_t(order[k] ^ k);  // (see sortOrder())
      const P& p = world.particleAt(i);
      if ((p.flags & both) != both) continue;
      const S x = p.position.x;
      Entry* e = end++;
      while (e != entries && x < e[-1].x) {
        *e = e[-1];
        --e;
      }
      e->x = x;
      e->index = i;
    }
    const uint8_t count = uint8_t(end - entries);
    // Keep the new order for the next step: the colliding particles
    // sorted, then the others (any order will do for them). (Written every
    // step, all of it: a test for "nothing moved" cost more flash than the
    // stores' cycles are worth.)
    {
      uint8_t k = 0;
      for (const Entry* e = entries; e != end; ++e, ++k) {
        order[k] = uint8_t(e->index ^ k);
      }
      for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
        if ((world.particleAt(i).flags & both) != both) {
          order[k] = uint8_t(i ^ k);
          ++k;
        }
      }
    }
    // Swept contacts only in a step that goes past the speed limit: below
    // it the plain sweep finds every pair that met.
    bool fast = false;
    const S spread = survey<kSwept>(world, fast);
    if (kSwept && fast) {
      sweep<true>(world, entries, count, spread, source);
    } else {
      sweep<false>(world, entries, count, spread, source);
    }
  }

  struct Entry {
    S x;
    uint8_t index;
  };

  // One look at the colliding particles: the spread of the sweep
  // (returned): the largest radius plus the contact margin; and the speed
  // limit (top of this file): whether the fastest moving one goes farther
  // in this step (by AxisSpeed's bound) than the smallest moving one's
  // radius. Past it, without swept contacts, the step raises
  // WorldError::kTunnelling; with them, it is `fast`, and the spread takes
  // in the longest move along x too. A loop of its own, with a pointer
  // walk: in the sort loop it cost three times as much (spilled
  // registers). (Left to the compiler: out of line it took 98 B more.) The
  // speeds are AxisSpeed's magnitudes: for fixed point the raw bits,
  // unsigned, with no saturating arithmetic in the loop.
  template <bool kSwept>
  static S survey(W& world, bool& fast) {
    typedef detail::AxisSpeed<S> Speed;
    typedef typename Speed::Sum Sum;
    const uint8_t both = P::kInUse | P::kCollides;
    Sum fastest = Sum(), fastestX = Sum();
    S smallest = S::largest(), largest = S();
    const P* p = &world.particleAt(0);
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i, ++p) {
      if ((p->flags & both) != both) continue;
      if (p->radius > largest) largest = p->radius;
      if (p->isResting()) continue;  // immovable or asleep
      const Sum speed = Speed::of(p->velocity);
      if (speed > fastest) fastest = speed;
      if (kSwept) {
        const Sum speedX = Speed::along(p->velocity.x);
        if (speedX > fastestX) fastestX = speedX;
      }
      if (p->radius < smallest) smallest = p->radius;
    }
    const Scaler<S>& byDt = WorldAccess::stepScaler(world);
    const S spread = largest + W::contactMargin();
    fast = byDt(Speed::toScalar(fastest)) > smallest;
    if (!kSwept) {
      if (fast) WorldAccess::raiseError(world, WorldError::kTunnelling);
      return spread;
    }
    return fast ? spread + byDt(Speed::toScalar(fastestX)) : spread;
  }

  // The pairs of the sorted list; spread from survey(). Out of line, so
  // that its frame is small: behind the list's frame, every spilled value
  // would cost more to reach.
  template <bool kSwept>
  TINYPARTICLE_NOINLINE static void sweep(W& world, const Entry* entries,
                                          uint8_t count, S spread,
                                          uint8_t source) {
    const S margin = W::contactMargin();
    // The sums of a radius and the margin (reach) and of a radius and the
    // spread (bound). A float's are kept while the radius stays the same
    // (in most scenes every particle has the same one): its adds cost about
    // 100 cycles each. Fixed point adds them again for each particle: its
    // adds are cheap, and the compare and copies of the cache took 110 B.
    S radius = S(), reach = margin, bound = spread;
    for (uint8_t m = 0; uint8_t(m + 1) < count; ++m) {
      const uint8_t i = entries[m].index;
      const P& p = world.particleAt(i);
      if (ScalarTraits<S>::kCoarse || !(p.radius == radius)) {
        radius = p.radius;
        reach = radius + margin;
        bound = radius + spread;
      }
      // Every later entry's centre is at or after this one's; those whose
      // centre is farther than this radius plus the largest one (and the
      // margin, and with swept contacts both moves along x), and all after
      // them, are apart along x.
      S high = entries[m].x + bound;
      if (kSwept) high += moveOf(world, p, p.velocity.x);
      for (uint8_t n = m + 1; n < count && !(high < entries[n].x); ++n) {
        const uint8_t j = entries[n].index;
        const P& q = world.particleAt(j);
        // Apart along an axis: |d| > r1 + r2 + margin (with swept
        // contacts, plus both moves along it). Tested here, before a call:
        // most pairs that overlap along x end here.
        const S outer = reach + q.radius;
        if (!kSwept) {
          if (fabs(p.position.y - q.position.y) > outer) continue;
          if (W::kDimensions == 3 &&
              fabs(p.position[2] - q.position[2]) > outer) {
            continue;
          }
        } else if (sweptApart(world, p, q, outer)) {
          continue;
        }
        // The lower slot index is a, as a sweep in slot order would have it.
        const bool inOrder = i < j;
        const uint8_t first = inOrder ? i : j, second = inOrder ? j : i;
        // In a fast step, a pair that was apart when it began and met in
        // it gets the contact of its first touch, also when it ends the
        // step overlapping: there the normal from the end positions would
        // be off (a ball 20 cm into another one in a step). (Called from
        // here, not from pair(): this is the deepest point of the step's
        // stack.)
        if (!kSwept || !sweptPair(world, first, second, outer, source)) {
          pair(world, first, second, inOrder ? p : q, inOrder ? q : p, outer,
               source);
        }
      }
    }
  }

  // The order of the particle slots by their centre's x, as of the last
  // step: a permutation of 0 .. capacity - 1, entry k holding its slot
  // XOR k, so that the zeroed array of a new sketch is the slot order
  // 0, 1, 2... (no flag, and no loop, to set it up).
  static uint8_t* sortOrder() {
    static const uint8_t kSize =
        W::kParticleCapacity > 0 ? W::kParticleCapacity : 1;
    static uint8_t order[kSize];
    return order;
  }

  // Particles i < j whose boxes overlap: outer = r1 + r2 + margin.
  // (a and b are those particles, which the sweep has at hand.)
  static void pair(W& world, uint8_t i, uint8_t j, const P& a, const P& b,
                   S outer, uint8_t source) {
    if (a.isResting() && b.isResting()) return;  // immovable or asleep
    // r1 + r2, from outer (the radii are far from saturating).
    const S reach = outer - W::contactMargin();
    const V delta = a.position - b.position;
    const S distanceSquared = delta.magnitudeSquared();
    if (distanceSquared > outer * outer) return;
    // The normal from the difference itself, not from distanceSquared: for
    // small balls in fixed point that square is a few units of the scalar
    // (r = 1 cm in Q16.16: 26 units at contact), and a normal from it would
    // be off by a few percent, a bounce gaining or losing as much energy.
    // In fixed point, unitAndDistance() (below) scales the difference up
    // first (Math/Newton.hpp), so the normal is unit length to a few units
    // of the scalar; the distance is the difference along it.
    V normal = delta;
    S distance = S();
    if (!detail::AxisDifference<S>::normalize(normal, distance) &&
        !unitAndDistance(normal, delta, distance)) {
      normal = V();
      normal.y = S(1);  // centres coincide: any direction will do
    }
    S penetration = reach - distance;
    WorldAccess::addContact(world, i, j, normal, penetration, source);
  }
  // The unit normal along delta and the distance along it; false when the
  // centres coincide. Fixed point by Newton's multiplies, so that a sketch
  // links no divide and no square root for its collisions; other scalars
  // by their square root and divide, which cost a float about half as many
  // cycles as the multiplies (a pile of floats: 10 % of its step).
  template <typename T, uint8_t N>
  static bool unitAndDistance(Vec<T, N>& normal, const Vec<T, N>&,
                              T& distance) {
    distance = normal.magnitudeAndNormalize();
    return !(distance == T());
  }
  template <uint8_t I, uint8_t F, uint8_t N>
  static bool unitAndDistance(Vec<Fixed<I, F>, N>& normal,
                              const Vec<Fixed<I, F>, N>& delta,
                              Fixed<I, F>& distance) {
    if (!detail::normalizeByMultiplies(normal)) return false;
    distance = dot(delta, normal);
    return true;
  }

  // ---- Swept contacts (World::addSweptCollisions()) ----------------------

  // How far a particle moved along one axis in this step, |v dt| (none for
  // an immovable or sleeping one): the integrator's own x += v dt.
  static S moveOf(W& world, const P& p, S velocity) {
    if (p.isResting()) return S();
    return fabs(WorldAccess::stepScaler(world)(velocity));
  }
  static V movesOf(W& world, const P& p) {
    V move;
    if (p.isResting()) return move;
    const Scaler<S>& byDt = WorldAccess::stepScaler(world);
    move.x = byDt(p.velocity.x);
    move.y = byDt(p.velocity.y);
    if (W::kDimensions == 3) move[2] = byDt(p.velocity[2]);
    return move;
  }

  // The boxes that the two particles swept in this step are apart along y
  // (or z): farther than outer plus both moves along it.
  TINYPARTICLE_NOINLINE static bool sweptApart(W& world, const P& p,
                                               const P& q, S outer) {
    if (fabs(p.position.y - q.position.y) >
        outer + moveOf(world, p, p.velocity.y) +
            moveOf(world, q, q.velocity.y)) {
      return true;
    }
    return W::kDimensions == 3 &&
           fabs(p.position[2] - q.position[2]) >
               outer + moveOf(world, p, p.velocity[2]) +
                   moveOf(world, q, q.velocity[2]);
  }

  // Whether a pair i < j was apart (farther than outer) when the step
  // began and came within outer during it; if so, it gets its contact here
  // (delta = a - b at the end of the step). Both moved in a straight line, so
  // their difference went from p0 = delta - d to delta, d the difference of
  // their moves. The contact is as at the first touch: its normal along
  // the difference where the distance first was r1 + r2 (for a grazing
  // pass, where it was least), and its depth what the pair must move back
  // along it, r1 + r2 - dot(delta, normal), more than r1 + r2 when the
  // centres passed each other. The resolver moves them back and bounces
  // them.
  TINYPARTICLE_NOINLINE static bool sweptPair(W& world, uint8_t i, uint8_t j,
                                              S outer, uint8_t source) {
    const P& a = world.particleAt(i);
    const P& b = world.particleAt(j);
    const V delta = a.position - b.position;
    const bool apart = delta.magnitudeSquared() > outer * outer;
    // (Few vectors, each updated in place: this runs deep in the step's
    // stack, next to the sort list.)
    V ds = movesOf(world, a);
    ds -= movesOf(world, b);
    // The path is at least |delta| - |d| away: along the axes, the largest
    // of delta's against the sum of d's. Slow pairs end here.
    S largest = fmax(fabs(delta.x), fabs(delta.y));
    S dSum = fabs(ds.x) + fabs(ds.y);
    if (W::kDimensions == 3) {
      largest = fmax(largest, fabs(delta[2]));
      dSum += fabs(ds[2]);
    }
    if (!(dSum > S())) return false;  // no relative move
    if (apart && largest - dSum > outer) return false;
    V p0 = delta;
    p0 -= ds;
    // In fixed point, the products below of centimetres would be a few
    // units: scale the lengths first by a power of two that brings the
    // largest to [1/2, 1) (exact up to the last bit; floats need none).
    S scale = S(1);
    if (ScalarTraits<S>::kCoarse) {
      largest = fmax(fmax(largest, dSum), outer);
      while (largest < S(0.5)) {
        largest = largest + largest;
        scale = scale + scale;
      }
      while (!(largest < S(1))) {
        largest = detail::half(largest);
        scale = detail::half(scale);
      }
      ds *= scale;
      p0 *= scale;
    }
    const S scaledOuter = outer * scale;
    const S outerSquared = scaledOuter * scaledOuter;
    const S along = dot(p0, ds);  // < 0 while the centres close
    const S lengthSquared = dot(ds, ds);
    const S startSquared = dot(p0, p0);
    // Touching at the start (then last step's contacts had it), not
    // closing, or a relative move too small to show after the scaling:
    // none.
    if (!(startSquared > outerSquared) || !(along < S()) ||
        !(lengthSquared > S())) {
      return false;
    }
    // The nearest point of the path must be inside it (the end is apart),
    // and within outer: its distance squared is
    // |p0|^2 - along^2 / |d|^2, compared without the division.
    if (apart && (!(-along < lengthSquared) ||
                  crossSquared(p0, ds) > outerSquared * lengthSquared)) {
      return false;
    }
    // The first touch: |p0 + t d| = r1 + r2, the smaller root t.
    const S reach = (a.radius + b.radius) * scale;
    const S discriminant =
        along * along - lengthSquared * (startSquared - reach * reach);
    S t = discriminant < S()
              ? -along / lengthSquared  // grazing: the nearest point
              : (-along - sqrt(discriminant)) / lengthSquared;
    if (t > S(1)) t = S(1);
    p0.addScaled(ds, t);  // the difference at the first touch
    if (p0.magnitudeAndNormalize() == S()) {
      p0 = -ds;  // met centre on centre: back the way a came
      p0.normalize();
    }
    WorldAccess::addContact(world, i, j, p0, (a.radius + b.radius) - dot(delta, p0),
                     source);
    return true;
  }
  // |u x v|^2.
  static S crossSquared(const Vec<S, 2>& u, const Vec<S, 2>& v) {
    const S c = u.x * v.y - u.y * v.x;
    return c * c;
  }
  static S crossSquared(const Vec<S, 3>& u, const Vec<S, 3>& v) {
    return cross(u, v).magnitudeSquared();
  }
};

}  // namespace tinyparticle
