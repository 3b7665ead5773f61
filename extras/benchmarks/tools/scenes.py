"""The scene benchmark: cycles per step on the Nano, errors against a
double-precision run of the same scene on the PC.

For every scene, scalar and step, SceneBenchmark is built and run in simavr
(the chain of 16 beads on a simulated ATmega2560: it does not fit the Nano's
RAM); host/SceneReference.cpp runs the same engine code with the Double
scalar and the same dt. Both report every particle's state at t = 0, 1 s and
10 s, and the largest link and energy errors over the whole run.

  pos_err_1s, pos_err_10s  the largest distance (m) between a particle's
                           position on the Nano and in the reference; NA for
                           the chaotic scenes (more than 2 balls)
  energy_drift             (E(10 s) - E(0)) / E(0) of the Nano's run, energies
                           computed in double from the states it reported
  ref_energy_drift         the same for the reference run: what the physics
                           and the integrator do without rounding (the balls
                           lose energy in every bounce, restitution 0.8)
  cycles_per_step          mean over the first 2 s of scene time
  cycles_last_1s           mean over the last second (9 s to 10 s): the
                           settled state, e.g. the pile of balls
  cycles_first_300         mean over the first 300 steps (how the engine
                           issue states its lever goal)
  (timeline.csv)           the mean over every eighth of a second of the 16
                           balls and the pile at dt = 1/256 s, for the
                           cycles-against-time plot
  max_link_err             the largest |length / L - 1| of any rod over the
                           run, on the target; ref_max_link_err the same in
                           the reference
  max_energy_err           the largest |E(t) - E(0)| over the run, in units
                           of the scene's reference energy (below), on the
                           target; ref_max_energy_err in the reference; NA
                           for the balls and the rope (they lose energy by
                           design)
  seconds                  the run's length (scene time)
  board                    nano (ATmega328P) or mega (ATmega2560), both 16 MHz

n counts the particles, the fixed ones included, except for the chain and
the rope, where it counts the beads (the rope has two posts more, the chain
its pivot).

Contact scenes (issue 10): pile, 16 balls released side by side 1 cm above
the floor of the box, without sleeping (what resting contacts cost each
step; the balls scene sleeps once settled); elastic_box, the 16 balls with
restitution 1 and no gravity (its reference energy: the kinetic energy at
the start); cradle, Newton's cradle (the first ball's drop m g L (1 - cos
60 degrees), 0.1 kg, 0.5 m).

Reference energies (what max_energy_err is divided by): the chain of N
beads, E_fall = m g 0.125 N (N + 1) / 2 (m = 0.05 kg: from level to
hanging); the pendulums, their swing m g L (1 - cos theta0); the lever,
m g L (0.1 kg, 0.15 m, from level); the spring, k (0.1 m)^2 / 2. E(t) is
computed after every step, in float on the target and in double on the PC.

Energy: kinetic 1/2 m v^2 plus m g h (g = 9.81 m/s^2, the engine's standard
gravity) for scenes with gravity, h measured from the lowest point the scene
can reach (for the lever and the pendulum the pivot's height less the rod's
length, both read from the reference's state at t = 0; for the balls the
floor, y = 0); the spring scene (no gravity) adds 1/2 k (|x| - rest)^2 with
its anchor at the origin, k = 100 N/m and rest = 0.5 m (Scenes/Spring.hpp).
The chains and the short pendulum give their drift in their reference
energy, (E(10 s) - E(0)) / E_ref; the rope's is NA.
"""
import math
import os
import struct
import subprocess

import runner
from runner import BENCH, REPO, BenchError, log

SKETCH = os.path.join(BENCH, "SceneBenchmark")
HOST_SOURCE = os.path.join(BENCH, "host", "SceneReference.cpp")

G = 9.81
SPRING_K = 100.0
SPRING_REST = 0.5

# (name, SCALAR id, fraction bits or None for float)
SCALARS = [("Q16.16", 1, 16), ("Q24.8", 2, 8), ("float", 3, None)]
Q16, FLOAT = SCALARS[0], SCALARS[2]
RATES = [1024, 256, 64]
# The pendulum's step-rate sweep (60 s each).
SWEEP_RATES = [128, 200, 256, 300, 400, 500, 600, 700, 800, 1000, 1024, 2048]


class Scene(object):
    """One scene of the benchmark and the runs it gets."""

    def __init__(self, name, scene_id, count, dim, n, scalars=SCALARS,
                 rates=RATES, seconds=10, board="nano", quick=False):
        self.name, self.scene_id, self.count, self.dim, self.n = (
            name, scene_id, count, dim, n)
        self.scalars, self.rates, self.seconds, self.board = (
            scalars, rates, seconds, board)
        self.quick = quick


