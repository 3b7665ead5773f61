"""The memory ladder: flash, RAM and cycles per step of MemoryBenchmark's rungs.

Each rung is built twice: as is, for its flash and RAM (avr-size of the ELF,
as nano-build reports them), and with BENCH_CYCLES=1, which adds Serial and the
cycle counter and prints the mean cycles of a step; that build is run in simavr.
"""
import os

import runner
from runner import BENCH, log

SKETCH = os.path.join(BENCH, "MemoryBenchmark")

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

COLUMNS = ["feature", "scalar", "dim", "flash", "ram", "flash_delta",
           "ram_delta", "cycles_per_step"]


def run(build_root, jobs, quick=False):
    """Rows of memory.csv. quick: the first three rungs, Q16.16 2D only.

    The ladder is cumulative, so its last rungs may not fit a Nano's
    30,720 B: they are built with the builder's limit raised to the chip's
    32 KB (NANO_MAX_FLASH), measured all the same, and the table marks
    them."""
    os.environ["NANO_MAX_FLASH"] = "32768"
    features = list(range(3)) if quick else list(range(len(FEATURES)))
    scalars = SCALARS[:1] if quick else SCALARS
    dims = DIMS[:1] if quick else DIMS
    logs = os.path.join(build_root, "logs")
    os.makedirs(logs, exist_ok=True)

    def size_task(s, d, f):
        def go():
            name = "mem-s%d-d%d-f%d" % (s, d, f)
            try:
                _, flash, ram = runner.nano_build(
                    SKETCH, os.path.join(build_root, name),
                    [("FEATURE", f), ("SCALAR", s), ("DIM", d)])
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
            name = "mem-s%d-d%d-f%d-cycles" % (s, d, f)
            try:
                elf, _, _ = runner.nano_build(
                    SKETCH, os.path.join(build_root, name),
                    [("FEATURE", f), ("SCALAR", s), ("DIM", d),
                     ("BENCH_CYCLES", 1)])
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
                known = flash is not None and prev and prev[0] is not None
                rows.append({
                    "feature": FEATURES[f], "scalar": scalar, "dim": str(d),
                    "flash": str(flash) if flash is not None else "NA",
                    "ram": str(ram) if ram is not None else "NA",
                    "flash_delta": str(flash - prev[0]) if known else "NA",
                    "ram_delta": str(ram - prev[1]) if known else "NA",
                    "cycles_per_step": str(c) if c is not None else "NA",
                })
                prev = (flash, ram)
    return rows
