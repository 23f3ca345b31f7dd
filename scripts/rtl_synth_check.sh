#!/usr/bin/env bash
# rtl_synth_check.sh — lint and quick synthesis check of rtl_ref/ (CTest test rtl_lint_synth).
#
# Usage: scripts/rtl_synth_check.sh BUILD_DIR [MODULE...]     (default: every module)
#        scripts/rtl_synth_check.sh --selftest                the checks catch a latch (full and
#                                                              coarse synth), an undriven net, a
#                                                              multiple driver and an iverilog warning
# For each module (each as the top of its own elaboration, default parameters):
#   1. Icarus: iverilog -g2005 -Wall -Wsensitivity-entire-vector -Wsensitivity-entire-array
#      -s MODULE: any output is a failure;
#   2. Yosys: read_verilog (Verilog-2005); hierarchy -check -top MODULE; proc; check -assert;
#      then a generic `synth -top MODULE` (for the modules holding a large RAM or ROM, error_map,
#      laserax_top and laserax_axil (the error map's 2 x 1024 x 24-bit RAM), dds_sincos (its
#      1024 x 17 table) and pso (its 769 x 37 chord ROM and three 64 x 56 array copies), only its
#      coarse part `synth -run :fine`: the memories stay memory cells instead of tens of
#      thousands of flip-flops (the former 2 x 2048 map took about 3 minutes; dds_sincos 29 s and
#      pso 46 s of a CI run, under 1 s and 9 s coarse); their logic around the memories is the
#      same RTL, and `make synth` maps each of them to the iCE40 with BRAMs);
#      check -assert; no latch cell may remain
#      ($dlatch, $adlatch, $dlatchsr, $_DLATCH*); the log must hold no "Latch inferred" and no
#      Yosys warning (undriven / multiple drivers / implicit nets / anything else).
# The table RAM image for dds_sincos / laserax_top is written by BUILD_DIR/lutgen into a scratch
# directory in which Yosys runs. Exit status 0 if every module passes.
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MODULES=(input_filter quad_decoder pulse_multiplier output_pacer rephase dds_sincos error_map laserax_top
         laserax_regs laserax_axil encoder_counter pso)
COARSE_MODULES=" dds_sincos error_map laserax_top laserax_axil pso "  # synth -run :fine (see above)
IVERILOG_FLAGS=(-g2005 -grelative-include -Wall -Wsensitivity-entire-vector -Wsensitivity-entire-array)
LATCH_CELLS='t:$dlatch t:$adlatch t:$dlatchsr t:$_DLATCH_* t:$_DLATCHSR_*'

die() { echo "rtl_synth_check: $*" >&2; exit 1; }
command -v iverilog >/dev/null || die "iverilog not installed (make deps)"
command -v yosys >/dev/null || die "yosys not installed (make deps)"

# iverilog_lint TOP FILE... — 0 if iverilog elaborates TOP silently
iverilog_lint() {
    local top="$1" out
    shift
    out="$(iverilog "${IVERILOG_FLAGS[@]}" -s "$top" -o /dev/null "$@" 2>&1)"
    local rc=$?
    if [ $rc -ne 0 ] || [ -n "$out" ]; then
        echo "$out" | sed 's/^/    iverilog: /'
        return 1
    fi
    return 0
}

# yosys_check DIR TOP SYNTH(0/1) FILE... — 0 if elaboration, check and synthesis are clean
yosys_check() {
    local dir="$1" top="$2" synth="$3" log script bad
    shift 3
    log="$dir/yosys_$top.log"
    # (-defer: every file is parsed, only the modules under top are elaborated; pso.v's ROM
    # initialiser alone took about 6 s of every check without it)
    script="read_verilog -defer $*; hierarchy -check -top $top; proc; check -assert; select -assert-none $LATCH_CELLS"
    if [ "$synth" = 1 ]; then
        script="$script; synth -top $top; check -assert; select -assert-none $LATCH_CELLS"
    elif [ "$synth" = coarse ]; then
        script="$script; synth -top $top -run :fine; check -assert; select -assert-none $LATCH_CELLS"
    fi
    if ! (cd "$dir" && yosys -q -l "$log" -p "$script" >/dev/null 2>&1); then
        grep -E 'ERROR|Warning|Latch inferred|problem' "$log" | grep -v '^ABC:' | head -20 | sed 's/^/    yosys: /'
        return 1
    fi
    # Yosys' own warnings (ABC's messages about its internal networks are not design warnings)
    bad="$(grep -E '^Warning:|Latch inferred' "$log" | grep -vc 'No latch inferred' || true)"
    if [ "$bad" != "0" ]; then
        grep -E '^Warning:|Latch inferred' "$log" | grep -v 'No latch inferred' | head -20 | sed 's/^/    yosys: /'
        return 1
    fi
    return 0
}

