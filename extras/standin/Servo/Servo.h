// STAND-IN for the Arduino Servo library's public interface.
//
// Used by extras/scripts/nano-build only when the real Servo library is not
// installed, so that sketches needing it (HapticLever) still compile and
// their size can be measured; such builds are marked in extras/sizes/nano.md.
// It drives no pin: it only remembers the last pulse width, so read() and
// readMicroseconds() answer as the real library would. Install the real
// Servo library (Library Manager: "Servo") to drive a servo.
#ifndef TINYPARTICLE_SERVO_STANDIN_H
#define TINYPARTICLE_SERVO_STANDIN_H

#include <stdint.h>

#define SERVO_STANDIN 1

#define MIN_PULSE_WIDTH 544       // us, the 0 degree end
#define MAX_PULSE_WIDTH 2400      // us, the 180 degree end
#define DEFAULT_PULSE_WIDTH 1500  // us, after attach()
#define REFRESH_INTERVAL 20000    // us between pulses
#define SERVOS_PER_TIMER 12
#define MAX_SERVOS 12
#define INVALID_SERVO 255

class Servo {
 public:
  Servo() : mPin(INVALID_SERVO), mMinUs(MIN_PULSE_WIDTH), mMaxUs(MAX_PULSE_WIDTH),
      mPulseUs(DEFAULT_PULSE_WIDTH) {}

  // Returns the channel (0 here), or INVALID_SERVO for a bad pin.
  uint8_t attach(int pin) { return attach(pin, MIN_PULSE_WIDTH, MAX_PULSE_WIDTH); }
  uint8_t attach(int pin, int minUs, int maxUs) {
    if (pin < 0 || pin >= INVALID_SERVO || minUs >= maxUs) return INVALID_SERVO;
    mPin = static_cast<uint8_t>(pin);
    mMinUs = minUs;
    mMaxUs = maxUs;
    return 0;
  }
  void detach() { mPin = INVALID_SERVO; }
  bool attached() { return mPin != INVALID_SERVO; }

  // Below MIN_PULSE_WIDTH the value is an angle in degrees (0..180),
  // otherwise a pulse width in microseconds; both are clamped to the range.
  void write(int value) {
    if (value < MIN_PULSE_WIDTH) {
      long angle = value < 0 ? 0 : (value > 180 ? 180 : value);
      value = static_cast<int>(mMinUs + angle * (mMaxUs - mMinUs) / 180);
    }
    writeMicroseconds(value);
  }
  void writeMicroseconds(int us) {
    mPulseUs = us < mMinUs ? mMinUs : (us > mMaxUs ? mMaxUs : us);
  }
  int read() {
    long span = mMaxUs - mMinUs;
    return static_cast<int>(((mPulseUs - mMinUs) * 180L + span / 2) / span);
  }
  int readMicroseconds() { return mPulseUs; }

 private:
  uint8_t mPin;
  int mMinUs;
  int mMaxUs;
  int mPulseUs;
};

#endif
