// The HapticLever device simulator: the sketch's ELF runs on simavr's
// ATmega328P, and this program closes the physical loop around it in
// simulated time (model.c: servo, foam and FSRs, physical lever, hand).
//
//   hil run --elf E --seconds T [options]   one scenario run (see usage())
//   hil reference --length L --seconds T [--force P] [--theta0 DEG]
//                                           the physics reference alone
//   hil sense --hand N                      the FSR readings a steady push gives
//   hil selftest                            checks of the model and reference
//
// `run` prints "result key=value" lines on stdout (simavr may print other
// lines there too) and writes CSV traces; the exit status is 0 when the
// simulation itself worked (whatever the lever did), 2 for bad usage, 3 when
// the simulated chip crashed or the firmware could not be loaded or
// measured.
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <simavr/avr_adc.h>
#include <simavr/avr_ioport.h>
#include <simavr/avr_uart.h>
#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <simavr/sim_irq.h>

#include "model.h"

#define F_CPU_HZ 16000000.0
#define CYCLES_PER_US (F_CPU_HZ / 1e6)
#define MODEL_CYCLES 400                    // 25 us model step
#define IGNORE_PULSES_CYCLES (16000000 / 50)  // the first 20 ms
#define VECTOR_TABLE_BYTES (26 * 4)         // ATmega328P

// Firmware memory layout (checked at run time, see check_memory_map()).
#define PARTICLE_BYTES 36     // Particle<Q16_16, 2>: 3 Vec2, 2 S, u16, 2 u8
#define TIMING_STEPS_PER_SECOND 6
#define TIMING_STEPS 23
#define TIMING_SLIPPED 27
// HardwareSerial of the Debian Arduino core 1.8.7: Stream (12 bytes), six
// register pointers (UCSR0A at 16, UDR0 at 22), then _written, rx head and
// tail, tx head and tail.
#define SERIAL_UCSRA_PTR 16
#define SERIAL_UDR_PTR 22
#define SERIAL_TX_HEAD 27

// The virtual lever and the push as the firmware holds them.
typedef struct {
  double x, y, vx, vy, deg, rate_deg_s, push_N;
} Virtual;

typedef struct {
  // Options.
  const char* elf;
  double seconds, length;
  int servo_pin_port, servo_pin_bit;  // 'D', 7
  double servo_phase_us;  // --servo-phase: the servo's frames this much later
  double phase_left_us;  // of the shift, still to make
  unsigned long long first_frame;  // cycle of the first accepted pulse's rise
  int profile_port, profile_bit;      // 'B', 0 (Arduino pin 8)
  FILE* trace;
  int trace_every;  // model steps per trace line
  FILE* passes_csv; // one line per pass of loop()
  FILE* uart;
  // Simulator.
  avr_t* avr;
  Device dev;
  PulseDecoder pulses;
  avr_irq_t* adc[3];
  long steps_since_trace;
  // Firmware symbols (data addresses), 0 when missing.
  uint32_t a_world, a_lever_end, a_timing, a_user_force, a_serial;
  int serial_ok;
  long tx_full_steps;
  int end_index;
  // Loop passes.
  int profile_level;
  int in_isr;
  uint16_t isr_sp;
  uint64_t isr_start, isr_cycles, isr_total;
  uint64_t last_edge;
  uint64_t pass_isr_start;
  uint32_t last_steps;
  long passes, pass_edges;
  uint64_t worst_pass, worst_pass_isr, worst_no_isr, pass_sum;
  uint64_t worst_quiet;  // worst pass that queued nothing for Serial
  uint8_t last_tx_head;
  long worst_pass_steps;
  long max_steps_per_pass, passes_no_step;
  uint64_t first_edge;
  Virtual pass_virtual;  // read at the top of the last pass of loop()
  long adc_conversions;
  long uart_bytes;
  long stalled_steps, model_steps;
  double max_abs_hand_N;
} Sim;

static Sim sim;

// ---- Firmware memory -------------------------------------------------------

static uint32_t rd32(uint32_t addr) {
  const uint8_t* d = sim.avr->data + addr;
  return (uint32_t)d[0] | ((uint32_t)d[1] << 8) | ((uint32_t)d[2] << 16) |
         ((uint32_t)d[3] << 24);
}

static double q16(uint32_t addr) { return (int32_t)rd32(addr) / 65536.0; }

