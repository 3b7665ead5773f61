"""The memory ladder: flash, RAM and cycles per step of MemoryBenchmark's rungs,
then whole scenes and the examples beside it.

Each rung is built twice: as is, for its flash and RAM (avr-size of the ELF,
as nano-build reports them), and with BENCH_CYCLES=1, which adds Serial and the
cycle counter and prints the mean cycles of a step; that build is run in simavr.
The scenes (MemoryBenchmark with SCENE=n: the lever alone) are built and run
the same way. The examples are not built here: their rows are the figures
of their own Nano builds in extras/sizes/nano.csv (`make sizes`).

The kind column says which a row is: rung, scene or example. Beside a row
stand the goals of issue 12 where it names one (GOALS), NA elsewhere:
flash_goal for the whole sketch, flash_delta_goal for what a rung adds to
the rung below (the first rung: to the empty sketch), ram_goal for its
static RAM.
"""
import csv
import os

import runner
from runner import BENCH, REPO, log

SKETCH = os.path.join(BENCH, "MemoryBenchmark")
EXAMPLE_SIZES = os.path.join(REPO, "extras", "sizes", "nano.csv")

# In ladder order; see MemoryBenchmark/Ladder.h.
FEATURES = [
    "empty sketch",
    "world + 1 particle + gravity",
    "drag",
    "spring",
    "anchored spring",
    "bungee",
    "buoyancy",
    "stiff spring",
    "custom force",
    "rod",
    "cable",
    "planes",
    "collisions",
]

SCALARS = [(1, "Q16.16"), (2, "float")]
DIMS = [2, 3]

# Whole scenes beside the ladder: (row name, MemoryBenchmark's SCENE, dim).
# The two-worlds row's flash_delta is what it adds to the lever scene: the
# cost of a second World type (issue 12, "the shared part once").
SCENES = [("lever scene", 1, 2), ("lever + a second World type", 2, 2)]

COLUMNS = ["feature", "scalar", "dim", "flash", "ram", "flash_delta",
           "ram_delta", "cycles_per_step", "kind", "flash_goal",
           "flash_delta_goal", "ram_goal"]
GOAL_COLUMNS = COLUMNS[-3:]

# The goals of issue 12 (bytes, Nano), by (kind, feature, scalar, dim); the
# examples' by (kind, name). HapticLever's is with the Servo stand-in.
GOALS = {
    ("rung", "world + 1 particle + gravity", "Q16.16", "2"): {
        "flash_delta_goal": 1500},
    ("rung", "rod", "Q16.16", "2"): {"flash_delta_goal": 2000},
    ("scene", "lever scene", "Q16.16", "2"): {"flash_goal": 5000},
    ("scene", "lever scene", "float", "2"): {"flash_goal": 6000},
    ("example", "HapticLever"): {"flash_goal": 11000},
    ("example", "BouncingBalls"): {"flash_goal": 12000, "ram_goal": 1200},
}


# Where a goal is not met yet: the most the figure may be, so that it only
# goes down (the figure when the ceiling was set, rounded up to 64 B; lower
# it when a change makes the figure smaller, drop it once the goal is met).
CEILINGS = {
    ("rung", "rod", "Q16.16", "2"): {"flash_delta_goal": 2816},
}

# Which figure each goal column bounds.
GOAL_OF = {"flash_goal": "flash", "flash_delta_goal": "flash_delta",
           "ram_goal": "ram"}


def key_of(row):
    """The row's key in GOALS and CEILINGS."""
    if row["kind"] == "example":
        return (row["kind"], row["feature"])
    return (row["kind"], row["feature"], row["scalar"], row["dim"])


def check_goals(rows):
    """(problems, notes) of the rows built here against issue 12's goals.

    A figure above its goal is a problem, unless CEILINGS names that goal as
    not met yet: then a figure above the ceiling is, and one between the two
    a note. A goal whose row is missing, or whose figure is NA, is a problem
    too: the check must see what it checks. The examples' rows are left to
    extras/sizes/budgets.csv, which `make test` checks on fresh builds (their
    rows here come from extras/sizes/nano.csv)."""
    problems, notes = [], []
    built = dict((key_of(r), r) for r in rows if r["kind"] != "example")
    for key, goals in sorted(GOALS.items()):
        if key[0] == "example":
            continue
        name = " ".join(key[1:])
        row = built.get(key)
        if row is None:
            problems.append("%s: no row, its goal is not checked" % name)
            continue
        for column, goal in sorted(goals.items()):
            figure = GOAL_OF[column]
            try:
                value = int(row[figure])
            except ValueError:
                problems.append("%s: %s is %s" % (name, figure, row[figure]))
                continue
            ceiling = CEILINGS.get(key, {}).get(column)
            if value <= goal:
                if ceiling is not None:
                    notes.append("%s: %s %d B meets its goal (%d B): drop its "
                                 "ceiling" % (name, figure, value, goal))
                continue
            if ceiling is None:
                problems.append("%s: %s %d B, above its goal of %d B"
                                % (name, figure, value, goal))
            elif value > ceiling:
                problems.append("%s: %s %d B, above its ceiling of %d B (goal "
                                "%d B, not met yet)" % (name, figure, value,
                                                       ceiling, goal))
            else:
                notes.append("%s: %s %d B, goal %d B not met yet (ceiling %d B)"
                             % (name, figure, value, goal, ceiling))
    return problems, notes


def with_goals(row):
    """row with its kind's goal columns (NA where the issue names none)."""
    goals = GOALS.get(key_of(row), {})
    for c in GOAL_COLUMNS:
        row[c] = str(goals[c]) if c in goals else "NA"
    return row


