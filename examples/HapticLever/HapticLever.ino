// HapticLever: the one-degree-of-freedom haptic interface of the seed report
// (chapter 2), an admittance display. One end of a small lever is physical,
// the other is virtual: a 0.1 kg weight on a rod whose length a dial sets
// between 23 and 48 cm. Two force-sensitive resistors (FSRs), in foam on a
// mount that a servo turns, measure how hard the user pushes the physical
// end; the sketch turns that push into a torque on the virtual lever, steps
// the world 1,024 times a second, and turns the servo to the virtual angle.
//
// What you should feel and see: let go, and the physical end flips up as the
// virtual weight falls, hits the end of the lever's 65 degree range and
// bounces back with half its speed. Push the end down and you lift the
// weight; hold the lever level and it stays still. A short lever (dial at
// 0) is quick and light, a long one slow and heavy. The Serial Plotter
// (115200 baud) draws the lever's angle, the user's force and the lever's
// length over time; define HAPTIC_FRAMES (below) for ASCII frames of the
// virtual lever with a status line in the Serial Monitor instead.
//
// Hardware: an Arduino Nano, two Interlink FSR 402 in 10 kOhm dividers on
// A0 (pushed down) and A1 (pushed up), a 10 kOhm dial on A2, an FS0521HV
// servo on pin 7 with its own 7.5 V supply; see extras/doc/wiring.md.
// Needs the Servo library (Library Manager: "Servo"). Without the device:
// `make demo DEMO=examples/HapticLever` prints the plotter's lines of the
// lever let go (nothing pushes; frames with HAPTIC_FRAMES), and `make hil`
// runs it on a simulated device with a hand, servo and sensors (extras/hil).
//
// How the loop stays stable. The servo takes a new angle only at its next
// 20 ms pulse and then lags about 10 ms more, so the mount that presses the
// foam follows the virtual lever 20-30 ms late. Held by a hand, the foam
// (about 5 N per degree at the sensors) is a stiff spring on the light
// virtual lever, and a spring that pushes late pumps energy in: the plain
// admittance loop oscillates (report 4.2.2). The report's cure, scaling the
// velocity down while the push opposes the motion, is a factor per step
// (its strength changes with the step rate) and it brakes every steady push
// too: a hand that holds two thirds of the weight stops the fall.
// This sketch uses two things from haptics instead, chosen by the scenarios
// of the device simulator (extras/hil: release, partial support, push and
// release, a rigid or springy grip at level):
//  - The servo is sent the angle the lever will have about 25 ms from now,
//    from its angular velocity and acceleration (a second-order prediction,
//    the acceleration's share of it looking a little less far ahead). This
//    cancels most of the servo's delay, which is what makes the loop
//    unstable; with a first-order prediction (velocity only) the held short
//    lever still oscillated, because the lead it gives comes with too much
//    gain at the oscillation's frequency.
//  - A damper across the foam, in the spirit of a virtual coupling (Colgate
//    et al. 1995): the foam is the coupling's spring, measured by the FSRs,
//    and its damper is computed from how fast the measured push changes,
//    push + kForceLead * d(push)/dt (d(push)/dt is the foam's stiffness
//    times its deflection rate). It is a time in seconds, not a factor per
//    step, so it does not depend on the step rate, and a steady push has no
//    rate: the weight held, lifted or let down slowly moves as the physics
//    says.
// What was not chosen: a passivity observer/controller (Hannaford and Ryu
// 2002) watches the energy at the user's port, but the oscillation also
// runs against a rigid grip, where no energy flows through that port, and
// the mount's real velocity is not measured; a low-pass filter on the force
// adds delay and makes the oscillation worse; damping the virtual lever's
// own motion makes the weight fall as if through water (report 4.2.2).
//
// The sketch never waits: the physics step runs alone in its pass of
// loop(); the analog inputs are converted one at a time while the loop does
// other work; serial output is written only when the transmit buffer has
// room for the whole line, and only between the servo's pulses (whose edges
// it would otherwise delay); the servo is commanded in microseconds (about
// 0.1 degree each).
#include <Servo.h>
#include <TinyParticle.h>