static int read_virtual(Virtual* v) {
  if (!sim.a_world || !sim.a_user_force) return 0;
  // leverEnd (the end particle's address in `world`) is set by setup().
  const uint32_t p =
      sim.avr->data[sim.a_lever_end] | sim.avr->data[sim.a_lever_end + 1] << 8;
  if (p < sim.a_world || (p - sim.a_world) % PARTICLE_BYTES != 0) return 0;
  sim.end_index = (int)((p - sim.a_world) / PARTICLE_BYTES);
  if (sim.end_index > 1) return 0;
  v->x = q16(p);
  v->y = q16(p + 4);
  v->vx = q16(p + 8);
  v->vy = q16(p + 12);
  const double r2 = v->x * v->x + v->y * v->y;
  v->deg = atan2(v->y, v->x) / DEG;
  v->rate_deg_s = r2 > 0 ? (v->x * v->vy - v->y * v->vx) / r2 / DEG : 0;
  const double fx = q16(sim.a_user_force), fy = q16(sim.a_user_force + 4);
  const double dist = sqrt(r2);
  // The sketch sets userForce = push * r_s / L / dist * (-y, x).
  v->push_N = dist > 0 ? (-fx * v->y + fy * v->x) / dist /
                             sim.dev.p.sensor_radius_m * sim.length
                       : 0;
  return 1;
}

static uint32_t timing_steps(void) {
  return sim.a_timing ? rd32(sim.a_timing + TIMING_STEPS) : 0;
}

// ---- simavr hooks ----------------------------------------------------------

// Timer1's counter, through simavr's own handlers of TCNT1 (which keep its
// compare and overflow events in step with the count).
#define TCNT1L_ADDR 0x84
#define TCNT1H_ADDR 0x85

static uint16_t timer1_read(void) {
  avr_t* avr = sim.avr;
  const int io = AVR_DATA_TO_IO(TCNT1L_ADDR);
  uint8_t lo = avr->io[io].r.c ? avr->io[io].r.c(avr, TCNT1L_ADDR, avr->io[io].r.param)
                               : avr->data[TCNT1L_ADDR];
  return (uint16_t)(lo | (avr->data[TCNT1H_ADDR] << 8));
}

static void timer1_write(uint16_t count) {
  avr_t* avr = sim.avr;
  const int io = AVR_DATA_TO_IO(TCNT1L_ADDR);
  avr->data[TCNT1H_ADDR] = (uint8_t)(count >> 8);
  if (avr->io[io].w.c)
    avr->io[io].w.c(avr, TCNT1L_ADDR, (uint8_t)(count & 0xff), avr->io[io].w.param);
  else
    avr->data[TCNT1L_ADDR] = (uint8_t)(count & 0xff);
}

// The phase of the servo's 20 ms frames against the firmware's events is
// set by how long setup() and loop() happen to take, and the hand's events
// come at any phase on a real device. --servo-phase shifts it: after the
// first pulse ends, Timer1 (0.5 us a tick; the servo library's alone) is set
// back by the phase, so every later frame starts that much later. At most
// 10 ms at the end of a pulse (the next frame's compare is then at most
// 30,000 ticks ahead, and the 16-bit counter must not wrap past it), the
// rest at the end of the next.
static void shift_servo_frames(void) {
  const double us = sim.phase_left_us > 10000 ? 10000 : sim.phase_left_us;
  sim.phase_left_us -= us;
  const uint16_t ticks = (uint16_t)(us * 2 + 0.5);
  timer1_write((uint16_t)(timer1_read() - ticks));
}

static void on_servo_pin(avr_irq_t* irq, uint32_t value, void* param) {
  (void)irq;
  (void)param;
  if (!value && sim.pulses.high && sim.phase_left_us > 0) shift_servo_frames();
  if (hil_pulse_edge(&sim.pulses, sim.avr->cycle, value != 0, CYCLES_PER_US,
                     IGNORE_PULSES_CYCLES)) {
    const double servo = hil_pulse_to_servo_deg(&sim.dev.p, sim.pulses.last_us);
    sim.dev.target_deg = hil_servo_to_lever_deg(&sim.dev.p, servo);
    sim.dev.have_target = 1;
    if (sim.pulses.accepted == 1) sim.first_frame = sim.pulses.rise;
  }
}

