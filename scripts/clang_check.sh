#!/usr/bin/env bash
# clang_check.sh — hls/ and its testbenches under clang++ with warnings as errors (issue 37;
# CTest clang_werror, label clang, in the release pass of `make test`).
#   bash scripts/clang_check.sh CLANG_BUILD_DIR [CMAKE_ARG...]
# 1. configures CLANG_BUILD_DIR with clang++ (Release, LASERAX_WERROR=ON, hls/ as C++14 as in
#    the default build; extra CMAKE_ARGs, e.g. the vendor include folders, are passed on);
# 2. builds the target hls_tb_build: laserax_hls, the hls/ header checks, every testbench that
#    reaches hls/ (own integer back end) and the synthesis top (laserax_axil.cpp: the whole chain)
#    under each vendor back end found (ap_int, ac_int) — clang's -Wconversion includes
#    -Wsign-conversion, which GCC's does not, and a few warnings are clang's only;
# 3. runs a few bit-exact testbenches (hls == golden) of that build.
# Prints `clang_check: PASS ...` or `clang_check: FAIL ...` as its last line; exit 0 / 1.
# The build dir is kept: a later run rebuilds only what changed. Logs: CLANG_BUILD_DIR.*.log.
# Variables: JOBS (2), CLANG_CXX (clang++).
set -uo pipefail
dir=${1:?usage: clang_check.sh CLANG_BUILD_DIR [CMAKE_ARG...]}
shift
src=$(cd "$(dirname "$0")/.." && pwd)
cxx=${CLANG_CXX:-clang++}
jobs=${JOBS:-2}
# the bit-exact testbenches run (a few seconds together): the random chain, the blocks the
# type layer's mixed-sign operators and the vendor-only warnings were found in, the csim top
tests='^(tb_chain_random|tb_pulse_multiplier|tb_output_pacer|tb_quad_decoder|tb_input_filter|tb_dds_sincos|tb_hls_csim)$'
start=$SECONDS
fail() { echo "clang_check: FAIL: $* ($((SECONDS - start)) s)"; exit 1; }

command -v "$cxx" >/dev/null || fail "$cxx not installed (make deps installs clang: scripts/setup_deps.sh test)"
version=$("$cxx" --version | head -n 1)
echo "clang_check: $version, build dir $dir"
mkdir -p "$dir"
if ! cmake -S "$src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
     -DLASERAX_WERROR=ON -DLASERAX_CLANG_CHECK=OFF "$@" >"$dir.configure.log" 2>&1; then
    tail -n 30 "$dir.configure.log"
    fail "configure (log: $dir.configure.log)"
fi
grep -E 'type back ends' "$dir.configure.log" | sed 's/^/  /'
if ! cmake --build "$dir" -j"$jobs" --target hls_tb_build >"$dir.build.log" 2>&1; then
    # the first diagnostics, with their context lines
    grep -E -A 4 ': (error|warning): ' "$dir.build.log" | head -n 40
    n=$(grep -c -E ': (error|warning): ' "$dir.build.log")
    fail "build with -Werror: $n diagnostics before the build stopped (log: $dir.build.log)"
fi
echo "clang_check: build of hls_tb_build done ($((SECONDS - start)) s)"
if ! ctest --test-dir "$dir" --output-on-failure -j"$jobs" -R "$tests" >"$dir.ctest.log" 2>&1; then
    tail -n 40 "$dir.ctest.log"
    fail "testbenches (log: $dir.ctest.log)"
fi
ran=$(grep -c -E 'Test +#[0-9]+: .* Passed' "$dir.ctest.log")
[ "$ran" -ge 7 ] || { cat "$dir.ctest.log"; fail "only $ran of the 7 testbenches ran"; }
echo "clang_check: PASS ($version: hls_tb_build with -Werror, $ran bit-exact testbenches passed, $((SECONDS - start)) s)"