typedef Q16_16 S;

// Arithmetic on constants that the compiler folds. Fixed's operators run
// through inline assembly (for their overflow checks), which it cannot fold:
// -kPushLimit would be computed at run time, at every use.
constexpr S negative(S constant) { return S::fromRaw(-constant.raw()); }
// a * n without rounding (the product of a value and a whole number is
// exact in fixed point): for |a * n| well inside Q16.16's range, as here.
inline S timesWhole(S a, int16_t n) { return S::fromRaw(a.raw() * n); }
// The sketch divides with whole numbers only, whose division the Arduino
// core links anyway: no fixed-point division is linked for it.

// ---- Wiring (extras/doc/wiring.md) ---------------------------------------
const uint8_t kFsrDownPin = A0;     // squeezed when the user pushes down
const uint8_t kFsrUpPin = A1;       // squeezed when the user pushes up
const uint8_t kLengthDialPin = A2;  // the dial for the virtual lever length
const uint8_t kServoPin = 7;

// ---- Output --------------------------------------------------------------
// By default one line `angle:<deg> force:<N> length:<m>` every 20 ms for
// the Serial Plotter, what tuning the device needs. Define HAPTIC_FRAMES for
// ASCII frames of the virtual lever and a status line in the Serial Monitor
// instead; they link the renderer, which the default leaves out to keep the
// sketch small (issue 12). extras/hil runs both.
// #define HAPTIC_FRAMES
#ifdef HAPTIC_FRAMES
const bool kPlotter = false;
#else
const bool kPlotter = true;
#endif

// ---- Calibration ----------------------------------------------------------
// One FSR reading (0-1023) to newtons; it runs outside the physics step,
// once per reading. The default is the report's Function 1,
// grams = x / (-1.30315751e-5 x^2 + 1.063940729e-2 x + 2.30339406), written
// with u = x / 1024 so that every term fits Q16.16; it reads the push a few
// percent off the measured points. To use your own sensors' measurements
// instead (the reading an FSR gives under known loads, in grams on the
// sensor, as the report measured on a scale), uncomment the define below
// and put the readings and grams into kFsrTable, each reading larger than
// the one before: a reading then becomes a force by straight lines between
// the points (the last one extended past the top; no force at or below the
// first). The table here is the report's Table D.1.
// #define HAPTIC_FSR_TABLE
#ifdef HAPTIC_FSR_TABLE
struct FsrPoint {
  uint16_t reading;
  uint16_t grams;
};
const FsrPoint kFsrTable[] PROGMEM = {
    {0, 50},    {415, 100}, {530, 150}, {640, 200},  {705, 250},  {755, 300},
    {790, 350}, {824, 400}, {855, 450}, {870, 500},  {880, 550},  {895, 600},
    {900, 700}, {906, 800}, {920, 900}, {940, 1100}, {950, 1500}};
const uint8_t kFsrPoints = sizeof(kFsrTable) / sizeof(kFsrTable[0]);

