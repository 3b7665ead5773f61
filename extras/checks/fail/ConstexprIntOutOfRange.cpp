// Must NOT compile: an integer out of range in a constant expression
// (Math/Fixed.hpp), here 200 in Q8.8 (at most 127.996).
// expect: call to non-constexpr function .*conversionOutOfRange
#include "TinyParticle.hpp"

constexpr tinyparticle::Q8_8 kTooLarge(200);
