// A contact's stored normal (Contacts/Contact.hpp). A Q16.16 world keeps
// each component in Q1.14, rounded to nearest: every component within half
// a Q1.14 unit (2^-15, two Q16.16 units) of the one given, +-1 and 0 exact,
// n and -n stored alike; so the stored normal's length is within
// sqrt(Dim) 2^-15 (< 2^-14) of the given one's. Checked on every Q16.16
// value of [-1, 1] and on unit normals of every quadrant and octant and
// near the axes, whose stored length must be within 2^-14 of 1 (given
// rounded to Q16.16 first, within sqrt(Dim) 2^-17 of 1: the sum is below
// 2^-14 in 2D, and 1.08 times 2^-14 at worst in 3D, for directions not
// among these). A truncating store (up to 3/4 of a unit short) fails the
// first bound.
// Q24.8 keeps its normal exactly; Float keeps its float Vec.
#include <AUnit.h>
#include <TinyParticle.h>
#include <math.h>

using aunit::TestRunner;

static const double kUnit14 = 1.0 / 16384;  // a Q1.14 unit, 2^-14

// (In a struct: the Arduino builder writes no prototypes for its members.)
struct Store {
  // The normal of a Contact<S, Dim> after storing `given`, read back.
  template <typename S, uint8_t Dim>
  static Vec<S, Dim> stored(const Vec<S, Dim>& given) {
    Contact<S, Dim> c;
    c.normal = given;
    Vec<S, Dim> back;
    for (uint8_t i = 0; i < Dim; ++i) back[i] = c.normal[i];
    return back;
  }

  template <uint8_t Dim>
  static double length(const Vec<Q16_16, Dim>& v) {
    double sum = 0;
    for (uint8_t i = 0; i < Dim; ++i) {
      sum += double(v[i].toFloat()) * v[i].toFloat();
    }
    return sqrt(sum);
  }

  // Stores the unit vector `exact` (rounded to Q16.16 first, as a generator
  // would give it) and its negation; counts the bounds broken; `worst` gets
  // the largest | |stored| - 1 | seen, in Q1.14 units.
  template <uint8_t Dim>
  static int checkUnit(const double* exact, double* worst) {
    typedef Vec<Q16_16, Dim> V;
    V given, negated;
    for (uint8_t i = 0; i < Dim; ++i) {
      given[i] = Q16_16(exact[i]);
      negated[i] = -given[i];
    }
    const V back = stored<Q16_16, Dim>(given);
    const V backNegated = stored<Q16_16, Dim>(negated);
    int broken = 0;
    for (uint8_t i = 0; i < Dim; ++i) {
      const int32_t error = back[i].raw() - given[i].raw();
      if (error > 2 || error < -2) ++broken;
      if (backNegated[i].raw() != -back[i].raw()) ++broken;
    }
    const double stretch = fabs(length<Dim>(back) - length<Dim>(given));
    if (stretch > sqrt(double(Dim)) * kUnit14 / 2) ++broken;
    const double fromOne = fabs(length<Dim>(back) - 1) / kUnit14;
    if (fromOne > 1) ++broken;
    if (fromOne > *worst) *worst = fromOne;
    return broken;
  }
};

// Angles in (0, pi/2) and at its ends, many of them near an axis
// (components of 2^-17 to 2^-12, below and at the rounding steps).
static const double kNearAxis[] = {0,           1.0 / 131072, 1.0 / 65536,
                                   3.0 / 65536, 1.0 / 32768,  5.0 / 65536,
                                   1.0 / 4096,  0.01};
static const uint8_t kNearCount = sizeof(kNearAxis) / sizeof(kNearAxis[0]);
static const double kHalfPi = 1.5707963267948966;

test(EveryQ16Value) {
  // Every Q16.16 component of [-1, 1] and a little beyond: within two
  // Q16.16 units (half a Q1.14 unit), ties away from zero (never shorter),
  // the same magnitude for x and -x.
  int broken = 0;
  for (int32_t raw = -65540; raw <= 65540; ++raw) {
    const Vec<Q16_16, 2> given(Q16_16::fromRaw(raw), Q16_16::fromRaw(-raw));
    const Vec<Q16_16, 2> back = Store::stored<Q16_16, 2>(given);
    const int32_t error = back.x.raw() - raw;
    if (error > 2 || error < -2) ++broken;
    if ((raw & 3) == 2 && !(raw > 0 ? error > 0 : error < 0)) ++broken;
    if (back.y.raw() != -back.x.raw()) ++broken;
  }
  assertEqual(broken, 0);
}

