// Must NOT compile: print(out, x) with a value that is not one of the
// library's scalars or vectors (here an int): the first error says what
// print() takes and what to use instead (Text/Print.hpp).
// expect: static assert.*print\(out, x\) prints a TinyParticle scalar
#include "TinyParticle.hpp"
using namespace tinyparticle;

struct Out {
  unsigned write(uint8_t) { return 1; }
} out;

void setup() { print(out, 3); }
