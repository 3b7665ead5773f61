"""Build sketches for the Nano, run them in simavr, in parallel.

Thin wrappers over the repository's extras/scripts/nano-build and
extras/scripts/simavr-run, plus the toolchain versions the tables name.
"""
import concurrent.futures
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
BENCH = os.path.dirname(HERE)
REPO = os.path.dirname(os.path.dirname(BENCH))
SCRIPTS = os.path.join(REPO, "extras", "scripts")
CORE = "/usr/share/arduino/hardware/arduino/avr"


class BenchError(Exception):
    pass


def log(msg):
    print("bench: " + msg, file=sys.stderr, flush=True)


def nano_build(sketch_dir, build_dir, defines=(), mega=False):
    """Compile (for a Mega 2560 with mega); return (elf path, flash bytes,
    ram bytes)."""
    cmd = [os.path.join(SCRIPTS, "nano-build")] + (["--mega"] if mega else [])
    cmd += [sketch_dir, build_dir]
    cmd += ["-D%s=%s" % (k, v) for k, v in defines]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True)
    if proc.returncode != 0:
        raise BenchError("build of %s %s failed:\n%s" % (
            os.path.basename(sketch_dir), " ".join(cmd[1:]), proc.stderr[-4000:]))
    figures = {}
    with open(os.path.join(build_dir, "nano-build.txt")) as f:
        for line in f:
            k, _, v = line.strip().partition("=")
            figures[k] = v
    return figures["elf"], int(figures["flash"]), int(figures["ram"])


def simavr_run(elf, timeout=600, until=r"^E$", log_path=None, mcu="atmega328p"):
    """Run an ELF in simavr until a line matches `until`; return its lines."""
    cmd = [os.path.join(SCRIPTS, "simavr-run"), elf, "--timeout", str(timeout),
           "--until", until, "--mcu", mcu]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True)
    if log_path:
        with open(log_path, "w") as f:
            f.write(proc.stdout)
    if proc.returncode != 0:
        raise BenchError("simavr run of %s failed (status %d):\n%s" % (
            elf, proc.returncode, proc.stderr[-2000:]))
    return proc.stdout.splitlines()


def parallel(tasks, jobs):
    """Run callables with at most `jobs` at a time; results in task order.
    On the first failure the tasks not yet started are dropped, the running
    ones finish, and that failure is raised."""
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(t) for t in tasks]
        done, _ = concurrent.futures.wait(
            futures, return_when=concurrent.futures.FIRST_EXCEPTION)
        for fut in futures:
            if fut.done() and fut.exception() is not None:
                for other in futures:
                    other.cancel()
                raise fut.exception()
        return [fut.result() for fut in futures]


def _output(cmd):
    try:
        return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                              universal_newlines=True).stdout.strip()
    except OSError:
        return ""


def toolchain():
    """Versions of what made the figures, for the table headers."""
    gcc = _output(["avr-gcc", "-dumpversion"]) or "unknown"
    simavr = _output(["dpkg-query", "-W", "-f", "${Version}", "simavr"]) or "unknown"
    core = "unknown"
    try:
        with open(os.path.join(CORE, "platform.txt")) as f:
            text = f.read()
        m = re.search(r"^version=(.*)$", text, re.M)
        n = re.search(r"^name=(.*)$", text, re.M)
        if m:
            core = "%s %s" % (n.group(1).strip() if n else "Arduino AVR Boards",
                              m.group(1).strip())
    except OSError:
        pass
    gxx = _output(["g++", "-dumpfullversion"]) or _output(["g++", "-dumpversion"])
    return {"avr-gcc": gcc, "simavr": simavr, "core": core,
            "g++": gxx or "unknown"}
