#!/usr/bin/env bash
# rtl_sim.sh — run one rtl_ref/ testbench against the golden vectors (CTest tests rtl_<block>).
#
# Usage: scripts/rtl_sim.sh SET BUILD_DIR          simulate one vector set
#        scripts/rtl_sim.sh --vectors BUILD_DIR    only (re)generate the vectors
#   SET: BLOCK (golden vectors of `laserax vectors`) or BLOCK_stress (rtl_stress_vectors), with
#   BLOCK one of input_filter quad_decoder pulse_multiplier output_pacer rephase dds_sincos
#   laserax_top. The testbench is rtl_ref/tb/tb_SET.v, or tb_BLOCK.v when the stress set has the
#   standard column layout.
#
# 1. Vectors, into BUILD_DIR/rtl_vectors: BUILD_DIR/laserax vectors --calls $RTL_CALLS (40000),
#    and BUILD_DIR/rtl_stress_vectors --calls $RTL_STRESS_CALLS (30000; top: 3x) when that tool is
#    built; generated once and reused while newer than both binaries and made with the same
#    counts (a lock serialises parallel tests).
# 2. The `// field` lines of SET.hex must equal the field list the testbench was written for.
# 3. iverilog -g2005 -Wall (plus the sensitivity warnings) on the testbench and rtl_ref/*.v: any
#    compiler output is an error (iverilog has no -Werror).
# 4. vvp; the run passes if it prints `PASS tb_BLOCK:` and no warning, error or FAIL line.
# Environment: RTL_CALLS, RTL_STRESS_CALLS (vector rows), RTL_ROWS (simulate only the first N rows),
#              RTL_VCD=FILE (dump a VCD of the run).
# Exit status 0 on PASS, 1 on any failure.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BLOCKS="input_filter quad_decoder pulse_multiplier output_pacer rephase dds_sincos laserax_top"
CALLS="${RTL_CALLS:-40000}"
STRESS_CALLS="${RTL_STRESS_CALLS:-30000}"
IVERILOG_FLAGS=(-g2005 -Wall -Wsensitivity-entire-vector -Wsensitivity-entire-array)

die() { echo "rtl_sim: $*" >&2; exit 1; }

[ $# -eq 2 ] || die "usage: rtl_sim.sh SET|--vectors BUILD_DIR"
block="$1"
[ -d "$2" ] || die "no build directory $2"
build="$(cd "$2" && pwd)"
laserax="$build/laserax"
stressgen="$build/rtl_stress_vectors"
vecdir="$build/rtl_vectors"
[ -x "$laserax" ] || die "$laserax not built"
command -v iverilog >/dev/null && command -v vvp >/dev/null || die "iverilog/vvp not installed (make deps)"

# ---- 1. vectors (once per laserax binary) -----------------------------------------------------
make_vectors() {
    local stamp="$vecdir/.stamp" tmp want have_stress=0
    [ -x "$stressgen" ] && have_stress=1
    want="calls $CALLS stress $have_stress $STRESS_CALLS"
    exec 9>"$build/rtl_vectors.lock"
    flock 9
    if [ ! -f "$stamp" ] || [ "$laserax" -nt "$stamp" ] || [ "$(cat "$stamp")" != "$want" ] ||
       { [ $have_stress = 1 ] && [ "$stressgen" -nt "$stamp" ]; }; then
        tmp="$(mktemp -d "$build/rtl_vectors.tmp.XXXXXX")"
        if ! (cd "$build" && ./laserax vectors --out "$tmp" --calls "$CALLS" >"$tmp/.log" 2>&1); then
            cat "$tmp/.log" >&2
            rm -rf "$tmp"
            die "laserax vectors failed"
        fi
        if [ $have_stress = 1 ] &&
           ! (cd "$build" && ./rtl_stress_vectors --out "$tmp" --calls "$STRESS_CALLS" >>"$tmp/.log" 2>&1); then
            cat "$tmp/.log" >&2
            rm -rf "$tmp"
            die "rtl_stress_vectors failed"
        fi
        echo "$want" >"$tmp/.stamp"
        rm -rf "$vecdir"
        mv "$tmp" "$vecdir"
        echo "rtl_sim: vectors written to $vecdir ($CALLS calls; stress vectors: $([ $have_stress = 1 ] && echo "$STRESS_CALLS calls" || echo "rtl_stress_vectors not built"))"
    fi
    flock -u 9
}
make_vectors
if [ "$block" = "--vectors" ]; then exit 0; fi

base="${block%_stress}"
case " $BLOCKS " in *" $base "*) ;; *) die "unknown vector set '$block' (BLOCK or BLOCK_stress, BLOCK one of: $BLOCKS)" ;; esac
tb="$ROOT/rtl_ref/tb/tb_$block.v"
[ -f "$tb" ] || tb="$ROOT/rtl_ref/tb/tb_$base.v"
tbmod="$(basename "$tb" .v)"
hex="$vecdir/$block.hex"
[ -f "$tb" ] || die "no testbench $tb"
[ -f "$hex" ] || die "no vector file $hex"

# ---- 2. field list ---------------------------------------------------------------------------
if ! diff <(sed -n 's#^// field \(.*\)$#\1#p' "$hex") <(sed -n 's#^//   field \(.*\)$#\1#p' "$tb") >/dev/null; then
    echo "rtl_sim: field list of $hex differs from the one $tb was written for:" >&2
    diff <(sed -n 's#^// field \(.*\)$#\1#p' "$hex") <(sed -n 's#^//   field \(.*\)$#\1#p' "$tb") >&2 || true
    exit 1
fi
rows="$(grep -cv '^//' "$hex")"
[ "$rows" -gt 0 ] || die "$hex has no rows"

# ---- 3. compile --------------------------------------------------------------------------------
work="$build/rtl_sim"
mkdir -p "$work"
params=(-P"$tbmod".N_MAX="$rows")
if grep -q 'parameter TBL_FILE' "$tb"; then
    params+=(-P"$tbmod".TBL_FILE="\"$vecdir/dds_table_p256.hex\"")
fi
vvpfile="$work/tb_$block.vvp"
complog="$work/tb_$block.compile.log"
if ! iverilog "${IVERILOG_FLAGS[@]}" -I "$ROOT/rtl_ref/tb" -s "$tbmod" "${params[@]}" -o "$vvpfile" \
        "$tb" "$ROOT"/rtl_ref/*.v >"$complog" 2>&1; then
    cat "$complog" >&2
    die "iverilog failed"
fi
if [ -s "$complog" ]; then
    cat "$complog" >&2
    die "iverilog printed warnings (must be clean)"
fi

# ---- 4. simulate -------------------------------------------------------------------------------
plus=(+vectors="$hex")
[ -n "${RTL_ROWS:-}" ] && plus+=(+rows="$RTL_ROWS")
[ -n "${RTL_VCD:-}" ] && plus+=(+vcd="$RTL_VCD")
simlog="$work/tb_$block.log"
echo "rtl_sim: $tbmod on $hex ($rows rows)"
rc=0
vvp -n "$vvpfile" "${plus[@]}" >"$simlog" 2>&1 || rc=$?
cat "$simlog"
if [ "$rc" -ne 0 ]; then die "vvp exited with $rc"; fi
# (grep -c reads its whole input: no SIGPIPE under pipefail)
bad="$(grep -v '^VCD info:' "$simlog" | grep -ciE 'warning|error|^FAIL' || true)"
[ "$bad" = "0" ] || die "$tbmod on $block FAILED"
grep -q "^PASS $tbmod:" "$simlog" || die "$tbmod: no PASS line"
exit 0
