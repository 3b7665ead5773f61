// STAND-IN Arduino core for the host: Print, Serial, time, main().
#include "Arduino.h"

#include <stdio.h>
#include <time.h>

// ---- Print ----

size_t Print::write(const uint8_t* buffer, size_t size) {
  size_t n = 0;
  while (size-- > 0) {
    if (write(*buffer++) == 0) break;
    ++n;
  }
  return n;
}

size_t Print::print(const __FlashStringHelper* s) {
  return write(reinterpret_cast<const char*>(s));
}

size_t Print::print(long n, int base) {
  if (base == 0) return write(static_cast<uint8_t>(n));
  if (base == 10 && n < 0) {
    size_t t = print('-');
    // 0 - (unsigned) n is defined even for the most negative long.
    return t + printNumber(0ul - static_cast<unsigned long>(n), 10);
  }
  return printNumber(static_cast<unsigned long>(n), static_cast<uint8_t>(base));
}

size_t Print::print(unsigned long n, int base) {
  if (base == 0) return write(static_cast<uint8_t>(n));
  return printNumber(n, static_cast<uint8_t>(base));
}

size_t Print::printNumber(unsigned long n, uint8_t base) {
  char digits[8 * sizeof(unsigned long) + 1];
  size_t count = 0;
  if (base < 2) base = 10;
  do {
    unsigned d = static_cast<unsigned>(n % base);
    digits[count++] = static_cast<char>(d < 10 ? '0' + d : 'A' + d - 10);
    n /= base;
  } while (n != 0);
  size_t written = 0;
  while (count > 0) written += write(static_cast<uint8_t>(digits[--count]));
  return written;
}

// Same rules as the AVR core: nan, inf, ovf outside the unsigned long range,
// rounding half away from zero at the last printed digit.
size_t Print::printFloat(double x, int digits) {
  if (isnan(x)) return print("nan");
  if (isinf(x)) return print("inf");
  if (x > 4294967040.0 || x < -4294967040.0) return print("ovf");
  size_t n = 0;
  if (x < 0.0) {
    n += print('-');
    x = -x;
  }
  double rounding = 0.5;
  for (int i = 0; i < digits; ++i) rounding /= 10.0;
  x += rounding;
  unsigned long whole = static_cast<unsigned long>(x);
  double rest = x - static_cast<double>(whole);
  n += print(whole);
  if (digits > 0) n += print('.');
  while (digits-- > 0) {
    rest *= 10.0;
    unsigned int d = static_cast<unsigned int>(rest);
    n += print(d);
    rest -= d;
  }
  return n;
}

// ---- Serial ----

HardwareSerial Serial;

size_t HardwareSerial::write(uint8_t c) { return fputc(c, stdout) == EOF ? 0 : 1; }
size_t HardwareSerial::write(const uint8_t* buffer, size_t size) {
  return fwrite(buffer, 1, size, stdout);
}
void HardwareSerial::flush() { fflush(stdout); }

// ---- time ----

static struct timespec gStart;

static unsigned long long elapsedMicros() {
  struct timespec now;
  clock_gettime(CLOCK_MONOTONIC, &now);
  long long us = (now.tv_sec - gStart.tv_sec) * 1000000LL + (now.tv_nsec - gStart.tv_nsec) / 1000;
  return static_cast<unsigned long long>(us);
}

// Truncated to unsigned long as on the board (where it wraps too).
unsigned long millis() { return static_cast<unsigned long>(elapsedMicros() / 1000u); }
unsigned long micros() { return static_cast<unsigned long>(elapsedMicros()); }

void delay(unsigned long ms) {
  struct timespec t;
  t.tv_sec = static_cast<time_t>(ms / 1000u);
  t.tv_nsec = static_cast<long>((ms % 1000u) * 1000000u);
  while (nanosleep(&t, &t) != 0) {}
}

void delayMicroseconds(unsigned int us) {
  struct timespec t;
  t.tv_sec = static_cast<time_t>(us / 1000000u);
  t.tv_nsec = static_cast<long>((us % 1000000u) * 1000u);
  while (nanosleep(&t, &t) != 0) {}
}

void yield() {}

// ---- main ----

// Command-line arguments, under the names EpoxyDuino documents.
int epoxy_argc;
const char* const* epoxy_argv;

int main(int argc, char** argv) {
  epoxy_argc = argc;
  epoxy_argv = argv;
  setvbuf(stdout, nullptr, _IOLBF, 0);
  clock_gettime(CLOCK_MONOTONIC, &gStart);
  setup();
  for (;;) {
    loop();
    yield();
  }
}
