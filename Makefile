# laserax — top-level entry points. Every target works on a fresh Debian machine: each one first
# checks the tools it needs (scripts/setup_deps.sh PROFILE) and installs what is missing (as root)
# or prints the apt command to run; `deps` checks everything. `run` and `vectors` build only the
# laserax program, `bench` only bench; `build` and `test` build every target.
#
#   make deps | build | run [ARGS=...] | test | soak | fuzz | bench | vectors | plot | synth | synth-sweep | formal | clean
#
# Variables: BUILD_DIR (build), ASAN_DIR (build-asan), BUILD_TYPE (Release), JOBS (2),
#            ARGS (arguments after `laserax run`), ASAN=0 (make test without the sanitizer pass),
#            CMAKE_ARGS (extra -D options for the main build).
SHELL      := /bin/bash
BUILD_DIR  ?= build
ASAN_DIR   ?= build-asan
BUILD_TYPE ?= Release
JOBS       ?= 2
ARGS       ?=
ASAN       ?= 1
CMAKE_ARGS ?=
PYTHON     := /usr/bin/python3
OUT        := out
MAKEFLAGS  += --no-print-directory

.PHONY: all help deps build run test soak fuzz bench vectors plot formal clean

all: build

help:
	@sed -n '1,10p' Makefile | sed 's/^# \{0,1\}//'

# deps PROFILE: build (compiler, cmake, Eigen), run (+ Debian python3 with numpy, matplotlib),
# synth (+ iverilog, yosys, nextpnr-ice40), test (+ z3, clang/libFuzzer, valgrind); see the script.
deps:
	@bash scripts/setup_deps.sh all
define configure
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(CMAKE_ARGS)
endef

build:
	@bash scripts/setup_deps.sh build
	$(configure)
	cmake --build $(BUILD_DIR) -j$(JOBS)

# The program writes its outputs under out/ (trace.csv, trace.vcd, events.csv). Builds the laserax
# target only (and the libraries it links).
run:
	@bash scripts/setup_deps.sh run
	$(configure)
	cmake --build $(BUILD_DIR) -j$(JOBS) --target laserax
	$(BUILD_DIR)/laserax run $(ARGS)

# Release tests (all but label soak), then the ASan+UBSan build in $(ASAN_DIR) (all but labels
# soak and slow_asan), then one summary line. ASAN=0 skips the sanitizer pass.
test:
	@bash scripts/setup_deps.sh test
	@$(MAKE) build
	@BUILD_DIR=$(BUILD_DIR) ASAN_DIR=$(ASAN_DIR) JOBS=$(JOBS) ASAN=$(ASAN) bash scripts/run_tests.sh

soak:
	@bash scripts/setup_deps.sh test
	@$(MAKE) build
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j$(JOBS) -L '^soak$$'

# libFuzzer targets (fuzz/*.cpp, clang++) built in $(BUILD_DIR)/fuzz and run FUZZ_SECONDS each on
# their committed corpus (fuzz/corpus/<target>); new inputs go to $(BUILD_DIR)/fuzz/corpus-new.
FUZZ_SECONDS ?= 300
# Every formal proof with both engines, the slow ones included (docs/FORMAL.md; about 10 min):
# Yosys' SAT engine (the default list and output_pacer_sum is left to z3) and yosys-smtbmc + z3.
formal:
	@bash scripts/setup_deps.sh test
	bash scripts/formal.sh
	bash scripts/formal.sh output_pacer_sum
	bash scripts/formal.sh --engine smtbmc quad_decoder quad_decoder_pins output_pacer pulse_multiplier \
	    pulse_multiplier_mul dds_sincos pulse_multiplier_seq output_pacer_sum rephase rephase_adj rephase_div error_map
	bash scripts/formal.sh --engine smtbmc --selftest

fuzz:
	@bash scripts/setup_deps.sh test
	FUZZ_SECONDS=$(FUZZ_SECONDS) bash scripts/fuzz.sh long $(BUILD_DIR)/fuzz

bench:
	@bash scripts/setup_deps.sh build
	$(configure)
	cmake --build $(BUILD_DIR) -j$(JOBS) --target bench
	$(BUILD_DIR)/bench
	@if command -v valgrind >/dev/null; then bash scripts/bench_ipc.sh $(BUILD_DIR)/bench; \
	 else echo "make bench: valgrind missing (make deps): no instructions-per-clock figures"; fi

vectors:
	@bash scripts/setup_deps.sh run
	$(configure)
	cmake --build $(BUILD_DIR) -j$(JOBS) --target laserax
	$(BUILD_DIR)/laserax vectors --out $(OUT)/vectors

# Plots out/trace.csv (and out/events.csv when present); runs `make run` first if there is no trace.
plot:
	@bash scripts/setup_deps.sh run
	@test -f $(OUT)/trace.csv || $(MAKE) --no-print-directory run
	$(PYTHON) scripts/plot_homing.py $(OUT)/trace.csv $(OUT)/homing.png

clean:
	rm -rf $(BUILD_DIR) $(ASAN_DIR) $(OUT) scripts/__pycache__

# ---- synth: rtl_ref/ through Yosys (generic and synth_ice40) and nextpnr-ice40 ----------------
# Prints (and writes to $(OUT)/synth/synth_report.md) LUTs, flip-flops, block RAMs and the
# nextpnr maximum clock frequency of every block and of the top. Not part of `make test`.
# Variables: SYNTH_DEVICE (hx8k | up5k), SYNTH_FREQ (target MHz, 100), SYNTH_ARGS (more options
# of scripts/synth_report.py, e.g. --modules rephase,dds_sincos or --no-pnr).
SYNTH_DEVICE ?= hx8k
SYNTH_FREQ   ?= 100
SYNTH_ARGS   ?=
# make synth-sweep: the seed sweep of issue 39 (min / median / max fmax over SWEEP_SEEDS per
# module, SWEEP_MODULES; prints numbers, checks nothing; about 1-2 min per seed and module).
SWEEP_SEEDS   ?= 1-8
SWEEP_MODULES ?= laserax_top,pso,encoder_counter
.PHONY: synth-sweep
synth-sweep:
	@bash scripts/setup_deps.sh synth
	@$(MAKE) build
	$(PYTHON) scripts/synth_report.py --build $(BUILD_DIR) --out $(OUT)/synth-sweep --device $(SYNTH_DEVICE) \
	    --freq $(SYNTH_FREQ) --jobs $(JOBS) --no-generic --modules $(SWEEP_MODULES) --seeds $(SWEEP_SEEDS) $(SYNTH_ARGS)

.PHONY: synth
synth:
	@bash scripts/setup_deps.sh synth
	@$(MAKE) build
	$(PYTHON) scripts/synth_report.py --build $(BUILD_DIR) --out $(OUT)/synth --device $(SYNTH_DEVICE) \
	    --freq $(SYNTH_FREQ) --jobs $(JOBS) $(SYNTH_ARGS)