def chain_energy(beads):
    return 0.05 * G * 0.125 * beads * (beads + 1) / 2


# count: the balls or the chain's beads (SceneBenchmark's BALLS)
SCENES = [
    Scene("lever", 1, 2, 2, 2),
    Scene("lever", 1, 2, 3, 2),
    Scene("pendulum", 2, 2, 2, 2),
    Scene("spring", 3, 1, 2, 1),
    Scene("balls", 4, 2, 2, 2, quick=True),
    Scene("balls", 4, 4, 2, 4),
    Scene("balls", 4, 8, 2, 8),
    Scene("balls", 4, 16, 2, 16),
    Scene("chain", 5, 2, 2, 2, [Q16, FLOAT], [1024, 256], quick=True),
    Scene("chain", 5, 4, 2, 4, [Q16, FLOAT], [1024, 256]),
    Scene("chain", 5, 8, 2, 8, [Q16, FLOAT], [1024, 256]),
    # The chain of 8 again on the Mega, so that the doubling from 8 to 16 is
    # measured on one chip (the Mega's calls take a cycle more: ~1 %).
    Scene("chain", 5, 8, 2, 8, [Q16, FLOAT], [1024, 256], board="mega"),
    Scene("chain", 5, 16, 2, 16, [Q16, FLOAT], [1024, 256], board="mega"),
    Scene("rope", 6, 7, 2, 7, [Q16, FLOAT], [256], seconds=20),
    Scene("pendulum_short", 7, 2, 2, 2, [Q16, FLOAT], [256]),
    Scene("pendulum_sweep", 2, 2, 2, 2, [Q16, FLOAT], SWEEP_RATES, seconds=60),
    Scene("pile", 8, 16, 2, 16, [Q16, FLOAT], [256]),
    Scene("elastic_box", 9, 16, 2, 16, [Q16, FLOAT], [256]),
    Scene("cradle", 10, 5, 2, 5, [Q16, FLOAT], [1024, 256]),
]

# The runs whose cycles per eighth of a second go to timeline.csv (and the
# cycles-against-time plot): the 16 balls and the pile at dt = 1/256 s.
TIMELINE_SCENES = ("balls", "pile")
TIMELINE_COLUMNS = ["scene", "scalar", "n", "dt_ms", "t", "cycles_per_step"]

# The reference energy of each scene (J) for the drift of the new scenes and
# for max_energy_err (the sketch divides by the same figures).
REFERENCE_ENERGY = {
    "chain": lambda sc: chain_energy(sc.count),
    "pendulum_short": lambda sc: 0.1 * G * 0.05 * (1 - math.cos(0.5)),
    "pendulum_sweep": lambda sc: 1.0 * G * 1.0 * (1 - math.cos(0.5)),
    "cradle": lambda sc: 0.1 * G * 0.5 * (1 - math.cos(math.pi / 3)),
}

COLUMNS = ["scene", "scalar", "dim", "n", "dt_ms", "cycles_per_step",
           "pos_err_1s", "pos_err_10s", "energy_drift", "cycles_last_1s",
           "ref_energy_drift", "cycles_first_300", "max_link_err",
           "max_energy_err", "ref_max_link_err", "ref_max_energy_err",
           "seconds", "board"]


def representable(frac, rate):
    """Whether the scalar has a step for this rate: at least one unit. It is
    the scalar's own 1 / rate, rounded (Q16.16: 66 units of 2^-16 s for
    1/1000 s, 0.7 % long)."""
    return frac is None or (1 << frac) >= rate


def decode(scalar, text):
    frac = dict((n, f) for n, _, f in SCALARS)[scalar]
    raw = int(text, 16)
    if frac is None:
        return struct.unpack(">f", raw.to_bytes(4, "big"))[0]
    if raw >= 1 << 31:
        raw -= 1 << 32
    return raw / float(1 << frac)


def parse_timeline(lines):
    """[(t at the end of the eighth, mean cycles per step)] from "C" lines."""
    out = []
    for line in lines:
        parts = line.split()
        if len(parts) == 4 and parts[0] == "C":
            k, cycles, steps = int(parts[1]), int(parts[2]), int(parts[3])
            if steps:
                out.append(((k + 1) / 8.0, cycles / float(steps)))
    return out


