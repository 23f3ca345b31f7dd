#!/usr/bin/env bash
# check_includes.sh — source-structure rules for laserax.
#
# Usage: scripts/check_includes.sh [--includes | --lint | --all | --selftest] [ROOT]
#   --includes (default)  include rules (CTest: include_rules)
#       golden/  must not include anything from hls/, rtl_ref/ or host/ (the golden models are
#                written from docs/DESIGN.md, never from the bit-true code or the host driver);
#       host/    the driver library a user links into controller software: may include only host/
#                headers (quoted) and system headers — nothing from golden/, tools/, tb/, hls/,
#                sysmodel/, rtl_ref/ or fuzz/;
#       sysmodel/ system models and test glue above the IP models: quoted includes only from
#                sysmodel/, hls/, golden/ and host/ (paths from the repo root) — nothing from
#                tools/, tb/, rtl_ref/ or fuzz/;
#       tools/   the laserax program and the other tools: quoted includes only from tools/,
#                sysmodel/, hls/, golden/ and host/ (paths from the repo root) — nothing from
#                tb/, rtl_ref/ or fuzz/;
#       hls/     must not include anything from golden/, tb/ or tools/, and may include only
#                hls/ headers, <cstdint>, <cstddef>, <climits>, <type_traits>, <utility> (compile-time
#                std::index_sequence only) and the Vitis headers
#                ap_int.h, ap_fixed.h, hls_stream.h and the Catapult headers ac_int.h, ac_fixed.h.
#   --lint                synthesisability lint of hls/ (CTest: lint_hls): no float, double,
#                malloc/calloc/realloc/free/alloca, new/delete, std::vector/map/string/cout/cerr
#                (and other std containers, std::function, smart pointers, threads), iostream,
#                printf family, throw/try/catch, virtual, dynamic_cast, typeid, exit/abort,
#                `using namespace std`.
#   --all                 both
#   --selftest            runs the checks on fixtures in a temporary folder and verifies that
#                         each violation is caught and each exemption is honoured
#   ROOT                  repository root to check (default: the folder above this script)
#
# In hls/, lines inside `#ifndef __SYNTHESIS__` (or `#if !defined(__SYNTHESIS__)`) blocks, and
# inside the `#else`/`#elif` branches of `#ifdef __SYNTHESIS__` blocks, are exempt (csim-only
# code). Nesting of all #if/#ifdef/#ifndef/#else/#elif/#endif is tracked. Comments are ignored,
# and for --lint string and character literals too.
# Prints every offending line as `path:line: [rule] reason: text`, then a PASS/FAIL line.
# Exit status: 0 pass, 1 violations, 2 usage error.
set -euo pipefail

mode=includes
root=""
for arg in "$@"; do
    case "$arg" in
        --includes) mode=includes ;;
        --lint)     mode=lint ;;
        --all)      mode=all ;;
        --selftest) mode=selftest ;;
        -h|--help)  sed -n '2,36p' "$0"; exit 0 ;;
        -*)         echo "check_includes.sh: unknown option $arg" >&2; exit 2 ;;
        *)          root="$arg" ;;
    esac
done
script_path="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/$(basename "${BASH_SOURCE[0]}")"
[ -n "$root" ] || root="$(cd "$(dirname "$script_path")/.." && pwd)"