static void on_profile_pin(avr_irq_t* irq, uint32_t value, void* param) {
  (void)irq;
  (void)param;
  // Only real changes of the pin's level count (pinMode may notify too).
  if ((value != 0) == sim.profile_level) return;
  sim.profile_level = value != 0;
  const uint64_t now = sim.avr->cycle;
  const uint32_t steps = timing_steps();
  // Interrupt cycles since the last edge (the pin is toggled by loop(), so
  // no handler is running now).
  const uint64_t isr = sim.isr_total - sim.pass_isr_start;
  if (sim.pass_edges > 0) {
    const uint64_t cycles = now - sim.last_edge;
    const long due = (long)(steps - sim.last_steps);
    sim.passes++;
    sim.pass_sum += cycles;
    if (cycles > sim.worst_pass) {
      sim.worst_pass = cycles;
      sim.worst_pass_isr = isr;
      sim.worst_pass_steps = due;
    }
    if (cycles - isr > sim.worst_no_isr) sim.worst_no_isr = cycles - isr;
    if (due > sim.max_steps_per_pass) sim.max_steps_per_pass = due;
    if (due == 0) sim.passes_no_step++;
    // Bytes the pass queued for Serial (its transmit head moved on).
    const uint8_t head =
        sim.serial_ok ? sim.avr->data[sim.a_serial + SERIAL_TX_HEAD] : 0;
    const int queued = (head - sim.last_tx_head) & 63;
    sim.last_tx_head = head;
    if (queued == 0 && cycles > sim.worst_quiet) sim.worst_quiet = cycles;
    if (sim.passes_csv) {
      fprintf(sim.passes_csv, "%.6f,%llu,%llu,%ld,%d\n", now / F_CPU_HZ,
              (unsigned long long)cycles, (unsigned long long)isr, due, queued);
    }
  } else {
    sim.first_edge = now;
    // Serial's constructor has run: check that the layout is the one
    // assumed (pointers to UCSR0A, 0xC0, and UDR0, 0xC6).
    if (sim.a_serial) {
      const uint8_t* d = sim.avr->data + sim.a_serial;
      sim.serial_ok = (d[SERIAL_UCSRA_PTR] | d[SERIAL_UCSRA_PTR + 1] << 8) == 0xC0 &&
                      (d[SERIAL_UDR_PTR] | d[SERIAL_UDR_PTR + 1] << 8) == 0xC6;
      sim.last_tx_head = d[SERIAL_TX_HEAD];
    }
  }
  // No store of the firmware is under way at the top of loop() (no
  // interrupt handler writes the lever or userForce): a consistent copy.
  Virtual v;
  memset(&v, 0, sizeof v);
  if (read_virtual(&v)) sim.pass_virtual = v;
  sim.pass_edges++;
  sim.last_edge = now;
  sim.last_steps = steps;
  sim.pass_isr_start = sim.isr_total;
}

static void on_adc_trigger(avr_irq_t* irq, uint32_t value, void* param) {
  (void)irq;
  (void)value;
  (void)param;
  sim.adc_conversions++;
}

static void on_uart(avr_irq_t* irq, uint32_t value, void* param) {
  (void)irq;
  (void)param;
  sim.uart_bytes++;
  if (sim.uart) fputc((int)(value & 0xff), sim.uart);
}

static void write_trace_line(double t) {
  // The firmware's state as it was at the top of the last pass of loop():
  // a live read may fall between the byte stores of a value (the AVR
  // writes a 32-bit number one byte at a time) and see half of each.
  const Virtual v = sim.pass_virtual;
  const Device* d = &sim.dev;
  fprintf(sim.trace,
          "%.5f,%.4f,%.4f,%.4f,%.1f,%.4f,%.2f,%.4f,%.4f,%.4f,%d,%d,%.4f,%d\n",
          t, d->mount_deg, d->lever_deg, d->have_target ? d->target_deg : 0.0,
          sim.pulses.last_us, v.deg, v.rate_deg_s, d->hand_N, d->down_N,
          d->up_N, (int)floor(hil_fsr_reading(d->down_N)),
          (int)floor(hil_fsr_reading(d->up_N)), v.push_N, d->stalled);
}

static avr_cycle_count_t model_step(avr_t* avr, avr_cycle_count_t when,
                                    void* param) {
  (void)param;
  const double h = MODEL_CYCLES / F_CPU_HZ;
  const double t = avr->cycle / F_CPU_HZ;
  hil_device_step(&sim.dev, t, h);
  sim.model_steps++;
  // The sketch's Serial transmit buffer (64 bytes, head and tail indices):
  // full means the next write() would wait for the line.
  if (sim.serial_ok) {
    const uint8_t head = avr->data[sim.a_serial + SERIAL_TX_HEAD];
    const uint8_t tail = avr->data[sim.a_serial + SERIAL_TX_HEAD + 1];
    if (((head + 1) & 63) == tail) sim.tx_full_steps++;
  }
  if (sim.dev.stalled) sim.stalled_steps++;
  if (fabs(sim.dev.hand_N) > sim.max_abs_hand_N)
    sim.max_abs_hand_N = fabs(sim.dev.hand_N);
  const HilParams* p = &sim.dev.p;
  avr_raise_irq(sim.adc[0],
                (uint32_t)hil_reading_to_mV(p, hil_fsr_reading(sim.dev.down_N)));
  avr_raise_irq(sim.adc[1],
                (uint32_t)hil_reading_to_mV(p, hil_fsr_reading(sim.dev.up_N)));
  if (sim.trace && ++sim.steps_since_trace >= sim.trace_every) {
    sim.steps_since_trace = 0;
    write_trace_line(t);
  }
  return when + MODEL_CYCLES;
}

static uint32_t find_symbol(const elf_firmware_t* fw, const char* name) {
  for (uint32_t i = 0; i < fw->symbolcount; ++i) {
    const avr_symbol_t* s = fw->symbol[i];
    if (s && strcmp(s->symbol, name) == 0) {
      uint32_t a = s->addr;
      if (a >= 0x800000) a -= 0x800000;  // data addresses in the ELF
      return a;
    }
  }
  return 0;
}

