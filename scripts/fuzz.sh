#!/usr/bin/env bash
# fuzz.sh — build the libFuzzer targets (fuzz/fuzz_*.cpp) with clang++ and run each on its
# committed seed corpus (fuzz/corpus/<target>).
#   bash scripts/fuzz.sh short|long FUZZ_BUILD_DIR
#   short: CTest fuzz_short, a fixed number of runs per target with a fixed -seed (a few seconds
#          each; deterministic, so a CI machine of any speed runs the same inputs as this one);
#   long:  make fuzz, $FUZZ_SECONDS (300) each, time-bounded.
# New interesting inputs go to FUZZ_BUILD_DIR/corpus-new/<target> (never into the committed
# corpus); a crash input is written to FUZZ_BUILD_DIR/crash-<target>-* and the script fails.
set -euo pipefail
mode=${1:?usage: fuzz.sh short|long FUZZ_BUILD_DIR}
dir=${2:?usage: fuzz.sh short|long FUZZ_BUILD_DIR}
src=$(cd "$(dirname "$0")/.." && pwd)
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not installed (make deps)"; exit 1; }
# short-mode runs per target (about 4 s each here): fuzz_regs steps both whole chains per input
short_runs() { case "$1" in fuzz_regs) echo 800 ;; *) echo 100000 ;; esac; }
case "$mode" in
    short) secs=60 ;;
    long) secs=${FUZZ_SECONDS:-300} ;;
    *) echo "fuzz.sh: mode must be short or long"; exit 2 ;;
esac
cmake -S "$src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ -DLASERAX_FUZZ=ON \
    -DLASERAX_WERROR=OFF -DLASERAX_HLS_CXX14=OFF >"$dir.configure.log" 2>&1 || { cat "$dir.configure.log"; exit 1; }
targets=()
for f in "$src"/fuzz/fuzz_*.cpp; do targets+=("$(basename "$f" .cpp)"); done
cmake --build "$dir" -j"${JOBS:-2}" --target "${targets[@]}" >"$dir.build.log" 2>&1 || { tail -40 "$dir.build.log"; exit 1; }
status=0
for t in "${targets[@]}"; do
    new="$dir/corpus-new/$t"
    [ "$mode" = short ] && rm -rf "$new"   # short: the same inputs on every run
    mkdir -p "$new"
    limit=(-max_total_time="$secs")
    [ "$mode" = short ] && limit=(-runs="$(short_runs "$t")" -max_total_time="$secs")
    echo "fuzz.sh: $t, ${limit[*]} on fuzz/corpus/$t"
    if ! ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        "$dir/$t" -seed=1 "${limit[@]}" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$dir/crash-$t-" "$new" "$src/fuzz/corpus/$t" >"$dir/$t.log" 2>&1; then
        echo "fuzz.sh: $t FAILED (input saved as $dir/crash-$t-*):"
        tail -40 "$dir/$t.log"
        status=1
    else
        grep -E 'stat::number_of_executed_units|stat::new_units_added' "$dir/$t.log" | sed "s/^/  $t /"
    fi
done
exit $status
