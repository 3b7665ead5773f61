// The ASCII renderer: where particles and links land on the character grid,
// circles by radius, the border, and line-by-line drawing.
#include <AUnit.h>
#include <TinyParticle.h>
#include <string.h>

using aunit::TestRunner;

// Collects what the renderer writes.
struct Capture {
  char text[300];
  uint16_t length;
  uint8_t lines;
  Capture() : length(0), lines(0) { text[0] = '\0'; }
  size_t write(uint8_t c) {
    if (c == '\n') ++lines;
    if (length + 1u < sizeof(text)) {
      text[length++] = char(c);
      text[length] = '\0';
    }
    return 1;
  }
};

template <bool B>
struct BoolType {};
typedef BoolType<true> TrueType;
typedef BoolType<false> FalseType;

template <typename S>
struct Checks {
  typedef World<S, 2, 3, 0, 1, 1> W;  // a cable needs a contact slot
  typedef typename W::Vec V;
  // 20 x 10 characters over 2 m x 2 m: cells of 0.1 m x 0.2 m.

  // Row `row` of a view holding one particle, as a C string; kShape:
  // ParticleShape::kCircles (the default) or kPoints.
  template <uint8_t kShape = ParticleShape::kCircles>
  static void row(const V& where, S radius, uint8_t row, char* out) {
    W w;
    w.addParticle(where, S(1), radius);
    AsciiRenderer<W, 20, 10, kShape> renderer(S(0), S(0), S(0.1), S(0.2));
    renderer.renderRow(w, row, out);
    out[20] = '\0';
  }

  // The four cases of the Edges tests, one bit each when drawn as
  // expected: just outside the left edge, just inside it, just below the
  // bottom edge, just above it.
  static uint8_t edges() {
    char line[21];
    uint8_t drawn = 0;
    row(V(-0.005, 1.1), S(), 4, line);
    if (strcmp(line, "                    ") == 0) drawn |= 1;
    row(V(0.005, 1.1), S(), 4, line);
    if (strcmp(line, "o                   ") == 0) drawn |= 2;
    row(V(1.05, -0.01), S(), 9, line);
    if (strcmp(line, "                    ") == 0) drawn |= 4;
    row(V(1.05, 0.01), S(), 9, line);
    if (strcmp(line, "          o         ") == 0) drawn |= 8;
    return drawn;
  }

  static void addLink(W& w, ParticleId a, ParticleId b, TrueType) {
    w.addRod(a, b, S(1.9));
  }
  static void addLink(W& w, ParticleId a, ParticleId b, FalseType) {
    w.addCable(a, b, S(1.9), S(0));
  }

  // A rod (or a cable) from a fixed particle near the top-left corner to
  // one near the top-right corner: row 0.
  // kLinkShape: LinkShape::kLines (the default) or kNone.
  template <bool kRod, uint8_t kLinkShape = LinkShape::kLines>
  static void link(char* out) {
    W w;
    V left(0.05, 1.9), right(1.95, 1.9);
    ParticleId a = w.addFixedParticle(left);
    ParticleId b = w.addParticle(right, S(1));
    addLink(w, a, b, BoolType<kRod>());
    AsciiRenderer<W, 20, 10, ParticleShape::kCircles, kLinkShape> renderer(
        S(0), S(0), S(0.1), S(0.2));
    renderer.renderRow(w, 0, out);
    out[20] = '\0';
  }

  // A whole frame, line by line (kFrame: FrameStyle::kBorder, the default,
  // or another style): returns how many calls returned false before the
  // one that returned true.
  template <uint8_t kFrame = FrameStyle::kBorder>
  static uint8_t frame(Capture& capture) {
    W w;
    V where(1.05, 1.1);
    w.addParticle(where, S(1));
    AsciiRenderer<W, 20, 10, ParticleShape::kCircles, LinkShape::kLines,
                  kFrame>
        renderer(S(0), S(0), S(0.1), S(0.2));
    uint8_t calls = 0;
    while (!renderer.drawLine(w, capture) && calls < 50) ++calls;
    return calls;
  }
};

// The constructor is constexpr: a global renderer needs no start-up code
// (this does not compile otherwise), in fixed and in floating point.
constexpr AsciiRenderer<World<Q16_16, 2, 1>, 4, 2> kConstantFixed(
    Q16_16(0), Q16_16(0), Q16_16(0.1), Q16_16(0.2));
constexpr AsciiRenderer<World<Float, 2, 1>, 4, 2> kConstantFloat(
    Float(0), Float(0), Float(0.1), Float(0.2));

// A point particle at (1.05, 1.1): column 10, row 4 from the top
// (y = 1.1 is 5.5 cells up, in the 6th row from the bottom).
test(PointParticle_Q16_16) {
  char line[21];
  Checks<Q16_16>::row(Checks<Q16_16>::V(1.05, 1.1), Q16_16(), 4, line);
  assertEqual(line, "          o         ");
  Checks<Q16_16>::row(Checks<Q16_16>::V(1.05, 1.1), Q16_16(), 3, line);
  assertEqual(line, "                    ");
}
test(PointParticle_Float) {
  char line[21];
  Checks<Float>::row(Checks<Float>::V(1.05, 1.1), Float(), 4, line);
  assertEqual(line, "          o         ");
}

