// HapticLever: the one-degree-of-freedom haptic interface of the seed report
// (chapter 2). One end of a small lever is physical, the other is virtual:
// a 0.1 kg weight on a rod whose length a dial sets between 23 and 48 cm.
// Two force-sensitive resistors (FSRs) measure how hard the user pushes the
// physical end; the simulation turns that into a force on the virtual end,
// steps the world, and a servo turns the lever to the virtual lever's angle.
// Let go, and the weight falls, flipping the physical end up; the lever's
// 65 degree range ends bounce it back with half its speed.
//
// As in the report (Code Blocks 2.1 and 2.2, sections 2.4 and 4.2.2):
//  - the FSR readings go through the report's fitted curve (Function 1),
//    down minus up, averaged over the last two readings;
//  - the force acts perpendicular to the lever, scaled by the mechanical
//    advantage (sensors 4 cm from the pivot / virtual lever length), through
//    a custom force generator that reads the sketch's vector;
//  - selective damping: when the user pushes against the motion harder than
//    0.5 N, the velocity is scaled down (this calms the oscillations of the
//    foam-backed sensor mount);
//  - the virtual lever is drawn as ASCII frames on Serial (115200 baud).
// Unlike the report, the range ends are two half-space planes through the
// pivot (restitution 0.5), the step is a fixed 1/256 s kept in step with
// the clock, and frames go out a line at a time so the physics never waits
// for the serial line.
//
// Without hardware (or in simavr, whose analog inputs read 0) there is no
// push: the lever falls to its lower end, bounces and settles, and the
// sketch keeps drawing five frames a second.
//
// Needs the Servo library (Library Manager: "Servo").
#include <Servo.h>
#include <TinyParticle.h>

// ---- Wiring -------------------------------------------------------------
const uint8_t kFsrDownPin = A0;     // squeezed when the user pushes down
const uint8_t kFsrUpPin = A1;       // squeezed when the user pushes up
const uint8_t kLengthDialPin = A2;  // the dial for the virtual lever length
const uint8_t kServoPin = 7;

// ---- The device -----------------------------------------------------------
typedef Q16_16 S;
const S kSensorDistance(0.04);      // m, FSRs to pivot
const S kShortest(0.23);            // m, dial at 0
const S kLengthSpan(0.25);          // m, dial at 1023: 0.48 m
const float kHalfRangeDegrees = 32.5f;  // the 65 degree range, centred
const S kEndBounce(0.5);            // restitution at the range ends
const S kDampingThreshold(0.5);     // N, section 4.2.2
const int kServoCentre = 90;        // degrees when the lever is level
const int kServoDirection = 1;      // -1 if the servo is mounted the other way
const int kFsrLimit = 960;          // the fitted curve has a pole near 990

// For measurements only (the device simulator in extras/hil defines it):
// a pin that changes state at every pass of loop(), so that each pass can be
// timed from outside. Leave it undefined on a real device.
// #define HAPTIC_PROFILE_PIN 8

// ---- The simulation ------------------------------------------------------
// The lever scene (pivot, 0.1 kg end, rod, gravity, user force) plus the two
// range ends: 2 particles, 2 forces, 3 constraints, 3 contacts.
typedef World<S, 2, 2, 2, 3, 3> HapticWorld;
HapticWorld world;
LeverScene lever;
Vec2<S> userForce;  // N, read by the custom force generator every step

const S kDt(1.0 / 256);
RealTimeLoop timing(256, 5);  // 256 steps a second, 5 frames a second
// The lever's end reaches 0.48 m: x from -0.1 to 0.5 m, y from -0.3 m up.
AsciiRenderer<HapticWorld, 30, 15> renderer(S(-0.1), S(-0.3), S(0.02),
                                            S(0.04));
Servo leverServo;

// Function 1 of the report: an FSR reading (0-1023) to grams,
// x / (-1.30315751e-5 x^2 + 1.063940729e-2 x + 2.30339406), written with
// u = x / 1024 so that every term fits Q16.16; then grams to newtons.
S fsrNewtons(int reading) {
  if (reading <= 0) return S();
  if (reading > kFsrLimit) reading = kFsrLimit;
  const S x(reading);
  const S u = x * S(1.0 / 1024);
  const S denominator =
      (S(-13.664495) * u + S(10.894753)) * u + S(2.30339406);
  return x / denominator * S(0.00981);
}

