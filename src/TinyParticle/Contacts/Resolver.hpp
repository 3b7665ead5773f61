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
//     that share a particle it moved, and in the same pass finds the next
//     contact to resolve.
// It stops when nothing is closing or penetrating, or after the iteration
// cap (default: twice the number of contacts).
//
// Divisions: the share of each particle is 1, 0 or 1/2 when one side is
// immovable or both masses are equal (walls, pivots, equal balls); only two
// different masses cost a division per resolved contact.
#pragma once

#include <stdint.h>

#include "../Math/Vec.hpp"
#include "../World/Handle.hpp"

namespace tinyparticle {

template <class W>
struct Resolver {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef typename W::ParticleType P;
  typedef typename W::ContactType C;

  // Resolves the world's contacts; returns the iterations used.
  static uint8_t resolve(W& world, S dt, uint8_t cap) {
    const uint8_t count = world.contactCount();
    if (count == 0) return 0;
    C* contacts = &world.contactAt(0);
    uint8_t next = kNoIndex;
    S worst = (S::max)();
    for (uint8_t j = 0; j < count; ++j) consider(contacts[j], j, worst, next);
    uint8_t iterations = 0;
    while (next != kNoIndex && iterations < cap) {
      const uint8_t current = next;
      C& contact = contacts[current];
      Change change;
      resolveOne(world, contact, dt, change);
      ++iterations;

      // Update the contacts that share a particle the resolution changed
      // (kAllIndex matches no contact), and pick the next one.
      const uint8_t ta = change.touchedA ? contact.a : kAllIndex;
      const uint8_t tb = change.touchedB ? contact.b : kAllIndex;
      next = kNoIndex;
      worst = (S::max)();
      for (uint8_t j = 0; j < count; ++j) {
        if (j == current) continue;  // neither closing nor penetrating now
        C& c = contacts[j];
        bool touched = false;
        if (c.a == ta) {
          if (change.movedA) c.penetration -= dot(change.moveA, c.normal);
          touched = true;
        } else if (c.a == tb) {
          if (change.movedB) c.penetration -= dot(change.moveB, c.normal);
          touched = true;
        }
        if (c.b == ta) {
          if (change.movedA) c.penetration += dot(change.moveA, c.normal);
          touched = true;
        } else if (c.b == tb) {
          if (change.movedB) c.penetration += dot(change.moveB, c.normal);
          touched = true;
        }
        if (touched && change.velocity) {
          c.separatingVelocity = separatingVelocity(world, c);
        }
        consider(c, j, worst, next);
      }
    }
    return iterations;
  }

  static S separatingVelocity(W& world, const C& c) {
    return separatingVelocity(world, c.a, c.b, c.normal);
  }

  // dot(va - vb, normal). An immovable particle counts as at rest, whatever
  // its velocity field says (it never moves).
  static S separatingVelocity(W& world, uint8_t a, uint8_t b, const V& normal) {
    const P& pa = world.particleAt(a);
    if (b == kNoIndex || world.particleAt(b).isStatic()) {
      return dot(pa.velocity, normal);
    }
    return dot(pa.velocity - world.particleAt(b).velocity, normal);
  }

 private:
  struct Change {
    V moveA, moveB;     // how far each particle moved (when moved*)
    bool touchedA;      // a's velocity or position changed
    bool touchedB;
    bool movedA;        // a's position changed
    bool movedB;
    bool velocity;      // velocities changed
  };

  // Keeps the contact if it is closing or penetrating and worse than
  // `worst`. Below the margins (World::speedMargin(), contactMargin()) a
  // contact counts as resolved: otherwise corrections that round to one unit
  // of the scalar (or, in float, that halve forever between a ball and the
  // floor under it) would be resolved again and again up to the cap. What
  // they leave is picked up by the next step.
  static void consider(const C& c, uint8_t index, S& worst, uint8_t& worstIndex) {
    if ((c.separatingVelocity < -W::speedMargin() ||
         c.penetration > W::contactMargin()) &&
        c.separatingVelocity < worst) {
      worst = c.separatingVelocity;
      worstIndex = index;
    }
  }