// ---- run ---------------------------------------------------------------------

static void usage(void) {
  fprintf(stderr,
          "usage:\n"
          "  hil run --elf E --seconds T [--length M] [--hand none|force|rigid|spring]\n"
          "          [--force t0:F0,t1:F1,...] [--hold DEG] [--set NAME=VALUE]...\n"
          "          [--servo-phase MS]  (the servo's frames MS later, 0..20)\n"
          "          [--trace CSV] [--trace-every STEPS] [--passes CSV] [--uart FILE]\n"
          "  hil reference --length M --seconds T [--force P] [--theta0 DEG]\n"
          "          [--trace CSV] [--h S]\n"
          "  hil sense --hand N [--set NAME=VALUE]...   (the readings a steady push gives)\n"
          "  hil selftest\n"
          "  hil params            (the baseline model parameters)\n"
          "Force profiles: newtons at the hand from each time on (+ pushes the\n"
          "physical end down, which lifts the virtual end).\n");
  exit(2);
}

static FILE* open_out(const char* path) {
  FILE* f = fopen(path, "w");
  if (!f) {
    perror(path);
    exit(2);
  }
  return f;
}

static int parse_set(HilParams* p, const char* arg) {
  char name[64];
  const char* eq = strchr(arg, '=');
  if (!eq || eq - arg >= (long)sizeof name) return 0;
  memcpy(name, arg, (size_t)(eq - arg));
  name[eq - arg] = 0;
  char* end;
  const double v = strtod(eq + 1, &end);
  if (end == eq + 1 || *end) return 0;
  return hil_params_set(p, name, v);
}

