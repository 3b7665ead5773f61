"""Cycles of the same scenes at another commit, beside this tree's.

bench.py --baseline REV checks a change's cost in time: REV's own scene
benchmark (its sketch, its library, its tools) runs in a temporary git
worktree of REV, removed afterwards, and its cycles per step join the rows
of this tree's scenes.csv that match on scene, scalar, dim, n, dt_ms and
seconds:

  cycles_baseline    REV's cycles_per_step (NA: REV has no such row, or it
                     is NA there)
  cycles_change_pct  (cycles_per_step - cycles_baseline) / cycles_baseline,
                     in %: positive is slower than REV
  baseline           REV as a short commit hash

REV must be able to run `tools/bench.py --scenes` itself (every commit since
that option came does).

A commit's cycles do not change while the toolchain does not (simavr counts
cycles exactly), so REV's rows are kept in build/bench/baseline/, named by
the commit, the scene names and the toolchain's versions, and a later run
with the same three reads them instead of measuring again (delete the
folder to measure anew).
"""
import csv
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile

from runner import REPO, BenchError, log, toolchain

COLUMNS = ["cycles_baseline", "cycles_change_pct", "baseline"]
KEY = ("scene", "scalar", "dim", "n", "dt_ms", "seconds", "board")


def git(*args):
    proc = subprocess.run(["git", "-C", REPO] + list(args), stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True)
    if proc.returncode != 0:
        raise BenchError("git %s failed: %s" % (" ".join(args), proc.stderr.strip()))
    return proc.stdout.strip()


def commit_of(rev):
    """REV as a short commit hash; a BenchError if git does not know it."""
    return git("rev-parse", "--short", "--verify", rev + "^{commit}")


def cache_path(commit, names):
    """Where REV's rows for these names are kept (see the top of this file)."""
    key = repr((git("rev-parse", "--verify", commit + "^{commit}"),
                sorted(names), sorted(toolchain().items())))
    digest = hashlib.sha1(key.encode("utf-8")).hexdigest()[:16]
    return os.path.join(REPO, "build", "bench", "baseline",
                        "%s-%s.csv" % (commit, digest))


def scene_rows(rev, names, jobs):
    """scenes.csv rows of REV for these scene names (bench.py --scenes
    spelling), measured in a temporary worktree of REV, or read from the
    rows kept by an earlier run."""
    commit = commit_of(rev)
    kept = cache_path(commit, names)
    if os.path.exists(kept):
        log("baseline %s: its rows kept in %s" % (commit, os.path.relpath(kept, REPO)))
        with open(kept, newline="") as f:
            return list(csv.DictReader(f))
    rows = measure(commit, names, jobs)
    os.makedirs(os.path.dirname(kept), exist_ok=True)
    with open(kept + ".tmp", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()) if rows else [])
        w.writeheader()
        w.writerows(rows)
    os.replace(kept + ".tmp", kept)
    return rows


def measure(commit, names, jobs):
    """REV's rows, from its own scene benchmark in a temporary worktree."""
    tmp = tempfile.mkdtemp(prefix="tinyparticle-baseline-")
    tree = os.path.join(tmp, "tree")
    out = os.path.join(tmp, "out")
    git("worktree", "add", "--detach", tree, commit)
    try:
        tool = os.path.join(tree, "extras", "benchmarks", "tools", "bench.py")
        cmd = [sys.executable, tool, "--scenes", ",".join(names), "--out", out,
               "--jobs", str(jobs)]
        log("baseline %s: its own scene benchmark in %s" % (commit, tree))
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True)
        if proc.returncode != 0:
            raise BenchError("the scene benchmark of %s failed:\n%s" % (
                commit, proc.stderr[-4000:]))
        with open(os.path.join(out, "scenes.csv"), newline="") as f:
            return list(csv.DictReader(f))
    finally:
        # A worktree left behind would hold REV checked out: always remove it.
        subprocess.run(["git", "-C", REPO, "worktree", "remove", "--force", tree],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        subprocess.run(["git", "-C", REPO, "worktree", "prune"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        shutil.rmtree(tmp, ignore_errors=True)


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def join(rows, base_rows, commit):
    """Add the COLUMNS to rows (in place) from REV's rows."""
    base = dict((tuple(r.get(k) for k in KEY), r) for r in base_rows)
    for r in rows:
        b = base.get(tuple(r.get(k) for k in KEY))
        now = number(r.get("cycles_per_step"))
        then = number(b.get("cycles_per_step")) if b else None
        r["cycles_baseline"] = "%.0f" % then if then is not None else "NA"
        change = None
        if now is not None and then:
            # rounded first, so that -0.04 % reads 0.0, not -0.0
            change = round(1000.0 * (now - then) / then) / 10.0 + 0.0
        r["cycles_change_pct"] = "%.1f" % change if change is not None else "NA"
        r["baseline"] = commit
    missing = sum(1 for r in rows if r["cycles_baseline"] == "NA"
                  and number(r.get("cycles_per_step")) is not None)
    if missing:
        log("baseline %s: no cycles for %d of the rows" % (commit, missing))
    return rows


def names_of(rows):
    """The --scenes names that cover these rows (every count of each)."""
    names = []
    for r in rows:
        if r["scene"] not in names:
            names.append(r["scene"])
    return names
