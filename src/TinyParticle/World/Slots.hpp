// The uniform slots of the force and constraint pools, and the pool storage.
//
// A slot is a function pointer plus the particles it acts on plus a union of
// the parameters of every generator type. The pointer is set by the World
// function that adds the generator, so a generator type that a sketch never
// adds is never instantiated and its code is not linked. A null pointer marks
// a free slot.
#pragma once

#include <stdint.h>

#include "../Contacts/Link.hpp"
#include "../Contacts/Plane.hpp"
#include "../Forces/Buoyancy.hpp"
#include "../Forces/CustomForce.hpp"
#include "../Forces/Drag.hpp"
#include "../Forces/Gravity.hpp"
#include "../Forces/Spring.hpp"
#include "../Forces/StiffSpring.hpp"
#include "../Math/Vec.hpp"

namespace tinyparticle {

// W is the world type; it is incomplete here, which is fine for a pointer.
template <typename S, uint8_t Dim, class W>
struct ForceSlot {
  typedef void (*Apply)(W& world, ForceSlot& slot, S dt);

  Apply apply;         // null: the slot is free
  uint8_t a;           // particle index, or kAllIndex
  uint8_t b;           // second particle, kAnchorIndex, or kNoIndex
  uint8_t generation;  // bumped when the slot is freed
  union Params {
    constexpr Params() : none(0) {}
    uint8_t none;
    GravityParams<S, Dim> gravity;
    DragParams<S> drag;
    SpringParams<S, Dim> spring;  // springs and bungees
    BuoyancyParams<S> buoyancy;
    StiffSpringParams<S, Dim> stiffSpring;
    CustomForceParams<S, Dim> custom;
  } params;

  constexpr ForceSlot() : apply(nullptr), a(0), b(0), generation(0), params() {}
  bool inUse() const { return apply != nullptr; }
};

template <typename S, uint8_t Dim, class W>
struct ConstraintSlot {
  typedef void (*Generate)(W& world, ConstraintSlot& slot, uint8_t index);

  Generate generate;   // null: the slot is free
  uint8_t a;           // particle index, or kAllIndex
  uint8_t b;           // second particle, kAnchorIndex, or kNoIndex
  uint8_t generation;  // bumped when the slot is freed
  S restitution;       // of the contacts it makes
  union Params {
    constexpr Params() : none(0) {}
    uint8_t none;
    LinkParams<S, Dim> link;  // rods and cables
    PlaneParams<S, Dim> plane;
    BoxParams<S, Dim> box;    // no larger than a link
  } params;

  constexpr ConstraintSlot()
      : generate(nullptr), a(0), b(0), generation(0), restitution(), params() {}
  static_assert(sizeof(BoxParams<S, Dim>) <= sizeof(LinkParams<S, Dim>),
                "a box's parameters must not make every constraint slot larger");
  bool inUse() const { return generate != nullptr; }
};

namespace detail {

// N objects of type T. A pool of capacity 0 is an empty base class of the
// world, so it takes no RAM; the loops over it vanish at compile time, so
// its at() is never executed.
template <typename T, uint8_t N>
struct Pool {
  T mItems[N];
  T& at(uint8_t i) { return mItems[i]; }
  const T& at(uint8_t i) const { return mItems[i]; }
};

template <typename T>
struct Pool<T, 0> {
  T& at(uint8_t) { return *reinterpret_cast<T*>(this); }
  const T& at(uint8_t) const { return *reinterpret_cast<const T*>(this); }
};

}  // namespace detail

}  // namespace tinyparticle