def parse_states(lines, scalar=None):
    """{t: [(index, inverse mass, position, velocity)]}, cycle sums, flags,
    (largest link error, largest energy error or None)."""
    states, cycles, flags, errors = {}, {}, None, None
    for line in lines:
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "P":
            t, i = int(parts[1]), int(parts[2])
            vals = parts[3:]
            if scalar is None:
                vals = [float(v) for v in vals]
            else:
                vals = [decode(scalar, v) for v in vals]
            d = (len(vals) - 1) // 2
            states.setdefault(t, []).append(
                (i, vals[0], vals[1:1 + d], vals[1 + d:1 + 2 * d]))
        elif parts[0] == "T":
            cycles[parts[1]] = (int(parts[2]), int(parts[3]))
        elif parts[0] == "W":
            flags = (int(parts[1]), int(parts[2]))
        elif parts[0] == "M":
            if scalar is None:
                errors = (float(parts[1]), float(parts[2]))
            else:
                errors = tuple(decode("float", v) for v in parts[1:3])
        elif line.startswith("# stack headroom "):
            headroom = int(parts[3])
            if headroom < 64:
                log("warning: only %d bytes of stack were never used" % headroom)
    for t in (0, 1, 10):
        if t not in states:
            raise BenchError("scene output lacks the state at t = %d s" % t)
    if errors is not None and errors[1] < 0:
        errors = (errors[0], None)
    return states, cycles, flags, errors


def distance(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def energy(scene, state, reference0):
    """Total energy (J) of a state; reference0 is the reference's t = 0 state
    (for the pivot's height and the rod's length)."""
    e = 0.0
    floor = 0.0
    if scene in ("lever", "pendulum", "pendulum_sweep", "pendulum_short"):
        pivot = [p for p in reference0 if p[1] == 0][0]
        bob = [p for p in reference0 if p[1] != 0][0]
        floor = pivot[2][1] - distance(pivot[2], bob[2])
    for _, inv_mass, pos, vel in state:
        if inv_mass == 0:
            continue
        m = 1.0 / inv_mass
        e += 0.5 * m * sum(v * v for v in vel)
        if scene == "spring":
            stretch = math.sqrt(sum(x * x for x in pos)) - SPRING_REST
            e += 0.5 * SPRING_K * stretch * stretch
        elif scene == "elastic_box":
            pass  # no gravity
        else:
            e += m * G * (pos[1] - floor)
    return e


def position_error(state, reference):
    ref = dict((p[0], p[2]) for p in reference)
    return max(distance(pos, ref[i]) for i, _, pos, _ in state)


def fmt(v, digits=3):
    if v is None:
        return "NA"
    return "%.*g" % (digits, v)


def build_host(build_root):
    exe = os.path.join(build_root, "SceneReference")
    cmd = ["g++", "-std=c++11", "-O2", "-Wall", "-Wextra", "-Werror", "-pedantic",
           "-I", os.path.join(REPO, "src"), "-I", os.path.join(BENCH, "host"),
           "-I", SKETCH, HOST_SOURCE, "-o", exe]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True)
    if proc.returncode != 0:
        raise BenchError("host reference build failed:\n" + proc.stdout[-4000:])
    return exe


def host_run(exe, sc, rate):
    proc = subprocess.run([exe, str(sc.scene_id), str(sc.count), str(sc.dim),
                           str(rate), str(sc.seconds)],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=600)
    if proc.returncode != 0:
        raise BenchError("host reference failed: " + proc.stderr)
    return proc.stdout.splitlines()


