// The physical side of the haptic lever and the physics reference; see
// model.h. Units: SI, angles in degrees unless a name says otherwise.
#include "model.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
  const char* name;
  size_t offset;
  const char* what;
} ParamName;

#define P(field, what) {#field, offsetof(HilParams, field), what}
static const ParamName kParamNames[] = {
    P(pulse_min_us, "us at servo 0 deg (Servo library default)"),
    P(pulse_max_us, "us at servo 180 deg"),
    P(servo_centre_deg, "servo angle with the lever level (sketch: 90)"),
    P(servo_direction, "+1 or -1 (sketch: kServoDirection)"),
    P(servo_rate_deg_s, "servo rate limit, deg/s (60 deg per 0.05 s)"),
    P(servo_tau_s, "servo first-order lag, s"),
    P(servo_stall_Nm, "servo stall torque, N m (21.3 kg cm)"),
    P(range_deg, "mount range, +-deg around centre"),
    P(sensor_radius_m, "FSRs to pivot, m"),
    P(preload_N, "force on each FSR at rest, N"),
    P(full_N, "loaded FSR at full foam compression, N"),
    P(full_deg, "mount-to-lever angle at full compression, deg"),
    P(foam_damping_Nms, "foam viscous torque per rad/s, N m s"),
    P(rigid_Nm_per_deg, "stiffness past full compression, N m per deg"),
    P(lever_inertia, "physical lever inertia about the pivot, kg m^2"),
    P(pivot_damping, "bearing friction, N m s"),
    P(hand_radius_m, "hand to pivot, m"),
    P(grip_mass_kg, "grip: hand mass, kg"),
    P(grip_k_N_m, "grip: stiffness, N/m"),
    P(grip_c_Ns_m, "grip: damping, N s/m"),
    P(mass_kg, "virtual end mass, kg"),
    P(gravity, "m/s^2"),
    P(restitution, "speed ratio at the stops"),
    P(short_m, "virtual length with the dial at 0, m"),
    P(span_m, "extra length with the dial at 1023, m"),
    P(vref_mV, "ADC reference (AVcc), mV"),
};
#undef P

void hil_params_default(HilParams* p) {
  p->pulse_min_us = 544;
  p->pulse_max_us = 2400;
  p->servo_centre_deg = 90;
  p->servo_direction = 1;
  p->servo_rate_deg_s = 60.0 / 0.05;
  p->servo_tau_s = 0.010;
  p->servo_stall_Nm = 0.213 * 9.80665;  // 21.3 kg cm: 52 N at 4 cm
  p->range_deg = 32.5;
  p->sensor_radius_m = 0.04;
  p->preload_N = 2.0;
  p->full_N = 15.0;
  p->full_deg = 2.8;
  p->foam_damping_Nms = 0.02;
  p->rigid_Nm_per_deg = 10.0;
  p->lever_inertia = 2.0e-4;
  p->pivot_damping = 1.0e-4;
  p->hand_radius_m = 0.20;
  p->grip_mass_kg = 0.3;
  p->grip_k_N_m = 300;
  p->grip_c_Ns_m = 4;
  p->mass_kg = 0.1;
  p->gravity = 9.81;
  p->restitution = 0.5;
  p->short_m = 0.23;
  p->span_m = 0.25;
  p->vref_mV = 5000;
}

int hil_params_set(HilParams* p, const char* name, double value) {
  for (size_t i = 0; i < sizeof kParamNames / sizeof kParamNames[0]; ++i) {
    if (strcmp(kParamNames[i].name, name) == 0) {
      double* field = (double*)((char*)p + kParamNames[i].offset);
      *field = value;
      return 1;
    }
  }
  return 0;
}

void hil_params_print(const HilParams* p, FILE* out) {
  for (size_t i = 0; i < sizeof kParamNames / sizeof kParamNames[0]; ++i) {
    const double* field =
        (const double*)((const char*)p + kParamNames[i].offset);
    fprintf(out, "param %s=%.6g  # %s\n", kParamNames[i].name, *field,
            kParamNames[i].what);
  }
}

// ---- Servo pulses -------------------------------------------------------

