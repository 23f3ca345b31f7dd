#!/usr/bin/env bash
# setup_deps.sh — make sure the tools a make target needs are present.
#
# Usage: scripts/setup_deps.sh [PROFILE]   (the Makefile passes its target's profile)
#   build   g++, cmake, make, Eigen 3                               (make build, make bench)
#   run     build + Debian's /usr/bin/python3 with numpy and matplotlib  (make run, vectors, plot)
#   synth   run + iverilog, yosys, nextpnr-ice40, fpga-icestorm     (make synth; icetime cross-check)
#   test    synth + z3, clang with libFuzzer, valgrind              (make test, soak, fuzz, formal)
#   all     the same as test (default; `make deps`)
#
# Quick when everything is there (a few `command -v` / file tests and one python import, no apt).
# Missing Debian packages are installed with apt-get when running as root; otherwise the exact
# command to run is printed and the script exits 1.
#
# Note: the `python3` first on PATH may be a separate interpreter (pyenv) without Debian's
# packages; the project always plots with /usr/bin/python3.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

PY=/usr/bin/python3
profile="${1:-all}"
case "$profile" in
    build|run|synth|test|all) ;;
    *) echo "setup_deps.sh: unknown profile '$profile' (build, run, synth, test, all)" >&2; exit 2 ;;
esac
want() {  # want LEVEL: true when the profile includes that level (build < run < synth < test = all)
    local order=(build run synth test) p l i
    for i in "${!order[@]}"; do [ "${order[$i]}" = "$1" ] && l=$i; done
    [ "$profile" = all ] && p=3 || for i in "${!order[@]}"; do [ "${order[$i]}" = "$profile" ] && p=$i; done
    [ "$p" -ge "$l" ]
}

# Prints the Debian packages that are missing, one per line.
missing_packages() {
    command -v g++            >/dev/null 2>&1 || echo g++
    command -v cmake          >/dev/null 2>&1 || echo cmake
    command -v make           >/dev/null 2>&1 || echo make
    [ -f /usr/include/eigen3/Eigen/Core ]     || echo libeigen3-dev
    if want run; then
        if [ ! -x "$PY" ]; then
            echo python3; echo python3-numpy; echo python3-matplotlib
        elif ! "$PY" -c 'import numpy, matplotlib' >/dev/null 2>&1; then
            "$PY" -c 'import numpy'      >/dev/null 2>&1 || echo python3-numpy
            "$PY" -c 'import matplotlib' >/dev/null 2>&1 || echo python3-matplotlib
        fi
    fi
    want synth || return 0
    command -v iverilog       >/dev/null 2>&1 || echo iverilog
    command -v yosys          >/dev/null 2>&1 || echo yosys
    command -v nextpnr-ice40  >/dev/null 2>&1 || echo nextpnr-ice40
    command -v icetime        >/dev/null 2>&1 || echo fpga-icestorm   # icepack, iceunpack, icetime
    [ -f /usr/share/fpga-icestorm/chipdb/chipdb-8k.txt ] || echo fpga-icestorm-chipdb
    want test || return 0
    command -v z3             >/dev/null 2>&1 || echo z3      # formal proofs, yosys-smtbmc engine
    command -v clang++        >/dev/null 2>&1 || echo clang
    # libFuzzer runtime (make fuzz, CTest fuzz_short): Debian's clang ships it in libclang-rt-N-dev
    if command -v clang++ >/dev/null 2>&1 && ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a \
            >/dev/null 2>&1; then
        echo "libclang-rt-$(clang++ -dumpversion | cut -d. -f1)-dev"
    fi
    command -v valgrind       >/dev/null 2>&1 || echo valgrind
}

present() {
    case "$profile" in
        build) echo "g++ cmake make eigen3" ;;
        run)   echo "g++ cmake make eigen3 $PY+numpy+matplotlib" ;;
        synth) echo "g++ cmake make eigen3 $PY+numpy+matplotlib iverilog yosys nextpnr-ice40 icestorm" ;;
        *)     echo "g++ cmake make eigen3 $PY+numpy+matplotlib iverilog yosys nextpnr-ice40 icestorm z3 valgrind clang+libFuzzer" ;;
    esac
}

mapfile -t missing < <(missing_packages)
if [ "${#missing[@]}" -eq 0 ]; then
    echo "deps ($profile): all present ($(present))"
    exit 0
fi

echo "deps: missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
    echo "deps: not root; install them with:"
    echo "  sudo apt-get install -y --no-install-recommends ${missing[*]}"
    echo "  (if apt cannot find them, run 'sudo apt-get update' first)"
    exit 1
fi

apt_install() { apt-get install -y --no-install-recommends "$@"; }
if ! apt_install "${missing[@]}"; then
    echo "deps: install failed, refreshing the package lists and retrying"
    apt-get update
    apt_install "${missing[@]}"
fi

mapfile -t still < <(missing_packages)
if [ "${#still[@]}" -ne 0 ]; then
    echo "deps: still missing after install: ${still[*]}" >&2
    exit 1
fi
echo "deps: installed ${missing[*]}"
