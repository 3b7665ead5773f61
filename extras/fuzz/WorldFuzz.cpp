// libFuzzer target (issue 13): small random scenes built from the input,
// stepped, and checked after every operation. Built with clang and
// -fsanitize=fuzzer,address,undefined (extras/fuzz/Makefile), so undefined
// behaviour and out-of-bounds accesses stop the run as well.
//
// The first byte picks the world (Q16.16 2D or 3D, Q24.8 2D, Float 2D);
// then each operation is a byte (which one) and its arguments. Checked:
//  - an add either returns a handle that looks up to its object, or an
//    invalid handle with an error bit set; a removed object's handle no
//    longer looks up (pools of at most 8 slots: far from 256 reuses);
//  - counts stay within the pools' capacities;
//  - after a step, no particle holds inf or NaN unless
//    WorldError::kNonFinite is set (Float), and no fixed-point component
//    sits at the scalar's edge (raw max or min: saturated) unless
//    MathError::kOverflow is set. (Inputs never hold the edge values
//    themselves, so a component there was saturated by the engine.)
// A violated check calls abort(), which libFuzzer reports with the input.
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "TinyParticle.hpp"

using namespace tinyparticle;

namespace {

class Input {
 public:
  Input(const uint8_t* data, size_t size) : mData(data), mSize(size) {}
  bool empty() const { return mSize == 0; }
  uint8_t byte() {
    if (mSize == 0) return 0;
    --mSize;
    return *mData++;
  }
  uint16_t word() { return uint16_t(byte() | (uint16_t(byte()) << 8)); }
  int32_t raw32() {
    uint32_t v = word();
    v |= uint32_t(word()) << 16;
    return int32_t(v);
  }

 private:
  const uint8_t* mData;
  size_t mSize;
};

// WORLDFUZZ_TRACE=1 when replaying a finding: each operation and the state
// of each particle after each step, on stderr.
const bool sTrace = getenv("WORLDFUZZ_TRACE") != nullptr;

[[noreturn]] void fail(const char* what) {
  fprintf(stderr, "WorldFuzz: %s\n", what);
  abort();
}

// ---- scalars from bytes: mostly small values, some anywhere in range,
// never the two edge values (see the top).
template <class S>
struct ScalarBits;

template <int I, int F>
struct ScalarBits<Fixed<I, F> > {
  typedef Fixed<I, F> S;
  typedef typename S::Raw Raw;
  static S make(Input& in) {
    const uint8_t kind = in.byte();
    int32_t raw;
    switch (kind & 3) {
      case 0:  // a few units: -8..8 with fine fraction
        raw = int32_t(int16_t(in.word())) >> (kind >> 5);
        raw = F >= 12 ? raw * (1L << (F - 12)) : raw >> (12 - F);
        break;
      case 1:  // whole numbers
        raw = int32_t(int8_t(in.byte())) * (1L << F);
        break;
      case 2:  // anywhere
        raw = in.raw32();
        break;
      default:  // tiny: a few raw units
        raw = int32_t(int8_t(in.byte()) >> (kind >> 5));
        break;
    }
    Raw r = Raw(raw);
    if (r == S::largest().raw()) --r;
    if (r == S::lowest().raw()) ++r;
    return S::fromRaw(r);
  }
  static bool atEdge(S x) { return x == S::largest() || x == S::lowest(); }
  static bool finite(S) { return true; }
  static S nonFinite(Input& in) { return make(in); }
};

template <>
struct ScalarBits<Float> {
  static Float make(Input& in) {
    const uint8_t kind = in.byte();
    switch (kind & 3) {
      case 0:
        return Float(double(int16_t(in.word())) / 4096.0 / double(1 << (kind >> 5)));
      case 1:
        return Float(int(int8_t(in.byte())));
      case 2: {
        // any finite float
        uint32_t bits = uint32_t(in.raw32());
        float f;
        memcpy(&f, &bits, sizeof f);
        if (!isfinite(f)) f = 0.0f;
        return Float(double(f));
      }
      default:
        return Float(double(int8_t(in.byte())) * 1e-7);
    }
  }
  static bool atEdge(Float) { return false; }
  static bool finite(Float x) { return isfinite(x.toFloat()); }
  static Float nonFinite(Input& in) {
    switch (in.byte() & 3) {
      case 0: return Float(double(NAN));
      case 1: return Float(double(INFINITY));
      case 2: return Float(double(-INFINITY));
      default: return Float(3.0e38);
    }
  }
};

template <class W>
class Scene {
 public:
  typedef typename W::Scalar S;
  typedef typename W::Vec V;
  typedef ScalarBits<S> Bits;
  static const uint8_t kKept = 8;

