// ASCII renderer: draws a world as text over any Print-like output (any type
// with write(uint8_t), such as Serial), line by line. It never holds a frame:
// only one line of kColumns characters, on the stack while that line is
// drawn, so a 40 x 20 view costs 41 bytes of stack instead of the seed's
// frame buffer.
//
// It shows the rectangle whose bottom-left corner is (left, bottom), each
// character cellWidth x cellHeight metres (terminal characters are about
// twice as tall as wide, so cellHeight = 2 cellWidth keeps circles round).
// A 3D world is seen along z (its x-y projection).
//
//   'O' a movable particle, filled to its radius ('o' if smaller than a cell)
//   '+' an immovable particle
//   '.' a rod, cable, spring, bungee or stiff spring (to its anchor, too)
//
// A scene whose particles are all smaller than half a cell (in width and in
// height) looks the same with ParticleShape::kPoints as the fourth template
// argument: each particle is then one character, where it is, and the
// circle code (a square root and a division per row, about 400 bytes on
// the Nano) is not linked.
//
// A sketch that never draws a link (no spring, rod or cable in its world)
// passes LinkShape::kNone as the fifth template argument: the slots are then
// not looked at, and the line code (about 400 bytes on the Nano) is not
// linked. One whose links are all rods or cables (no springs) passes
// LinkShape::kRodsAndCables: the force slots are then not looked at (about
// 240 bytes less in examples/HapticLever). (A world's type cannot tell:
// any force or constraint slot may hold a spring or a rod at run time.)
//
// The frame around the view and the ANSI "cursor home" code before each
// frame are the sixth template argument, FrameStyle::kBorder (the default),
// kPlain (neither), kHome or kBorder | kHome: a setting fixed at compile
// time links only the code it uses (about 100 bytes less in
// examples/HapticLever than the two run-time switches it replaced).
//
// Draw a whole frame with draw(), or one line per call with drawLine() so
// that a sketch never waits for a slow serial line (check that the output
// has lineLength() bytes free first).
#pragma once

#include <stdint.h>

#include "../Configuration.hpp"
#include "../Debug/Profile.hpp"
#include "../Core/Access.hpp"
#include "../Core/Generator.hpp"
#include "../Math/Fixed.hpp"
#include "../Math/Float.hpp"

namespace tinyparticle {

// How the renderer draws particles (its fourth template argument).
namespace ParticleShape {
enum : uint8_t {
  kCircles = 0,  // filled to the radius
  kPoints = 1,   // one character at the centre, whatever the radius
};
}

// How the renderer draws springs, rods and cables (its fifth template
// argument).
namespace LinkShape {
enum : uint8_t {
  kLines = 0,          // a line of '.' from end to end
  kNone = 1,           // not drawn, and no code for them linked
  kRodsAndCables = 2,  // rods and cables as kLines; springs not drawn, and
                       // no code for the force slots linked
};
}

// What the renderer draws around the view (its sixth template argument):
// flags, combined with |.
namespace FrameStyle {
enum : uint8_t {
  kPlain = 0,   // the rows only
  kBorder = 1,  // a frame of '-', '|' and '+' around the view
  kHome = 2,    // the ANSI "cursor home" code before each frame, so that a
                // terminal redraws in place instead of scrolling
};
}

template <class W, uint8_t kColumns = 40, uint8_t kRows = 20,
          uint8_t kParticleShape = ParticleShape::kCircles,
          uint8_t kLinkShape = LinkShape::kLines,
          uint8_t kFrame = FrameStyle::kBorder>
class AsciiRenderer {
  static_assert(kColumns >= 1 && kColumns <= 200 && kRows >= 1,
                "1..200 columns, at least 1 row");

 public:
  typedef typename W::Scalar S;
  typedef typename W::Vec V;

  // constexpr: a global renderer with constant bounds costs no start-up
  // code (its scales are folded at compile time). A cell size of 0 gives
  // the largest scale (as S(16) / 0 does, without its error flag).
  constexpr AsciiRenderer(S left, S bottom, S cellWidth, S cellHeight)
      : mX(left, scaleFor(cellWidth)),
        mY(bottom, scaleFor(cellHeight)),
        mLine(0) {}