S fsrNewtons(int reading) {
  // At or below the first point the FSR reads nothing: no force.
  if (reading <= int(pgm_read_word(&kFsrTable[0].reading))) return S();
  uint8_t i = 1;
  while (i < kFsrPoints - 1 &&
         reading > int(pgm_read_word(&kFsrTable[i].reading))) {
    ++i;
  }
  const int r0 = pgm_read_word(&kFsrTable[i - 1].reading);
  const int r1 = pgm_read_word(&kFsrTable[i].reading);
  const int g0 = pgm_read_word(&kFsrTable[i - 1].grams);
  const int g1 = pgm_read_word(&kFsrTable[i].grams);
  const S grams = S(g0) + S(reading - r0) / S(r1 - r0) * S(g1 - g0);
  return grams * S(0.00981);
}
#else
const int kFsrLimit = 960;  // the fitted curve has a pole near 990
// newtons = x * 0.00981 / denominator in one division of whole numbers:
// x * 0.00981 N/g in units of 2^-28 (at most 2.6e9)
// over the denominator (0.50 to 4.6) in units of 2^-14 is newtons in units
// of 2^-14, within 2.5e-4 of the curve (the fixed-point quotient: 2e-4).
// It runs for every reading: a second division for the last two bits
// would take the loop's spare time that the frames need.
const uint32_t kNewtonsPerGram28 = 2633365;  // round(0.00981 * 2^28)
S fsrNewtons(int reading) {
  if (reading <= 0) return S();
  if (reading > kFsrLimit) reading = kFsrLimit;
  const S u = S::fromRaw(long(reading) * 64);  // x / 1024, exactly
  const S denominator =
      (S(-13.664495) * u + S(10.894753)) * u + S(2.30339406);
  const uint32_t d = (uint32_t(denominator.raw()) + 2) >> 2;
  const uint32_t n = uint32_t(reading) * kNewtonsPerGram28;
  return S::fromRaw(long((n + d / 2) / d) * 4);
}
#endif

// ---- The device ----------------------------------------------------------
const S kSensorDistance(0.04);      // m, FSRs to pivot
const S kShortest(0.23);            // m, dial at 0
const S kLengthSpan(0.25 / 1023);   // m per dial step: 0.48 m at 1023
// The lever's 65 degree range, centred on level: cos and sin of 32.5 deg.
const S kStopCos(0.843391);
const S kStopSin(0.537300);
const S kRangeRadians(0.567232);
// Restitution at the range ends: 1/2 (rangeEnds() halves the speed).
// Slower than this (m/s) into a range end, the end rests on it: about what
// gravity adds in two steps.
const S kRestingSpeed(0.02);
// The servo: the Servo library's default pulse range (544 us at 0 degrees,
// 2400 us at 180), level at 90 degrees.
const int kServoMinUs = 544;
const int kServoMaxUs = 2400;
const int kServoLevelUs = 1472;
const S kServoUsPerRadian(1856.0 / 3.14159265);
const int kServoRangeUs = 335;      // 32.5 degrees
const int kServoDirection = 1;      // -1 if the servo is mounted the other way

// ---- Stabilisation (see the opening comment) -----------------------------
// The damper across the foam, as a time: damping / foam stiffness. The push
// is averaged over about 4 ms and its rate over about 8 ms (prepareStep()).
// A push that steps from nothing to F gives the weight kForceLead * F more
// momentum than F alone would, until the push ends and takes it back: a
// pushed lever climbs faster and higher than physics says. So the time is
// about the shortest that still settles every grip of the simulator.
const S kForceLead(0.010);   // s
const S kPushLimit(40);       // N: the most the damper may make of a push
// How far ahead the servo is sent: about its frame and lag for the lever's
// velocity, less for its acceleration, since the user's push in it closes
// the loop through the foam and a longer horizon adds gain at the loop's
// frequency. Gravity's share looks exactly as far ahead as the push's: with
// a longer horizon of its own, a push that balances the weight (no
// acceleration) sent the servo half a degree below the lever it holds still,
// and the foam kicked the lever when the servo first went there. The times
// were tuned in
// the device simulator, including its runs with other foam damping, preload
// and lever inertia; much shorter or longer ones let the held short lever
// oscillate again.
const S kServoLead(0.0275);   // s
const double kPushLead = 0.0175;  // s

// For measurements only (the device simulator in extras/hil defines it):
// a pin that changes state at every pass of loop(), so that each pass can be
// timed from outside. Leave it undefined on a real device.
// #define HAPTIC_PROFILE_PIN 8

