// The scalar a MemoryBenchmark build measures, chosen by SCALAR: 1 = Q16_16
// (the default), 2 = Float. `Stored` is what a result is written to a
// volatile as, so that the compiler keeps the step: the raw Q16.16 bits, or
// the float. The ladder, the lever scene and the two-world scene share it.
#pragma once

#include <TinyParticle.h>

#ifndef SCALAR
#define SCALAR 1
#endif

namespace measuredScalar {

#if SCALAR == 1
typedef Q16_16 S;
typedef int32_t Stored;
inline Stored stored(S x) { return x.raw(); }
#elif SCALAR == 2
typedef Float S;
typedef float Stored;
inline Stored stored(S x) { return x.toFloat(); }
#else
#error "SCALAR must be 1 (Q16_16) or 2 (Float)"
#endif

}  // namespace measuredScalar