  // Characters per line, newline included (and the cursor-home code before
  // a frame's first line, with FrameStyle::kHome).
  static uint8_t lineLength() {
    return uint8_t(kColumns + 1 + 2 * kBorder + 3 * kHome);
  }

  // Draws a whole frame.
  template <class Out>
  void draw(const W& world, Out& out) {
    mLine = 0;
    while (!drawLine(world, out)) {
    }
  }

  // Draws the next line of the current frame; true after its last line (the
  // next call starts a new frame).
  template <class Out>
  bool drawLine(const W& world, Out& out) {
    TINYPARTICLE_PROFILE_BEGIN(kProfileRender);
    const uint8_t first = kBorder ? 1 : 0;
    const uint8_t total = uint8_t(kRows + 2 * first);
    if (mLine == 0 && kHome) {
      out.write(uint8_t(27));
      out.write(uint8_t('['));
      out.write(uint8_t('H'));
    }
    // A border line is a row of '-' between '+': one loop writes both.
    const bool edge = kBorder && (mLine == 0 || mLine == total - 1);
    char text[kColumns];
    if (edge) {
      for (uint8_t c = 0; c < kColumns; ++c) text[c] = '-';
    } else {
      renderRow(world, uint8_t(mLine - first), text);
    }
    const uint8_t side = edge ? '+' : '|';
    if (kBorder) out.write(side);
    for (uint8_t c = 0; c < kColumns; ++c) out.write(uint8_t(text[c]));
    if (kBorder) out.write(side);
    out.write(uint8_t('\n'));
    ++mLine;
    const bool done = mLine >= total;
    if (done) mLine = 0;
    TINYPARTICLE_PROFILE_END(kProfileRender);
    return done;
  }

  // Fills `text` with row `row` of the view (0 is the top).
  void renderRow(const W& world, uint8_t row, char* text) const {
    for (uint8_t c = 0; c < kColumns; ++c) text[c] = ' ';
    // The row's band in sub-cell units, y growing upwards.
    const Units low = Units((kRows - 1 - row) * kSub);
    const Units high = Units(low + kSub);

    // Each generator's kind tells how it is drawn (Core/Generator.hpp).
    if (kLinkShape == LinkShape::kLines) {
      for (uint8_t i = 0; i < W::kForceCapacity; ++i) {
        drawSlot(world, WorldAccess::force(world, i), low, high, text);
      }
    }
    if (kLinkShape != LinkShape::kNone) {
      for (uint8_t i = 0; i < W::kConstraintCapacity; ++i) {
        drawSlot(world, WorldAccess::constraint(world, i), low, high, text);
      }
    }
    for (uint8_t i = 0; i < W::kParticleCapacity; ++i) {
      const typename W::ParticleType& p = WorldAccess::particle(world, i);
      if (p.inUse()) drawParticle(p, low, text);
    }
  }

 private:
  static const bool kBorder = (kFrame & FrameStyle::kBorder) != 0;
  static const bool kHome = (kFrame & FrameStyle::kHome) != 0;

  // Positions in sub-cell units, clamped to +-kLimit: 16 bits hold them
  // and the sum or difference of two (8-bit code works on half the bytes),
  // 32 bits their products.
  typedef int16_t Units;
  // Where the view starts along an axis, and its sub-cell units per metre.
  struct Axis {
    constexpr Axis(S from, S unitsPerMetre)
        : origin(from), scale(unitsPerMetre) {}
    S origin;
    S scale;
  };
  static const Units kSub = 16;       // sub-cell units per cell
  static const Units kLimit = 16000;

