// STAND-IN for the Arduino Servo library that drives its pins, for the
// device simulator (extras/hil) only.
//
// Our own code, written from the Servo library's documented behaviour: up to
// 12 servos share Timer1 (so analogWrite on pins 9 and 10 is lost); each one
// gets a high pulse of 544..2400 us (0..180 degrees) in turn, and the train of
// pulses repeats every 20 ms (50 Hz frames). write(v) takes degrees when v is
// below 544 and microseconds otherwise; widths are clamped to the attach()
// range. extras/scripts/nano-build uses it when SERVO_PULSES=1 is set; users
// build with the real Servo library.
#ifndef TINYPARTICLE_SERVO_PULSES_H
#define TINYPARTICLE_SERVO_PULSES_H

#include <stdint.h>

#define SERVO_STANDIN 1
#define SERVO_STANDIN_PULSES 1

#define MIN_PULSE_WIDTH 544       // us, the 0 degree end
#define MAX_PULSE_WIDTH 2400      // us, the 180 degree end
#define DEFAULT_PULSE_WIDTH 1500  // us, after attach()
#define REFRESH_INTERVAL 20000    // us from one frame's start to the next
#define SERVOS_PER_TIMER 12
#define MAX_SERVOS 12
#define INVALID_SERVO 255

class Servo {
 public:
  Servo();
  // Returns the channel, or INVALID_SERVO (bad pin, range or no channel left).
  uint8_t attach(int pin);
  uint8_t attach(int pin, int minUs, int maxUs);
  void detach();
  bool attached();
  void write(int value);
  void writeMicroseconds(int us);
  int read();
  int readMicroseconds();

 private:
  uint8_t mChannel;
  int16_t mMinUs;  // the attach() range
  int16_t mMaxUs;
};

#endif