// ---- The simulation ------------------------------------------------------
// The lever scene (pivot, 0.1 kg end, rod, gravity, user force): 2
// particles, 1 force (the user's; gravity takes none), 1 constraint; rods
// take no contacts. The range ends
// are kept by the sketch (rangeEnds() below), not by two planes of the
// engine: at 1,024 steps a second their contacts cost about 2,000 cycles a
// step when the lever rests on one, more than the step can spare.
// (The device simulator, extras/hil, reads world, leverEnd, userForce and
// timing by their names.)
typedef World<S, 2, 2, 1, 1, 0> HapticWorld;
HapticWorld world;
ConstraintId leverRodId;              // the rod, whose length the dial sets
HapticWorld::ParticleType* leverEnd;  // the end, looked up once in setup()
// The rod's parameters (its length and the 1 / length the solver uses),
// looked up once in setup(); setLength() keeps both.
const HapticWorld::LinkParamsType* leverRod;
Vec2<S> userForce;  // N, read by the custom force generator every step

// 1,024 steps a second: timing is the one place that sets the step.
RealTimeLoop timing(1024, kPlotter ? 50 : 5);
// The lever's end reaches 0.48 m: x from -0.1 to 0.5 m, y from -0.3 m up.
// 24 x 12 characters of 2.5 x 5 cm, one line per pass of loop() (the
// cycles of the passes: extras/hil, "5 loop").
// The end (radius 1 cm) is smaller than half a cell: drawn as a point, the
// same characters without the renderer's circle code.
// Its links are one rod: the force slot (the user's force) is not looked
// at.
AsciiRenderer<HapticWorld, 24, 12, ParticleShape::kPoints,
              LinkShape::kRodsAndCables>
    renderer(S(-0.1), S(-0.3), S(0.025), S(0.05));
Servo leverServo;

// ---- Analog inputs without waiting ---------------------------------------
// start() begins a conversion, ready() says when it is done (13 ADC clocks,
// 104 us on a 16 MHz Nano), value() gives it. On the ATmega328P this is the
// ADC's registers; on other boards it falls back to analogRead(), which
// waits, and its reading is ready a conversion's time later, so that the
// loop's other work (the serial output) still gets passes of its own.
#if defined(__AVR_ATmega328P__)
struct AnalogInput {
  static void begin() {  // AVcc reference, clock / 128 (125 kHz)
    ADCSRA = _BV(ADEN) | _BV(ADPS2) | _BV(ADPS1) | _BV(ADPS0);
  }
  static void start(uint8_t pin) {
    ADMUX = _BV(REFS0) | ((pin - A0) & 0x07);
    ADCSRA |= _BV(ADSC);
  }
  static bool ready() { return !(ADCSRA & _BV(ADSC)); }
  static int value() { return ADC; }
};
#else
struct AnalogInput {
  static int last;
  static uint16_t startMicros;
  static void begin() {}
  static void start(uint8_t pin) {
    last = analogRead(pin);
    startMicros = uint16_t(micros());
  }
  static bool ready() {
    return uint16_t(uint16_t(micros()) - startMicros) >= 104;
  }
  static int value() { return last; }
};
int AnalogInput::last = 0;
uint16_t AnalogInput::startMicros = 0;
#endif

// A conversion waited for, in setup() only (the same conversion as
// analogRead(), without linking it).
int readAnalogNow(uint8_t pin) {
  AnalogInput::start(pin);
  while (!AnalogInput::ready()) {
  }
  return AnalogInput::value();
}

// The inputs in turn: down, up, down, up, ... and the dial every 32nd.
uint8_t inputTurn = 0;
uint8_t inputPin() {
  if ((inputTurn & 31) == 31) return kLengthDialPin;
  return (inputTurn & 1) ? kFsrUpPin : kFsrDownPin;
}

// The values carried from pass to pass, in one struct. The functions that
// use several of them reach them through a pointer the optimizer cannot
// fold (detail::throughPointer(), Configuration.hpp): on the AVR a Q16.16
// value loaded or stored through a pointer takes 8 bytes of code, from its
// fixed address 16.
struct LeverState {
  S downNewtons, upNewtons;  // the last reading of each FSR
  S push;                    // N at the sensors, averaged (down minus up)
  S pushRate;                // N/s, averaged
  S inverseLengthSquared;    // 1 / m^2 of the virtual lever
  S forcePerNewton;          // sensor distance / length^2: push to end force
  S forceScale;              // 1/s^2: the user's force on the end / its offset
  S stopX, stopY;            // m: the end at the upper range end (lower: y < 0)
};
LeverState state;
int dialReading = -100;    // the dial's reading behind the lever length