  // A scaled value's sub-cell units, rounded down and clamped to +-kLimit:
  // the clamp on the raw value, then its integer part with the sign bit
  // flipped (never negative, so no negative number is shifted).
  template <uint8_t I, uint8_t F>
  static Units unitsOf(Fixed<I, F> v) {
    typedef Fixed<I, F> T;
    // In 32 bits: the limit lies beyond a 16-bit format's range. (From 18
    // fraction bits on, every value lies within it.)
    const int32_t limit = F <= 17 ? int32_t(kLimit) << (F <= 17 ? F : 0)
                                  : int32_t(0x7FFFFFFF);
    int32_t raw = v.raw();
    if (raw > limit) raw = limit;
    if (raw < -limit) raw = -limit;
    const typename T::URaw biased = typename T::URaw(
        typename T::URaw(raw) ^ (typename T::URaw(1) << (T::kTotalBits - 1)));
    return Units(int32_t(biased >> F) -
                 (int32_t(1) << (T::kTotalBits - 1 - F)));
  }
  static Units unitsOf(Float v) {
    float f = v.toFloat();
    if (f > float(kLimit)) f = float(kLimit);
    if (f < -float(kLimit)) f = -float(kLimit);
    const Units whole = Units(f);                     // toward zero
    return float(whole) > f ? Units(whole - 1) : whole;  // down
  }
  // One out-of-line routine for both axes: x and y share its code.
  // The axis is passed by address (a call then loads 2 bytes, not 8);
  // a length (a radius) is scaled without the origin.
  static TINYPARTICLE_NOINLINE Units toUnits(S v, const Axis& axis,
                                             bool isLength) {
    return unitsOf((isLength ? v : v - axis.origin) * axis.scale);
  }
  // A position's x and y into out[0] and out[1].
  static TINYPARTICLE_NOINLINE void pointUnits(const V& p, const Axis& x,
                                               const Axis& y, Units* out) {
    out[0] = toUnits(p.x, x, false);
    out[1] = toUnits(p.y, y, false);
  }

  // kSub / cell (sub-cell units per metre), rounded as the scalar's own
  // division rounds it, in a constant expression.
  template <uint8_t I, uint8_t F>
  static constexpr Fixed<I, F> scaleFor(Fixed<I, F> cell) {
    typedef Fixed<I, F> T;
    return T::fromRaw(scaleRaw<T>(
        (typename T::UWide(kSub) << (2 * F)),
        cell.raw() < 0 ? typename T::UWide(typename T::URaw(
                             typename T::URaw(0) - typename T::URaw(cell.raw())))
                       : typename T::UWide(cell.raw()),
        cell.raw() < 0));
  }
  // |quotient| of numerator / divisor, rounded half up, then signed and
  // saturated as Fixed's divide does.
  template <class T>
  static constexpr typename T::Raw scaleRaw(typename T::UWide numerator,
                                            typename T::UWide divisor,
                                            bool negative) {
    return divisor == 0
               ? T::kRawMax
               : saturate<T>((numerator + divisor / 2) / divisor, negative);
  }
  template <class T>
  static constexpr typename T::Raw saturate(typename T::UWide m,
                                            bool negative) {
    return m == 0 ? typename T::Raw(0)
           : negative ? (m > typename T::UWide(T::kRawMax) + 1
                           ? T::kRawMin
                           : typename T::Raw(-typename T::Raw(m - 1) - 1))
                    : (m > typename T::UWide(T::kRawMax)
                           ? T::kRawMax
                           : typename T::Raw(m));
  }
  static constexpr Float scaleFor(Float cell) {
    return cell.toFloat() == 0.0f ? Float::largest()
                                  : Float(float(kSub) / cell.toFloat());
  }

  static TINYPARTICLE_NOINLINE void mark(char* text, Units fromCell,
                                         Units toCell, char c) {
    if (fromCell < 0) fromCell = 0;
    if (toCell > Units(kColumns) - 1) toCell = Units(kColumns - 1);
    for (Units k = fromCell; k <= toCell; ++k) {
      // A particle hides a link; a link never hides a particle.
      if (c == '.' && text[k] != ' ') continue;
      text[k] = c;
    }
  }

  // floor(v / kSub) for negative v too, without shifting a negative value:
  // v + 32768 (the sign bit flipped) is never negative, and 32768 / kSub
  // is whole.
  static Units cellOf(Units v) {
    static_assert(32768 % kSub == 0, "kSub divides 2^15");
    return Units(Units((uint16_t(v) ^ 0x8000u) / kSub) - 32768 / kSub);
  }

  // round(sqrt(n)) is not needed: floor is enough for a character grid.
  static int32_t floorSqrt(int32_t n) {
    if (n <= 0) return 0;
    uint32_t x = uint32_t(n);
    uint32_t root = 0;
    uint32_t probe = 1UL << 30;
    while (probe > x) probe >>= 2;
    while (probe != 0) {
      if (x >= root + probe) {
        x -= root + probe;
        root = (root >> 1) + probe;
      } else {
        root >>= 1;
      }
      probe >>= 2;
    }
    return int32_t(root);
  }

