// The physical side of the haptic lever, for the device simulator: servo,
// foam-backed force sensors (FSRs), the physical lever and the user's hand,
// plus the independent physics reference (a point mass on a massless rod).
// Pure C, no simavr: hil.c wires it to the simulated ATmega328P, and the
// self-checks test it alone.
#ifndef HIL_MODEL_H
#define HIL_MODEL_H

#include <stddef.h>
#include <stdio.h>

#define HIL_PI 3.14159265358979323846
#define DEG (HIL_PI / 180.0)

// Every number the model uses; hil_params_default() gives the baseline,
// `--set name=value` on the command line changes one (see kParamNames).
typedef struct {
  // Servo (the report's FS0521HV) and the Servo library's mapping.
  double pulse_min_us, pulse_max_us;  // 0 and 180 degrees
  double servo_centre_deg;            // servo angle when the lever is level
  double servo_direction;             // +1 or -1, as the sketch's constant
  double servo_rate_deg_s;            // rate limit: 60 deg per 0.05 s
  double servo_tau_s;                 // first-order lag
  double servo_stall_Nm;              // 21.3 kg cm
  double range_deg;                   // the mount turns +-range around centre
  // Foam and FSRs.
  double sensor_radius_m;  // FSRs to pivot
  double preload_N;        // each FSR at rest
  double full_N;           // the loaded FSR at full compression
  double full_deg;         // mount-to-lever angle at full compression
  double foam_damping_Nms; // viscous part of the foam, as a torque per rad/s
  double rigid_Nm_per_deg; // beyond full compression: the structure
  // The physical lever and the hand.
  double lever_inertia;   // kg m^2, the physical lever about its pivot
  double pivot_damping;   // N m s, bearing friction (viscous)
  double hand_radius_m;   // where the hand acts
  double grip_mass_kg, grip_k_N_m, grip_c_Ns_m;  // the hand as a grip
  // The virtual lever (for the reference and the dial).
  double mass_kg, gravity, restitution;
  double short_m, span_m;  // the dial: 0 -> short_m, 1023 -> short + span
  double vref_mV;
} HilParams;

void hil_params_default(HilParams* p);
// Sets one parameter by name; returns 0 when the name is unknown.
int hil_params_set(HilParams* p, const char* name, double value);
void hil_params_print(const HilParams* p, FILE* out);

// ---- Servo pulses -------------------------------------------------------
// Pulse width (us) to servo angle (degrees, 0..180), the inverse of the
// Servo library's linear map; then to the lever's angle from level.
double hil_pulse_to_servo_deg(const HilParams* p, double width_us);
double hil_servo_to_lever_deg(const HilParams* p, double servo_deg);

// Decodes edges on the servo pin into pulse widths.
typedef struct {
  unsigned long long rise;  // cycle of the last rising edge
  int high;
  double last_us;           // last accepted width, 0 before the first
  unsigned long long last_at;
  long accepted, ignored;
} PulseDecoder;
// Feeds one edge; returns 1 when a pulse was accepted (its width in
// last_us). Pulses ending before ignore_cycles are dropped, as are widths
// outside 400..2600 us.
int hil_pulse_edge(PulseDecoder* d, unsigned long long cycle, int level,
                   double cycles_per_us, unsigned long long ignore_cycles);

// ---- FSRs -----------------------------------------------------------------
// The force on one FSR (N) to its ADC reading: piecewise linear through the
// measurements of the report's Table D.1 (reading against grams), extended
// past 1,500 g with the last segment's slope and clamped to 0..1023.
double hil_fsr_reading(double newtons);
// The voltage (mV) on the analog pin that the ADC turns into `reading`
// (simavr: reading = floor(mV * 1023 / Vref)): the middle of its step.
double hil_reading_to_mV(const HilParams* p, double reading);
// The firmware's own curve (the report's Function 1) for comparisons.
double hil_function1_grams(double reading);

// The force on each pad, N, for the lever turned `delta_deg` relative to the
// mount (positive squeezes the "down" FSR) turning at delta_rate (deg/s).
void hil_pad_forces(const HilParams* p, double delta_deg, double delta_rate,
                    double* down_N, double* up_N);

// The lever's turn against the mount (deg) at which the pads' torque
// balances a steady hand force (N at the hand), by bisection.
double hil_static_delta(const HilParams* p, double hand_N);

// ---- The physical system ---------------------------------------------------
enum { HAND_NONE, HAND_FORCE, HAND_RIGID, HAND_SPRING };

typedef struct {
  double t[64], f[64];  // piecewise constant: f[i] from t[i] on
  int n;
} ForceProfile;
// Parses "t0:f0,t1:f1,..." (seconds:newtons, increasing times); 0 on error.
int hil_profile_parse(ForceProfile* fp, const char* text);
double hil_profile_at(const ForceProfile* fp, double t);

typedef struct {
  HilParams p;
  int hand;            // HAND_*
  ForceProfile force;  // HAND_FORCE: N at the hand, + pushes the end down
  double hold_deg;     // HAND_RIGID / HAND_SPRING: the held lever angle
  // State (angles in degrees from level; + lifts the virtual end).
  double mount_deg;    // the servo's output, what the hand feels
  double mount_rate;   // deg/s, in the last step
  double lever_deg, lever_rate;  // the physical lever, deg and deg/s
  double target_deg;   // from the last pulse
  int have_target;
  // Outputs of the last step.
  double down_N, up_N, hand_N, load_Nm;
  int stalled;
} Device;

void hil_device_init(Device* d, const HilParams* p);
// Advances the physical system by h seconds at time t.
void hil_device_step(Device* d, double t, double h);

// ---- The physics reference ------------------------------------------------
// A point mass m on a massless rod of length L about a fixed pivot, gravity
// g, a torque from the hand (force at hand_radius, perpendicular), and
// stops at +-range with restitution e; RK4 with step h and the stop
// crossings located within the step. Angles in radians.
typedef struct {
  double L, m, g, e, range, hand_radius;
  const ForceProfile* force;  // may be null: no hand
  double theta, omega, t;
  int resting;  // held against a stop
  long bounces;
} Reference;

void hil_reference_init(Reference* r, const HilParams* p, double length,
                        const ForceProfile* force, double theta0);
void hil_reference_step(Reference* r, double h);

#endif
