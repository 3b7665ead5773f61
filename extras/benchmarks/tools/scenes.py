"""The scene benchmark: cycles per step on the Nano, errors against a
double-precision run of the same scene on the PC.

For every scene, scalar and step, SceneBenchmark is built and run in simavr;
host/SceneReference.cpp runs the same engine code with the Double scalar and
the same dt. Both report every particle's state at t = 0, 1 s and 10 s.

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

Energy: kinetic 1/2 m v^2 plus m g h (g = 9.81 m/s^2, the engine's standard
gravity) for scenes with gravity, h measured from the lowest point the scene
can reach (for the lever and the pendulum the pivot's height less the rod's
length, both read from the reference's state at t = 0; for the balls the
floor, y = 0); the spring scene (no gravity) adds 1/2 k (|x| - rest)^2 with
its anchor at the origin, k = 100 N/m and rest = 0.5 m (Scenes/Spring.hpp).
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

# (name, scene id, balls, dim, particles)
SCENES = [
    ("lever", 1, 2, 2, 2),
    ("lever", 1, 2, 3, 2),
    ("pendulum", 2, 2, 2, 2),
    ("spring", 3, 1, 2, 1),
    ("balls", 4, 2, 2, 2),
    ("balls", 4, 4, 2, 4),
    ("balls", 4, 8, 2, 8),
    ("balls", 4, 16, 2, 16),
]

# (name, SCALAR id, fraction bits or None for float)
SCALARS = [("Q16.16", 1, 16), ("Q24.8", 2, 8), ("float", 3, None)]
SHIFTS = [10, 8, 6]

COLUMNS = ["scene", "scalar", "dim", "n", "dt_ms", "cycles_per_step",
           "pos_err_1s", "pos_err_10s", "energy_drift", "cycles_last_1s",
           "ref_energy_drift", "cycles_first_300"]


def representable(frac, shift):
    return frac is None or shift <= frac


def decode(scalar, text):
    frac = dict((n, f) for n, _, f in SCALARS)[scalar]
    raw = int(text, 16)
    if frac is None:
        return struct.unpack(">f", raw.to_bytes(4, "big"))[0]
    if raw >= 1 << 31:
        raw -= 1 << 32
    return raw / float(1 << frac)


def parse_states(lines, scalar=None):
    """{t: [(index, inverse mass, position, velocity)]}, cycle sums, flags."""
    states, cycles, flags = {}, {}, None
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
        elif line.startswith("# stack headroom "):
            headroom = int(parts[3])
            if headroom < 64:
                log("warning: only %d bytes of stack were never used" % headroom)
    for t in (0, 1, 10):
        if t not in states:
            raise BenchError("scene output lacks the state at t = %d s" % t)
    return states, cycles, flags


def distance(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def energy(scene, state, reference0):
    """Total energy (J) of a state; reference0 is the reference's t = 0 state
    (for the pivot's height and the rod's length)."""
    e = 0.0
    floor = 0.0
    if scene in ("lever", "pendulum"):
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


def host_run(exe, scene_id, balls, dim, shift):
    proc = subprocess.run([exe, str(scene_id), str(balls), str(dim), str(shift)],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=300)
    if proc.returncode != 0:
        raise BenchError("host reference failed: " + proc.stderr)
    return proc.stdout.splitlines()


def run(build_root, jobs, quick=False):
    # quick: 2 balls, Q16.16, dt = 1/256 (a point of the cycles-against-N plot)
    scenes = [s for s in SCENES if s[0] == "balls" and s[2] == 2] if quick else SCENES
    scalars = SCALARS[:1] if quick else SCALARS
    shifts = [8] if quick else SHIFTS
    logs = os.path.join(build_root, "logs")
    os.makedirs(logs, exist_ok=True)
    exe = build_host(build_root)

    combos = [(sc, sl, sh) for sc in scenes for sl in scalars for sh in shifts]

    def target_task(sc, sl, sh):
        def go():
            if not representable(sl[2], sh):
                return None
            name = "scene-%s%d-n%d-%s-s%d" % (sc[0], sc[3], sc[2],
                                              sl[0].replace(".", "_"), sh)
            elf, _, _ = runner.nano_build(
                SKETCH, os.path.join(build_root, name),
                [("SCENE", sc[1]), ("BALLS", sc[2]), ("SCALAR", sl[1]),
                 ("DIM", sc[3]), ("SHIFT", sh)])
            lines = runner.simavr_run(elf, timeout=1800, log_path=os.path.join(
                logs, name + ".txt"))
            return lines
        return go

    log("SceneBenchmark: %d runs" % sum(
        1 for c in combos if representable(c[1][2], c[2])))
    outputs = runner.parallel([target_task(*c) for c in combos], jobs)

    refs = {}
    rows = []
    for (sc, sl, sh), out in zip(combos, outputs):
        name, scene_id, balls, dim, n = sc
        key = (scene_id, balls, dim, sh)
        if key not in refs:
            refs[key] = parse_states(host_run(exe, scene_id, balls, dim, sh))
        ref_states, _, ref_flags = refs[key]
        row = {"scene": name, "scalar": sl[0], "dim": str(dim), "n": str(n),
               "dt_ms": "%.4g" % (1000.0 / (1 << sh))}
        if out is None:
            for c in COLUMNS[5:]:
                row[c] = "NA"
            rows.append(row)
            continue
        states, cycles, flags = parse_states(out, sl[0])
        if flags and flags != (0, 0):
            log("%s %s %dD n=%d dt=1/%d: error flags world %d math %d" % (
                name, sl[0], dim, n, 1 << sh, flags[0], flags[1]))
        first, last = cycles.get("first"), cycles.get("last")
        row["cycles_per_step"] = "%.0f" % (first[0] / first[1]) if first else "NA"
        row["cycles_last_1s"] = "%.0f" % (last[0] / last[1]) if last else "NA"
        f300 = cycles.get("first300")
        row["cycles_first_300"] = "%.0f" % (f300[0] / f300[1]) if f300 else "NA"
        chaotic = name == "balls" and n > 2
        row["pos_err_1s"] = "NA" if chaotic else fmt(
            position_error(states[1], ref_states[1]))
        row["pos_err_10s"] = "NA" if chaotic else fmt(
            position_error(states[10], ref_states[10]))
        e0 = energy(name, states[0], ref_states[0])
        e10 = energy(name, states[10], ref_states[0])
        row["energy_drift"] = fmt((e10 - e0) / e0) if e0 else "NA"
        r0 = energy(name, ref_states[0], ref_states[0])
        r10 = energy(name, ref_states[10], ref_states[0])
        row["ref_energy_drift"] = fmt((r10 - r0) / r0) if r0 else "NA"
        rows.append(row)
    return rows