def run(build_root, jobs, quick=False, names=None):
    """(rows, timeline rows). names: only the scenes of these names."""
    # quick: 2 balls and a chain of 2, Q16.16, dt = 1/256 (a point of the
    # cycles-against-N plots, and every column); names: only these scenes
    scenes = [s for s in SCENES if s.quick] if quick else SCENES
    if names:  # "balls", or "balls:16" for one count
        unknown = set(n.split(":")[0] for n in names) - set(s.name for s in SCENES)
        if unknown:
            raise BenchError("no such scene: %s" % ", ".join(sorted(unknown)))
        scenes = [s for s in scenes if s.name in names
                  or "%s:%d" % (s.name, s.count) in names]
    logs = os.path.join(build_root, "logs")
    os.makedirs(logs, exist_ok=True)
    exe = build_host(build_root)

    combos = [(sc, sl, rate) for sc in scenes
              for sl in (sc.scalars[:1] if quick else sc.scalars)
              for rate in ([256] if quick else sc.rates)]

    def target_task(sc, sl, rate):
        def go():
            if not representable(sl[2], rate):
                return None
            name = "scene-%s%d-n%d-%s-r%d-t%d%s" % (
                sc.name, sc.dim, sc.count, sl[0].replace(".", "_"), rate,
                sc.seconds, "-mega" if sc.board == "mega" else "")
            elf, _, _ = runner.nano_build(
                SKETCH, os.path.join(build_root, name),
                [("SCENE", sc.scene_id), ("BALLS", sc.count), ("SCALAR", sl[1]),
                 ("DIM", sc.dim), ("RATE", rate), ("SECONDS", sc.seconds)],
                mega=sc.board == "mega")
            lines = runner.simavr_run(elf, timeout=1800, log_path=os.path.join(
                logs, name + ".txt"), mcu="atmega2560" if sc.board == "mega"
                else "atmega328p")
            return lines
        return go

    # The harness (state printing, error checks) comes on top of the scene:
    # the largest builds pass a Nano's 30,720 B by a few hundred bytes, so
    # they are built against the chip's whole 32 KB (no bootloader in
    # simavr); the cycles are the scene's either way.
    os.environ["NANO_MAX_FLASH"] = "32768"
    log("SceneBenchmark: %d runs" % sum(
        1 for c in combos if representable(c[1][2], c[2])))
    outputs = runner.parallel([target_task(*c) for c in combos], jobs)

    refs = {}
    rows = []
    timeline = []
    for (sc, sl, rate), out in zip(combos, outputs):
        name, n = sc.name, sc.n
        key = (sc.scene_id, sc.count, sc.dim, rate, sc.seconds)
        if key not in refs:
            refs[key] = parse_states(host_run(exe, sc, rate))
        ref_states, _, ref_flags, ref_errors = refs[key]
        row = {"scene": name, "scalar": sl[0], "dim": str(sc.dim), "n": str(n),
               "dt_ms": "%.4g" % (1000.0 / rate), "seconds": str(sc.seconds),
               "board": sc.board}
        if out is None:
            for c in COLUMNS[5:-2]:
                row[c] = "NA"
            rows.append(row)
            continue
        states, cycles, flags, errors = parse_states(out, sl[0])
        if name in TIMELINE_SCENES and rate == 256 and sc.count == 16:
            for t, c in parse_timeline(out):
                timeline.append({"scene": name, "scalar": sl[0], "n": str(n),
                                 "dt_ms": row["dt_ms"], "t": "%g" % t,
                                 "cycles_per_step": "%.0f" % c})
        if flags and flags != (0, 0):
            log("%s %s %dD n=%d dt=1/%d: error flags world %d math %d" % (
                name, sl[0], sc.dim, n, rate, flags[0], flags[1]))
        first, last = cycles.get("first"), cycles.get("last")
        row["cycles_per_step"] = "%.0f" % (first[0] / first[1]) if first else "NA"
        row["cycles_last_1s"] = "%.0f" % (last[0] / last[1]) if last else "NA"
        f300 = cycles.get("first300")
        row["cycles_first_300"] = "%.0f" % (f300[0] / f300[1]) if f300 else "NA"
        chaotic = name in ("balls", "elastic_box") and n > 2
        row["pos_err_1s"] = "NA" if chaotic else fmt(
            position_error(states[1], ref_states[1]))
        row["pos_err_10s"] = "NA" if chaotic else fmt(
            position_error(states[10], ref_states[10]))
        e0 = energy(name, states[0], ref_states[0])
        e10 = energy(name, states[10], ref_states[0])
        r0 = energy(name, ref_states[0], ref_states[0])
        r10 = energy(name, ref_states[10], ref_states[0])
        if name == "rope":
            row["energy_drift"] = row["ref_energy_drift"] = "NA"
        elif name in REFERENCE_ENERGY:
            scale = REFERENCE_ENERGY[name](sc)
            row["energy_drift"] = fmt((e10 - e0) / scale)
            row["ref_energy_drift"] = fmt((r10 - r0) / scale)
        else:
            row["energy_drift"] = fmt((e10 - e0) / e0) if e0 else "NA"
            row["ref_energy_drift"] = fmt((r10 - r0) / r0) if r0 else "NA"
        for prefix, errs in (("", errors), ("ref_", ref_errors)):
            link, en = errs if errs else (None, None)
            row[prefix + "max_link_err"] = fmt(link) if (
                link is not None and sc.name not in (
                    "balls", "spring", "pile", "elastic_box")) else "NA"
            row[prefix + "max_energy_err"] = fmt(en)
        rows.append(row)
    return rows, timeline