// Radius 0.25 m at the same place: 2.5 cells wide and 1.25 cells tall each
// side. Its centre row covers the cells whose centres lie within 2.5 cells
// (columns 8 to 12); one row up or down, within 2.5 sqrt(1 - 0.8^2) = 1.5
// cells (columns 9 to 11); two rows away, nothing.
test(Circle_Q16_16) {
  typedef Checks<Q16_16> C;
  char line[21];
  C::row(C::V(1.05, 1.1), Q16_16(0.25), 4, line);
  assertEqual(line, "        OOOOO       ");
  C::row(C::V(1.05, 1.1), Q16_16(0.25), 3, line);
  assertEqual(line, "         OOO        ");
  C::row(C::V(1.05, 1.1), Q16_16(0.25), 5, line);
  assertEqual(line, "         OOO        ");
  C::row(C::V(1.05, 1.1), Q16_16(0.25), 6, line);
  assertEqual(line, "                    ");
}
test(Circle_Float) {
  typedef Checks<Float> C;
  char line[21];
  C::row(C::V(1.05, 1.1), Float(0.25), 4, line);
  assertEqual(line, "        OOOOO       ");
  C::row(C::V(1.05, 1.1), Float(0.25), 5, line);
  assertEqual(line, "         OOO        ");
}

// ParticleShape::kPoints: one character at the centre. A particle smaller
// than half a cell each way (radius 0.04 m: 0.4 and 0.2 cells) looks the
// same as with circles, at every sub-cell offset of its centre near a cell
// corner; a large one is one 'O' instead of a disc.
test(Points) {
  typedef Checks<Q16_16> C;
  char points[21], circles[21];
  for (uint8_t i = 0; i < 10; ++i) {
    for (uint8_t j = 0; j < 10; ++j) {
      const C::V where(Q16_16(0.95) + Q16_16(i) * Q16_16(0.02),
                       Q16_16(1.1) + Q16_16(j) * Q16_16(0.02));
      for (uint8_t r = 2; r <= 5; ++r) {
        C::row<ParticleShape::kPoints>(where, Q16_16(0.04), r, points);
        C::row(where, Q16_16(0.04), r, circles);
        assertEqual(points, circles);
      }
    }
  }
  C::row<ParticleShape::kPoints>(C::V(1.05, 1.1), Q16_16(0.25), 4, points);
  assertEqual(points, "          O         ");
  C::row<ParticleShape::kPoints>(C::V(1.05, 1.1), Q16_16(0.25), 3, points);
  assertEqual(points, "                    ");
}

// Off the view: nothing drawn, nothing written outside the line.
test(OffScreen) {
  typedef Checks<Q16_16> C;
  char line[22];
  line[21] = '#';
  C::row(C::V(100.0, 1.1), Q16_16(0.5), 4, line);
  assertEqual(line, "                    ");
  C::row(C::V(-100.0, -100.0), Q16_16(5), 4, line);
  assertEqual(line, "                    ");
  assertEqual(line[21], '#');
}

// A twentieth of a cell outside the view's left or bottom edge is outside
// it (positions round down to sixteenths of a cell; rounded toward zero,
// they would land in the first column or the last row); as far inside, in.
test(Edges_Q16_16) { assertEqual((int) Checks<Q16_16>::edges(), 15); }
test(Edges_Float) { assertEqual((int) Checks<Float>::edges(), 15); }

// A rod or a cable is dots between its ends; the fixed end shows as '+'.
// (The Float world draws a cable: a rod there would link a second rod
// solver, and the sketch would not fit the Nano.)
test(RodLine) {
  char line[21];
  Checks<Q16_16>::link<true>(line);
  assertEqual(line, "+..................o");
  Checks<Float>::link<false>(line);
  assertEqual(line, "+..................o");
}

// LinkShape::kNone: the same rod is not drawn, its ends still are.
test(LinksNotDrawn) {
  char line[21];
  Checks<Q16_16>::link<true, LinkShape::kNone>(line);
  assertEqual(line, "+                  o");
}

// 10 rows plus two border lines of 22 characters and a newline each; the
// 12th call completes the frame.
test(FrameByLines) {
  Capture capture;
  assertEqual((int) Checks<Q16_16>::frame(capture), 11);
  assertEqual((int) capture.lines, 12);
  assertEqual((int) capture.length, 12 * 23);
  assertEqual(capture.text[0], '+');
  assertEqual(capture.text[21], '+');
  assertEqual(capture.text[23], '|');
  assertEqual(capture.text[23 + 4 * 23 + 1 + 10], 'o');  // row 4, column 10
}

// Without the border and with the cursor-home code: the code, then 10
// rows of 20 characters and a newline each; the 10th call completes it.
test(FrameWithoutBorderWithHome) {
  Capture capture;
  assertEqual((int) Checks<Q16_16>::frame<FrameStyle::kHome>(capture), 9);
  assertEqual((int) capture.lines, 10);
  assertEqual((int) capture.length, 3 + 10 * 21);
  assertEqual(capture.text[0], '\x1b');
  assertEqual(capture.text[1], '[');
  assertEqual(capture.text[2], 'H');
  assertEqual(capture.text[3], ' ');
  assertEqual(capture.text[3 + 20], '\n');
  assertEqual(capture.text[3 + 4 * 21 + 10], 'o');  // row 4, column 10
}

// lineLength(): the most a drawLine() call writes (the frames above: 23
// characters a line with the border; the home code and 21 without it).
test(LineLength) {
  typedef Checks<Q16_16>::W W;
  typedef AsciiRenderer<W, 20, 10> Bordered;
  typedef AsciiRenderer<W, 20, 10, ParticleShape::kCircles, LinkShape::kLines,
                        FrameStyle::kHome>
      Homed;
  typedef AsciiRenderer<W, 20, 10, ParticleShape::kCircles, LinkShape::kLines,
                        FrameStyle::kPlain>
      Plain;
  assertEqual((int) Bordered::lineLength(), 23);
  assertEqual((int) Homed::lineLength(), 3 + 21);
  assertEqual((int) Plain::lineLength(), 21);
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
