// Generators: how a force or a contact generator is kept in a world's slot
// and run each step. The built-in ones (Forces/, Contacts/) and a sketch's
// own go through the same runners below; extras/doc/design.md, "Adding a
// generator", tells how to write one.
//
// A slot holds a function pointer (the runner for one generator class), the
// particles it acts on (a, and b for a pair), a kind and the parameters.
// The kind says which class the parameters are: the position of that class
// in the world's list of parameter classes (World/Slots.hpp), so code that
// must know what a slot holds (the renderer, setLength(), the resolver's
// collision test) asks the kind, never the layout or the indices.
//
// Where a generator's parameters live:
//  - a built-in generator's, in the slot itself (a union of the built-in
//    classes, as large as the largest: in 2D Q16.16, 16 bytes for forces
//    and 26 for constraints);
//  - a sketch's generator, in the sketch: the slot holds a pointer to the
//    object, which must outlive the slot. The sketch changes its fields
//    whenever it likes (no lookup), it may be of any size, and the slots
//    do not grow for it. It costs one pointer load per step.
//
// The shape of a generator, what its runner calls (each shape has its
// runner below; "each" is a runner of its own, so that the one-particle
// runner has no loop and no test of a):
//   force, one particle or each:  void apply(Particle& p, S dt)
//   force, a pair:                void apply(Particle& a, Particle& b, S dt)
//   contact, one particle or each:
//     bool contact(const Particle& p, Vec& normal, S& penetration)
//   contact, a pair:
//     bool contact(const Particle& a, const Particle& b, Vec& normal,
//                  S& penetration)
// A contact generator returns true when a contact is to be made: the unit
// normal pushes p (or a) out, and the penetration is positive while the
// constraint is violated. The runners for one particle and for each skip
// immovable particles (a contact generator over each also those that do
// not collide or sleep, as the planes do); a pair's contact generator is
// skipped when both ends are immovable, a pair's force never.
#pragma once

#include <stdint.h>

#include "Access.hpp"
#include "Handle.hpp"

namespace tinyparticle {

// How the renderer draws a generator's slot (each parameter class says).
namespace SlotShape {
enum : uint8_t {
  kNone = 0,  // not drawn (a field such as gravity, a plane)
  kPair = 1,  // a line from particle a to particle b
  // A line from a to b, or to the class's `anchor` member when
  // b == kAnchorIndex (springs, stiff springs, rods and cables).
  kAnchorable = 2,
};
}

// What a slot holds for a generator of the sketch: a pointer to it.
struct SketchGenerator {
  static const uint8_t kShape = SlotShape::kNone;
  void* object;
};

namespace detail {

// The anchor of an anchorable parameter class; null for the others.
template <class T, class V, bool kAnchorable>
struct AnchorOf {
  static const V* of(const T&) { return nullptr; }
};
template <class T, class V>
struct AnchorOf<T, V, true> {
  static const V* of(const T& params) { return &params.anchor; }
};

}  // namespace detail

// The parameters of a slot: a union of the listed classes, with a kind for
// each (1 for the first class, 0 for none). Registering a built-in
// generator is adding its class to the list (World/Slots.hpp).
template <typename... Ts>
union ParamUnion;

template <>
union ParamUnion<> {
  uint8_t none;
  constexpr ParamUnion() : none(0) {}
  static uint8_t shapeOf(uint8_t) { return SlotShape::kNone; }
  template <class V>
  const V* anchorOf(uint8_t) const {
    return nullptr;
  }
};

template <typename T, typename... Ts>
union ParamUnion<T, Ts...> {
  T head;
  ParamUnion<Ts...> tail;

  constexpr ParamUnion() : tail() {}

  // The parameters as class C (whose kind the slot holds).
  template <class C>
  C& as();
  template <class C>
  const C& as() const;