  void drawParticle(const typename W::ParticleType& p, Units low,
                    char* text) const {
    Units point[2];
    pointUnits(p.position, mX, mY, point);
    const Units x = point[0], y = point[1];
    const Units rx = toUnits(p.radius, mX, true);
    // (Points need no height: the call is not made for them.)
    const Units ry = kParticleShape == ParticleShape::kCircles
                         ? toUnits(p.radius, mY, true)
                         : Units(0);
    const char c = p.isStatic() ? '+' : (rx < kSub / 2 ? 'o' : 'O');
    const Units centre = Units(low + kSub / 2);  // of the row's cells
    const Units dy = Units(centre - y);
    bool drawn = false;
    if (kParticleShape == ParticleShape::kCircles && ry > 0 && dy <= ry &&
        dy >= -ry) {
      // Half-width of the ellipse at this height, in sub-cell units.
      const Units hx = Units(
          rx * floorSqrt(int32_t(ry) * ry - int32_t(dy) * dy) / ry);
      // Cells whose centre c * kSub + kSub / 2 lies in [x - hx, x + hx].
      const Units from = Units(-cellOf(Units(-(x - hx - kSub / 2))));
      const Units to = cellOf(Units(x + hx - kSub / 2));
      if (from <= to) {
        mark(text, from, to, c);
        drawn = true;
      }
    }
    if (!drawn && y >= low && y < low + kSub) {
      const Units cell = cellOf(x);
      mark(text, cell, cell, c);
    }
  }

  // A spring, stiff spring, rod or cable: a line from particle a to b or
  // to its anchor.
  template <class Slot>
  void drawSlot(const W& world, const Slot& slot, Units low, Units high,
                char* text) const {
    const uint8_t shape = Slot::Params::shapeOf(slot.kind);
    if (shape == SlotShape::kNone) return;
    const V* end = slot.b == kAnchorIndex
                       ? slot.params.template anchorOf<V>(slot.kind)
                       : &WorldAccess::particle(world, slot.b).position;
    if (end == nullptr) return;
    drawLink(WorldAccess::particle(world, slot.a).position, *end, low, high,
             text);
  }

  // x of the segment from `lower` to `upper` (each {x, y}, the first no
  // higher than the second) at height y, between its ends' heights: out of
  // line, its 32-bit product and division once in flash.
  static TINYPARTICLE_NOINLINE Units xAtHeight(const Units* lower,
                                               const Units* upper, Units y) {
    if (y <= lower[1]) return lower[0];
    if (y >= upper[1]) return upper[0];
    // Strictly between the ends: rise and up are positive, and all the
    // differences fit 16 bits (the ends are within +-kLimit). In
    // magnitudes, with the unsigned 16 x 16-bit multiply and 32-bit divide
    // that other code links anyway (the quotient truncated as a signed one
    // would be); the result lies between the ends' x.
    const int16_t across = int16_t(upper[0] - lower[0]);
    const uint16_t rise = uint16_t(y - lower[1]);
    const uint16_t up = uint16_t(upper[1] - lower[1]);
    const uint16_t width = across < 0 ? uint16_t(-across) : uint16_t(across);
    const Units shift = Units(uint32_t(rise) * width / up);
    return Units(across < 0 ? lower[0] - shift : lower[0] + shift);
  }

  void drawLink(const V& pa, const V& pb, Units low, Units high,
                char* text) const {
    // The ends as {x, y} in sub-cell units.
    Units a[2], b[2];
    pointUnits(pa, mX, mY, a);
    pointUnits(pb, mX, mY, b);
    const bool aLower = a[1] <= b[1];
    const Units* lower = aLower ? a : b;
    const Units* upper = aLower ? b : a;
    if (upper[1] < low || lower[1] >= high) return;
    // x where the segment enters and leaves the band (a level one: its
    // ends).
    Units xa = lower[0], xb = upper[0];
    if (lower[1] != upper[1]) {
      xa = xAtHeight(lower, upper, low);
      xb = xAtHeight(lower, upper, Units(high - 1));
    }
    if (xa > xb) {
      const Units t = xa; xa = xb; xb = t;
    }
    mark(text, cellOf(xa), cellOf(xb), '.');
  }

  Axis mX, mY;
  uint8_t mLine;
};

}  // namespace tinyparticle