  explicit Scene(Input& in) : mIn(in) { forget(); }

  void run() {
    clearMathErrors();
    uint16_t operations = 0;
    while (!mIn.empty() && operations++ < 200) {
      mWorld.clearError();  // each operation's own bits
      const uint8_t op = mIn.byte();
      if (sTrace) fprintf(stderr, "op %d\n", op % 24);
      bool added = false, ok = true;
      switch (op % 24) {
        case 0: ok = keep(mParticles, mWorld.addParticle(vec(), scalar(), scalar())); added = true; break;
        case 1: ok = keep(mParticles, mWorld.addFixedParticle(vec(), scalar())); added = true; break;
        case 2: {
          const ParticleId id = particle();
          if (mWorld.removeParticle(id) && mWorld.particle(id) != nullptr) fail("removed particle still live");
          break;
        }
        case 3: ok = keep(mForces, mWorld.addGravity()); added = true; break;
        case 4: ok = keep(mForces, mWorld.addGravity(particle(), scalar())); added = true; break;
        case 5: ok = keep(mForces, mWorld.addDrag(particle(), scalar(), scalar())); added = true; break;
        case 6: ok = keep(mForces, mWorld.addSpring(particle(), particle(), scalar(), scalar())); added = true; break;
        case 7: ok = keep(mForces, mWorld.addSpring(particle(), vec(), scalar(), scalar())); added = true; break;
        case 8: ok = keep(mForces, mWorld.addBungee(particle(), particle(), scalar(), scalar())); added = true; break;
        case 9: ok = keep(mForces, mWorld.addStiffSpring(particle(), vec(), scalar(), scalar(), scalar())); added = true; break;
        case 10: ok = keep(mConstraints, mWorld.addRod(particle(), particle(), scalar())); added = true; break;
        case 11: ok = keep(mConstraints, mWorld.addRod(particle(), vec(), scalar())); added = true; break;
        case 12: ok = keep(mConstraints, mWorld.addCable(particle(), particle(), scalar(), scalar())); added = true; break;
        case 13: ok = keep(mConstraints, mWorld.addPlane(vec(), scalar(), scalar())); added = true; break;
        case 14: mWorld.addBox(vec(), vec(), scalar()); break;
        case 15:  // plain or swept collisions, by the op's top bit
          ok = keep(mConstraints, (op & 0x80) ? mWorld.addSweptCollisions(scalar())
                                              : mWorld.addCollisions(scalar()));
          added = true;
          break;
        case 16: {
          const ConstraintId id = constraint();
          if (mWorld.removeConstraint(id) && mWorld.constraint(id) != nullptr) fail("removed constraint still live");
          break;
        }
        case 17: mWorld.setLength(constraint(), scalar()); break;
        case 18: mWorld.applyForce(particle(), vec()); break;
        case 19: setState(); break;
        case 20: steps(); break;
        case 21: mWorld.clear(); forget(); break;
        case 22: {
          const ForceId id = force();
          if (mWorld.removeForce(id) && mWorld.force(id) != nullptr) fail("removed force still live");
          break;
        }
        default: {
          typename W::ParticleType* p = mWorld.particle(particle());
          if (p != nullptr) {
            p->setDampingRate(scalar());
            p->setCollides((op & 0x80) != 0);
          }
          break;
        }
      }
      if (added && !ok && mWorld.error() == 0) fail("add refused without an error bit");
      if (mWorld.particleCount() > W::kParticleCapacity) fail("particle count beyond capacity");
    }
    steps();
  }

 private:
  S scalar() {
    const S x = Bits::make(mIn);
    if (sTrace) fprintf(stderr, "  arg %.9g\n", double(x.toFloat()));
    return x;
  }
  V vec() {
    V v;
    for (uint8_t k = 0; k < W::kDimensions; ++k) v[k] = scalar();
    return v;
  }

  // A handle the scene got back, or now and then any bits at all.
  template <class Id>
  Id pick(const Id* kept) {
    const uint8_t b = mIn.byte();
    if ((b & 0xF0) == 0xF0) return Id(mIn.byte(), mIn.byte());
    return kept[b % kKept];
  }
  ParticleId particle() { return pick(mParticles); }
  ForceId force() { return pick(mForces); }
  ConstraintId constraint() { return pick(mConstraints); }