  static void resolveOne(W& world, C& contact, S dt, Change& change) {
    P& a = world.particleAt(contact.a);
    P* b = contact.b != kNoIndex ? &world.particleAt(contact.b) : nullptr;
    bool movesA = !a.isStatic();
    bool movesB = b != nullptr && !b->isStatic();
    change.movedA = change.movedB = change.velocity = false;
    if (!movesA && !movesB) {
      change.touchedA = change.touchedB = false;
      contact.penetration = S();
      contact.separatingVelocity = S();
      return;
    }
    // A's share of each correction: its inverse mass over the sum. Exact
    // without a division when one side is immovable or the masses are equal.
    S shareA = S(1);
    if (!movesA) {
      shareA = S();
    } else if (movesB) {
      shareA = a.inverseMass == b->inverseMass
                   ? S(0.5)
                   : a.inverseMass / (a.inverseMass + b->inverseMass);
    }

    // 1. Velocity.
    const S separating = contact.separatingVelocity;
    S deltaV = S();
    if (separating < S()) {
      const S restitution = world.restitutionOf(contact.source);
      const bool stacked = movesB && movesA && world.isCollision(contact.source);
      S target = S();
      deltaV = -separating;
      if (restitution != S() || stacked) {
        // The closing velocity that this step's accelerations can have
        // built, along the normal.
        const S alongA = movesA ? dot(a.acceleration, contact.normal) : S();
        const S alongB = movesB ? dot(b->acceleration, contact.normal) : S();
        if (deltaV > (fabs(alongA) + fabs(alongB)) * dt) {
          if (restitution != S()) {
            // A real impact: bounce, but not the part of the closing
            // velocity that the relative acceleration built in this step.
            target = -(separating * restitution);
            S built = (alongA - alongB) * dt;
            if (built < S()) {
              target += restitution * built;
              if (target < S()) target = S();
            }
            deltaV = target - separating;
          }
        } else if (stacked) {
          // Resting, one ball on another: the one that the acceleration
          // presses onto the other takes the whole correction, as if the
          // lower one were held by what it rests on (shock propagation).
          // Otherwise a stack on the floor passes the correction down and up
          // again, halving it each time, and eats the iteration budget.
          if (alongA < S()) {
            shareA = S(1);
            movesB = false;
          } else if (alongB > S()) {
            shareA = S();
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

    // The same split for both corrections: a moves along the normal by its
    // share, b against it by the rest (so the two add up exactly).
    S penetration = contact.penetration;
    const bool penetrating = penetration > S();
    if (penetrating) {
      contact.penetration = S();
    } else {
      penetration = S();
    }
    S velocityA = deltaV, penetrationA = penetration;
    S velocityB = S(), penetrationB = S();
    if (!movesA) {
      velocityA = penetrationA = S();
      velocityB = deltaV;
      penetrationB = penetration;
    } else if (movesB) {
      velocityA = deltaV * shareA;
      penetrationA = penetration * shareA;
      velocityB = deltaV - velocityA;
      penetrationB = penetration - penetrationA;
    }
    if (movesA) {
      if (change.velocity) a.velocity.addScaled(contact.normal, velocityA);
      if (penetrating) {
        change.moveA = contact.normal * penetrationA;
        a.position += change.moveA;
        change.movedA = true;
      }
    }
    if (movesB) {
      if (change.velocity) b->velocity.addScaled(contact.normal, -velocityB);
      if (penetrating) {
        change.moveB = contact.normal * -penetrationB;
        b->position += change.moveB;
        change.movedB = true;
      }
    }
    change.touchedA = movesA;
    change.touchedB = movesB;
  }
};

}  // namespace tinyparticle
