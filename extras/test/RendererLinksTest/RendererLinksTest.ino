// The ASCII renderer's lines: slanted rods (in view and leaving it), and
// LinkShape::kRodsAndCables (rods drawn, springs not). Apart from
// RendererTest, whose sketch is near the Nano's flash.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;

// The helpers sit in a struct, where the IDE's generated prototypes do not
// reach (a template's would not compile).
struct Lines {
  // LinkShape::kRodsAndCables: a rod (row 0) is drawn as with kLines, a
  // spring (row 2) is not; with kLines both are.
  template <uint8_t kLinkShape>
  static void rodAndSpring(char* rodRow, char* springRow) {
    typedef World<Q16_16, 2, 4, 1, 1, 0> W;
    W w;
    const ParticleId a = w.addFixedParticle(W::Vec(0.05, 1.9));
    const ParticleId b = w.addParticle(W::Vec(1.95, 1.9), Q16_16(1));
    const ParticleId c = w.addFixedParticle(W::Vec(0.05, 1.5));
    const ParticleId d = w.addParticle(W::Vec(1.95, 1.5), Q16_16(1));
    w.addRod(a, b, Q16_16(1.9));
    w.addSpring(c, d, Q16_16(10), Q16_16(1.9));
    AsciiRenderer<W, 20, 10, ParticleShape::kPoints, kLinkShape> renderer(
        Q16_16(0), Q16_16(0), Q16_16(0.1), Q16_16(0.2));
    renderer.renderRow(w, 0, rodRow);
    renderer.renderRow(w, 2, springRow);
    rodRow[20] = springRow[20] = '\0';
  }

  // A slanted rod, from (x0, 0.1) to (x1, 1.9), 20 x 10 cells of 0.1 x 0.2 m
  // (x0 < 0: it leaves the view on the left). Each row between its ends
  // holds one unbroken run of dots; the run holds the column where the rod
  // crosses the row's middle height (when that is in view), and reaches at
  // most one column (the positions' rounding to 1/16 of a cell) past the
  // columns where it crosses the row's lower and upper edges. A row the rod
  // crosses wholly left of the view has no dots (one that it leaves within
  // the rounding of the view's edge is not checked). Returns the first row
  // that breaks this, or -1.
  static int slantedRowBroken(double x0, double x1) {
    typedef World<Q16_16, 2, 2, 0, 1, 0> W;
    W w;
    const ParticleId a = w.addFixedParticle(W::Vec(x0, 0.1));
    const ParticleId b = w.addParticle(W::Vec(x1, 1.9), Q16_16(1));
    w.addRod(a, b, Q16_16(2));
    AsciiRenderer<W, 20, 10, ParticleShape::kPoints> renderer(
        Q16_16(0), Q16_16(0), Q16_16(0.1), Q16_16(0.2));
    const double slope = (x1 - x0) / 1.8;  // metres of x per metre of y
    for (uint8_t row = 1; row < 9; ++row) {  // the rows without an end
      char text[20];
      renderer.renderRow(w, row, text);
      const double low = 0.2 * (9 - row);  // the row's lower edge
      const double atLow = x0 + (low - 0.1) * slope;
      const double atMiddle = atLow + 0.1 * slope;
      const double atHigh = atLow + 0.2 * slope;
      const double left = atLow < atHigh ? atLow : atHigh;
      const double right = atLow < atHigh ? atHigh : atLow;
      int first = -1, last = -1, dots = 0;
      for (int c = 0; c < 20; ++c) {
        if (text[c] == '.') {
          if (first < 0) first = c;
          last = c;
          ++dots;
        } else if (text[c] != ' ') {
          return row;
        }
      }
      // Wholly left of the view, or within the rounding of its edge: the
      // band's top is drawn from 1/16 of a cell (0.0125 m) below its edge,
      // and each end is rounded by up to 1/16 of a cell (0.00625 m) in x.
      const double edge = 0.0125 * (slope < 0 ? -slope : slope) + 0.0125;
      if (right < -edge) {
        if (dots != 0) return row;
        continue;
      }
      if (right < edge) continue;
      if (dots == 0 || dots != last - first + 1) return row;
      const int middleColumn = int(atMiddle / 0.1);
      if (atMiddle >= 0 && (middleColumn < first || middleColumn > last)) {
        return row;
      }
      const int leftColumn = left < 0 ? 0 : int(left / 0.1);
      if (first < leftColumn - 1 || last > int(right / 0.1) + 1) return row;
    }
    return -1;
  }
};

test(RodsAndCablesOnly) {
  char rod[21], spring[21];
  Lines::rodAndSpring<LinkShape::kRodsAndCables>(rod, spring);
  assertEqual(rod, "+..................o");
  assertEqual(spring, "+                  o");
  Lines::rodAndSpring<LinkShape::kLines>(rod, spring);
  assertEqual(rod, "+..................o");
  assertEqual(spring, "+..................o");
}

test(SlantedLine) {
  assertEqual(Lines::slantedRowBroken(0.05, 1.95), -1);
  assertEqual(Lines::slantedRowBroken(-0.95, 0.95), -1);
  assertEqual(Lines::slantedRowBroken(1.95, 0.05), -1);  // falling to the right
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
