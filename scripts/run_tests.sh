#!/usr/bin/env bash
# run_tests.sh — the body of `make test` (expects the release build in $BUILD_DIR to be done).
#   1. ctest in $BUILD_DIR, excluding label soak;
#   2. unless ASAN=0: configure and build $ASAN_DIR with LASERAX_SANITIZE=ON and run ctest there,
#      excluding labels soak and slow_asan;
#   3. a summary, ending with the line `summary: N passed, M failed`. Exit 1 if anything failed.
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR="${BUILD_DIR:-build}"
ASAN_DIR="${ASAN_DIR:-build-asan}"
JOBS="${JOBS:-2}"
ASAN="${ASAN:-1}"

total_pass=0
total_fail=0
report=()

# run_ctest TAG DIR LABEL-EXCLUDE-REGEX
run_ctest() {
    local tag="$1" dir="$2" exclude="$3" log rc line pct failed all
    log="$dir/ctest-summary.log"
    echo "==== $tag: ctest --test-dir $dir -LE '$exclude'"
    ctest --test-dir "$dir" --output-on-failure -j"$JOBS" -LE "$exclude" 2>&1 | tee "$log"
    rc=${PIPESTATUS[0]}
    line="$(grep -E '[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n 1)"
    if [[ "$line" =~ ([0-9]+)%\ tests\ passed,\ ([0-9]+)\ tests?\ failed\ out\ of\ ([0-9]+) ]]; then
        failed="${BASH_REMATCH[2]}"; all="${BASH_REMATCH[3]}"
    elif grep -q 'No tests were found' "$log" && [ "$rc" -eq 0 ]; then
        failed=0; all=0
    else
        failed=1; all=1   # ctest itself failed
    fi
    if [ "$rc" -ne 0 ] && [ "$failed" -eq 0 ]; then failed=1; all=$((all + 1)); fi
    total_pass=$((total_pass + all - failed))
    total_fail=$((total_fail + failed))
    report+=("$tag: $((all - failed)) passed, $failed failed")
}

run_ctest release "$BUILD_DIR" '^soak$'

if [ "$ASAN" != "0" ]; then
    echo "==== asan: building $ASAN_DIR (LASERAX_SANITIZE=ON)"
    if cmake -S . -B "$ASAN_DIR" -DCMAKE_BUILD_TYPE=Release -DLASERAX_SANITIZE=ON \
       && cmake --build "$ASAN_DIR" -j"$JOBS"; then
        run_ctest asan "$ASAN_DIR" '^(soak|slow_asan)$'
    else
        total_fail=$((total_fail + 1))
        report+=("asan: build FAILED")
    fi
else
    report+=("asan: skipped (ASAN=0)")
fi

echo "==== make test"
for r in "${report[@]}"; do echo "  $r"; done
echo "summary: $total_pass passed, $total_fail failed"
[ "$total_fail" -eq 0 ]
