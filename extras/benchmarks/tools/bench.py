#!/usr/bin/env python3
"""Regenerate the benchmark figures: CSVs, markdown tables and plots.

    bench.py                 everything, into extras/benchmarks/ (make bench)
    bench.py --quick [--out DIR]
                             a few operations and one scene, the whole pipeline,
                             into DIR (a fresh temporary folder by default);
                             the committed outputs are left alone
    bench.py --only ops,scenes,memory,report
                             some stages (report = tables, plots, README)
    bench.py --scenes lever,chain,balls:16 [--out DIR]
                             only these scenes (every scalar, dimension and
                             step of theirs; balls:16 for one count),
                             printed as a table and written
                             to DIR/scenes.csv (a fresh temporary folder by
                             default); the committed outputs are left alone
    bench.py --baseline REV [--scenes ...] [--only ...]
                             also run the scene benchmark of commit REV (in a
                             temporary git worktree, removed afterwards) and
                             add its cycles beside this tree's in scenes.csv
                             and scenes.md (cycles_baseline, cycles_change_pct,
                             baseline; see tools/baseline.py)

Runs on the simulated Nano (simavr) through extras/scripts/nano-build and
extras/scripts/simavr-run, two at a time by default (--jobs). Raw UART logs
land in build/bench/logs/. Python standard library only; plots need gnuplot.
"""
import argparse
import csv
import os
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import baseline  # noqa: E402
import memory  # noqa: E402
import ops  # noqa: E402
import report  # noqa: E402
import runner  # noqa: E402
import scenes  # noqa: E402
from runner import BENCH, REPO, log  # noqa: E402

OPS_GROUPS = [1, 2, 3, 4, 5, 6]


def name_of(path):
    return os.path.basename(path)


def write_csv(path, columns, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, lineterminator="\n",
                           extrasaction="ignore")
        w.writeheader()
        for row in rows:
            w.writerow(row)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def run_ops(out_dir, build_root, jobs, quick):
    sketch = os.path.join(BENCH, "AutoBenchmark")
    logs = os.path.join(build_root, "logs")
    os.makedirs(logs, exist_ok=True)
    variants = [("quick", [("BENCH_QUICK", 1), ("BENCH_CHUNKS", 1)])] if quick else [
        ("g%d" % g, [("BENCH_GROUP", g)]) for g in OPS_GROUPS]

    def task(name, defines):
        def go():
            elf, flash, ram = runner.nano_build(
                sketch, os.path.join(build_root, "AutoBenchmark-" + name), defines)
            log("AutoBenchmark %s: flash %d, ram %d; running" % (name, flash, ram))
            return runner.simavr_run(elf, timeout=900, log_path=os.path.join(
                logs, "AutoBenchmark-%s.txt" % name))
        return go

    outputs = runner.parallel([task(n, d) for n, d in variants], jobs)
    rows = ops.sort_rows(ops.parse(line for out in outputs for line in out))
    if not rows:
        raise runner.BenchError("AutoBenchmark produced no figures")
    path = os.path.join(out_dir, "ops.csv")
    write_csv(path, ops.COLUMNS, rows)
    log("measured %s (%d rows)" % (name_of(path), len(rows)))
    return rows


def run_memory(out_dir, build_root, jobs, quick):
    rows = memory.run(build_root, jobs, quick)
    path = os.path.join(out_dir, "memory.csv")
    write_csv(path, memory.COLUMNS, rows)
    log("measured %s (%d rows)" % (name_of(path), len(rows)))
    # Issue 12's goals. In quick mode (`make test`) check_outputs() reports
    # and fails on the problems; here only the notes, and in full mode the
    # problems too.
    problems, notes = memory.check_goals(rows)
    for line in notes + ([] if quick else problems):
        log("size goal: " + line)
    return rows


