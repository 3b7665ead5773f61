// The collisions' short way for a difference of centres along x
// (detail::AxisDifference, Contacts/Collisions.hpp) against its reference,
// Vec::magnitudeAndNormalize(): the same unit vector and length, bit for
// bit, on every input class it tells apart: both signs, 2D and 3D, every
// power of two up to its limit 2^kTop and the values beside each, in
// Q16.16, Q24.8 and Q8.8; and it declines a zero vector, a vector along
// another axis or off the axes, and magnitudes from 2^kTop on. On the PC
// it also checks every magnitude below 2^kTop.
#include <AUnit.h>
#include <TinyParticle.h>

using aunit::TestRunner;
using tinyparticle::Vec;
using tinyparticle::detail::AxisDifference;

template <class T, uint8_t D>
struct AxisCheck {
  typedef typename T::Raw Raw;
  // Along axis `axis`, raw magnitude m, the sign of `sign`: true if the
  // short way agrees with the reference (or declines, where it must).
  static bool agrees(uint8_t axis, uint32_t m, int8_t sign) {
    Vec<T, D> fast, reference;
    fast[axis] = T::fromRaw(Raw(sign < 0 ? -Raw(m) : Raw(m)));
    reference = fast;
    T length = T(), referenceLength = reference.magnitudeAndNormalize();
    const bool taken = AxisDifference<T>::normalize(fast, length);
    // It takes a vector along x below the limit, and declines the others.
    const bool inRange = axis == 0 && m != 0 &&
                         m < (uint32_t(1) << AxisDifference<T>::kTop);
    if (taken != inRange) return false;
    if (!taken) return true;
    if (length.raw() != referenceLength.raw()) return false;
    for (uint8_t k = 0; k < D; ++k) {
      if (fast[k].raw() != reference[k].raw()) return false;
    }
    return true;
  }
  // Every axis and sign at 2^k - 1, 2^k, 2^k + 1 for k up to kTop.
  static uint16_t classFailures() {
    uint16_t failures = 0;
    for (uint8_t axis = 0; axis < D; ++axis) {
      for (uint8_t k = 0; k <= AxisDifference<T>::kTop; ++k) {
        const uint32_t p = uint32_t(1) << k;
        for (int8_t sign = -1; sign <= 1; sign += 2) {
          if (!agrees(axis, p - 1, sign)) ++failures;
          if (!agrees(axis, p, sign)) ++failures;
          if (!agrees(axis, p + 1, sign)) ++failures;
        }
      }
    }
    return failures;
  }
  // Two components nonzero: declined.
  static bool declinesOffAxis() {
    Vec<T, D> v;
    v.x = T::fromRaw(Raw(5));
    v.y = T::fromRaw(Raw(-3));
    T length;
    return !AxisDifference<T>::normalize(v, length) && v.x.raw() == 5 &&
           v.y.raw() == -3;
  }
};

// (Named types: a template's comma would split a macro's arguments.)
typedef AxisCheck<Q16_16, 2> Q16In2D;
typedef AxisCheck<Q16_16, 3> Q16In3D;
typedef AxisCheck<Q24_8, 2> Q24In2D;
typedef AxisCheck<Q24_8, 3> Q24In3D;
typedef AxisCheck<Q8_8, 2> Q8In2D;
typedef AxisCheck<Q8_8, 3> Q8In3D;

test(AxisDifference_Q16_16) {
  assertEqual(Q16In2D::classFailures(), uint16_t(0));
  assertEqual(Q16In3D::classFailures(), uint16_t(0));
  assertTrue(Q16In2D::declinesOffAxis());
  assertTrue(Q16In3D::declinesOffAxis());
}

test(AxisDifference_Q24_8) {
  assertEqual(Q24In2D::classFailures(), uint16_t(0));
  assertEqual(Q24In3D::classFailures(), uint16_t(0));
  assertTrue(Q24In2D::declinesOffAxis());
}

test(AxisDifference_Q8_8) {
  assertEqual(Q8In2D::classFailures(), uint16_t(0));
  assertEqual(Q8In3D::classFailures(), uint16_t(0));
  assertTrue(Q8In2D::declinesOffAxis());
}

#if defined(EPOXY_DUINO)
// Every magnitude below the limit, both signs (a few seconds on the PC;
// too long for the simulated Nano).
template <class T>
static uint32_t everyFailure() {
  uint32_t failures = 0;
  const uint32_t top = uint32_t(1) << AxisDifference<T>::kTop;
  for (uint32_t m = 1; m < top; ++m) {
    if (!AxisCheck<T, 2>::agrees(0, m, 1)) ++failures;
    if (!AxisCheck<T, 2>::agrees(0, m, -1)) ++failures;
  }
  return failures;
}

test(AxisDifference_Every) {
  TestRunner::setTimeout(0);
  assertEqual(everyFailure<Q8_8>(), uint32_t(0));
  assertEqual(everyFailure<Q24_8>(), uint32_t(0));
  assertEqual(everyFailure<Q16_16>(), uint32_t(0));
}
#endif

void setup() {
#if !defined(EPOXY_DUINO)
  delay(1000);
#endif
  Serial.begin(115200);
  while (!Serial);
}

void loop() { TestRunner::run(); }