double hil_pulse_to_servo_deg(const HilParams* p, double width_us) {
  return (width_us - p->pulse_min_us) * 180.0 /
         (p->pulse_max_us - p->pulse_min_us);
}

double hil_servo_to_lever_deg(const HilParams* p, double servo_deg) {
  return (servo_deg - p->servo_centre_deg) * p->servo_direction;
}

int hil_pulse_edge(PulseDecoder* d, unsigned long long cycle, int level,
                   double cycles_per_us, unsigned long long ignore_cycles) {
  if (level) {
    d->rise = cycle;
    d->high = 1;
    return 0;
  }
  if (!d->high) return 0;
  d->high = 0;
  const double us = (double)(cycle - d->rise) / cycles_per_us;
  if (cycle < ignore_cycles || us < 400 || us > 2600) {
    d->ignored++;
    return 0;
  }
  d->last_us = us;
  d->last_at = cycle;
  d->accepted++;
  return 1;
}

// ---- FSRs -----------------------------------------------------------------

// Table D.1 of the report: the measured points, grams on the scale and the
// analog reading (10 kOhm divider, 5 V).
static const double kGrams[] = {50,  100, 150, 200, 250, 300, 350, 400, 450,
                                500, 550, 600, 700, 800, 900, 1100, 1500};
static const double kReading[] = {0,   415, 530, 640, 705, 755, 790, 824, 855,
                                  870, 880, 895, 900, 906, 920, 940, 950};
#define TABLE_N ((int)(sizeof kGrams / sizeof kGrams[0]))

double hil_fsr_reading(double newtons) {
  const double g = newtons / 9.81 * 1000.0;
  double r;
  if (g <= kGrams[0]) {
    r = 0;
  } else if (g >= kGrams[TABLE_N - 1]) {
    const double slope = (kReading[TABLE_N - 1] - kReading[TABLE_N - 2]) /
                         (kGrams[TABLE_N - 1] - kGrams[TABLE_N - 2]);
    r = kReading[TABLE_N - 1] + slope * (g - kGrams[TABLE_N - 1]);
  } else {
    int i = 1;
    while (g > kGrams[i]) ++i;
    const double s = (g - kGrams[i - 1]) / (kGrams[i] - kGrams[i - 1]);
    r = kReading[i - 1] + s * (kReading[i] - kReading[i - 1]);
  }
  return r < 0 ? 0 : (r > 1023 ? 1023 : r);
}

double hil_reading_to_mV(const HilParams* p, double reading) {
  // simavr takes whole millivolts and reads floor(mV * 1023 / Vref): the
  // smallest whole mV inside the reading's step gives exactly that reading.
  const double r = floor(reading);
  double mV = ceil(r * p->vref_mV / 1023.0);
  if (floor(mV * 1023.0 / p->vref_mV) < r) mV += 1;  // rounding guard
  return mV;
}

double hil_function1_grams(double x) {
  return x / (-1.30315751e-5 * x * x + 1.063940729e-2 * x + 2.30339406);
}

// Each pad is foam with force f(c) = a c + b c^2 (c: its compression,
// in degrees of lever turn). At rest both are compressed c0 = full/2 and
// give the preload; turning by `full` brings one to c0 + full (full_N)
// and unloads the other (it leaves the lever at half the travel).
static double pad_force(const HilParams* p, double c) {
  const double c0 = p->full_deg / 2, c1 = c0 + p->full_deg;
  // Solve a c0 + b c0^2 = preload, a c1 + b c1^2 = full.
  const double det = c0 * c1 * c1 - c1 * c0 * c0;
  const double a = (p->preload_N * c1 * c1 - p->full_N * c0 * c0) / det;
  const double b = (p->full_N * c0 - p->preload_N * c1) / det;
  if (c <= 0) return 0;
  if (c <= c1) return a * c + b * c * c;
  // Past full compression the structure carries the rest, stiffly.
  return p->full_N + p->rigid_Nm_per_deg / p->sensor_radius_m * (c - c1);
}