def run_scenes(out_dir, build_root, jobs, quick, names=None, base=None):
    """base: a commit whose cycles go beside these (bench.py --baseline)."""
    commit = baseline.commit_of(base) if base else None  # fail before measuring
    rows, timeline = scenes.run(build_root, jobs, quick, names)
    columns = scenes.COLUMNS
    if commit:
        baseline.join(rows, baseline.scene_rows(
            commit, names or baseline.names_of(rows), jobs), commit)
        columns = scenes.COLUMNS + baseline.COLUMNS
    path = os.path.join(out_dir, "scenes.csv")
    write_csv(path, columns, rows)
    log("measured %s (%d rows)" % (name_of(path), len(rows)))
    if timeline:
        path = os.path.join(out_dir, "timeline.csv")
        write_csv(path, scenes.TIMELINE_COLUMNS, timeline)
        log("measured %s (%d rows)" % (name_of(path), len(timeline)))
    return rows


def check_outputs(out_dir, stages):
    """The quick check: every stage wrote well-formed figures."""
    problems = []

    def numbers(rows, columns, what):
        for r in rows:
            for c in columns:
                try:
                    v = float(r[c])
                except (KeyError, ValueError):
                    problems.append("%s: %s is %r in %r" % (what, c, r.get(c), r))
                    continue
                if not v == v or v < 0 and c.startswith("cycles"):
                    problems.append("%s: %s is %r" % (what, c, r[c]))

    expected = {"ops": ("ops.csv", ops.COLUMNS, ["cycles", "max_abs_err", "rms_err"]),
                "scenes": ("scenes.csv", scenes.COLUMNS,
                           ["cycles_per_step", "pos_err_1s", "pos_err_10s",
                            "energy_drift"]),
                "memory": ("memory.csv", memory.COLUMNS, ["flash", "ram"])}
    for stage, (name, columns, numeric) in expected.items():
        if stage not in stages:
            continue
        path = os.path.join(out_dir, name)
        if not os.path.exists(path):
            problems.append("%s is missing" % name)
            continue
        with open(path, newline="") as f:
            header = f.readline().strip().split(",")
        if header != columns:
            problems.append("%s has columns %s" % (name, header))
        rows = read_csv(path)
        if not rows:
            problems.append("%s has no rows" % name)
        numbers(rows, numeric, name)
        if stage == "memory":
            # issue 12's goals, or the ceilings of those not met yet
            problems.extend(memory.check_goals(rows)[0])
        if stage == "scenes":
            # the rigid-link columns, where the scene has rods
            numbers([r for r in rows if r["scene"] == "chain"],
                    ["max_link_err", "max_energy_err", "ref_max_link_err",
                     "ref_max_energy_err"], name)
    if "report" in stages:
        for name in ("ops.md", "scenes.md", "memory.md"):
            path = os.path.join(out_dir, name)
            if not os.path.exists(path) or "Generated, do not edit" not in open(path).read():
                problems.append("%s is missing or not marked generated" % name)
        plots = ["ops.svg", "scenes.svg"]
        scene_rows = read_csv(os.path.join(out_dir, "scenes.csv")) or []
        if any(r["scene"] == "chain" for r in scene_rows):
            plots.append("chains.svg")
        for name in plots:
            path = os.path.join(out_dir, name)
            if not os.path.exists(path) or os.path.getsize(path) < 1000:
                problems.append("%s is missing or empty" % name)
    return problems


STAGES = ["ops", "scenes", "memory", "report"]