def example_rows():
    """One row per example, from extras/sizes/nano.csv (no build here)."""
    if not os.path.exists(EXAMPLE_SIZES):
        log("%s is missing: no example rows (run `make sizes`)" % EXAMPLE_SIZES)
        return []
    with open(EXAMPLE_SIZES, newline="") as f:
        sizes = list(csv.DictReader(f))
    return [with_goals({
        "feature": r["example"], "scalar": "NA", "dim": "NA",
        "flash": r["flash"], "ram": r["ram"], "flash_delta": "NA",
        "ram_delta": "NA", "cycles_per_step": "NA", "kind": "example"})
        for r in sizes]


def run(build_root, jobs, quick=False):
    """Rows of memory.csv. quick: the rungs that issue 12's goals name and
    the first three, Q16.16 2D only, and the scenes (every scalar).

    The ladder is cumulative, so its last rungs may not fit a Nano's
    30,720 B: they are built with the builder's limit raised to the chip's
    32 KB (NANO_MAX_FLASH), measured all the same, and the table marks
    them."""
    os.environ["NANO_MAX_FLASH"] = "32768"
    # (Quick: the rod rung and the one below it, for its delta.)
    features = [0, 1, 2, 8, 9] if quick else list(range(len(FEATURES)))
    scalars = SCALARS[:1] if quick else SCALARS
    dims = DIMS[:1] if quick else DIMS
    logs = os.path.join(build_root, "logs")
    os.makedirs(logs, exist_ok=True)

    # A rung is (scalar, dim, feature); a scene (scalar, dim, "S<scene>").
    def defines(s, d, f):
        if isinstance(f, str):
            return [("SCENE", f[1:]), ("SCALAR", s), ("DIM", d)]
        return [("FEATURE", f), ("SCALAR", s), ("DIM", d)]

    def size_task(s, d, f):
        def go():
            name = "mem-s%d-d%d-f%s" % (s, d, f)
            try:
                _, flash, ram = runner.nano_build(
                    SKETCH, os.path.join(build_root, name), defines(s, d, f))
            except runner.BenchError as e:
                # The whole ladder may pass even the chip's 32 KB: NA.
                if "will not fit" not in str(e) and "overflowed" not in str(e):
                    raise
                log("MemoryBenchmark %s: does not fit the chip's 32 KB, NA" % name)
                return None, None
            return flash, ram
        return go

    def cycle_task(s, d, f):
        def go():
            if f == 0:
                return None
            name = "mem-s%d-d%d-f%s-cycles" % (s, d, f)
            try:
                elf, _, _ = runner.nano_build(
                    SKETCH, os.path.join(build_root, name),
                    defines(s, d, f) + [("BENCH_CYCLES", 1)])
            except runner.BenchError as e:
                # With Serial and the counter added, the last rungs may pass
                # the ATmega328P's 32 KB: no cycle figure (NA) for them.
                if "will not fit" not in str(e) and "overflowed" not in str(e):
                    raise
                log("MemoryBenchmark %s: does not fit the chip, cycles NA" % name)
                return None
            lines = runner.simavr_run(elf, timeout=300, log_path=os.path.join(
                logs, name + ".txt"))
            for line in lines:
                parts = line.split()
                if len(parts) == 3 and parts[0] == "R" and parts[1] == str(f):
                    return int(parts[2])
                if line.startswith("# errors") and not line.endswith(
                        "world 0 math 0"):
                    log("MemoryBenchmark %s: %s" % (name, line))
            raise runner.BenchError("MemoryBenchmark %s printed no figure" % name)
        return go

    combos = [(s, d, f) for s, _ in scalars for d in dims for f in features]
    combos += [(s, d, "S%d" % scene) for s, _ in SCALARS
               for _, scene, d in SCENES]
    tasks = [size_task(*c) for c in combos] + [cycle_task(*c) for c in combos]
    log("MemoryBenchmark: %d builds" % (len(combos) + sum(1 for c in combos if c[2])))
    results = runner.parallel(tasks, jobs)
    sizes = dict(zip(combos, results[:len(combos)]))
    cycles = dict(zip(combos, results[len(combos):]))

    rows = []
    for s, scalar in scalars:
        for d in dims:
            prev = None
            for f in features:
                flash, ram = sizes[(s, d, f)]
                c = cycles[(s, d, f)]
                # (A delta only over the rung just below: quick skips some.)
                known = (flash is not None and prev and prev[0] is not None
                         and prev[2] == f - 1)
                rows.append(with_goals({
                    "feature": FEATURES[f], "scalar": scalar, "dim": str(d),
                    "flash": str(flash) if flash is not None else "NA",
                    "ram": str(ram) if ram is not None else "NA",
                    "flash_delta": str(flash - prev[0]) if known else "NA",
                    "ram_delta": str(ram - prev[1]) if known else "NA",
                    "cycles_per_step": str(c) if c is not None else "NA",
                    "kind": "rung",
                }))
                prev = (flash, ram, f)
    for name, scene, d in SCENES:
        for s, scalar in SCALARS:
            flash, ram = sizes[(s, d, "S%d" % scene)]
            c = cycles[(s, d, "S%d" % scene)]
            # Scene 2 against scene 1 (the lever alone), as for a rung.
            base = sizes.get((s, d, "S1")) if scene == 2 else None
            known = base is not None and base[0] is not None and flash is not None
            rows.append(with_goals({
                "feature": name, "scalar": scalar, "dim": str(d),
                "flash": str(flash) if flash is not None else "NA",
                "ram": str(ram) if ram is not None else "NA",
                "flash_delta": str(flash - base[0]) if known else "NA",
                "ram_delta": str(ram - base[1]) if known else "NA",
                "cycles_per_step": str(c) if c is not None else "NA",
                "kind": "scene"}))
    return rows + example_rows()