static int cmd_run(int argc, char** argv) {
  HilParams params;
  hil_params_default(&params);
  memset(&sim, 0, sizeof sim);
  sim.length = 0.23;
  sim.seconds = 2;
  sim.trace_every = 40;  // 1 ms
  int hand = HAND_NONE;
  double hold = 0;
  const char* force = NULL;
  for (int i = 2; i < argc; ++i) {
    const char* a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!v) usage();
    ++i;
    if (!strcmp(a, "--elf")) sim.elf = v;
    else if (!strcmp(a, "--seconds")) sim.seconds = atof(v);
    else if (!strcmp(a, "--length")) sim.length = atof(v);
    else if (!strcmp(a, "--servo-phase")) sim.servo_phase_us = atof(v) * 1000;
    else if (!strcmp(a, "--hold")) hold = atof(v);
    else if (!strcmp(a, "--force")) force = v;
    else if (!strcmp(a, "--trace")) sim.trace = open_out(v);
    else if (!strcmp(a, "--trace-every")) sim.trace_every = atoi(v);
    else if (!strcmp(a, "--passes")) sim.passes_csv = open_out(v);
    else if (!strcmp(a, "--uart")) sim.uart = open_out(v);
    else if (!strcmp(a, "--set")) {
      if (!parse_set(&params, v)) {
        fprintf(stderr, "hil: bad --set %s (names: hil params)\n", v);
        return 2;
      }
    } else if (!strcmp(a, "--hand")) {
      if (!strcmp(v, "none")) hand = HAND_NONE;
      else if (!strcmp(v, "force")) hand = HAND_FORCE;
      else if (!strcmp(v, "rigid")) hand = HAND_RIGID;
      else if (!strcmp(v, "spring")) hand = HAND_SPRING;
      else usage();
    } else {
      usage();
    }
  }
  if (!sim.elf || sim.seconds <= 0 || sim.trace_every < 1 ||
      sim.servo_phase_us < 0 || sim.servo_phase_us >= 20000)
    usage();
  sim.phase_left_us = sim.servo_phase_us;

  hil_device_init(&sim.dev, &params);
  sim.dev.hand = hand;
  sim.dev.hold_deg = hold;
  sim.dev.lever_deg = hand == HAND_FORCE || hand == HAND_NONE ? 0 : hold;
  if (hand == HAND_FORCE &&
      (!force || !hil_profile_parse(&sim.dev.force, force))) {
    fprintf(stderr, "hil: --hand force needs --force t0:F0,...\n");
    return 2;
  }
  // A hand that pushes from the start has already pressed the lever into
  // the foam (no ringing of the light lever from a push out of nowhere).
  if (hand == HAND_FORCE)
    sim.dev.lever_deg = hil_static_delta(&params, hil_profile_at(&sim.dev.force, 0));

  elf_firmware_t fw;
  memset(&fw, 0, sizeof fw);
  if (elf_read_firmware(sim.elf, &fw) != 0) {
    fprintf(stderr, "hil: cannot read %s\n", sim.elf);
    return 3;
  }
  // Arduino ELFs carry no .mmcu section: the chip and clock by hand.
  strcpy(fw.mmcu, "atmega328p");
  fw.frequency = (uint32_t)F_CPU_HZ;
  avr_t* avr = avr_make_mcu_by_name(fw.mmcu);
  if (!avr) {
    fprintf(stderr, "hil: simavr knows no atmega328p\n");
    return 3;
  }
  sim.avr = avr;
  avr_init(avr);
  avr->log = LOG_ERROR;
  avr_load_firmware(avr, &fw);
  avr->frequency = (uint32_t)F_CPU_HZ;
  // simavr assumes 3.3 V unless told: the Nano runs on 5 V.
  avr->vcc = avr->avcc = avr->aref = (uint32_t)params.vref_mV;

  sim.a_world = find_symbol(&fw, "world");
  sim.a_lever_end = find_symbol(&fw, "leverEnd");
  sim.a_timing = find_symbol(&fw, "timing");
  sim.a_user_force = find_symbol(&fw, "userForce");
  if (!sim.a_world || !sim.a_lever_end || !sim.a_timing || !sim.a_user_force) {
    fprintf(stderr,
            "hil: symbols world, leverEnd, timing, userForce not all found\n");
    return 3;
  }

  sim.a_serial = find_symbol(&fw, "Serial");

  // UART: capture, no console printing, no sleeping on polls.
  uint32_t flags = 0;
  avr_ioctl(avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
  flags &= ~(uint32_t)(AVR_UART_FLAG_STDIO | AVR_UART_FLAG_POLL_SLEEP);
  avr_ioctl(avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
  avr_irq_register_notify(
      avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT),
      on_uart, NULL);

  avr_irq_register_notify(
      avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('D'), IOPORT_IRQ_PIN0 + 7),
      on_servo_pin, NULL);
  avr_irq_register_notify(
      avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('B'), IOPORT_IRQ_PIN0 + 0),
      on_profile_pin, NULL);
  for (int i = 0; i < 3; ++i)
    sim.adc[i] = avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_ADC0 + i);
  avr_irq_register_notify(
      avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_OUT_TRIGGER),
      on_adc_trigger, NULL);

  // The dial: 0 V for the shortest lever, 5 V for the longest.
  double dial = (sim.length - params.short_m) / params.span_m;
  dial = dial < 0 ? 0 : (dial > 1 ? 1 : dial);
  avr_raise_irq(sim.adc[2], (uint32_t)hil_reading_to_mV(&params, dial * 1023));
  avr_raise_irq(sim.adc[0], (uint32_t)hil_reading_to_mV(
                                &params, hil_fsr_reading(params.preload_N)));
  avr_raise_irq(sim.adc[1], (uint32_t)hil_reading_to_mV(
                                &params, hil_fsr_reading(params.preload_N)));

  avr_cycle_timer_register(avr, MODEL_CYCLES, model_step, NULL);
  if (sim.trace)
    fprintf(sim.trace,
            "t,servo_deg,lever_deg,target_deg,pulse_us,virtual_deg,"
            "virtual_rate_deg_s,hand_N,fsr_down_N,fsr_up_N,adc_down,adc_up,"
            "fw_push_N,stalled\n");
  if (sim.passes_csv) fprintf(sim.passes_csv, "t,cycles,isr_cycles,steps,serial_bytes\n");

  const uint64_t end = (uint64_t)(sim.seconds * F_CPU_HZ);
  int state = cpu_Running;
  while (avr->cycle < end) {
    state = avr_run(avr);
    if (state == cpu_Done || state == cpu_Crashed) break;
    // Interrupt time: the core has just jumped to a vector when the PC
    // lands in the vector table; the handler ends when the stack pointer
    // rises above where the return address was pushed (RETI popped it).
    const uint16_t sp = (uint16_t)(avr->data[R_SPL] | (avr->data[R_SPH] << 8));
    if (!sim.in_isr) {
      if (avr->pc >= 4 && avr->pc < VECTOR_TABLE_BYTES) {
        sim.in_isr = 1;
        sim.isr_sp = sp;
        sim.isr_start = avr->cycle;
      }
    } else if (sp >= sim.isr_sp + 2) {
      sim.in_isr = 0;
      sim.isr_total += avr->cycle - sim.isr_start;
    }
  }
  if (state == cpu_Crashed) {
    fprintf(stderr, "hil: the simulated ATmega328P crashed at pc=0x%x\n",
            (unsigned)avr->pc);
    return 3;
  }

  Virtual v;
  memset(&v, 0, sizeof v);
  read_virtual(&v);
  printf("result serial_layout_ok=%d\n", sim.serial_ok);
  printf("result serial_tx_full_s=%.6f\n",
         sim.tx_full_steps * (MODEL_CYCLES / F_CPU_HZ));
  const double t_end = avr->cycle / F_CPU_HZ;
  const double run_s = (avr->cycle - sim.first_edge) / F_CPU_HZ;
  const uint32_t steps = timing_steps();
  printf("result seconds=%.4f\n", t_end);
  printf("result first_loop_s=%.6f\n", sim.first_edge / F_CPU_HZ);
  printf("result first_frame_s=%.6f\n", sim.first_frame / F_CPU_HZ);
  // Where the frames start within 20 ms of the chip's time (the last one).
  printf("result frame_phase_ms=%.3f\n",
         fmod(sim.pulses.rise / F_CPU_HZ * 1000, 20.0));
  printf("result end_index=%d\n", sim.end_index);
  printf("result virtual_radius_m=%.5f\n", sqrt(v.x * v.x + v.y * v.y));
  printf("result virtual_deg=%.4f\n", v.deg);
  printf("result servo_deg=%.4f\n", sim.dev.mount_deg);
  printf("result passes=%ld\n", sim.passes);
  printf("result worst_pass_cycles=%llu\n", (unsigned long long)sim.worst_pass);
  printf("result worst_pass_isr_cycles=%llu\n",
         (unsigned long long)sim.worst_pass_isr);
  printf("result worst_pass_steps=%ld\n", sim.worst_pass_steps);
  printf("result worst_quiet_pass_cycles=%llu\n",
         (unsigned long long)sim.worst_quiet);
  printf("result worst_pass_without_isr_cycles=%llu\n",
         (unsigned long long)sim.worst_no_isr);
  printf("result mean_pass_cycles=%.1f\n",
         sim.passes ? (double)sim.pass_sum / sim.passes : 0.0);
  printf("result isr_fraction=%.5f\n",
         (double)sim.isr_total / (double)(avr->cycle ? avr->cycle : 1));
  printf("result max_steps_per_pass=%ld\n", sim.max_steps_per_pass);
  printf("result passes_without_step=%ld\n", sim.passes_no_step);
  printf("result steps=%lu\n", (unsigned long)steps);
  printf("result slipped_steps=%lu\n",
         (unsigned long)rd32(sim.a_timing + TIMING_SLIPPED));
  printf("result steps_per_second_setting=%u\n",
         (unsigned)(sim.avr->data[sim.a_timing + TIMING_STEPS_PER_SECOND] |
                    (sim.avr->data[sim.a_timing + TIMING_STEPS_PER_SECOND + 1]
                     << 8)));
  printf("result step_rate_hz=%.3f\n", run_s > 0 ? steps / run_s : 0.0);
  printf("result adc_conversions=%ld\n", sim.adc_conversions);
  printf("result adc_conversions_per_pass=%.3f\n",
         sim.passes ? (double)sim.adc_conversions / sim.passes : 0.0);
  printf("result uart_bytes=%ld\n", sim.uart_bytes);
  printf("result pulses=%ld\n", sim.pulses.accepted);
  printf("result pulses_ignored=%ld\n", sim.pulses.ignored);
  printf("result stalled_fraction=%.5f\n",
         sim.model_steps ? (double)sim.stalled_steps / sim.model_steps : 0.0);
  printf("result max_hand_N=%.4f\n", sim.max_abs_hand_N);
  if (sim.trace) fclose(sim.trace);
  if (sim.passes_csv) fclose(sim.passes_csv);
  if (sim.uart) fclose(sim.uart);
  if (sim.pass_edges < 2 || sim.pulses.accepted == 0) {
    fprintf(stderr, "hil: no loop passes or no servo pulses were seen\n");
    return 3;
  }
  return 0;
}

