#!/usr/bin/env bash
# setup_deps.sh — make sure the build, test, RTL and plotting tools are present.
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

# Prints the Debian packages that are missing, one per line.
missing_packages() {
    command -v g++            >/dev/null 2>&1 || echo g++
    command -v cmake          >/dev/null 2>&1 || echo cmake
    command -v make           >/dev/null 2>&1 || echo make
    [ -f /usr/include/eigen3/Eigen/Core ]     || echo libeigen3-dev
    command -v iverilog       >/dev/null 2>&1 || echo iverilog
    command -v yosys          >/dev/null 2>&1 || echo yosys
    command -v nextpnr-ice40  >/dev/null 2>&1 || echo nextpnr-ice40
    command -v z3             >/dev/null 2>&1 || echo z3      # formal proofs, yosys-smtbmc engine
    command -v clang++        >/dev/null 2>&1 || echo clang
    # libFuzzer runtime (make fuzz, CTest fuzz_short): Debian's clang ships it in libclang-rt-N-dev
    if command -v clang++ >/dev/null 2>&1 && ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a \
            >/dev/null 2>&1; then
        echo "libclang-rt-$(clang++ -dumpversion | cut -d. -f1)-dev"
    fi
    command -v valgrind       >/dev/null 2>&1 || echo valgrind
    if [ ! -x "$PY" ]; then
        echo python3; echo python3-numpy; echo python3-matplotlib
    elif ! "$PY" -c 'import numpy, matplotlib' >/dev/null 2>&1; then
        "$PY" -c 'import numpy'      >/dev/null 2>&1 || echo python3-numpy
        "$PY" -c 'import matplotlib' >/dev/null 2>&1 || echo python3-matplotlib
    fi
}

mapfile -t missing < <(missing_packages)
if [ "${#missing[@]}" -eq 0 ]; then
    echo "deps: all present (g++ cmake make eigen3 iverilog yosys nextpnr-ice40 z3 valgrind clang+libFuzzer $PY+numpy+matplotlib)"
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
