// The pulse generator of the ServoPulses stand-in (see Servo.h).
//
// Timer1 runs freely at 2 MHz (prescaler 8, 0.5 us per tick); its compare A
// interrupt walks a small state machine: raise channel i's pin, schedule the
// fall after its width, lower it and go on to the next channel; after the
// last one, wait for the end of the 20 ms frame. Compare times are kept in
// wrapping 16-bit tick arithmetic, so the counter is never reset and frame
// starts are exactly 40,000 ticks apart.
#include <Arduino.h>
#include <avr/interrupt.h>

#include "Servo.h"

namespace {

const uint16_t kTicksPerUs = 2;  // F_CPU / 8 / 1 MHz at 16 MHz
const uint16_t kFrameTicks = REFRESH_INTERVAL * kTicksPerUs;

// What the interrupt needs of each channel; the attach() range lives in the
// Servo object, so that the table costs about what the library's does.
struct Channel {
  volatile uint8_t* port;  // PORTx of the pin, null when detached
  uint8_t mask;
  volatile uint16_t ticks;  // the pulse width, read by the interrupt
};

Channel channels[MAX_SERVOS];
uint8_t channelCount = 0;
volatile int8_t current = -1;  // the channel whose pulse is on, -1 between frames
uint16_t frameStart = 0;
bool timerRunning = false;

void startTimer() {
  uint8_t sreg = SREG;
  cli();
  TCCR1A = 0;               // normal mode, no output compare pins
  TCCR1B = _BV(CS11);       // prescaler 8
  frameStart = TCNT1 + 100; // the first frame starts 50 us from now
  OCR1A = frameStart;
  TIFR1 = _BV(OCF1A);       // forget an old match
  TIMSK1 |= _BV(OCIE1A);
  current = -1;
  timerRunning = true;
  SREG = sreg;
}


}  // namespace

ISR(TIMER1_COMPA_vect) {
  int8_t i = current;
  if (i >= 0) {  // end of channel i's pulse
    Channel& c = channels[i];
    if (c.port != nullptr) *c.port &= uint8_t(~c.mask);
  }
  // Find the next attached channel in this frame.
  for (++i; i < int8_t(channelCount); ++i) {
    Channel& c = channels[i];
    if (c.port != nullptr) {
      *c.port |= c.mask;
      OCR1A = OCR1A + c.ticks;
      current = i;
      return;
    }
  }
  // None left: the next frame starts kFrameTicks after this one did.
  frameStart += kFrameTicks;
  OCR1A = frameStart;
  current = -1;
}

Servo::Servo()
    : mChannel(INVALID_SERVO), mMinUs(MIN_PULSE_WIDTH), mMaxUs(MAX_PULSE_WIDTH) {
  if (channelCount < MAX_SERVOS) {
    mChannel = channelCount++;
    Channel& c = channels[mChannel];
    c.port = nullptr;
    c.ticks = DEFAULT_PULSE_WIDTH * kTicksPerUs;
  }
}

uint8_t Servo::attach(int pin) { return attach(pin, MIN_PULSE_WIDTH, MAX_PULSE_WIDTH); }

uint8_t Servo::attach(int pin, int minUs, int maxUs) {
  if (mChannel == INVALID_SERVO || pin < 0 || pin >= NUM_DIGITAL_PINS ||
      minUs >= maxUs) {
    return INVALID_SERVO;
  }
  pinMode(pin, OUTPUT);
  digitalWrite(pin, LOW);
  Channel& c = channels[mChannel];
  uint8_t sreg = SREG;
  cli();
  mMinUs = int16_t(minUs);
  mMaxUs = int16_t(maxUs);
  c.mask = digitalPinToBitMask(pin);
  c.port = portOutputRegister(digitalPinToPort(pin));
  SREG = sreg;
  if (!timerRunning) startTimer();
  return mChannel;
}

void Servo::detach() {
  if (mChannel == INVALID_SERVO) return;
  Channel& c = channels[mChannel];
  uint8_t sreg = SREG;
  cli();
  if (c.port != nullptr) *c.port &= uint8_t(~c.mask);
  c.port = nullptr;
  SREG = sreg;
}

bool Servo::attached() {
  return mChannel != INVALID_SERVO && channels[mChannel].port != nullptr;
}

void Servo::write(int value) {
  if (mChannel == INVALID_SERVO) return;
  if (value < MIN_PULSE_WIDTH) {
    const long angle = value < 0 ? 0 : (value > 180 ? 180 : value);
    value = int(mMinUs + angle * (mMaxUs - mMinUs) / 180);
  }
  writeMicroseconds(value);
}

void Servo::writeMicroseconds(int us) {
  if (mChannel == INVALID_SERVO) return;
  Channel& c = channels[mChannel];
  if (us < mMinUs) us = mMinUs;
  if (us > mMaxUs) us = mMaxUs;
  const uint16_t ticks = uint16_t(us) * kTicksPerUs;
  uint8_t sreg = SREG;
  cli();
  c.ticks = ticks;
  SREG = sreg;
}

int Servo::read() {
  if (mChannel == INVALID_SERVO) return 0;
  const long span = mMaxUs - mMinUs;
  return int(((readMicroseconds() - mMinUs) * 180L + span / 2) / span);
}

int Servo::readMicroseconds() {
  if (mChannel == INVALID_SERVO) return 0;
  uint8_t sreg = SREG;
  cli();
  const uint16_t ticks = channels[mChannel].ticks;
  SREG = sreg;
  return int(ticks / kTicksPerUs);
}