// ---- reference --------------------------------------------------------------

static int cmd_reference(int argc, char** argv) {
  HilParams params;
  hil_params_default(&params);
  double length = 0.23, seconds = 2, theta0 = 0, h = 1e-5;
  const char* force = NULL;
  FILE* trace = NULL;
  for (int i = 2; i < argc; ++i) {
    const char* a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!v) usage();
    ++i;
    if (!strcmp(a, "--length")) length = atof(v);
    else if (!strcmp(a, "--seconds")) seconds = atof(v);
    else if (!strcmp(a, "--theta0")) theta0 = atof(v);
    else if (!strcmp(a, "--h")) h = atof(v);
    else if (!strcmp(a, "--force")) force = v;
    else if (!strcmp(a, "--trace")) trace = open_out(v);
    else if (!strcmp(a, "--set")) {
      if (!parse_set(&params, v)) usage();
    } else {
      usage();
    }
  }
  ForceProfile fp;
  if (force && !hil_profile_parse(&fp, force)) usage();
  Reference r;
  hil_reference_init(&r, &params, length, force ? &fp : NULL, theta0 * DEG);
  if (trace) fprintf(trace, "t,theta_deg,omega_deg_s\n");
  const long n = (long)(seconds / h + 0.5);
  const long every = (long)(1e-3 / h + 0.5);
  for (long i = 0; i <= n; ++i) {
    if (trace && i % (every ? every : 1) == 0)
      fprintf(trace, "%.5f,%.5f,%.4f\n", r.t, r.theta / DEG, r.omega / DEG);
    hil_reference_step(&r, h);
  }
  printf("result bounces=%ld\n", r.bounces);
  printf("result theta_deg=%.5f\n", r.theta / DEG);
  if (trace) fclose(trace);
  return 0;
}

