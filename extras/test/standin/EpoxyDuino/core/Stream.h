// STAND-IN for Arduino's Stream on the host: the input side is always empty.
#ifndef TINYPARTICLE_STANDIN_STREAM_H
#define TINYPARTICLE_STANDIN_STREAM_H

#include "Print.h"

class Stream : public Print {
 public:
  virtual int available() = 0;
  virtual int read() = 0;
  virtual int peek() = 0;
};

// Serial: writes to the process's standard output; reads nothing.
class HardwareSerial : public Stream {
 public:
  void begin(unsigned long) {}
  void begin(unsigned long, uint8_t) {}
  void end() {}
  explicit operator bool() { return true; }
  int available() override { return 0; }
  int read() override { return -1; }
  int peek() override { return -1; }
  int availableForWrite() override { return 63; }
  void flush() override;
  size_t write(uint8_t c) override;
  size_t write(const uint8_t* buffer, size_t size) override;
  using Print::write;
};

extern HardwareSerial Serial;

#endif
