#!/usr/bin/env bash
# bench_ipc.sh — instructions per simulated clock (the deterministic speed figure).
#   bash scripts/bench_ipc.sh BUILD_DIR/bench [SHORT_CALLS] [LONG_CALLS]
# Every figure is a difference of two runs under valgrind --tool=callgrind, a short and a long one
# ((Ir(long) - Ir(short)) / (calls(long) - calls(short))), so start-up and the reading of the
# default table cancel out. Instruction counts of a fixed binary on a fixed stimulus are
# deterministic (no timer, no sampling).
# 1. The chain call: the inclusive count of the bench's non-inlined chain_step, i.e. the call of
#    laserax_top::tick and every block step inlined into it, the instructions the model spends per
#    simulated clock (issue 37's target: <= 400 with one hardware-form path per block). Not counted: the bench loop around the call (its stimulus,
#    the pins of quadrature index t / 37, about 20 per clock).
# 2. Every bench item alone (`bench CALLS --only KEY`), its loop included: the chain item is the
#    chain call plus that loop; the block items inline the block's step into the loop.
# 3. The chain call split by block: the instructions of laserax_top::tick (or of chain_step when
#    GCC inlines tick there) by the source file of the inlined code (callgrind_annotate; needs the
#    line information the build gives bench, -g).
set -euo pipefail
bench=${1:?usage: bench_ipc.sh BUILD_DIR/bench [SHORT_CALLS] [LONG_CALLS]}
short=${2:-100000}
long=${3:-300000}
command -v valgrind >/dev/null || { echo "bench_ipc.sh: valgrind not installed (make deps)"; exit 1; }
# KEY|label (KEY: a substring of the bench item name)
items=("hls laserax_top|hls laserax_top + bench loop" "quad_decoder|hls quad_decoder" "pulse_multiplier|hls pulse_multiplier"
       "output_pacer|hls output_pacer" "rephase|hls rephase" "dds_sincos|hls dds_sincos"
       "golden laserax_top|golden laserax_top" "tb style|hls + golden + compare (tb style)")
measure() {  # CALLS KEY -> "instructions calls"
    local out ir calls
    out=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bench" "$1" --only "$2" 2>&1)
    ir=$(printf '%s\n' "$out" | sed -n 's/.*Collected : *\([0-9]*\).*/\1/p' | tail -n 1)
    calls=$(printf '%s\n' "$out" | sed -n 's/.*(\([0-9]*\) calls in .*/\1/p' | tail -n 1)
    [ -n "$ir" ] && [ -n "$calls" ] || { echo "bench_ipc.sh: no figure for '$2':"; printf '%s\n' "$out" | tail -5; exit 1; }
    echo "$ir $calls"
}
# the chain item with a callgrind profile: "calls N", "incl N" (chain_step inclusive) and
# "file Ir" lines of the code inlined into laserax_top::tick
by_file() {  # CALLS
    local f out
    f=$(mktemp)
    out=$(valgrind --tool=callgrind --callgrind-out-file="$f" "$bench" "$1" --only "hls laserax_top" 2>&1)
    printf '%s\n' "$out" | sed -n 's/.*(\([0-9]*\) calls in .*/calls \1/p' | tail -n 1
    if command -v callgrind_annotate >/dev/null; then
        callgrind_annotate --inclusive=yes --auto=no "$f" 2>/dev/null | grep -v "=>" |
            sed -n 's/^ *\([0-9,]*\) .*:(anonymous namespace)::chain_step(.*/incl \1/p' | tr -d ',' | head -n 1
        callgrind_annotate --inclusive=no --auto=no "$f" 2>/dev/null | grep -v "=>" |
            sed -n 's/^ *\([0-9,]*\) .*  *\([^ :]*\):\(lx::laserax_top::step\|lx::laserax_top::tick\|(anonymous namespace)::chain_step\)(.*/\2 \1/p' | tr -d ',' |
            sed 's|^[^ ]*/\(hls/[^ ]*\) |\1 |'   # (absolute paths of the build: keep from hls/ on)
    fi
    rm -f "$f"
}
s1=$(by_file "$short")
s2=$(by_file "$long")
echo "instructions per simulated clock (valgrind callgrind, Ir; ($long - $short)-call difference per item):"
chain=$(awk 'FNR == 1 { part++ }
             $1 == "calls" { c[part] = $2 }
             $1 == "incl" { v[part] = $2 }
             END { if (v[1] != "" && v[2] != "") printf "%.1f", (v[2] - v[1]) / (c[2] - c[1]) }' \
        <(printf '%s\n' "$s1") <(printf '%s\n' "$s2"))
if [ -n "$chain" ]; then
    printf '  %-34s %10s instructions / clock   (issue 37: <= 400)\n' "hls laserax_top, the chain call" "$chain"
else
    echo "  hls laserax_top, the chain call: no figure (callgrind_annotate missing or chain_step inlined)"
fi
for it in "${items[@]}"; do
    key=${it%%|*}
    label=${it#*|}
    read -r i1 c1 < <(measure "$short" "$key")
    read -r i2 c2 < <(measure "$long" "$key")
    awk -v l="$label" -v i1="$i1" -v i2="$i2" -v c1="$c1" -v c2="$c2" \
        'BEGIN { printf "  %-34s %10.1f instructions / clock\n", l, (i2 - i1) / (c2 - c1) }'
done
if printf '%s\n' "$s2" | grep -q '^hls/'; then
    echo "the chain call by block (instructions / clock of the code inlined into laserax_top::tick, by source file):"
    awk 'FNR == 1 { part++ }
         $1 == "calls" { c[part] = $2; next }
         $1 == "incl" { next }
         { v[part, $1] += $2; k[$1] = 1 }
         END { for (f in k) printf "  %-34s %10.1f\n", f, (v[2, f] - v[1, f]) / (c[2] - c[1]) }' \
        <(printf '%s\n' "$s1") <(printf '%s\n' "$s2") | sort -k2 -rn
else
    echo "the chain call by block: no line information in $bench (build it with -g) or callgrind_annotate missing"
fi
