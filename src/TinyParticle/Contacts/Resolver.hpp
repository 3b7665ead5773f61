// The contact resolver (after Millington's Cyclone, reworked for an 8-bit
// CPU).
//
// Each iteration takes the contact with the most negative separating
// velocity among those still closing or still penetrating, and:
//  1. resolves its velocity: the separating velocity becomes
//     -restitution * closing velocity, except for the part of the closing
//     velocity that this step's acceleration alone built up, which is removed
//     without a bounce (the resting-contact fix: a ball on the floor neither
//     jitters nor sinks). Millington's fix looks at the relative acceleration
//     only, which misses stacks: a ball resting on a ball that the floor has
//     just stopped closes at g dt although both feel the same gravity. So a
//     contact whose closing speed is within what the accelerations of both
//     particles can build in one step (|a_a.n| + |a_b.n|) dt gets no bounce
//     at all; faster ones bounce as Millington's do;
//  2. moves both particles out of penetration, in the ratio of their inverse
//     masses;
//  3. updates the penetration and separating velocity of only those contacts
//     that share a particle it moved, then finds the next contact to resolve
//     in one pass. Contacts whose particles are in no other contact (a ball
//     alone on the floor) are resolved first, each once, in one pass: they
//     neither change nor depend on any other.
// It stops when nothing is closing or penetrating, or after the iteration
// cap (default: twice the number of contacts).
//
// Divisions: the share of each particle is 1, 0 or 1/2 when one side is
// immovable or both masses are equal (walls, pivots, equal balls); only two
// different masses cost a reciprocal per resolved contact (the compact one:
// a scene whose step never divides links no fast divide for it).
//
// Arithmetic with the contact normal skips the zeros and ones of an axis
// plane's normal in fixed point (Contact.hpp), and a multiply by dt may be a
// shift (Scaler).
#pragma once

#include <stdint.h>

#include "../Math/Scaler.hpp"
#include "../Math/Vec.hpp"
#include "../Math/Zero.hpp"
#include "../Core/Handle.hpp"
#include "Contact.hpp"
#include "../Core/Access.hpp"

namespace tinyparticle {

template <class W>
struct Resolver {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef typename W::ParticleType P;
  typedef typename W::ContactType C;

  // Resolves the world's contacts; returns the iterations used. byDt
  // multiplies by the step's dt. (Out of line: inlined into World::step()
  // with the integrator, the two crowded its registers; apart, the 16
  // balls' step is 1 % faster and 230 B smaller.)
  TINYPARTICLE_NOINLINE static uint8_t resolve(W& world,
                                               const Scaler<S>& byDt,
                                               uint8_t cap) {
    const uint8_t count = world.contactCount();
    if (count == 0) return 0;
    C* const contacts = &WorldAccess::contact(world, 0);
    // Below these a contact counts as resolved (see updateAndFindWorst()).
    const S closing = -W::speedMargin();
    const S deep = W::contactMargin();
    // A world of one contact slot: once resolved, its contact is done, and
    // nothing else is linked. (A single contact in a larger pool takes the
    // one pass below: a shortcut for it cost more flash than it saved.)
    if (W::kContactCapacity <= 1) {
      if (cap == 0 || !isActive(contacts[0], closing, deep)) return 0;
      Change change;
      resolveAny(world, contacts[0], byDt, change);
      return 1;
    }
    // The particles in more than one contact: a resolution changes other
    // contacts only through them (a ball alone on the floor touches none).
    // For each particle slot, whether it is in no contact (0), one (1) or
    // more (above 1) (a byte each: a bit per slot cost shifts and masks on
    // every look, more than the bytes save); b = kNoIndex (scenery) counts
    // none.
    uint8_t uses[kSlots];
    for (uint8_t i = 0; i < kSlots; ++i) uses[i] = 0;
    for (uint8_t j = 0; j < count; ++j) {
      const uint8_t a = contacts[j].a, b = contacts[j].b;
      // (0, then 1, 3, 7...: shifted in, no compare.)
      if (a < kSlots) uses[a] = uint8_t(uses[a] << 1 | 1);
      if (b < kSlots) uses[b] = uint8_t(uses[b] << 1 | 1);
    }
    // A contact whose particles are in no other contact changes no other
    // one, and no other one changes it: it is resolved once, in one pass,
    // with the same result as when the search below would have reached it
    // (balls resting on the floor apart from each other). Resolved, it is
    // neither closing nor penetrating, so the search and the updates after
    // each resolution are left with the list of the contacts that share
    // particles (in index order, so ties go as over the whole pool).
    uint8_t linked[W::kContactCapacity > 0 ? W::kContactCapacity : 1];
    uint8_t linkedCount = 0;
    uint8_t iterations = 0;
    // (One for all resolutions: each writes every field it reads.)
    Change change;
    for (uint8_t j = 0; j < count; ++j) {
      C& contact = contacts[j];
      if (isShared(uses, contact.a) || isShared(uses, contact.b)) {
        linked[linkedCount++] = j;
        continue;
      }
      if (iterations == cap || !isActive(contact, closing, deep)) continue;
      resolveAny(world, contact, byDt, change);
      ++iterations;
    }
    if (linkedCount == 0) return iterations;
    // (Nothing changed yet: the first pass only looks for the worst.)
    change.touched[0] = change.touched[1] = kAllIndex;
    uint8_t current = kNoIndex;
    for (;;) {
      const uint8_t next =
          updateAndFindWorst(world, linked, linkedCount, current, change);
      if (next == kNoIndex || iterations >= cap) break;
      // (The contact just resolved is neither closing nor penetrating now,
      // so it is not picked again.)
      resolveAny(world, contacts[next], byDt, change);
      ++iterations;
      current = next;
    }
    return iterations;
  }
  static uint8_t resolve(W& world, S dt, uint8_t cap) {
    return resolve(world, Scaler<S>(dt), cap);
  }