S leverLength() {
  return kShortest + kLengthSpan * S(analogRead(kLengthDialPin)) *
                         S(1.0 / 1023);
}

// A range end: the plane through the pivot along angle `degrees`, facing
// the allowed side (up for the lower end, down for the upper one). Its
// offset is minus the end's radius, so the centre stops on the line.
void addRangeEnd(float degrees, bool lower) {
  const float radians = degrees * 0.0174533f;
  const float nx = lower ? -sin(radians) : sin(radians);
  const float ny = lower ? cos(radians) : -cos(radians);
  world.addPlane(Vec2<S>(nx, ny), -world.particle(lever.end)->radius,
                 kEndBounce);
}

S pushes[2];  // the last two net FSR forces, N
uint8_t nextPush = 0;

// Reads the sensors and the dial; sets the user force and the rod length.
void readDevice() {
  pushes[nextPush] = fsrNewtons(analogRead(kFsrDownPin)) -
                     fsrNewtons(analogRead(kFsrUpPin));
  nextPush ^= 1;
  const S push = (pushes[0] + pushes[1]) * S(0.5);

  const S length = leverLength();
  world.setLength(lever.rod, length);

  // Perpendicular to the lever (a quarter turn counterclockwise): pushing
  // the physical end down lifts the virtual end.
  const Vec2<S>& end = world.particle(lever.end)->position;
  const S distance = end.magnitude();
  if (distance == S()) return;
  const S scale = push * kSensorDistance / length / distance;
  userForce = Vec2<S>(-end.y * scale, end.x * scale);
}

// Section 4.2.2: when the user pushes against the motion harder than the
// threshold, scale the velocity down by threshold / push.
void selectiveDamping() {
  HapticWorld::ParticleType* end = world.particle(lever.end);
  const S speed = end->velocity.magnitude();
  if (speed == S()) return;
  const S along = dot(userForce, end->velocity) / speed;
  if (along < -kDampingThreshold) {
    end->velocity *= kDampingThreshold / -along;
  }
}

int leverDegrees() {
  const Vec2<S>& end = world.particle(lever.end)->position;
  return (atan2(end.y, end.x) * S(57.29578)).toInt();
}

void setup() {
  Serial.begin(115200);
  leverServo.attach(kServoPin);
#ifdef HAPTIC_PROFILE_PIN
  pinMode(HAPTIC_PROFILE_PIN, OUTPUT);
#endif
  lever = buildLever(world, &userForce, leverLength());
  addRangeEnd(-kHalfRangeDegrees, true);
  addRangeEnd(kHalfRangeDegrees, false);
  Serial.println(F("HapticLever: push the lever; turn the dial for its length"));
}

bool drawing = false;

void loop() {
#ifdef HAPTIC_PROFILE_PIN
  *portOutputRegister(digitalPinToPort(HAPTIC_PROFILE_PIN)) ^=
      digitalPinToBitMask(HAPTIC_PROFILE_PIN);
#endif
  uint8_t due = timing.stepsDue();
  if (due > 0) readDevice();
  for (; due > 0; --due) {
    selectiveDamping();
    world.step(kDt);
  }
  const int degrees = leverDegrees();
  leverServo.write(kServoCentre + kServoDirection * degrees);

  if (!drawing && timing.frameDue()) drawing = true;
  while (drawing && Serial.availableForWrite() >= renderer.lineLength()) {
    if (renderer.drawLine(world, Serial)) {
      drawing = false;
      Serial.print(F("angle "));
      Serial.print(degrees);
      Serial.print(F(" deg  push "));
      Serial.print(userForce.magnitude().toFloat(), 2);
      Serial.print(F(" N  length "));
      Serial.print(leverLength().toFloat(), 2);
      Serial.println(F(" m"));
    }
  }
}