void hil_pad_forces(const HilParams* p, double delta_deg, double delta_rate,
                    double* down_N, double* up_N) {
  const double c0 = p->full_deg / 2;
  const double cd = c0 + delta_deg, cu = c0 - delta_deg;
  double down = pad_force(p, cd), up = pad_force(p, cu);
  // Viscous part, only while a pad touches; stronger in the rigid range.
  const double rate_rad = delta_rate * DEG;
  double c = p->foam_damping_Nms / p->sensor_radius_m;  // N per rad/s
  const double k_rigid = p->rigid_Nm_per_deg / DEG;      // N m per rad
  const double c_rigid =
      1.4 * sqrt(k_rigid * p->lever_inertia) / p->sensor_radius_m;
  if (cd > 0) down += (cd > c0 + p->full_deg ? c + c_rigid : c) * rate_rad;
  if (cu > 0) up -= (cu > c0 + p->full_deg ? c + c_rigid : c) * rate_rad;
  *down_N = down > 0 ? down : 0;
  *up_N = up > 0 ? up : 0;
}

double hil_static_delta(const HilParams* p, double hand_N) {
  const double target = hand_N * p->hand_radius_m / p->sensor_radius_m;
  double lo = -2 * p->full_deg, hi = 2 * p->full_deg, down, up;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    hil_pad_forces(p, mid, 0, &down, &up);
    if (down - up < target) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

// ---- Force profiles -------------------------------------------------------

int hil_profile_parse(ForceProfile* fp, const char* text) {
  fp->n = 0;
  const char* s = text;
  while (*s) {
    char* end;
    const double t = strtod(s, &end);
    if (end == s || *end != ':') return 0;
    s = end + 1;
    const double f = strtod(s, &end);
    if (end == s) return 0;
    if (fp->n == 64 || (fp->n > 0 && t < fp->t[fp->n - 1])) return 0;
    fp->t[fp->n] = t;
    fp->f[fp->n] = f;
    fp->n++;
    s = end;
    if (*s == ',') ++s;
    else if (*s) return 0;
  }
  return fp->n > 0;
}

double hil_profile_at(const ForceProfile* fp, double t) {
  double f = 0;
  for (int i = 0; i < fp->n && fp->t[i] <= t; ++i) f = fp->f[i];
  return f;
}

// ---- The physical system ---------------------------------------------------

void hil_device_init(Device* d, const HilParams* p) {
  memset(d, 0, sizeof *d);
  d->p = *p;
  d->hand = HAND_NONE;
}

static double clampd(double x, double lo, double hi) {
  return x < lo ? lo : (x > hi ? hi : x);
}

void hil_device_step(Device* d, double t, double h) {
  const HilParams* p = &d->p;
  const double r_s = p->sensor_radius_m, r_h = p->hand_radius_m;

  // Pads first: their reaction is the servo's load.
  const double delta = d->lever_deg - d->mount_deg;
  // The foam's damping sees the lever's rate against the mount's rate of
  // the last step (the mount moves after this).
  hil_pad_forces(p, delta, d->lever_rate - d->mount_rate, &d->down_N,
                 &d->up_N);
  const double net = d->down_N - d->up_N;  // pushes the mount +, lever -
  d->load_Nm = net * r_s;

  // Servo: lag toward the target, rate limit, and a linear torque-speed
  // line: against a load it slows, at the stall torque it stops, beyond
  // it is driven back.
  double v = 0;
  if (d->have_target) {
    const double target =
        clampd(d->target_deg, -p->range_deg, p->range_deg);
    double v_cmd = (target - d->mount_deg) / p->servo_tau_s;
    v_cmd = clampd(v_cmd, -p->servo_rate_deg_s, p->servo_rate_deg_s);
    const double s =
        v_cmd > 0 ? 1 : (v_cmd < 0 ? -1 : (d->load_Nm > 0 ? -1 : 1));
    const double opposing = -s * d->load_Nm;
    const double v_dir =
        p->servo_rate_deg_s * (1 - opposing / p->servo_stall_Nm);
    d->stalled = v_dir < fabs(v_cmd);
    v = v_dir >= 0 ? s * fmin(fabs(v_cmd), v_dir) : s * v_dir;
  } else {
    d->stalled = 0;
  }
  const double before = d->mount_deg;
  d->mount_deg = clampd(before + v * h, -p->range_deg, p->range_deg);
  d->mount_rate = (d->mount_deg - before) / h;

  // The physical lever.
  const double tau_pad = -net * r_s;
  if (d->hand == HAND_RIGID) {
    d->lever_deg = d->hold_deg;
    d->lever_rate = 0;
    d->hand_N = -tau_pad / r_h;
    return;
  }
  double inertia = p->lever_inertia, tau_hand = 0;
  if (d->hand == HAND_FORCE) {
    d->hand_N = hil_profile_at(&d->force, t);
    tau_hand = d->hand_N * r_h;
  } else if (d->hand == HAND_SPRING) {
    inertia += p->grip_mass_kg * r_h * r_h;
    const double x = r_h * (d->lever_deg - d->hold_deg) * DEG;
    const double xdot = r_h * d->lever_rate * DEG;
    d->hand_N = -p->grip_k_N_m * x - p->grip_c_Ns_m * xdot;
    tau_hand = d->hand_N * r_h;
  } else {
    d->hand_N = 0;
  }
  const double alpha = (tau_pad + tau_hand -
                        p->pivot_damping * d->lever_rate * DEG) / inertia;
  d->lever_rate += alpha / DEG * h;
  d->lever_deg += d->lever_rate * h;
}

// ---- The physics reference ------------------------------------------------

void hil_reference_init(Reference* r, const HilParams* p, double length,
                        const ForceProfile* force, double theta0) {
  memset(r, 0, sizeof *r);
  r->L = length;
  r->m = p->mass_kg;
  r->g = p->gravity;
  r->e = p->restitution;
  r->range = p->range_deg * DEG;
  r->hand_radius = p->hand_radius_m;
  r->force = force;
  r->theta = theta0;
}

static double ref_accel(const Reference* r, double t, double theta) {
  const double hand = r->force ? hil_profile_at(r->force, t) : 0;
  return (hand * r->hand_radius - r->m * r->g * r->L * cos(theta)) /
         (r->m * r->L * r->L);
}

static void rk4(const Reference* r, double t, double h, double* th,
                double* om) {
  const double t0 = *th, w0 = *om;
  const double k1t = w0, k1w = ref_accel(r, t, t0);
  const double k2t = w0 + 0.5 * h * k1w,
               k2w = ref_accel(r, t + 0.5 * h, t0 + 0.5 * h * k1t);
  const double k3t = w0 + 0.5 * h * k2w,
               k3w = ref_accel(r, t + 0.5 * h, t0 + 0.5 * h * k2t);
  const double k4t = w0 + h * k3w, k4w = ref_accel(r, t + h, t0 + h * k3t);
  *th = t0 + h / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
  *om = w0 + h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
}

void hil_reference_step(Reference* r, double h) {
  if (r->resting) {
    // Stays against its stop while the net torque presses it there.
    const double a = ref_accel(r, r->t, r->theta);
    if ((r->theta < 0 && a > 0) || (r->theta > 0 && a < 0)) {
      r->resting = 0;
    } else {
      r->t += h;
      return;
    }
  }
  double left = h;
  for (int guard = 0; guard < 8 && left > 0; ++guard) {
    double th = r->theta, om = r->omega;
    rk4(r, r->t, left, &th, &om);
    const double stop = th < -r->range ? -r->range
                        : th > r->range ? r->range : 0;
    if (stop == 0) {
      r->theta = th;
      r->omega = om;
      r->t += left;
      return;
    }
    // The crossing, by bisection on the fraction of the step.
    double lo = 0, hi = left;
    for (int i = 0; i < 40; ++i) {
      const double mid = 0.5 * (lo + hi);
      double t2 = r->theta, w2 = r->omega;
      rk4(r, r->t, mid, &t2, &w2);
      if ((stop < 0 && t2 < stop) || (stop > 0 && t2 > stop)) hi = mid;
      else lo = mid;
    }
    double t2 = r->theta, w2 = r->omega;
    rk4(r, r->t, hi, &t2, &w2);
    r->t += hi;
    left -= hi;
    r->theta = stop;
    r->omega = -r->e * w2;
    r->bounces++;
    if (fabs(r->omega) < 1e-3) {  // bounces too small to matter: at rest
      r->omega = 0;
      r->resting = 1;
      r->t += left;
      return;
    }
  }
  r->t += left;
}