selftest() {
    local dir fails=0 n=0
    dir="$(mktemp -d /tmp/rtl_synth_check_selftest.XXXXXX)"
    cat >"$dir/good.v" <<'EOF'
`default_nettype none
module good (input wire i_clk, input wire i_rst, input wire i_d, output wire o_q);
    reg q_q;
    always @(posedge i_clk) q_q <= i_rst ? 1'b0 : i_d;
    assign o_q = q_q;
endmodule
EOF
    cat >"$dir/latch.v" <<'EOF'
`default_nettype none
module latch (input wire i_en, input wire i_d, output wire o_q);
    reg q;
    always @* if (i_en) q = i_d;
    assign o_q = q;
endmodule
EOF
    cat >"$dir/undriven.v" <<'EOF'
`default_nettype none
module undriven (input wire i_d, output wire o_q);
    wire x;
    assign o_q = x & i_d;
endmodule
EOF
    cat >"$dir/multi.v" <<'EOF'
`default_nettype none
module multi (input wire i_a, input wire i_b, output wire o_q);
    assign o_q = i_a;
    assign o_q = i_b;
endmodule
EOF
    cat >"$dir/iwarn.v" <<'EOF'
`default_nettype none
module iwarn (input wire [3:0] i_v, output wire o_q);
    assign o_q = i_v[5];
endmodule
EOF
    expect() {  # expect pass|fail WHAT COMMAND...
        local want="$1" what="$2" got
        shift 2
        n=$((n + 1))
        if "$@" >/dev/null 2>&1; then got=pass; else got=fail; fi
        if [ "$got" != "$want" ]; then
            echo "  selftest: $what: expected $want, got $got"
            fails=$((fails + 1))
        fi
    }
    expect pass "clean module, yosys"    yosys_check "$dir" good 1 "$dir/good.v"
    expect pass "clean module, iverilog" iverilog_lint good "$dir/good.v"
    expect fail "latch"                  yosys_check "$dir" latch 1 "$dir/latch.v"
    expect pass "clean module, coarse"   yosys_check "$dir" good coarse "$dir/good.v"
    expect fail "latch, coarse synth"    yosys_check "$dir" latch coarse "$dir/latch.v"
    expect fail "undriven net"           yosys_check "$dir" undriven 0 "$dir/undriven.v"
    expect fail "multiple drivers"       yosys_check "$dir" multi 0 "$dir/multi.v"
    expect fail "iverilog warning"       iverilog_lint iwarn "$dir/iwarn.v"
    rm -rf "$dir"
    if [ $fails -eq 0 ]; then
        echo "rtl_synth_check selftest: PASS ($n cases)"
        return 0
    fi
    echo "rtl_synth_check selftest: FAIL ($fails of $n cases)"
    return 1
}

if [ "${1:-}" = "--selftest" ]; then
    selftest
    exit $?
fi

[ $# -ge 1 ] || die "usage: rtl_synth_check.sh BUILD_DIR [MODULE...] | --selftest"
[ -d "$1" ] || die "no build directory $1"
build="$(cd "$1" && pwd)"
shift
[ $# -gt 0 ] && MODULES=("$@")
[ -x "$build/lutgen" ] || die "$build/lutgen not built"

selftest || die "the checker itself is broken"

work="$build/rtl_synth_check"
rm -rf "$work"
mkdir -p "$work"
"$build/lutgen" --period 256 --amplitude 32767 --hex "$work/dds_table_p256.hex" >/dev/null ||
    die "lutgen failed"
sources=("$ROOT"/rtl_ref/input_filter.v "$ROOT"/rtl_ref/quad_decoder.v "$ROOT"/rtl_ref/pulse_multiplier.v
         "$ROOT"/rtl_ref/output_pacer.v "$ROOT"/rtl_ref/rephase.v "$ROOT"/rtl_ref/dds_sincos.v
         "$ROOT"/rtl_ref/error_map.v "$ROOT"/rtl_ref/laserax_top.v "$ROOT"/rtl_ref/laserax_regs.v
         "$ROOT"/rtl_ref/laserax_axil.v "$ROOT"/rtl_ref/encoder_counter.v "$ROOT"/rtl_ref/pso.v)

fails=0
for m in "${MODULES[@]}"; do
    [ -f "$ROOT/rtl_ref/$m.v" ] || die "no rtl_ref/$m.v"
    t0=$SECONDS
    status=PASS
    iverilog_lint "$m" "${sources[@]}" || status=FAIL
    mode=1
    what=synth
    case "$COARSE_MODULES" in *" $m "*) mode=coarse; what="synth -run :fine" ;; esac
    yosys_check "$work" "$m" "$mode" "${sources[@]}" || status=FAIL
    echo "rtl_synth_check: $m: $status (iverilog -Wall, yosys proc/check/$what, no latches; $((SECONDS - t0)) s)"
    [ "$status" = PASS ] || fails=$((fails + 1))
done
if [ $fails -ne 0 ]; then
    echo "rtl_synth_check: FAIL ($fails of ${#MODULES[@]} modules)"
    exit 1
fi
echo "rtl_synth_check: PASS (${#MODULES[@]} modules)"
