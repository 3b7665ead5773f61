// A sketch that must build with a warning about an unused variable:
// `make -C extras/checks warnings` builds it with extras/scripts/nano-build
// to show that -Wall -Wextra reach the compiler (Debian's core alone would
// pass -w and stay silent). It also calls a function defined further down,
// which builds only when arduino-cli's ctags step adds its prototype.
#include <TinyParticle.h>

void setup() {
  int unusedOnPurpose = 1;
  report();
}

void loop() {}

void report() {}