  static uint8_t shapeOf(uint8_t kind) {
    return kind == 1 ? uint8_t(T::kShape) : ParamUnion<Ts...>::shapeOf(uint8_t(kind - 1));
  }
  template <class V>
  const V* anchorOf(uint8_t kind) const {
    return kind == 1 ? detail::AnchorOf<T, V, T::kShape ==
                                                  SlotShape::kAnchorable>::of(head)
                     : tail.template anchorOf<V>(uint8_t(kind - 1));
  }
};

// KindOf<C, ParamUnion<...> >: the kind of class C, and its member. A class
// that is not in the list does not compile ("incomplete type KindOf").
template <class C, class U>
struct KindOf;
template <class C, typename... Ts>
struct KindOf<C, ParamUnion<C, Ts...> > {
  static const uint8_t value = 1;
  static C& of(ParamUnion<C, Ts...>& u) { return u.head; }
  static const C& of(const ParamUnion<C, Ts...>& u) { return u.head; }
};
template <class C, typename T, typename... Ts>
struct KindOf<C, ParamUnion<T, Ts...> > {
  typedef KindOf<C, ParamUnion<Ts...> > Next;
  static const uint8_t value = uint8_t(1 + Next::value);
  static C& of(ParamUnion<T, Ts...>& u) { return Next::of(u.tail); }
  static const C& of(const ParamUnion<T, Ts...>& u) { return Next::of(u.tail); }
};

template <typename T, typename... Ts>
template <class C>
inline C& ParamUnion<T, Ts...>::as() {
  return KindOf<C, ParamUnion>::of(*this);
}
template <typename T, typename... Ts>
template <class C>
inline const C& ParamUnion<T, Ts...>::as() const {
  return KindOf<C, ParamUnion>::of(*this);
}

// Where a runner finds its generator: in the slot, or in the sketch.
struct InSlot {
  template <class G, class Slot>
  static G& of(Slot& slot) {
    return slot.params.template as<G>();
  }
};
struct InSketch {
  template <class G, class Slot>
  static G& of(Slot& slot) {
    return *static_cast<G*>(slot.params.template as<SketchGenerator>().object);
  }
};

// The force runners' W is the step's ForceStep<S, Dim> (World/Slots.hpp),
// the same type for every world of that scalar and dimension; the contact
// runners' W is the world.

// Runs a force on particle a: g.apply(p, dt), unless p is immovable.
template <class W, class G, class Where>
struct ForceRunner {
  static void apply(W& world, typename W::ForceSlot& slot,
                    typename W::Scalar dt) {
    G& g = Where::template of<G>(slot);
    typename W::ParticleType& p = WorldAccess::particle(world, slot.a);
    if (!p.isStatic()) g.apply(p, dt);
  }
};

// Runs a force on every movable particle (a is kAllIndex).
template <class W, class G, class Where>
struct EachForceRunner {
  typedef typename W::ParticleType P;

  static void apply(W& world, typename W::ForceSlot& slot,
                    typename W::Scalar dt) {
    G& g = Where::template of<G>(slot);
    for (uint8_t i = 0; i < world.particleCount; ++i) {
      P& p = WorldAccess::particle(world, i);
      if ((p.flags & (P::kInUse | P::kStatic)) == P::kInUse) g.apply(p, dt);
    }
  }
};

// Runs a force between particles a and b: g.apply(pa, pb, dt).
template <class W, class G, class Where>
struct PairForceRunner {
  static void apply(W& world, typename W::ForceSlot& slot,
                    typename W::Scalar dt) {
    Where::template of<G>(slot).apply(WorldAccess::particle(world, slot.a),
                                      WorldAccess::particle(world, slot.b),
                                      dt);
  }
};

// Runs a contact generator for particle a, unless it is immovable.
template <class W, class G, class Where>
struct ContactRunner {
  static void generate(W& world, typename W::ConstraintSlot& slot,
                       uint8_t source) {
    const typename W::ParticleType& p = WorldAccess::particle(world, slot.a);
    if (p.isStatic()) return;
    typename W::Vec normal;
    typename W::Scalar penetration;
    if (Where::template of<G>(slot).contact(p, normal, penetration)) {
      WorldAccess::addContact(world, slot.a, kNoIndex, normal, penetration,
                              source);
    }
  }
};

// Runs a contact generator for every colliding, movable, awake particle (a
// is kAllIndex).
template <class W, class G, class Where>
struct EachContactRunner {
  typedef typename W::ParticleType P;

  static void generate(W& world, typename W::ConstraintSlot& slot,
                       uint8_t source) {
    G& g = Where::template of<G>(slot);
    typename W::Vec normal;
    typename W::Scalar penetration;
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const P& p = WorldAccess::particle(world, i);
      if ((p.flags & (P::kInUse | P::kCollides | P::kStatic | P::kAsleep)) !=
          (P::kInUse | P::kCollides)) {
        continue;
      }
      if (g.contact(p, normal, penetration)) {
        WorldAccess::addContact(world, i, kNoIndex, normal, penetration,
                                source);
      }
    }
  }
};

// Runs a contact generator between particles a and b.
template <class W, class G, class Where>
struct PairContactRunner {
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef typename W::ParticleType P;

  static void generate(W& world, typename W::ConstraintSlot& slot,
                       uint8_t source) {
    const P& a = WorldAccess::particle(world, slot.a);
    const P& b = WorldAccess::particle(world, slot.b);
    if (a.isStatic() && b.isStatic()) return;
    V normal;
    S penetration;
    if (Where::template of<G>(slot).contact(a, b, normal, penetration)) {
      WorldAccess::addContact(world, slot.a, slot.b, normal, penetration,
                              source);
    }
  }
};

}  // namespace tinyparticle