test(AxesExact) {
  typedef Vec<Q16_16, 3> V3;
  const V3 axes[] = {V3(1.0, 0.0, 0.0), V3(0.0, -1.0, 0.0), V3(0.0, 0.0, 1.0),
                     V3(-1.0, 0.0, 0.0)};
  for (uint8_t k = 0; k < 4; ++k) {
    const bool exact = Store::stored<Q16_16, 3>(axes[k]) == axes[k];
    assertTrue(exact);
  }
}

test(Quadrants) {
  // Each angle of kNearAxis from either axis, and 24 angles between, in
  // all four quadrants (by the signs of the components).
  double worst = 0;
  int broken = 0, cases = 0;
  for (uint8_t k = 0; k < 2 * kNearCount + 24; ++k) {
    const double angle =
        k < kNearCount       ? kNearAxis[k]
        : k < 2 * kNearCount ? kHalfPi - kNearAxis[k - kNearCount]
                             : (k - 2 * kNearCount + 0.5) * kHalfPi / 24;
    for (uint8_t signs = 0; signs < 4; ++signs) {
      const double exact[2] = {(signs & 1 ? -1 : 1) * cos(angle),
                               (signs & 2 ? -1 : 1) * sin(angle)};
      broken += Store::checkUnit<2>(exact, &worst);
      ++cases;
    }
  }
  assertEqual(cases, 4 * (2 * kNearCount + 24));
  assertEqual(broken, 0);
  assertLessOrEqual(worst, 1.0);
}

test(Octants) {
  // Directions of the first octant (a grid of spherical angles, and ones
  // within kNearAxis of an axis or of a coordinate plane), with each of
  // the three axes first and all eight sign patterns.
  double worst = 0;
  int broken = 0, cases = 0;
  for (uint8_t polar = 0; polar < kNearCount + 5; ++polar) {
    const double theta = polar < kNearCount
                             ? kNearAxis[polar]
                             : (polar - kNearCount + 0.5) * kHalfPi / 5;
    for (uint8_t azimuth = 0; azimuth < kNearCount + 5; ++azimuth) {
      const double phi = azimuth < kNearCount ? kNearAxis[azimuth]
                         : (azimuth - kNearCount + 0.5) * kHalfPi / 5;
      const double base[3] = {cos(theta), sin(theta) * cos(phi),
                              sin(theta) * sin(phi)};
      for (uint8_t first = 0; first < 3; ++first) {
        for (uint8_t signs = 0; signs < 8; ++signs) {
          double exact[3];
          for (uint8_t i = 0; i < 3; ++i) {
            exact[i] = (signs & (1 << i) ? -1 : 1) * base[(i + first) % 3];
          }
          broken += Store::checkUnit<3>(exact, &worst);
          ++cases;
        }
      }
    }
  }
  assertEqual(cases, 24 * (kNearCount + 5) * (kNearCount + 5));
  assertEqual(broken, 0);
  assertLessOrEqual(worst, 1.0);
}

test(Q24_8Exact) {
  // Q24.8's normal fits 16 bits as it is: stored without loss.
  int broken = 0;
  for (int32_t raw = -256; raw <= 256; ++raw) {
    const Vec<Q24_8, 3> given(Q24_8::fromRaw(raw), Q24_8::fromRaw(-raw),
                              Q24_8::fromRaw(raw / 2));
    if (!(Store::stored<Q24_8, 3>(given) == given)) ++broken;
  }
  assertEqual(broken, 0);
}

test(Sizes) {
  // 16 bits a component in 32-bit fixed point; Float keeps its floats.
  assertEqual(int(sizeof(Contact<Q16_16, 2>::Normal)), 4);
  assertEqual(int(sizeof(Contact<Q16_16, 3>::Normal)), 6);
  assertEqual(int(sizeof(Contact<Q24_8, 2>::Normal)), 4);
  assertEqual(int(sizeof(Contact<Float, 2>::Normal)),
              int(sizeof(Vec<Float, 2>)));
#if defined(__AVR__)
  assertEqual(int(sizeof(Contact<Q16_16, 2>)), 15);
  assertEqual(int(sizeof(Contact<Q16_16, 3>)), 17);
#endif
}

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
