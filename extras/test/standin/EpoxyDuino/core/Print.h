// STAND-IN for Arduino's Print class on the host (see ../README.md).
// Same public interface as ArduinoCore-avr's Print, so code that prints to a
// Print& (and classes that derive from Print) builds the same way here and on
// the board. Our own implementation.
#ifndef TINYPARTICLE_STANDIN_PRINT_H
#define TINYPARTICLE_STANDIN_PRINT_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define DEC 10
#define HEX 16
#define OCT 8
#define BIN 2

class __FlashStringHelper;

class Print {
 public:
  Print() : mWriteError(0) {}

  int getWriteError() { return mWriteError; }
  void clearWriteError() { mWriteError = 0; }

  virtual size_t write(uint8_t) = 0;
  virtual size_t write(const uint8_t* buffer, size_t size);
  size_t write(const char* str) {
    return str == nullptr ? 0 : write(reinterpret_cast<const uint8_t*>(str), strlen(str));
  }
  size_t write(const char* buffer, size_t size) {
    return write(reinterpret_cast<const uint8_t*>(buffer), size);
  }
  virtual int availableForWrite() { return 0; }
  virtual void flush() {}

  size_t print(const __FlashStringHelper* s);
  size_t print(const char s[]) { return write(s); }
  size_t print(char c) { return write(static_cast<uint8_t>(c)); }
  size_t print(unsigned char n, int base = DEC) { return print(static_cast<unsigned long>(n), base); }
  size_t print(int n, int base = DEC) { return print(static_cast<long>(n), base); }
  size_t print(unsigned int n, int base = DEC) { return print(static_cast<unsigned long>(n), base); }
  size_t print(long n, int base = DEC);
  size_t print(unsigned long n, int base = DEC);
  size_t print(double x, int digits = 2) { return printFloat(x, digits); }

  size_t println() { return write("\r\n"); }
  template <typename T>
  size_t println(T value) { size_t n = print(value); return n + println(); }
  template <typename T>
  size_t println(T value, int format) { size_t n = print(value, format); return n + println(); }

 protected:
  void setWriteError(int err = 1) { mWriteError = err; }

 private:
  size_t printNumber(unsigned long n, uint8_t base);
  size_t printFloat(double x, int digits);
  int mWriteError;
};

#endif