// ---- sense ------------------------------------------------------------------

// The readings a steady hand force gives (the physical lever at rest where
// the pads' torque balances the hand's).
static int cmd_sense(int argc, char** argv) {
  HilParams params;
  hil_params_default(&params);
  double hand = 0;
  for (int i = 2; i < argc; ++i) {
    const char* a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!v) usage();
    ++i;
    if (!strcmp(a, "--hand")) hand = atof(v);
    else if (!strcmp(a, "--set")) {
      if (!parse_set(&params, v)) usage();
    } else {
      usage();
    }
  }
  const double delta = hil_static_delta(&params, hand);
  double down = 0, up = 0;
  hil_pad_forces(&params, delta, 0, &down, &up);
  printf("result delta_deg=%.6f\n", delta);
  printf("result down_N=%.6f\nresult up_N=%.6f\n", down, up);
  printf("result adc_down=%d\nresult adc_up=%d\n",
         (int)floor(hil_fsr_reading(down)), (int)floor(hil_fsr_reading(up)));
  return 0;
}

// ---- selftest ---------------------------------------------------------------

static int failures = 0;

static void check(int ok, const char* name, const char* fmt, double a,
                  double b) {
  printf("%s %s: ", ok ? "PASS" : "FAIL", name);
  printf(fmt, a, b);
  printf("\n");
  if (!ok) failures++;
}