  // The contact pool's policy, for a contact a generator records: the next
  // free slot; when the pool is full, the least severe contact (the largest
  // separating velocity) gives way to a more severe one, and either way one
  // contact is dropped (World counts it and raises kContactsDropped).
  // Returns the slot, or kNoIndex when the new contact is the one dropped.
  static uint8_t slotFor(W& world, S separating) {
    const uint8_t count = world.contactCount();
    if (count < W::kContactCapacity) {
      WorldAccess::takeContactSlot(world);
      return count;
    }
    WorldAccess::dropContact(world);
    if (W::kContactCapacity == 0) return kNoIndex;
    uint8_t slot = 0;
    for (uint8_t i = 1; i < W::kContactCapacity; ++i) {
      if (WorldAccess::contact(world, i).separatingVelocity >
          WorldAccess::contact(world, slot).separatingVelocity) {
        slot = i;
      }
    }
    if (!(separating < WorldAccess::contact(world, slot).separatingVelocity)) {
      return kNoIndex;
    }
    return slot;
  }

  static S separatingVelocity(W& world, const C& c) {
    return separatingVelocityAlong(world, c.a, c.b, c.normal);
  }

  // dot(va - vb, normal). An immovable particle counts as at rest, whatever
  // its velocity field says (it never moves). The normal is taken in the
  // form a contact stores (Contact::Normal), so that a contact's recorded
  // separating velocity is the one the resolver computes from it.
  static S separatingVelocity(W& world, uint8_t a, uint8_t b, const V& normal) {
    const typename C::Normal& stored = detail::storedNormal(
        normal, static_cast<const typename C::Normal*>(nullptr));
    return separatingVelocityAlong(world, a, b, stored);
  }
  // The same with the normal in its stored form.
  static S separatingVelocityStored(W& world, uint8_t a, uint8_t b,
                                    const typename C::Normal& normal) {
    return separatingVelocityAlong(world, a, b, normal);
  }

  // dot(v, normal) for a contact normal (a Vec, or a contact's stored form
  // Contact::Normal): the same result, without the multiplies by the zeros
  // and ones of axis planes' normals.
  template <class N>
  static S along(const V& v, const N& normal) {
    return detail::alongNormal(v, normal);
  }

 private:
  // separatingVelocity() with the normal in its stored form. (Left to the
  // compiler: forced out of line, a scene with one caller paid for a call.)
  static S separatingVelocityAlong(W& world, uint8_t a, uint8_t b,
                                   const typename C::Normal& normal) {
    // (va - vb, then one dot with the normal: the same arithmetic as
    // component by component, in one copy of the code.)
    V relative = world.particleAt(a).velocity;
    if (b != kNoIndex && !world.particleAt(b).isStatic()) {
      relative -= world.particleAt(b).velocity;
    }
    return along(relative, normal);
  }

