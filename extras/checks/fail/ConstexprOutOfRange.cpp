// Must NOT compile: a conversion out of range in a constant expression
// (Math/Fixed.hpp). At run time the same conversion saturates and raises
// MathError::kOverflow; here it is an error that names the reason.
// expect: call to non-constexpr function .*conversionOutOfRange
#include "TinyParticle.hpp"

constexpr tinyparticle::Q16_16 kTooLarge(1e5);
