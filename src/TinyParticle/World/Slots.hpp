// The uniform slots of the force and constraint pools, the list of the
// built-in generators' parameter classes, and the pool storage.
//
// A slot is a function pointer (the runner of one generator class,
// Core/Generator.hpp), the particles it acts on, a kind and a union of the
// parameter classes. The pointer is set by the World function that adds the
// generator, so a generator that a sketch never adds is never instantiated
// and its code is not linked. A null pointer (kind 0) marks a free slot.
//
// Registering a built-in generator is one line: its class in the list
// below (and World's add function that places it). A sketch's generator
// needs none: its slot holds a SketchGenerator, a pointer to it.
#pragma once

#include <stdint.h>

#include "../Contacts/Link.hpp"
#include "../Contacts/Plane.hpp"
#include "../Core/Generator.hpp"
#include "../Core/Particle.hpp"
#include "../Forces/Buoyancy.hpp"
#include "../Forces/CustomForce.hpp"
#include "../Forces/Drag.hpp"
#include "../Forces/Gravity.hpp"
#include "../Forces/Spring.hpp"
#include "../Forces/StiffSpring.hpp"
#include "../Math/Vec.hpp"

namespace tinyparticle {

// Particle collisions keep no parameters: the class only gives them their
// kind (the resolver asks World::isCollision()).
struct CollisionParams {
  static const uint8_t kShape = SlotShape::kNone;
};

template <typename S, uint8_t Dim>
struct ForceParamList {
  typedef ParamUnion<GravityForce<S, Dim>,
                     DragForce<S, Dim>,
                     SpringForce<S, Dim, false>,
                     SpringForce<S, Dim, true>,
                     AnchoredSpringForce<S, Dim, false>,
                     AnchoredSpringForce<S, Dim, true>,
                     BuoyancyForce<S, Dim>,
                     StiffSpringForce<S, Dim>,
                     CustomForce<S, Dim>,
                     SketchGenerator>
      Type;
};

template <typename S, uint8_t Dim>
struct ConstraintParamList {
  typedef ParamUnion<LinkParams<S, Dim>,  // rods and cables
                     PlaneConstraint<S, Dim>,
                     BoxParams<S, Dim>,
                     CollisionParams,
                     SketchGenerator>
      Type;
};

template <typename S, uint8_t Dim>
struct ForceSlot;

// What a force generator's runner sees of the world during a step: the
// particle pool. World::step() builds one on the stack. The runners
// take it instead of the world, so that every World<S, Dim, ...> type
// shares the force slots' type, the runners and the code that places and
// runs them (issue 12).
template <typename S, uint8_t Dim>
struct ForceStep {
  typedef S Scalar;
  typedef tinyparticle::Vec<S, Dim> Vec;
  typedef Particle<S, Dim> ParticleType;
  typedef tinyparticle::ForceSlot<S, Dim> ForceSlot;

  ParticleType* particles;
  uint8_t particleCount;

  // For WorldAccess, as a world's.
  ParticleType& particleAt(uint8_t i) { return particles[i]; }
};

// The same for every world of this scalar and dimension.
template <typename S, uint8_t Dim>
struct ForceSlot {
  typedef void (*Apply)(ForceStep<S, Dim>& forces, ForceSlot& slot, S dt);
  typedef typename ForceParamList<S, Dim>::Type Params;

  Apply apply;         // null: the slot is free
  uint8_t a;           // particle index, or kAllIndex
  uint8_t b;           // second particle, kAnchorIndex, or kNoIndex
  uint8_t generation;  // bumped when the slot is freed
  uint8_t kind;        // KindOf<class, Params>::value; 0 when free
  Params params;

  constexpr ForceSlot()
      : apply(nullptr), a(0), b(0), generation(0), kind(0), params() {}
  bool inUse() const { return apply != nullptr; }
  // Whether it holds a generator of class C.
  template <class C>
  bool holds() const {
    return kind == KindOf<C, Params>::value;
  }
};

template <typename S, uint8_t Dim, class W>
struct ConstraintSlot {
  typedef void (*Generate)(W& world, ConstraintSlot& slot, uint8_t index);
  typedef typename ConstraintParamList<S, Dim>::Type Params;

  Generate generate;   // null: the slot is free
  uint8_t a;           // particle index, or kAllIndex
  uint8_t b;           // second particle, kAnchorIndex, or kNoIndex
  uint8_t generation;  // bumped when the slot is freed
  uint8_t kind;        // KindOf<class, Params>::value; 0 when free
  S restitution;       // of the contacts it makes
  Params params;

  constexpr ConstraintSlot()
      : generate(nullptr), a(0), b(0), generation(0), kind(0), restitution(),
        params() {}
  static_assert(sizeof(BoxParams<S, Dim>) <= sizeof(LinkParams<S, Dim>),
                "a box's parameters must not make every constraint slot larger");
  bool inUse() const { return generate != nullptr; }
  template <class C>
  bool holds() const {
    return kind == KindOf<C, Params>::value;
  }
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