void setLeverLength(int reading) {
  LeverState& s = *detail::throughPointer(&state);
  dialReading = reading;
  const S length = kShortest + timesWhole(kLengthSpan, reading);
  world.setLength(leverRodId, length);
  // 1 / L^2 as the square of the rod's 1 / L, which setLength() has just
  // computed: Q16.16 holds L^2 only to 1.4e-4 of itself at 0.23 m, and
  // 1 / L to 2e-6.
  s.inverseLengthSquared = leverRod->inverseLength * leverRod->inverseLength;
  s.forcePerNewton = kSensorDistance * s.inverseLengthSquared;
  s.stopX = kStopCos * length;
  s.stopY = kStopSin * length;
}

// Collects a finished conversion and starts the next; false if none was
// finished.
bool serviceInputs() {
  if (!AnalogInput::ready()) return false;
  const uint8_t pin = inputPin();
  const int reading = AnalogInput::value();
  ++inputTurn;
  AnalogInput::start(inputPin());
  if (pin != kLengthDialPin) {
    (pin == kFsrDownPin ? state.downNewtons : state.upNewtons) =
        fsrNewtons(reading);
  } else if (reading > dialReading + 3 || reading < dialReading - 3) {
    setLeverLength(reading);  // a few steps of hysteresis against jitter
  }
  return true;
}

// ---- The range ends -------------------------------------------------------
// Above or below either end (the rod at +-32.5 degrees: the end's height
// beyond +-stopY), the lever's end is put back on it and, if it is still
// moving out, sent back with half its speed, or stopped when it is slower
// than kRestingSpeed. The lower end is handled as the upper one mirrored
// (y and its velocity negated; positions and speeds are far from the
// range of S, so negating their raw values is safe); there the range end's
// direction is u = (cos, sin) and the lever leaves the range along
// t = (-sin, cos).
const int8_t kStopHoldSteps = 24;
int8_t stopHold = 0;  // steps left, - at the lower end, + at the upper

// y and its velocity negated: the lower end becomes the upper one. (One
// negation out of line, called four times; in a struct, where the IDE's
// generated prototypes, which would name HapticWorld before its typedef,
// do not reach.)
struct Mirror {
  static TINYPARTICLE_NOINLINE void negate(S& value) {
    value = S::fromRaw(-value.raw());
  }
  static void y(HapticWorld::ParticleType* p) {
    negate(p->position.y);
    negate(p->velocity.y);
  }
};

void rangeEnds() {
  LeverState& s = *detail::throughPointer(&state);
  HapticWorld::ParticleType* const end = leverEnd;
  const bool lower = end->position.y < S();
  if (lower) Mirror::y(end);
  Vec2<S>& x = end->position;
  Vec2<S>& v = end->velocity;
  if (x.y > s.stopY) {
    x.x = s.stopX;
    x.y = s.stopY;
    const S out = kStopCos * v.y - kStopSin * v.x;  // along t
    if (out > S()) {  // moving out
      S back = S();
      if (out > kRestingSpeed) {
        back = S::fromRaw(-((out.raw() + 1) >> 1));  // -out / 2, rounded as S
        // The servo takes a new angle only every 20 ms: after a bounce it
        // is kept at the range end for a little longer than that, or the
        // prediction turns it back before the felt lever has reached the
        // end.
        stopHold = lower ? -kStopHoldSteps : kStopHoldSteps;
      }
      v.x = negative(kStopSin) * back;
      v.y = kStopCos * back;
    }
  }
  if (lower) Mirror::y(end);
}

