#!/usr/bin/env bash
# cli_bad_invocations.sh — CTest cli_bad_invocations: every laserax subcommand rejects bad command
# lines with a non-zero exit and a message that names the option (and the allowed range), and
# --help works on every subcommand. Issue 12's cases first, then more of the same kinds.
#   bash scripts/cli_bad_invocations.sh BUILD_DIR/laserax
# Each case runs in an empty temporary folder with a 60 s timeout (a hang fails the case).
set -u
LASERAX=$(readlink -f "${1:?usage: cli_bad_invocations.sh PATH/TO/laserax}")
[ -x "$LASERAX" ] || { echo "cli_bad_invocations: $LASERAX is not executable"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cd "$TMP" || exit 1
fails=0
cases=0

# expect EXIT REGEX ARGS...: exit status EXIT (2 for a usage error) and REGEX in stderr (or stdout
# for EXIT 0)
expect() {
    local want=$1 re=$2
    shift 2
    cases=$((cases + 1))
    local out err rc
    out=$(timeout 60 "$LASERAX" "$@" 2>"$TMP/.err" </dev/null)
    rc=$?
    err=$(cat "$TMP/.err")
    local text=$err
    [ "$want" = 0 ] && text=$out
    if [ "$rc" != "$want" ] || ! grep -Eq -- "$re" <<<"$text"; then
        fails=$((fails + 1))
        printf 'FAIL: laserax'; printf " '%s'" "$@"; printf '\n  exit %s (want %s); stderr: %s\n  want /%s/\n' "$rc" "$want" "${err:0:300}" "$re"
    fi
}

# ---- issue 12 ----------------------------------------------------------------------------------
expect 2 'run: --pitch-um: 1e10 is out of range \(allowed'          run --pitch-um 1e10
expect 2 'pso: --window-um: .* is out of range \(allowed'           pso --window-um -1e300:1e300
expect 2 'counters: --wait: .1e30. is not an integer \(allowed'     counters --wait 1e30
expect 2 'counters: --rate-hz: -1 is out of range \(allowed \(0, '  counters --rate-hz -1
expect 2 'run: --speed: 1e-300 is out of range \(allowed \[0.01, 1000\]\)' run --speed 1e-300
expect 2 'run: --ratio: 0 is out of range \(allowed 1\.\.137438953471\)' run --ratio 0
expect 2 'run: --cycles: -1 is out of range \(allowed 1\.\.50000000\)' run --cycles -1
expect 2 'run: --period: 4294967552 is out of range \(allowed 8\.\.4096, multiple of 8\)' run --period 4294967552
expect 2 'vectors: --calls: .100abc. is not an integer \(allowed 100\.\.100000000\)' vectors --calls 100abc
expect 2 'vectors: --seed: .abc. is not an unsigned integer'        vectors --seed abc
expect 2 'vectors: --out: empty value'                              vectors --out ''
expect 2 'counters: --wait: .1e12. is not an integer'               counters --wait 1e12
expect 2 'gantry: --resolution: 0 is out of range \(allowed 8\.\.1048576, multiple of 8\)' gantry --resolution 0
expect 0 'usage: laserax vectors'                                   vectors --help
# ---- --help on every subcommand ----------------------------------------------------------------
expect 0 'usage: laserax'                                           --help
expect 0 'usage: laserax'                                           run --help
expect 0 '--calls N'                                                vectors -h
expect 0 '--temp-c'                                                 compensate --help
expect 0 'usage: laserax pso'                                       pso --help
expect 0 'usage: laserax counters'                                  counters --help
expect 0 '--resolution'                                             gantry --help
# ---- more: syntax (whole string, no '+', no blanks, no inf/nan, no octal surprises) ------------
expect 2 'run: --period: .\+256. is not an integer'                  run --period +256
expect 2 'run: --period: . 256. is not an integer'                  run --period ' 256'
expect 2 'run: --period: .256 . is not an integer'                  run --period '256 '
expect 2 'run: --period: 010 is out of range'                       run --period 010
expect 2 'run: --speed: .nan. is not a finite number'               run --speed nan
expect 2 'run: --speed: .inf. is not a finite number'               run --speed inf
expect 2 'run: --speed: .0x10. is not a finite number'              run --speed 0x10
expect 2 'run: --speed: .5mm. is not a finite number'               run --speed 5mm
expect 2 'run: --seed: .0x. is not an unsigned integer'             run --seed 0x
expect 2 'run: --seed: .-1. is not an unsigned integer'             run --seed -1
expect 2 'run: --seed: 18446744073709551616 is out of range'        run --seed 18446744073709551616
expect 2 'run: --period: needs a value'                             run --period
expect 2 "run: unknown option '--bogus'"                            run --bogus
expect 2 "laserax: unknown command 'bogus'"                         bogus
# ---- more: ranges --------------------------------------------------------------------------------
expect 2 'run: --dir: .0. is not allowed \(allowed \+1, 1, -1\)'    run --dir 0
expect 2 'run: --dir: .2. is not allowed'                           run --dir 2
expect 2 'run: --air-index: 1.5 is out of range \(allowed \[1, 1.01\)\)' run --air-index 1.5
expect 2 'run: --cycles: 50000001 is out of range'                  run --cycles 50000001
expect 2 'run: --cycles: 0 is out of range'                         run --cycles 0
expect 2 'run: --bounce-nm: -1 is out of range'                     run --bounce-nm -1
expect 2 'run: --pitch-um: 21 um is not a legal period'             run --pitch-um 21
expect 2 'run: --pitch-um: 0 is out of range'                       run --pitch-um 0
expect 2 'run: --origin-um: 1e300 is out of range'                  run --origin-um 1e300
expect 2 'run: --out: empty value'                                  run --out ''
expect 2 'vectors: --calls: 99 is out of range'                     vectors --calls 99
expect 2 'vectors: --calls: .1e3. is not an integer'                vectors --calls 1e3
expect 2 'vectors: --calls: 100000001 is out of range'              vectors --calls 100000001
expect 2 "vectors: unknown option '--bogus'"                        vectors --bogus 1
expect 2 'pso: --k: 32 is out of range \(allowed 0\.\.31\)'         pso --k 32
expect 2 'pso: --k: .1.5. is not an integer'                        pso --k 1.5
expect 2 'pso: --pulse-w: -1 is out of range'                       pso --pulse-w -1
expect 2 'pso: --speed-mm-s: 0 is out of range \(allowed \(0, '     pso --speed-mm-s 0
expect 2 'pso: --speed-mm-s: 1e4 is out of range'                   pso --speed-mm-s 1e4
expect 2 'pso: --window-um: 1:0 is out of range'                    pso --window-um 1:0
expect 2 'pso: --window-um: needs LO:HI'                            pso --window-um abc
expect 2 'pso: --dist-um: 1e12 is out of range'                     pso --dist-um 1e12
expect 2 'pso: --seed: -1 is out of range'                          pso --seed -1
expect 2 'pso: --out: empty value'                                  pso --out ''
expect 2 'counters: --calls: 999 is out of range'                   counters --calls 999
expect 2 'counters: --enc-speed: 0.3 is out of range'               counters --enc-speed 0.3
expect 2 'counters: --wait: 2147483648 is out of range'             counters --wait 2147483648
expect 2 'counters: --rate-hz: 1e30 is out of range'                counters --rate-hz 1e30
expect 2 'counters: --k-bits-mm: 0 is out of range'                 counters --k-bits-mm 0
expect 2 'gantry: --period: 260 is out of range \(allowed 8\.\.4096, multiple of 8\)' gantry --period 260
expect 2 'gantry: --compliance: 0 is out of range \(allowed \(0, 1\]\)' gantry --compliance 0
expect 2 "gantry: --arm: 'foo' is not allowed \(allowed own, both, hold\)" gantry --arm foo
expect 2 'gantry: --resolution: 16 is below the period'             gantry --resolution 16
expect 2 'gantry: --phase1 / --phase2: must be 0..P-1'              gantry --period 64 --phase1 64
expect 2 'gantry: --seed: -1 is out of range'                       gantry --seed -1
expect 2 'gantry: --map-grid: 0 is out of range'                    gantry --map-grid 0
expect 2 "compensate: --temp-c: 'abc' is not a finite number"       compensate --temp-c abc
expect 2 "compensate: --temp-c: '1e400' is not a finite number"     compensate --temp-c 1e400
expect 2 'compensate: --rh: 101 is out of range \(allowed \[0, 100\]\)' compensate --rh 101
expect 2 "compensate: --equation: 'foo' is not allowed \(allowed edlen, ciddor\)" compensate --equation foo
expect 2 'compensate: --material: empty value'                      compensate --material ''
expect 2 'compensate: --pressure-pa: needs a value'                 compensate --pressure-pa

# ---- issue 36: pace_m and the controller's counter input (docs/CONTROLLER.md) ------------------
expect 2 'run: --pace-m: 1 is out of range \(allowed 2\.\.65535\)'   run --pace-m 1
expect 2 'run: --pace-m: 65536 is out of range \(allowed 2\.\.65535\)' run --pace-m 65536
expect 2 'run: --pace-m: .4\.5. is not an integer'                  run --pace-m 4.5
expect 2 'run: --controller-sample-mhz: 0 is out of range \(allowed \(0, 1000\]\)' run --controller-sample-mhz 0
expect 2 'run: --controller-sample-mhz: 1001 is out of range'       run --controller-sample-mhz 1001
expect 2 'run: --controller-sample-mhz: .nan. is not a finite number' run --controller-sample-mhz nan
expect 2 'run: --controller-sample-mhz: needs a value'              run --controller-sample-mhz
expect 2 'run: --controller-filter: -1 is out of range \(allowed 0\.\.65535\)' run --controller-filter -1
expect 2 'run: --controller-filter: 65536 is out of range'          run --controller-filter 65536
expect 2 'run: --controller-sample-mhz: needs --controller-filter as well' run --controller-sample-mhz 25
expect 2 'run: --controller-filter: needs --controller-sample-mhz as well' run --controller-filter 15 --force-pace
expect 2 'run: --pace-m 4 is unsafe .* smallest safe pace_m is 61 \(it allows at most 1639344 counts/s = 128\.07 mm/s\)' run --pace-m 4 --controller-sample-mhz 25 --controller-filter 15
expect 2 'run: --pace-m 60 is unsafe .* smallest safe pace_m is 61' run --pace-m 60 --controller-sample-mhz 25 --controller-filter 15
expect 2 'run: --pace-m 30 is unsafe .* smallest safe pace_m is 31' run --pace-m 30 --controller-sample-mhz 50 --controller-filter 15
expect 2 'run: --pace-m 6 is unsafe .* smallest safe pace_m is 7'   run --pace-m 6 --controller-sample-mhz 50 --controller-filter 3
expect 2 'run: --controller-filter: .* more than pace_m can hold'   run --controller-sample-mhz 25 --controller-filter 20000
expect 2 "vectors: the vectors' pace_m 3 is unsafe .* smallest safe pace_m is 5" vectors --calls 100 --controller-sample-mhz 100 --controller-filter 4
expect 2 'vectors: --controller-filter: needs --controller-sample-mhz as well' vectors --controller-filter 4
expect 2 'vectors: --controller-sample-mhz: -1 is out of range'     vectors --controller-sample-mhz -1
expect 0 '--controller-sample-mhz F'                                run --help
expect 0 '--force-pace'                                             vectors --help

echo "cli_bad_invocations: $cases cases, $fails failed"
[ "$fails" = 0 ]