static int cmd_selftest(void) {
  HilParams p;
  hil_params_default(&p);

  // Servo pulses: the Servo library's ends and centre, decoded from edges.
  {
    const double widths[] = {544, 1472, 2400}, angles[] = {0, 90, 180};
    double worst = 0;
    for (int i = 0; i < 3; ++i) {
      PulseDecoder d;
      memset(&d, 0, sizeof d);
      const unsigned long long rise = 400000;  // after the ignored 20 ms
      hil_pulse_edge(&d, rise, 1, CYCLES_PER_US, IGNORE_PULSES_CYCLES);
      hil_pulse_edge(&d, rise + (unsigned long long)(widths[i] * 16), 0,
                     CYCLES_PER_US, IGNORE_PULSES_CYCLES);
      const double err = fabs(hil_pulse_to_servo_deg(&p, d.last_us) - angles[i]);
      if (err > worst) worst = err;
    }
    check(worst <= 0.01, "servo pulse 544/1472/2400 us decodes to 0/90/180 deg",
          "worst error %.4f deg (tolerance %.2f)", worst, 0.01);
    PulseDecoder d;
    memset(&d, 0, sizeof d);
    hil_pulse_edge(&d, 1000, 1, CYCLES_PER_US, IGNORE_PULSES_CYCLES);
    hil_pulse_edge(&d, 1000 + 1500 * 16, 0, CYCLES_PER_US, IGNORE_PULSES_CYCLES);
    check(d.accepted == 0 && d.ignored == 1,
          "servo pulse in the first 20 ms is ignored", "accepted %.0f, ignored %.0f",
          (double)d.accepted, (double)d.ignored);
    check(fabs(hil_servo_to_lever_deg(&p, 90 + 32.5) - 32.5) < 1e-12,
          "servo 122.5 deg is the lever at +32.5 deg", "%.4f deg (%.0f)",
          hil_servo_to_lever_deg(&p, 122.5), 0.0);
  }

  // FSR sensor model against Table D.1.
  {
    double worst = 0;
    static const double g[] = {100, 200, 450, 900, 1500};
    static const double r[] = {415, 640, 855, 920, 950};
    for (int i = 0; i < 5; ++i) {
      const double e = fabs(hil_fsr_reading(g[i] * 9.81 / 1000) - r[i]);
      if (e > worst) worst = e;
    }
    check(worst < 1e-9, "FSR model passes through Table D.1 points",
          "worst error %.2g counts (tolerance %.0g)", worst, 1e-9);
    const double pre = hil_fsr_reading(2.0);  // 203.9 g: 640 + 3.9/50 * 65
    const double expect = 640 + (2.0 / 9.81 * 1000 - 200) / 50 * 65;
    check(fabs(pre - expect) < 0.01 && floor(pre) == 645,
          "FSR model: 2 N preload reads 645", "%.3f (expected %.3f)", pre, expect);
    int bad = -1;
    for (int reading = 0; reading <= 1023; ++reading) {
      const double mV = hil_reading_to_mV(&p, reading);
      if (floor(mV * 1023 / p.vref_mV) != reading || mV > p.vref_mV) bad = reading;
    }
    check(bad < 0, "ADC: every reading's millivolts read back as that reading",
          "first failure %.0f (of %.0f)", (double)bad, 1023.0);
    // The fit error that the firmware sees at the top of the table.
    const double fit = hil_function1_grams(950);
    check(fabs(fit - 1461.9) < 1.0, "Function 1 at 950 is the report's 1461.9 g",
          "%.1f g (expected %.1f)", fit, 1461.9);
  }

  // Foam.
  {
    double d, u;
    hil_pad_forces(&p, 0, 0, &d, &u);
    check(fabs(d - p.preload_N) < 1e-9 && fabs(u - p.preload_N) < 1e-9,
          "foam at rest: both FSRs at the preload", "%.4f N and %.4f N", d, u);
    hil_pad_forces(&p, p.full_deg, 0, &d, &u);
    check(fabs(d - p.full_N) < 1e-9 && u == 0,
          "foam at 2.8 deg: loaded side 15 N, other side unloaded",
          "%.4f N and %.4f N", d, u);
    int monotone = 1;
    double last = -1e9;
    for (double a = -4; a <= 4; a += 0.01) {
      hil_pad_forces(&p, a, 0, &d, &u);
      if (d - u < last) monotone = 0;
      last = d - u;
    }
    check(monotone, "foam: net force rises with the angle over +-4 deg",
          "%.0f of %.0f steps", monotone ? 800.0 : 0.0, 800.0);
    // A steady push: where the pads hold the lever, their torque is the
    // hand's (in the foam's soft middle, at the loaded end, and at 15 N).
    double worst = 0;
    const double hands[] = {0.3, 1.1281, 2.354, 3.0};
    for (int i = 0; i < 4; ++i) {
      hil_pad_forces(&p, hil_static_delta(&p, hands[i]), 0, &d, &u);
      const double err = fabs((d - u) * p.sensor_radius_m -
                              hands[i] * p.hand_radius_m);
      if (err > worst) worst = err;
    }
    check(worst < 1e-9, "foam: a steady push balanced (hil sense)",
          "largest torque mismatch %.2g N m (tolerance %.0g)", worst, 1e-9);
  }

  // The physics reference against small-angle results.
  {
    const double L = 0.23, g = p.gravity;
    // A pendulum: the lever hanging down (no stops), 1 degree swing.
    HilParams q = p;
    q.range_deg = 179;
    Reference r;
    hil_reference_init(&r, &q, L, NULL, (-90 + 1) * DEG);
    const double h = 1e-5;
    double last_omega = 0, first = -1, third = -1;
    int crossings = 0;
    while (r.t < 3 && crossings < 3) {
      hil_reference_step(&r, h);
      if ((last_omega < 0) != (r.omega < 0) && r.t > h) {
        ++crossings;
        if (crossings == 1) first = r.t;
        if (crossings == 3) third = r.t;
      }
      last_omega = r.omega;
    }
    const double period = third - first, expect = 2 * HIL_PI * sqrt(L / g);
    check(fabs(period / expect - 1) < 1e-3,
          "reference: small swing period is 2 pi sqrt(L/g)",
          "%.6f s (analytic %.6f s, tolerance 0.1 %%)", period, expect);
    // The start of a fall from level: theta = -g t^2 / (2 L).
    hil_reference_init(&r, &p, L, NULL, 0);
    while (r.theta > -2 * DEG) hil_reference_step(&r, h);
    const double t2 = sqrt(2 * 2 * DEG * L / g);
    check(fabs(r.t / t2 - 1) < 2e-3,
          "reference: a fall from level through 2 deg takes sqrt(2 theta L / g)",
          "%.6f s (analytic %.6f s, tolerance 0.2 %%)", r.t, t2);
    // Energy at the stop, then the bounce.
    hil_reference_init(&r, &p, L, NULL, 0);
    double before = 0;
    while (r.bounces == 0) {
      before = r.omega;
      hil_reference_step(&r, h);
    }
    const double impact = sqrt(2 * g * sin(p.range_deg * DEG) / L);
    check(fabs(fabs(before) / impact - 1) < 1e-3,
          "reference: speed at the stop from energy",
          "%.5f rad/s (analytic %.5f)", fabs(before), impact);
    check(fabs(r.omega / impact - p.restitution) < 2e-3,
          "reference: speed ratio after the bounce", "%.5f (expected %.2f)",
          r.omega / impact, p.restitution);
  }
  printf("%d failed\n", failures);
  return failures ? 1 : 0;
}

int main(int argc, char** argv) {
  if (argc < 2) usage();
  if (!strcmp(argv[1], "run")) return cmd_run(argc, argv);
  if (!strcmp(argv[1], "reference")) return cmd_reference(argc, argv);
  if (!strcmp(argv[1], "selftest")) return cmd_selftest();
  if (!strcmp(argv[1], "sense")) return cmd_sense(argc, argv);
  if (!strcmp(argv[1], "params")) {
    HilParams p;
    hil_params_default(&p);
    hil_params_print(&p, stdout);
    return 0;
  }
  usage();
  return 2;
}