// x / 2^k rounded down, as an arithmetic shift gives it, without shifting
// a negative number.
inline int32_t floorShift(int32_t x, uint8_t k) {
  return x >= 0 ? x >> k : -(-(x + 1) >> k) - 1;
}

// ---- Between steps --------------------------------------------------------
// The physics step is the longest regular pass of the loop (about 8,500
// cycles of the 15,625 in a step period), so it runs alone; the pass after
// it keeps the range ends, prepares the next step and commands the servo.
// The push with the damper across the foam acts as a torque about the
// pivot, perpendicular to the virtual lever (a quarter turn counterclockwise:
// pushing the physical end down lifts the virtual end).
void prepareStep() {
  LeverState& s = *detail::throughPointer(&state);
  rangeEnds();
  // Averages with weights 1/4 and 1/8 per step, as shifts. (Each FSR reads
  // under 19 N, so |change| < 10 N: its raw value times 1,024 fits.)
  const S change =
      S::fromRaw(floorShift((s.downNewtons - s.upNewtons - s.push).raw(), 2));
  s.push += change;
  s.pushRate += S::fromRaw(floorShift(
      change.raw() * long(timing.stepsPerSecond()) - s.pushRate.raw(), 3));
  S felt = s.push + s.pushRate * kForceLead;
  if (felt > kPushLimit) felt = kPushLimit;
  if (felt < negative(kPushLimit)) felt = negative(kPushLimit);
  const Vec2<S>& end = leverEnd->position;
  s.forceScale = felt * s.forcePerNewton;
  userForce.x = -end.y;
  userForce.y = end.x;
  userForce *= s.forceScale;
}

// The lever's angle from level, asin(y / L) of the end's height: within
// the range ends (sin 32.5 deg = 0.537) an odd polynomial fitted up to 0.56
// is within 3.4e-5 rad of it (0.02 us of servo command), as close as
// atan2(), without its code and table.
S leverRadians() {
  const S s = leverEnd->position.y * leverRod->inverseLength;
  const S s2 = s * s;
  return s + s * s2 * (S(0.163293) + S(0.103055) * s2);
}

// The servo is sent the angle the lever will have a little later, from its
// angular velocity and acceleration (a second-order prediction), which
// makes up for most of the servo's delay.
void commandServo() {
  const HapticWorld::ParticleType* end = leverEnd;
  const Vec2<S>& x = end->position;
  const S turnRate =
      (x.x * end->velocity.y - x.y * end->velocity.x) *
      state.inverseLengthSquared;
  // Gravity's angular acceleration is -g x / L^2, the user's forceScale /
  // mass (the end's 0.1 kg, from buildLever()); their sum, the lever's,
  // looks kPushLead ahead (see there).
  // (forceScale x 10 stays below 310: the push is limited to kPushLimit.)
  const S gravity = S(9.81) * x.x * state.inverseLengthSquared;
  S angle = leverRadians() + turnRate * kServoLead +
            (timesWhole(state.forceScale, 10) - gravity) *
                S(kPushLead * kPushLead * 0.5);
  if (stopHold != 0) {
    angle = stopHold < 0 ? negative(kRangeRadians) : kRangeRadians;
    stopHold += stopHold < 0 ? 1 : -1;
  }
  // Never past the range ends (the prediction overshoots them at a bounce).
  S offset = angle * kServoUsPerRadian;
  if (offset > S(kServoRangeUs)) offset = S(kServoRangeUs);
  if (offset < S(-kServoRangeUs)) offset = S(-kServoRangeUs);
  // Rounded to whole microseconds (halves up), shifted by 512 us so that
  // no negative number is shifted.
  const int us =
      int(uint32_t(offset.raw() + 0x8000L + (512L << 16)) >> 16) - 512;
  leverServo.writeMicroseconds(kServoLevelUs + kServoDirection * us);
}

// ---- Serial output, never waiting ----------------------------------------
// Lines are put together in a buffer on the stack and written in one go
// when the transmit buffer has room for the whole line.
const uint8_t kLineMax = 52;