  static bool isActive(const C& c, S closing, S deep) {
    return c.separatingVelocity < closing || c.penetration > deep;
  }

  // The particle slots' count for the sharing counts (at least one: ISO
  // C++ has no zero-size arrays); whether particle i is in more than one
  // contact.
  static const uint8_t kSlots =
      W::kParticleCapacity > 0 ? W::kParticleCapacity : 1;
  static bool isShared(const uint8_t* uses, uint8_t i) {
    return i < kSlots && uses[i] > 1;
  }

  // What a resolution changed, for the contacts that share its particles:
  // for side a (0) and b (1), the particle whose velocity or position it
  // changed (touched) and the one it moved (moved), or kAllIndex (no
  // contact's particle), and how far that one moved.
  struct Change {
    // (Left unconstructed, the moves in a union: every resolution writes
    // each field that is read after it; zeroing them cost 32 B of stores.)
    Change() {}
    union {
      V move[2];
    };
    uint8_t touched[2];
    uint8_t moved[2];
    bool velocity;      // velocities changed
  };

  // velocity += normal * dv, move = normal * dx, position += move (dv or
  // dx may be 0: nothing to multiply then). (Left to the compiler: called
  // from resolveAny()'s loop over the two sides only, out of line it took
  // 54 B more.)
  static void push(P& p, const typename C::Normal& normal, S dv, S dx,
                   V& move) {
    detail::pushAlongNormal(p.velocity, p.position, move, normal, dv, dx);
  }

  // One pass over the list `linked` (contact indices, ascending). First,
  // after a resolution of contact `current`: the penetration and separating
  // velocity of every other contact on it that shares a particle the
  // resolution changed (kAllIndex matches no contact; the contacts off the
  // list share none). Then, of each, whether it is the worst so far: the
  // index of the contact with the most negative separating velocity (ties:
  // the lowest index) among those closing (below -World::speedMargin()) or
  // penetrating (deeper than World::contactMargin()); kNoIndex if none.
  // Below the margins a contact counts as resolved: otherwise corrections
  // that round to one unit of the scalar (or, in float, that halve forever
  // between a ball and the floor under it) would be resolved again and
  // again up to the cap. What they leave is picked up by the next step.
  // (One pass for both: the two passes apart, each out of line, took 26 B
  // more. Left to the compiler: from its one caller, out of line it took
  // 58 B more.)
  static uint8_t updateAndFindWorst(
      W& world, const uint8_t* linked, uint8_t count, uint8_t current,
      const Change& change) {
    C* const contacts = &WorldAccess::contact(world, 0);
    const S closing = -W::speedMargin();
    const S deep = W::contactMargin();
    uint8_t worstIndex = kNoIndex;
    S worst = S::largest();
    for (uint8_t k = 0; k < count; ++k) {
      const uint8_t j = linked[k];
      C* const c = &contacts[j];
      const uint8_t a = c->a, b = c->b;
      if (j != current &&
          (a == change.touched[0] || a == change.touched[1] ||
           b == change.touched[0] || b == change.touched[1])) {
        for (uint8_t side = 0; side < 2; ++side) {
          const uint8_t moved = change.moved[side];
          if (moved != a && moved != b) continue;
          // (a moved along the normal: shallower; b: deeper.)
          const S shift = along(change.move[side], c->normal);
          c->penetration = moved == a ? c->penetration - shift
                                      : c->penetration + shift;
        }
        if (change.velocity) {
          c->separatingVelocity = separatingVelocity(world, *c);
        }
      }
      const S separating = c->separatingVelocity;
      if (separating < worst && isActive(*c, closing, deep)) {
        worst = separating;
        worstIndex = j;
      }
    }
    return worstIndex;
  }