def measure_scenes(names, out, jobs, base=None):
    """Some scenes alone: a table on stdout and scenes.csv in `out` (never
    the committed folder: a partial CSV there would disagree with the
    tables made from it)."""
    out_dir = out or tempfile.mkdtemp(prefix="tinyparticle-scenes-")
    if os.path.realpath(out_dir) == os.path.realpath(BENCH):
        log("--scenes writes a partial scenes.csv: give another --out")
        return 2
    build_root = os.path.join(REPO, "build", "bench")
    os.makedirs(out_dir, exist_ok=True)
    os.makedirs(build_root, exist_ok=True)
    try:
        rows = run_scenes(out_dir, build_root, jobs, False, names, base)
    except runner.BenchError as e:
        log("FAILED: %s" % e)
        return 1
    shown = ["scene", "scalar", "dim", "n", "dt_ms", "cycles_per_step",
             "max_link_err", "max_energy_err", "ref_max_energy_err"]
    if base:
        shown[6:] = ["cycles_baseline", "cycles_change_pct"]
        report.write(os.path.join(out_dir, "scenes.md"), report.scenes_markdown(
            rows, runner.toolchain(), False))
    print(" ".join("%-9s" % c[:9] for c in shown))
    for r in rows:
        print(" ".join("%-9s" % r[c] for c in shown))
    log("scenes.csv in %s" % out_dir)
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out", help="output folder (default: extras/benchmarks, "
                    "or a new temporary folder with --quick)")
    ap.add_argument("--only", help="comma-separated stages: " + ",".join(STAGES))
    ap.add_argument("--scenes", help="comma-separated scene names (lever, "
                    "chain, balls:16 for one count, ...): measure only these, "
                    "outside the committed outputs")
    ap.add_argument("--baseline", metavar="REV", help="a commit (hash, branch, "
                    "tag) whose scene benchmark runs beside this tree's: its "
                    "cycles per step go beside these in scenes.csv and "
                    "scenes.md")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    if args.baseline and args.quick:
        ap.error("--baseline does not go with --quick")
    if args.scenes:
        return measure_scenes(args.scenes.split(","), args.out, args.jobs,
                              args.baseline)

    stages = args.only.split(",") if args.only else STAGES
    for s in stages:
        if s not in STAGES:
            ap.error("unknown stage %r" % s)
    if args.baseline and "scenes" not in stages:
        ap.error("--baseline needs the scenes stage")
    temporary = args.quick and not args.out
    if args.quick:
        out_dir = args.out or tempfile.mkdtemp(prefix="tinyparticle-bench-")
        build_root = os.path.join(REPO, "build", "bench-quick")
    else:
        out_dir = args.out or BENCH
        build_root = os.path.join(REPO, "build", "bench")
    os.makedirs(out_dir, exist_ok=True)
    os.makedirs(build_root, exist_ok=True)
    committed = os.path.realpath(out_dir) == os.path.realpath(BENCH)

    start = time.time()
    # The measuring stages write into a staging folder; their CSVs replace the
    # ones in out_dir only once every stage asked for has succeeded, so a
    # failed run never leaves a CSV that disagrees with its tables.
    staging = tempfile.mkdtemp(prefix="tinyparticle-staging-")
    copied = False
    try:
        if "ops" in stages:
            run_ops(staging, build_root, args.jobs, args.quick)
        if "scenes" in stages:
            run_scenes(staging, build_root, args.jobs, args.quick,
                       args.scenes.split(",") if args.scenes else None,
                       args.baseline)
        if "memory" in stages:
            run_memory(staging, build_root, args.jobs, args.quick)
        for name in sorted(os.listdir(staging)):
            shutil.copyfile(os.path.join(staging, name), os.path.join(out_dir, name))
        copied = True
        if "report" in stages:
            report.generate(out_dir, runner.toolchain(), quick=args.quick,
                            update_readme=committed and not args.quick)
        if args.quick:
            problems = check_outputs(out_dir, stages)
            for p in problems:
                log("FAILED: " + p)
            if problems:
                log("outputs kept in %s" % out_dir)
                return 1
    except runner.BenchError as e:
        log("FAILED: %s" % e)
        if temporary:
            log("outputs kept in %s" % out_dir)
        elif not copied:
            log("no CSV in %s was changed" % out_dir)
        return 1
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    if temporary:
        shutil.rmtree(out_dir, ignore_errors=True)
        log("quick check passed in %.0f s" % (time.time() - start))
    else:
        log("done in %.0f s; outputs in %s" % (time.time() - start, out_dir))
    return 0


if __name__ == "__main__":
    sys.exit(main())