// ...and only between the servo's pulses. The Servo library starts and ends
// each pulse in a Timer1 interrupt; when Serial's transmit interrupt (one
// per byte sent) is running at that moment, the edge comes several
// microseconds late, and the servo turns by half a degree for that frame:
// a lever at rest twitches. So a line is queued only after a pulse has
// ended (the pin is watched at every pass of loop()) and only if it and the
// bytes already queued leave the UART before the next pulse can begin.
#ifdef SERIAL_TX_BUFFER_SIZE
const int kTxQueueMax = SERIAL_TX_BUFFER_SIZE - 1;
#else
const int kTxQueueMax = 63;
#endif
const uint16_t kByteUs = 87;          // 10 bits at 115200 baud
const uint16_t kServoFrameUs = 20000; // from one pulse's start to the next
// The quiet time after a pulse's end: the frame less the longest pulse we
// command and a margin for seeing the end up to a pass of loop() late.
const uint16_t kQuietUs =
    kServoFrameUs - (kServoLevelUs + kServoRangeUs) - 1000;
uint16_t pulseEndMicros;   // micros() when the last pulse was seen ending
uint8_t servoPinState = 0; // bit 0: a pulse is on; bit 1: one has ended

// The servo pin's level, as digitalRead() reads it (without its check for
// a PWM timer, which the servo pin does not use). On the ATmega328P from
// its pin map (digital 0-7: port D, 8-13: port B) at compile time, without
// the core's lookup tables; elsewhere through them.
#if defined(__AVR_ATmega328P__)
static_assert(kServoPin <= 13, "a digital pin of the Nano");
inline bool servoPinHigh() {
  return kServoPin < 8 ? (PIND & _BV(kServoPin & 7)) != 0
                       : (PINB & _BV((kServoPin - 8) & 7)) != 0;
}
#else
inline bool servoPinHigh() {
  return (*portInputRegister(digitalPinToPort(kServoPin)) &
          digitalPinToBitMask(kServoPin)) != 0;
}
#endif

void watchServoPulse() {
  if (servoPinHigh()) {
    servoPinState |= 1;
  } else if (servoPinState & 1) {
    pulseEndMicros = uint16_t(micros());
    servoPinState = 2;
  }
}

// True when a line of n bytes may be queued now: Serial's transmit buffer
// has room for it and one byte more (never full: the next byte would wait),
// and it leaves the UART between two pulses (see above). Without pulses
// (none yet, or no servo attached) there is nothing to keep clear.
bool serialQuiet(uint8_t n) {
  const int room = Serial.availableForWrite();
  if (room <= n) return false;
  if (servoPinState & 1) return false;  // a pulse is on
  if (servoPinState == 0) return true;
  int bytes = kTxQueueMax - room + n + 1;
  if (bytes < 0) bytes = 0;
  const uint16_t since = uint16_t(micros()) - pulseEndMicros;
  if (since > 2 * kServoFrameUs) {  // the pulses have stopped
    servoPinState = 0;
    return true;
  }
  return since <= kQuietUs && uint16_t(bytes) * kByteUs <= kQuietUs - since;
}

// A value with two decimals (magnitudes up to 655.35). Out of line, as
// writeStatus() below: inlined into loop(), each made it longer than the
// call (a measurement: 96 bytes for both).
const uint16_t kPowersOfTen[] PROGMEM = {10000, 1000, 100, 10, 1};
TINYPARTICLE_NOINLINE uint8_t appendHundredths(char* line, uint8_t n,
                                               S value) {
  uint32_t magnitude = uint32_t(value.raw());
  if (value < S()) {
    line[n++] = '-';
    magnitude = 0UL - magnitude;
  }
  if (magnitude > 65535UL * 655) magnitude = 65535UL * 655;
  uint16_t h = uint16_t((magnitude * 100 + 0x8000UL) >> 16);
  // Digits by subtracting powers of ten (16-bit: several times faster on
  // the AVR than 32-bit digits, and no division linked); leading zeros
  // are left out down to the units (0.05, not .05).
  bool leading = true;
  for (uint8_t i = 0; i < 5; ++i) {
    const uint16_t power = pgm_read_word(&kPowersOfTen[i]);
    char digit = '0';
    while (h >= power) {
      h -= power;
      ++digit;
    }
    if (digit != '0' || i == 2) leading = false;
    if (!leading) line[n++] = digit;
    if (i == 2) line[n++] = '.';
  }
  return n;
}