  // Resolves one contact: velocity, then penetration. (Out of line: called
  // from three places.)
  TINYPARTICLE_NOINLINE static void resolveAny(W& world, C& contact,
                                               const Scaler<S>& byDt,
                                               Change& change) {
    P& a = world.particleAt(contact.a);
    P* b = contact.b != kNoIndex ? &world.particleAt(contact.b) : nullptr;
    bool movesA = !a.isStatic();
    bool movesB = b != nullptr && !b->isStatic();
    change.velocity = false;
    // A sleeper pushed by a contact that became active here: all wake.
    if (a.isAsleep() || (b != nullptr && b->isAsleep())) {
      WorldAccess::wakeInContacts(world);
    }
    // (Neither moving, as between two immovable particles, takes the same
    // path: nothing is pushed, and the contact ends resolved.)
    // 1. Velocity.
    const S separating = contact.separatingVelocity;
    S deltaV = S();
    if (detail::isNegative(separating)) {
      const S restitution = WorldAccess::restitutionOf(world, contact.source);
      const bool stacked = movesB && movesA &&
                           WorldAccess::isCollision(world, contact.source);
      S target = S();
      deltaV = -separating;
      if (!detail::isZero(restitution) || stacked) {
        // The closing velocity that this step's accelerations can have
        // built, along the normal.
        const S alongA =
            WorldAccess::accelerationAlong(world, a, contact.normal);
        const S alongB =
            movesB ? WorldAccess::accelerationAlong(world, *b, contact.normal)
                   : S();
        if (deltaV > byDt(fabs(alongA) + fabs(alongB))) {
          if (!detail::isZero(restitution)) {
            // A real impact: bounce, but not the part of the closing
            // velocity that the relative acceleration built in this step
            // (restitution times the rest; one multiply).
            S bounced = deltaV;
            const S built = byDt(alongA - alongB);
            if (built < S()) {
              bounced += built;
              if (bounced < S()) bounced = S();
            }
            target = restitution * bounced;
            deltaV += target;
          }
        } else if (stacked) {
          // Resting, one ball on another: the one that the acceleration
          // presses onto the other takes the whole correction, as if the
          // lower one were held by what it rests on (shock propagation).
          // Otherwise a stack on the floor passes the correction down and up
          // again, halving it each time, and eats the iteration budget.
          if (alongA < S()) {
            movesB = false;
          } else if (alongB > S()) {
            movesA = false;
          }
        }
        // A contact within what the accelerations alone explain gets no
        // bounce at all (a ball resting on the floor, or on another ball
        // that the floor has just stopped), so it neither jitters nor sinks.
      }
      contact.separatingVelocity = target;
      change.velocity = true;
    }

    // A's share of each correction: its inverse mass over the sum. Exact
    // without a division when one side is immovable or the masses are equal.
    // (Two different masses take the compact reciprocal: slower than the
    // fast divide, but small, and set-up links it anyway for the inverse
    // masses; a step that never divides then links no fast divide. Both
    // move, so both inverse masses are positive, and so is their sum.)
    // (Worked out after the velocity: a resting contact may have taken a
    // side's motion away.)
    S shareA = S(1);
    if (!movesA) {
      shareA = S();
    } else if (movesB) {
      shareA = a.inverseMass == b->inverseMass
                   ? S(0.5)
                   : a.inverseMass * detail::compactReciprocalOfPositive(
                                         a.inverseMass + b->inverseMass);
    }

    // The same split for both corrections: a moves along the normal by its
    // share, b against it by the rest (so the two add up exactly).
    S penetration = contact.penetration;
    const bool penetrating = detail::isPositive(penetration);
    if (penetrating) {
      contact.penetration = S();
    } else {
      penetration = S();
    }
    // (shareA is 0 when a does not move: b then takes it all. b's push is
    // written as a's part less the whole, the negated rest, without a
    // negation.)
    S velocityA = deltaV, penetrationA = penetration;
    if (movesB) {
      velocityA = deltaV * shareA;
      penetrationA = penetration * shareA;
    }
    // Side a (0), then b (1), in one copy of the code.
    for (uint8_t side = 0; side < 2; ++side) {
      P* const p = side == 0 ? &a : b;
      const uint8_t index = side == 0 ? contact.a : contact.b;
      const bool moves = side == 0 ? movesA : movesB;
      uint8_t touched = kAllIndex, moved = kAllIndex;
      if (moves) {
        // (b's share only where b moves: in float, two library calls less
        // per resolution against a wall.)
        S dv = velocityA, dx = penetrationA;
        if (side != 0) {
          dv -= deltaV;
          dx -= penetration;
        }
        push(*p, contact.normal, dv, dx, change.move[side]);
        touched = index;
        if (penetrating) moved = index;
      }
      change.touched[side] = touched;
      change.moved[side] = moved;
    }
  }
};

}  // namespace tinyparticle
