// Linked for the ATmega328P by `make -C extras/checks nofloat`: a fixed-point
// program that prints scalars and vectors (Text/Print.hpp) and converts a
// double known only at run time (by integer steps on its bits) must link no
// float routine (avr-libc's __addsf3, __mulsf3, __divsf3...). The output is
// a register, so nothing is optimised away.
#include <avr/io.h>

#include "TinyParticle.hpp"

struct RegisterOut {
  size_t write(uint8_t c) {
    GPIOR0 = c;
    return 1;
  }
};

int main() {
  RegisterOut out;
  tinyparticle::Q16_16 x = tinyparticle::Q16_16::fromRaw(int32_t(GPIOR1) << 8);
  tinyparticle::print(out, x);
  tinyparticle::print(out, x, 2);
  tinyparticle::println(out, tinyparticle::Vec2<tinyparticle::Q16_16>(x, -x));
  tinyparticle::println(out, tinyparticle::Q24_8::fromRaw(GPIOR2));
  tinyparticle::println(out, tinyparticle::Q8_8::fromRaw(int16_t(GPIOR2)), 4);
  volatile double setting = 0.3;  // not a constant: the run-time conversion
  tinyparticle::println(out, tinyparticle::Q16_16(double(setting)));
  return 0;
}