// The status line (or the plotter's line); false if there is no room yet.
// Each '#' of the text is a value, in the order of the list.
const char kStatusText[] PROGMEM =
    "angle # deg  push # N  length # m\r\n";
const char kPlotterText[] PROGMEM = "angle:# force:# length:#\r\n";

TINYPARTICLE_NOINLINE bool writeStatus() {
  const S values[] = {leverRadians() * S(57.29578), state.push,
                      leverRod->length};
  char line[kLineMax];
  uint8_t n = 0;
  uint8_t k = 0;
  const char* p = kPlotter ? kPlotterText : kStatusText;
  for (char c = pgm_read_byte(p); c != 0; c = pgm_read_byte(++p)) {
    if (c == '#') {
      n = appendHundredths(line, n, values[k++]);
    } else {
      line[n++] = c;
    }
  }
  if (!serialQuiet(n)) return false;
  Serial.write(reinterpret_cast<const uint8_t*>(line), n);
  return true;
}

// ---- Setup and loop ------------------------------------------------------
void setup() {
  LeverState& s = *detail::throughPointer(&state);
  Serial.begin(115200);
  // The push starts from the sensors as they are (a hand may already be on
  // the lever), not from zero: a push from nothing would kick the weight.
  AnalogInput::begin();
  const S down = fsrNewtons(readAnalogNow(kFsrDownPin));
  const S up = fsrNewtons(readAnalogNow(kFsrUpPin));
  s.downNewtons = down;
  s.upNewtons = up;
  s.push = down - up;
  leverServo.attach(kServoPin, kServoMinUs, kServoMaxUs);
#ifdef HAPTIC_PROFILE_PIN
  pinMode(HAPTIC_PROFILE_PIN, OUTPUT);
#endif
  const LeverScene lever = buildLever(world, &userForce, kShortest);
  leverRodId = lever.rod;
  leverEnd = world.particle(lever.end);
  leverRod = world.constraintParams<HapticWorld::LinkParamsType>(lever.rod);
  setLeverLength(readAnalogNow(kLengthDialPin));
  // The first step needs the push as a force too (later steps get it from
  // the pass before them), or gravity alone acts for that step.
  prepareStep();
  AnalogInput::start(inputPin());
  if (!kPlotter) {
    Serial.print(F("HapticLever: push the lever; turn the dial for its length\r\n"));
  }
}

enum Output : uint8_t { kIdle, kFrame, kStatus };
Output output = kIdle;
bool stepped = false;

void loop() {
#ifdef HAPTIC_PROFILE_PIN
  *portOutputRegister(digitalPinToPort(HAPTIC_PROFILE_PIN)) ^=
      digitalPinToBitMask(HAPTIC_PROFILE_PIN);
#endif
  watchServoPulse();
  // A pass either steps the physics or does one piece of the other work,
  // so that no pass is long and every step comes on time.
  if (stepped) {
    stepped = false;
    prepareStep();
    commandServo();
    return;
  }
  if (timing.runSteps(world) > 0) {
    stepped = true;
    return;
  }
  if (serviceInputs()) return;
  if (output == kIdle && timing.frameDue()) output = kPlotter ? kStatus : kFrame;
  if (output == kIdle || timing.microsToNextStep() < 100) return;
  // (!kPlotter: in plotter mode the renderer's code is not linked.)
  if (!kPlotter && output == kFrame) {
    if (serialQuiet(renderer.lineLength()) &&
        renderer.drawLine(world, Serial)) {
      output = kStatus;
    }
  } else if (writeStatus()) {
    output = kIdle;
  }
}
