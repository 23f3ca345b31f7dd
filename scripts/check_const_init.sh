#!/usr/bin/env bash
# check_const_init.sh — the static state of hls/ is constant-initialised (issue 37, finding 2).
#
# Usage: scripts/check_const_init.sh CXX ROOT [--selftest]
#   1. ROOT/tb/const_init/const_init.cpp, compiled as C++20: every block of the top and the top
#      itself as `constinit` objects (the compiler rejects any that needs a run-time constructor);
#   2. ROOT/hls/laserax_axil.cpp (the Vitis top, own integer types), compiled at -O0 (no
#      optimiser that could turn a dynamic initialiser into a constant one): its object file must
#      have no guard variable, no __cxa_guard_* call and no global constructor (nm).
#   --selftest: the same two rules on fixtures that break them (a constructor with a body; a
#      function-local static built at run time) must fail, and a constant one must pass.
# Prints one PASS/FAIL line; exit 0 pass, 1 fail, 2 usage.
set -uo pipefail
cxx=${1:-}; root=${2:-}; mode=${3:-}
if [ -z "$cxx" ] || [ -z "$root" ] || [ ! -d "$root/hls" ]; then
    echo "usage: check_const_init.sh CXX ROOT [--selftest]" >&2; exit 2
fi
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# rule 1: constinit of SRC (C++20); rule 2: nm of the -O0 object of SRC
constinit_ok() { "$cxx" -std=c++20 -I"$root" -fsyntax-only "$1" 2>"$tmp/ci.log"; }
no_dynamic_init() {
    "$cxx" -std=c++17 -O0 -I"$root" -c "$1" -o "$tmp/obj.o" 2>"$tmp/cc.log" || { cat "$tmp/cc.log"; return 2; }
    ! nm -C "$tmp/obj.o" | grep -E 'guard variable|__cxa_guard_|_GLOBAL__sub_I|__cxx_global_var_init' >"$tmp/nm.log"
}

if [ "$mode" = --selftest ]; then
    fail=0
    cat >"$tmp/bad_ctor.cpp" <<'CPP'
struct reg { int x; reg() { x = 1; } };
constinit reg g;
CPP
    cat >"$tmp/good.cpp" <<'CPP'
struct reg { int x = 1; };
constinit reg g;
int f() { static reg r; return r.x++; }
CPP
    cat >"$tmp/good_static.cpp" <<'CPP'
struct reg { int x = 1; };
int f() { static reg r; return r.x++; }
CPP
    cat >"$tmp/bad_static.cpp" <<'CPP'
struct reg { int x; reg() { for (int i = 0; i < 4; ++i) x += i; } };
int f() { static reg r; return r.x++; }
CPP
    if constinit_ok "$tmp/bad_ctor.cpp"; then echo "selftest: a constructor body passed constinit"; fail=1; fi
    if ! constinit_ok "$tmp/good.cpp"; then echo "selftest: a constant initialiser failed constinit"; fail=1; fi
    if no_dynamic_init "$tmp/bad_static.cpp"; then echo "selftest: a run-time static passed the nm check"; fail=1; fi
    if ! no_dynamic_init "$tmp/good_static.cpp"; then echo "selftest: a constant static failed the nm check"; fail=1; fi
    [ $fail -eq 0 ] && echo "check_const_init --selftest: PASS" || echo "check_const_init --selftest: FAIL"
    exit $fail
fi

fail=0
if ! constinit_ok "$root/tb/const_init/const_init.cpp"; then
    grep -E 'error' "$tmp/ci.log" | head -n 20
    echo "hls_const_init: a block of hls/ needs a run-time constructor (see above)"; fail=1
fi
no_dynamic_init "$root/hls/laserax_axil.cpp"; rc=$?
if [ $rc -ne 0 ]; then
    [ $rc -eq 1 ] && { cut -c1-160 "$tmp/nm.log"; echo "hls_const_init: hls/laserax_axil.cpp builds its static state at run time"; }
    fail=1
fi
[ $fail -eq 0 ] && echo "hls_const_init: PASS (constinit of every block and the top; laserax_axil.o has no guard or global constructor)" \
                || echo "hls_const_init: FAIL"
exit $fail