# ---------------------------------------------------------------------------------------------
# The awk checker. Variables: mode (includes|lint), hlsnames (" a.h b.h " basenames in hls/).
# Each input file is named relative to the root, so its first path component is its folder.
# ---------------------------------------------------------------------------------------------
read -r -d '' AWK_PROG <<'AWK' || true
function reset_file() { inbc = 0; depth = 0 }
function isident(c) { return c ~ /[A-Za-z0-9_]/ }
# Splits line s into code1 (comments removed, literals kept) and code2 (comments and the contents
# of string/char literals removed). Block comments may span lines (state in inbc).
function strip(s,    n, i, c, nx, q, prev) {
    code1 = ""; code2 = ""; n = length(s); i = 1; prev = ""
    while (i <= n) {
        c = substr(s, i, 1); nx = substr(s, i + 1, 1)
        if (inbc) {
            if (c == "*" && nx == "/") { inbc = 0; i += 2; code1 = code1 " "; code2 = code2 " " }
            else i++
            continue
        }
        if (c == "/" && nx == "/") break
        if (c == "/" && nx == "*") { inbc = 1; i += 2; continue }
        if (c == "\"" || (c == "'" && !isident(prev))) {
            q = c; code1 = code1 c; code2 = code2 c; i++
            while (i <= n) {
                c = substr(s, i, 1)
                if (c == "\\") { code1 = code1 substr(s, i, 2); i += 2; continue }
                code1 = code1 c; i++
                if (c == q) break
            }
            code2 = code2 q; prev = q
            continue
        }
        code1 = code1 c; code2 = code2 c; prev = c; i++
    }
}
function recompute_exempt(   k) {
    exempt = 0
    for (k = 1; k <= depth; k++)
        if ((kind[k] == "nsyn" && branch[k] == 0) || (kind[k] == "syn" && branch[k] > 0)) exempt = 1
}
function report(rule, msg) {
    printf "%s:%d: [%s] %s: %s\n", FILENAME, FNR, rule, msg, raw
    bad++
}
function hasword(s, w) { return match(s, "(^|[^A-Za-z0-9_])" w "([^A-Za-z0-9_]|$)") }
function check_include(folder, t, quoted,   base) {
    if (folder == "golden") {
        if (t ~ /^(\.\.\/)*(hls|rtl_ref|host)\//) report("include", "golden/ must not include hls/, rtl_ref/ or host/")
        return
    }
    if (folder == "host") {
        if (!quoted) return
        if (t ~ /^host\/[^.\/][^\/]*$/) return
        report("include", "host/ may include only host/ headers (nothing from golden/, tools/, tb/, hls/, sysmodel/, rtl_ref/, fuzz/)")
        return
    }
    if (folder == "sysmodel") {
        if (!quoted) return
        if (t ~ /^(sysmodel|hls|golden|host)\/[^.\/]/ && t !~ /\.\./) return
        report("include", "sysmodel/ may include only sysmodel/, hls/, golden/, host/ headers (nothing from tools/, tb/, rtl_ref/, fuzz/)")
        return
    }
    if (folder == "tools") {
        if (!quoted) return
        if (t ~ /^(tools|sysmodel|hls|golden|host)\/[^.\/]/ && t !~ /\.\./) return
        report("include", "tools/ may include only tools/, sysmodel/, hls/, golden/, host/ headers (nothing from tb/, rtl_ref/, fuzz/)")
        return
    }
    if (folder != "hls" || exempt) return
    if (t ~ /^(\.\.\/)*(golden|tb|tools)\//) { report("include", "hls/ must not include golden/, tb/ or tools/"); return }
    if (t ~ /\.\./) { report("include", "hls/ include with '..' (use paths from the repo root)"); return }
    if (t == "cstdint" || t == "climits" || t == "type_traits" || t == "cstddef" || t == "utility") return
    if (t == "ap_int.h" || t == "ap_fixed.h" || t == "hls_stream.h" || t == "ac_int.h" || t == "ac_fixed.h") return
    if (t ~ /^hls\//) return
    if (quoted && t !~ /\// && index(hlsnames, " " t " ")) return
    report("include", "header not allowed in hls/ (only hls/*, <cstdint>, <cstddef>, <climits>, <type_traits>, <utility>, ap_int.h, ap_fixed.h, hls_stream.h, ac_int.h, ac_fixed.h outside #ifndef __SYNTHESIS__)")
}
function lint(s,   t) {
    t = s
    gsub(/=[ \t]*delete/, "= DELETED_FUNCTION", t)
    if (hasword(t, "float"))   report("lint", "float")
    if (hasword(t, "double"))  report("lint", "double")
    if (match(t, /(^|[^A-Za-z0-9_])(malloc|calloc|realloc|free|alloca)[ \t]*\(/)) report("lint", "dynamic memory (malloc/calloc/realloc/free/alloca)")
    if (hasword(t, "new"))     report("lint", "new")
    if (hasword(t, "delete"))  report("lint", "delete")
    if (match(t, /std[ \t]*::[ \t]*(vector|map|multimap|string|cout|cerr|clog|list|deque|set|multiset|unordered_map|unordered_set|function|shared_ptr|unique_ptr|thread|mutex)([^A-Za-z0-9_]|$)/)) report("lint", "std library container/stream/allocation")
    if (hasword(t, "iostream")) report("lint", "iostream")
    if (match(t, /(^|[^A-Za-z0-9_])(printf|fprintf|sprintf|snprintf|puts|putchar)[ \t]*\(/)) report("lint", "printf family")
    if (hasword(t, "throw"))   report("lint", "throw")
    if (hasword(t, "try"))     report("lint", "try")
    if (hasword(t, "catch"))   report("lint", "catch")
    if (hasword(t, "virtual")) report("lint", "virtual (no dynamic dispatch in synthesis)")
    if (hasword(t, "dynamic_cast")) report("lint", "dynamic_cast")
    if (hasword(t, "typeid"))  report("lint", "typeid")
    if (match(t, /(^|[^A-Za-z0-9_.>])(exit|abort)[ \t]*\(/)) report("lint", "exit/abort")
    if (match(t, /using[ \t]+namespace[ \t]+std([^A-Za-z0-9_]|$)/)) report("lint", "using namespace std")
}
FNR == 1 { reset_file(); nfiles++ }
{
    raw = $0
    sub(/\r$/, "", raw)
    strip(raw)
    folder = FILENAME; sub(/\/.*/, "", folder)
    d = code1
    if (d ~ /^[ \t]*#/) {
        sub(/^[ \t]*#[ \t]*/, "", d)
        if (d ~ /^ifndef[ \t]+__SYNTHESIS__[ \t]*$/ || d ~ /^if[ \t]*!+[ \t]*defined[ \t]*\(?[ \t]*__SYNTHESIS__[ \t]*\)?[ \t]*(&&.*)?$/) {
            depth++; kind[depth] = "nsyn"; branch[depth] = 0; recompute_exempt(); next
        }
        if (d ~ /^ifdef[ \t]+__SYNTHESIS__[ \t]*$/ || d ~ /^if[ \t]+defined[ \t]*\(?[ \t]*__SYNTHESIS__[ \t]*\)?[ \t]*$/) {
            depth++; kind[depth] = "syn"; branch[depth] = 0; recompute_exempt(); next
        }
        if (d ~ /^if(n?def)?([^A-Za-z0-9_]|$)/) { depth++; kind[depth] = "other"; branch[depth] = 0; recompute_exempt(); next }
        if (d ~ /^(else|elif)([^A-Za-z0-9_]|$)/) { if (depth > 0) branch[depth]++; recompute_exempt(); next }
        if (d ~ /^endif([^A-Za-z0-9_]|$)/) { if (depth > 0) depth--; recompute_exempt(); next }
        if (mode == "includes" && d ~ /^include[ \t]*[<"]/) {
            t = d; sub(/^include[ \t]*/, "", t)
            quoted = (substr(t, 1, 1) == "\"")
            t = substr(t, 2); sub(/[>"].*$/, "", t)
            check_include(folder, t, quoted)
            next
        }
    }
    if (mode == "lint" && folder == "hls" && !exempt) lint(code2)
}
END {
    if (depth > 0 && nfiles > 0) { }  # unbalanced #if is the compiler's business
    exit (bad > 0) ? 1 : 0
}
AWK

list_files() {  # folder -> source files under ROOT/folder, relative to ROOT, sorted
    [ -d "$root/$1" ] || return 0
    (cd "$root" && find "$1" -type f \( -name '*.h' -o -name '*.hh' -o -name '*.hpp' -o -name '*.cpp' \
        -o -name '*.cc' -o -name '*.cxx' -o -name '*.inc' -o -name '*.ipp' -o -name '*.tpp' \) | LC_ALL=C sort)
}

run_check() {  # check-mode test-name folders...
    local m="$1" name="$2"; shift 2
    local files=() f
    for f in "$@"; do
        while IFS= read -r line; do files+=("$line"); done < <(list_files "$f")
    done
    local hlsnames=" "
    if [ -d "$root/hls" ]; then
        for f in "$root"/hls/*; do [ -f "$f" ] && hlsnames+="$(basename "$f") "; done
    fi
    if [ "${#files[@]}" -eq 0 ]; then
        echo "$name: PASS (no files to check under: $*)"
        return 0
    fi
    local out rc=0
    out="$(cd "$root" && awk -v mode="$m" -v hlsnames="$hlsnames" "$AWK_PROG" "${files[@]}")" || rc=$?
    if [ "$rc" -eq 0 ]; then
        echo "$name: PASS (${#files[@]} files checked under: $*)"
        return 0
    fi
    [ -n "$out" ] && printf '%s\n' "$out"
    if [ "$rc" -eq 1 ]; then
        echo "$name: FAIL ($(printf '%s\n' "$out" | grep -c '') violation(s))"
    else
        echo "$name: FAIL (checker error, awk exit $rc)"
    fi
    return 1
}

selftest() {
    local tmp fails=0 n=0
    tmp="$(mktemp -d "${TMPDIR:-/tmp}/laserax_checks.XXXXXX")"
    trap 'rm -rf "$tmp"' RETURN
    # expect MODE EXPECTED(pass|fail) CASE-NAME, files given on stdin, one per line, as "path|content" with \\n escapes
    expect() {
        local m="$1" want="$2" case_name="$3" dir="$tmp/$3" line path content got
        rm -rf "$dir"; mkdir -p "$dir/hls" "$dir/golden" "$dir/tb" "$dir/tools"
        while IFS= read -r line; do
            [ -n "$line" ] || continue
            path="${line%%|*}"; content="${line#*|}"
            mkdir -p "$(dirname "$dir/$path")"
            printf '%b\n' "$content" >> "$dir/$path"
        done
        n=$((n + 1))
        if bash "$script_path" "--$m" "$dir" > "$dir.log" 2>&1; then got=pass; else got=fail; fi
        if [ "$got" != "$want" ]; then
            fails=$((fails + 1))
            echo "selftest: case '$case_name' ($m): expected $want, got $got"
            sed 's/^/    /' "$dir.log"
        fi
    }
    local clean_hls
    clean_hls='hls/a.h|#pragma once\n#include <cstdint>\n#include <climits>\n#include <type_traits>\n#include <cstddef>\n#include <utility>\n#include "hls/b.h"\n#include "b.h"\n#ifdef LASERAX_USE_AP_TYPES\n#include <ap_int.h>\n#include "ap_fixed.h"\n#include <hls_stream.h>\n#elif defined(LASERAX_USE_AC_TYPES)\n#include <ac_int.h>\n#endif\n// no float, double, new or printf here\n/* block comment: std::vector<float> v;\n   throw new double; */\nstruct X { X(const X&) = delete; int32_t new_pos; int to_double; };\ninline const char* name() { return "float new try"; }\nconstexpr int kSep = 1'"'"'000;\n#ifndef __SYNTHESIS__\n#include <iostream>\n#include <vector>\n#ifdef FOO\n#endif\ninline void dbg(double v) { std::cout << v; std::vector<float> q; printf("x"); }\n#endif\n#ifdef __SYNTHESIS__\nint synth_only;\n#else\n#include <cstdio>\ninline void dbg2() { float f = 0; (void)f; }\n#endif\n#if !defined(__SYNTHESIS__) && defined(DEBUG)\ninline void dbg3() { throw 1; }\n#endif'
    local clean_all="$clean_hls"$'\n''hls/b.h|#pragma once\n#include <cstdint>'$'\n''golden/g.cpp|#include "golden/g.h"\n#include <Eigen/Core>\n#include <cmath>\n#include <vector>'$'\n''tb/tb_x.cpp|#include "hls/a.h"\n#include "golden/g.h"'$'\n''tools/t.cpp|#include "hls/a.h"'

    expect includes pass clean          <<<"$clean_all"
    expect lint     pass clean_lint     <<<"$clean_all"
    expect includes pass empty          <<<""
    expect lint     pass empty_lint     <<<""
    expect includes fail golden_hls     <<<'golden/g.cpp|#include "hls/a.h"'
    expect includes fail golden_hls_rel <<<'golden/sub/g.h|#include "../hls/a.h"'
    expect includes fail golden_rtl     <<<'golden/g.h|#include "rtl_ref/x.h"'
    expect includes fail golden_host    <<<'golden/g.cpp|#include "host/regmap.h"'
    expect includes pass host_clean     <<<'host/r.cpp|#include "host/r.h"\n#include <cmath>\n#include <string>\n// #include "golden/g.h" in a comment'
    expect includes fail host_golden    <<<'host/r.h|#include "golden/laserax_top.h"'
    expect includes fail host_tools     <<<'host/r.cpp|#include "tools/laserax/cli_util.h"'
    expect includes fail host_tb        <<<'host/r.cpp|#include "tb/tb_util.h"'
    expect includes fail host_hls       <<<'host/r.h|#include "hls/laserax_top.h"'
    expect includes fail host_sysmodel  <<<'host/r.h|#include "sysmodel/sim.h"'
    expect includes fail host_relative  <<<'host/r.h|#include "../golden/g.h"'
    expect includes fail host_bare      <<<'host/r.h|#include "r2.h"'
    expect includes fail host_ifdef     <<<'host/r.h|#ifndef __SYNTHESIS__\n#include "golden/g.h"\n#endif'
    expect includes pass sysmodel_clean <<<'sysmodel/s.cpp|#include "sysmodel/s.h"\n#include "hls/a.h"\n#include "golden/g.h"\n#include "host/r.h"\n#include <vector>\n// #include "tools/laserax/x.h" in a comment'
    expect includes fail sysmodel_tools <<<'sysmodel/s.cpp|#include "tools/laserax/vectors.h"'
    expect includes fail sysmodel_tb    <<<'sysmodel/s.h|#include "tb/tb_util.h"'
    expect includes fail sysmodel_rtl   <<<'sysmodel/s.h|#include "rtl_ref/x.vh"'
    expect includes fail sysmodel_fuzz  <<<'sysmodel/s.h|#include "fuzz/f.h"'
    expect includes fail sysmodel_rel   <<<'sysmodel/s.h|#include "../tools/laserax/x.h"'
    expect includes fail sysmodel_bare  <<<'sysmodel/s.h|#include "s2.h"'
    expect includes fail sysmodel_ifdef <<<'sysmodel/s.h|#ifndef __SYNTHESIS__\n#include "tools/laserax/x.h"\n#endif'
    expect includes pass tools_clean    <<<'tools/laserax/c.cpp|#include "tools/laserax/c.h"\n#include "sysmodel/s.h"\n#include "hls/a.h"\n#include "golden/g.h"\n#include "host/r.h"\n#include <cstdio>'
    expect includes fail tools_tb       <<<'tools/laserax/c.cpp|#include "tb/tb_util.h"'
    expect includes fail tools_tb_top   <<<'tools/bench.cpp|#include "tb/tb_util.h"'
    expect includes fail tools_rtl      <<<'tools/lutgen.cpp|#include "rtl_ref/x.vh"'
    expect includes fail tools_fuzz     <<<'tools/laserax/c.cpp|#include "fuzz/f.h"'
    expect includes fail tools_rel      <<<'tools/laserax/c.cpp|#include "../../tb/tb_util.h"'
    expect includes fail tools_bare     <<<'tools/laserax/c.cpp|#include "c.h"'
    expect includes fail golden_hls_ifn <<<'golden/g.h|#ifndef __SYNTHESIS__\n#include "hls/a.h"\n#endif'
    expect includes fail hls_golden     <<<'hls/a.h|#include "golden/g.h"'
    expect includes fail hls_tb         <<<'hls/a.h|#include "tb/x.h"'
    expect includes fail hls_tools      <<<'hls/a.h|#include "tools/laserax/x.h"'
    expect includes fail hls_vector     <<<'hls/a.h|#include <vector>'
    expect includes fail hls_cmath      <<<'hls/a.cpp|#include <cmath>'
    expect includes fail hls_stdint_h   <<<'hls/a.h|#include <stdint.h>'
    expect includes fail hls_unknown_q  <<<'hls/a.h|#include "nothere.h"'
    expect includes fail hls_else_br    <<<'hls/a.h|#ifndef __SYNTHESIS__\n#else\n#include <iostream>\n#endif'
    expect includes fail hls_after_nest <<<'hls/a.h|#ifndef __SYNTHESIS__\n#ifdef X\n#endif\n#endif\n#include <string>'
    expect lint     fail lint_float     <<<'hls/a.h|float x;'
    expect lint     fail lint_double    <<<'hls/a.cpp|static double y = 0;'
    expect lint     fail lint_malloc    <<<'hls/a.h|void* p = malloc(4);'
    expect lint     fail lint_new       <<<'hls/a.h|int* p = new int;'
    expect lint     fail lint_delete    <<<'hls/a.h|void f(int* p) { delete p; }'
    expect lint     fail lint_vector    <<<'hls/a.h|std::vector<int> v;'
    expect lint     fail lint_map       <<<'hls/a.h|std :: map<int,int> m;'
    expect lint     fail lint_string    <<<'hls/a.h|std::string s;'
    expect lint     fail lint_cout      <<<'hls/a.h|void f() { std::cout << 1; }'
    expect lint     fail lint_cerr      <<<'hls/a.h|void f() { std::cerr << 1; }'
    expect lint     fail lint_iostream  <<<'hls/a.h|#include <iostream>'
    expect lint     fail lint_printf    <<<'hls/a.h|void f() { printf("%d", 1); }'
    expect lint     fail lint_throw     <<<'hls/a.h|void f() { throw 1; }'
    expect lint     fail lint_trycatch  <<<'hls/a.h|void f() { try { } catch (...) { } }'
    expect lint     fail lint_virtual   <<<'hls/a.h|struct B { virtual void f(); };'
    expect lint     fail lint_else_br   <<<'hls/a.h|#ifndef __SYNTHESIS__\nint ok;\n#else\nfloat bad;\n#endif'
    expect lint     fail lint_after     <<<'hls/a.h|#ifndef __SYNTHESIS__\n#if 1\n#else\n#endif\nfloat ok;\n#endif\nfloat bad;'
    expect lint     fail lint_syn_first <<<'hls/a.h|#ifdef __SYNTHESIS__\nfloat bad;\n#endif'
    expect lint     fail lint_other_if  <<<'hls/a.h|#ifdef DEBUG\nfloat bad;\n#endif'
    expect lint     fail lint_after_bc  <<<'hls/a.h|/* float\n ok */ double bad;'
    expect lint     pass lint_nested_ok <<<'hls/a.h|#ifndef __SYNTHESIS__\n#ifdef FOO\nfloat ok1;\n#else\ndouble ok2;\n#endif\nfloat ok3;\n#endif'
    if [ "$fails" -eq 0 ]; then
        echo "check_scripts_selftest: PASS ($n cases)"
        return 0
    fi
    echo "check_scripts_selftest: FAIL ($fails of $n cases)"
    return 1
}

case "$mode" in
    includes) run_check includes include_rules golden hls host sysmodel tools ;;
    lint)     run_check lint lint_hls hls ;;
    all)      rc=0; run_check includes include_rules golden hls host sysmodel tools || rc=1
              run_check lint lint_hls hls || rc=1; exit "$rc" ;;
    selftest) selftest ;;
esac