  // Records a handle from an add; false when it was refused. A handle the
  // world gave out must look up.
  bool keep(ParticleId* kept, ParticleId id) {
    if (!id.isValid()) return false;
    if (mWorld.particle(id) == nullptr) fail("new particle handle does not look up");
    kept[id.index % kKept] = id;
    return true;
  }
  bool keep(ForceId* kept, ForceId id) {
    if (!id.isValid()) return false;
    // (The world's gravity has no slot to look up: World::kGravityIndex.)
    if (id.index != W::kGravityIndex && mWorld.force(id) == nullptr) {
      fail("new force handle does not look up");
    }
    kept[id.index % kKept] = id;
    return true;
  }
  bool keep(ConstraintId* kept, ConstraintId id) {
    if (!id.isValid()) return false;
    if (mWorld.constraint(id) == nullptr) fail("new constraint handle does not look up");
    kept[id.index % kKept] = id;
    return true;
  }
  void forget() {
    for (uint8_t i = 0; i < kKept; ++i) {
      mParticles[i] = ParticleId();
      mForces[i] = ForceId();
      mConstraints[i] = ConstraintId();
    }
  }

  // Sets a movable particle's position or velocity, now and then to inf or
  // NaN (Float): what a sketch might write.
  void setState() {
    typename W::ParticleType* p = mWorld.particle(particle());
    const uint8_t how = mIn.byte();
    if (p == nullptr) return;
    V& target = (how & 1) ? p->velocity : p->position;
    target = vec();
    if ((how & 0x0E) == 0x0E && !p->isImmovable()) {
      target[how >> 4 & 1] = Bits::nonFinite(mIn);
    }
  }

  void steps() {
    S dt = scalar();
    const uint8_t count = uint8_t(1 + mIn.byte() % 64);
    const uint8_t how = mIn.byte();
    if (how & 1) dt = S(1.0 / 256);  // the usual step, often
    for (uint8_t n = 0; n < count; ++n) {
      if (how & 2) {
        mWorld.step(dt, uint8_t(1 + (how >> 4)));
      } else {
        mWorld.step(dt);
      }
      // A refused step (dt <= 0 or NaN) moves nothing, so it also leaves
      // an injected inf or NaN where it was, unflagged.
      if (dt > S()) checkState();
    }
  }

  void checkState() {
    const bool flaggedNonFinite = (mWorld.error() & WorldError::kNonFinite) != 0;
    const bool flaggedOverflow = (mathErrors() & MathError::kOverflow) != 0;
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const typename W::ParticleType& p = mWorld.particleAt(i);
      if (!p.inUse() || p.isImmovable()) continue;
      if (sTrace) {
        fprintf(stderr, "  p%d x", i);
        for (uint8_t k = 0; k < W::kDimensions; ++k) fprintf(stderr, " %.9g", double(p.position[k].toFloat()));
        fprintf(stderr, " v");
        for (uint8_t k = 0; k < W::kDimensions; ++k) fprintf(stderr, " %.9g", double(p.velocity[k].toFloat()));
        fprintf(stderr, " 1/m %.9g r %.9g err %d math %d\n", double(p.inverseMass.toFloat()),
                double(p.radius.toFloat()), mWorld.error(), mathErrors());
      }
      for (uint8_t k = 0; k < W::kDimensions; ++k) {
        if (!flaggedNonFinite &&
            (!Bits::finite(p.position[k]) || !Bits::finite(p.velocity[k]))) {
          fail("inf or NaN in a particle without kNonFinite");
        }
        if (!flaggedOverflow &&
            (Bits::atEdge(p.position[k]) || Bits::atEdge(p.velocity[k]))) {
          fail("a component at the scalar's edge without kOverflow");
        }
      }
    }
  }

  Input& mIn;
  W mWorld;
  ParticleId mParticles[kKept];
  ForceId mForces[kKept];
  ConstraintId mConstraints[kKept];
};

template <class W>
void runScene(Input& in) {
  Scene<W> scene(in);
  scene.run();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Input in(data, size);
  switch (in.byte() & 3) {
    case 0: runScene<World<Q16_16, 2, 6, 6, 8, 8> >(in); break;
    case 1: runScene<World<Q16_16, 3, 6, 6, 8, 8> >(in); break;
    case 2: runScene<World<Q24_8, 2, 6, 6, 8, 8> >(in); break;
    default: runScene<World<Float, 2, 6, 6, 8, 8> >(in); break;
  }
  return 0;
}
