# TinyParticle: build, test and run everything on a simulated Arduino Nano.
#
#   make demo     build an example for the Nano and run it in simavr
#   make test     every check, host test, target test and example build
#
# More in README.md ("Commands"). Each target first checks its Debian packages
# (extras/scripts/setup-packages): as root it installs what is missing,
# otherwise it prints the apt-get line to run. Then it builds arduino-cli,
# once, outside the repository (extras/scripts/arduino-cli-setup).

SCRIPTS := extras/scripts
DEMO_SECONDS ?= 8
JOBS ?= 2
# The demo example (DEMO=examples/Name runs another one).
DEMO ?= examples/BouncingBalls

.PHONY: help setup demo test test-host test-target checks sizes bench bench-quick hil verify-asm fuzz stability clean

help:
	@sed -n '3,4p' Makefile | sed 's/^# *//'
	@echo "More commands: see README.md"

setup:
	@$(SCRIPTS)/setup-packages all

# Builds $(DEMO) and shows its Serial output live; simavr is stopped after
# DEMO_SECONDS seconds of wall time (the usual way a demo ends).
demo:
	@$(SCRIPTS)/setup-packages demo
	@elf=$$($(SCRIPTS)/nano-build $(DEMO) build/nano/$(DEMO)) && \
	echo "Running $(DEMO) on a simulated ATmega328P for $(DEMO_SECONDS) s (Ctrl-C stops it)" && \
	$(SCRIPTS)/simavr-run "$$elf" --timeout $(DEMO_SECONDS) --timeout-ok --ansi

test:
	@$(SCRIPTS)/setup-packages test
	@$(SCRIPTS)/run-tests --jobs $(JOBS)

test-host:
	@$(SCRIPTS)/setup-packages test
	@$(SCRIPTS)/run-tests --jobs $(JOBS) --only host

test-target:
	@$(SCRIPTS)/setup-packages test
	@$(SCRIPTS)/run-tests --jobs $(JOBS) --only target

checks:
	@$(SCRIPTS)/setup-packages test
	@$(SCRIPTS)/run-tests --jobs $(JOBS) --only checks

sizes:
	@$(SCRIPTS)/setup-packages demo
	@$(SCRIPTS)/run-tests --jobs $(JOBS) --only examples

# Where a sketch's flash goes, by part of the library (extras/scripts/size-report).
SKETCH ?= $(DEMO)
.PHONY: size-report
size-report:
	@$(SCRIPTS)/setup-packages demo
	@$(SCRIPTS)/size-report $(SKETCH)

# Benchmarks live in extras/benchmarks (their Makefile does the work).
bench:
	@$(SCRIPTS)/setup-packages bench
	@if [ -f extras/benchmarks/Makefile ]; then $(MAKE) --no-print-directory -C extras/benchmarks; \
	else echo "bench: extras/benchmarks/Makefile does not exist yet"; exit 1; fi

# The whole benchmark pipeline on a few operations and one scene, into a
# temporary folder (committed figures untouched): a check step of `make test`.
bench-quick:
	@$(SCRIPTS)/setup-packages bench
	@$(MAKE) --no-print-directory -C extras/benchmarks quick

# The HapticLever device simulator (extras/hil): every scenario, the results
# table, CSV traces and plots. Exits 0 when device goals fail (they are
# goals), non-zero when the simulator itself breaks. Its self-checks run in
# `make test` (kind "hil" of extras/scripts/run-tests).
hil:
	@$(SCRIPTS)/setup-packages hil
	@$(MAKE) --no-print-directory -C extras/hil

# The AVR assembly against the portable reference, by input class, on simavr
# (extras/verify-asm/README.md). Long: shards run JOBS at a time.
verify-asm:
	@$(SCRIPTS)/setup-packages test
	@$(SCRIPTS)/verify-asm --jobs $(JOBS) $(VERIFY_ASM_FLAGS)

# The world fuzzer (extras/fuzz) for FUZZ_SECONDS (default 300) seconds;
# its corpus stays in build/fuzz/corpus, findings in build/fuzz/crash-*.
fuzz:
	@$(SCRIPTS)/setup-packages fuzz
	@$(MAKE) --no-print-directory -C extras/fuzz run

# The stability suite (extras/test/StabilitySuite*Test) on the host and the
# simulated Nano, then its table: extras/stability/results.csv and
# extras/stability/README.md.
stability:
	@$(SCRIPTS)/setup-packages test
	@$(SCRIPTS)/run-tests --jobs $(JOBS) --only host,target --filter StabilitySuite; \
	status=$$?; extras/stability/collect && exit $$status

clean:
	rm -rf build
	@$(MAKE) --no-print-directory -C extras/test clean
