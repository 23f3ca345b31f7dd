#!/usr/bin/python3
"""gen_regmap.py — the laserax register map: validates regmap/laserax_regs.csv (the single source
of truth) and generates every file that depends on it.

Usage (Python 3 standard library only):
    /usr/bin/python3 scripts/gen_regmap.py            validate and (re)write the generated files
    /usr/bin/python3 scripts/gen_regmap.py --check    validate, regenerate in memory and compare
                                                      with the files on disk (CTest regmap_generated)
    /usr/bin/python3 scripts/gen_regmap.py --selftest malformed CSVs must be rejected with a
                                                      file:line message (CTest regmap_generator_selftest)
Options: --csv PATH (default regmap/laserax_regs.csv), --out-dir DIR (default: the repository root).

Generated (each with the header line of GENERATED_NOTE):
    hls/laserax_axil.h, hls/laserax_axil.cpp   Vitis HLS top: one s_axilite scalar per register;
                                             its debug taps (LASERAX_HLS_DEBUG_TAPS, default 0)
                                             are the outputs rtl_ref/laserax_top.v ties to 0
                                             with DEBUG_TAPS = 0 (read from that file)
    hls/laserax_regmap.h                     lx::regmap constants + static_asserts against lx::axis_regs
    host/regmap_table.h, .cpp                host table, the host settings struct lxt::axis_settings
                                             and its accessors
    host/laserax_regs_c.h                    C header for firmware
    sysmodel/regmap_models.h, .cpp           accessors of lx::axis_regs and golden::axis_regs,
                                             to_hls / to_golden / settings_from
    sysmodel/laserax_axil_call.h              laserax_axil() behind a model of the HLS IP's
                                             s_axilite slave (registers 0 at power-up)
    docs/REGISTERS.md                        the documented map
    rtl_ref/laserax_regs.v                   Verilog AXI4-Lite slave holding the map (o_<name> ports)

Validation (the first error is reported as `FILE:LINE: message`, exit status 1): the header row,
unique lower-case names, offsets 32-bit aligned from 0x10 and not overlapping (a register wider
than 32 bits takes consecutive words), 1 <= width <= 64 (unsigned at most 63: the host table keeps
values in int64), width-1 registers unsigned, reset/min/max inside the width, min <= max, min and
max on the step, reset legal (min..max, step), pulse registers reset to 0, known access and check
values, check cfg/map with a range or step, member paths well-formed and unique, unique word names
in the RTL slave (A_<NAME>, A_<NAME>_<w>).
Exit status: 0 ok, 1 invalid CSV or (--check) a difference, 2 usage error.
"""
import argparse
import csv
import difflib
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CSV_REL = "regmap/laserax_regs.csv"
COMMAND = "/usr/bin/python3 scripts/gen_regmap.py"
GENERATED_NOTE = "GENERATED FILE - do not edit. Source: %s. Command: %s" % (CSV_REL, COMMAND)
FIRST_OFFSET = 0x10
COLUMNS = ["name", "offset", "width", "signed", "reset", "access", "units", "min", "max", "step",
           "check", "rule", "hls_member", "golden_member", "description"]
ACCESS = ("rw", "pulse", "port")
CHECKS = ("cfg", "map", "none")
# words that the hls lint (scripts/check_includes.sh --lint) or the synthesisability grep flag
HLS_FORBIDDEN = re.compile(r"\b(float|double|new|delete|throw|try|catch|virtual|iostream)\b|\b(malloc|calloc|realloc|free|alloca|printf)\s*\(")


class CsvError(Exception):
    def __init__(self, path, line, msg):
        Exception.__init__(self, "%s:%d: %s" % (path, line, msg))


class Reg:
    """One row of the CSV."""

    def __init__(self, line, row):
        self.line = line
        for k, v in zip(COLUMNS, row):
            setattr(self, "raw_" + k, v)
        self.name = row[0]

    @property
    def words(self):
        return (self.width + 31) // 32

    @property
    def span(self):  # bytes of address space: the data words plus the reserved control word
        return 4 * (self.words + 1)

    @property
    def reserved(self):  # offset of the reserved control word
        return self.offset + 4 * self.words

    @property
    def upper(self):
        return self.name.upper()

    @property
    def lx_type(self):
        if self.width == 1:
            return "bool"
        return "lx::%s<%d>" % ("sint" if self.signed else "uint", self.width)

    @property
    def lo(self):  # smallest value of the width
        return -(1 << (self.width - 1)) if self.signed else 0

    @property
    def hi(self):  # largest value of the width
        return (1 << (self.width - 1)) - 1 if self.signed else (1 << self.width) - 1

    @property
    def any_range(self):
        return self.min is None and self.max is None

    @property
    def eff_min(self):
        return self.lo if self.min is None else self.min

    @property
    def eff_max(self):
        return self.hi if self.max is None else self.max

    def bits(self, v):
        return v & ((1 << self.width) - 1)


# ------------------------------------------------------------------------------------------------
# parsing and validation
# ------------------------------------------------------------------------------------------------
def parse_int(path, line, col, text, allow_dash=False, hexa=False):
    t = text.strip()
    if allow_dash and t == "-":
        return None
    pat = r"0[xX][0-9A-Fa-f]+" if hexa else r"-?[0-9]+"
    if not re.fullmatch(pat, t):
        raise CsvError(path, line, "column %s: '%s' is not a %s%s" %
                       (col, text, "hex number (0x..)" if hexa else "decimal integer",
                        " or '-'" if allow_dash else ""))
    return int(t, 16) if hexa else int(t, 10)


MEMBER_RE = re.compile(r"[a-z_][a-z0-9_]*(\[[0-9]+\])?(\.[a-z_][a-z0-9_]*(\[[0-9]+\])?)*")


def load(path):
    """Reads and validates the CSV; returns the registers sorted by offset. Raises CsvError."""
    try:
        with open(path, "r", encoding="utf-8") as f:
            lines = f.read().split("\n")
    except OSError as e:
        raise CsvError(path, 0, "cannot read: %s" % e.strerror)
    header_seen = False
    regs = []
    for no, text in enumerate(lines, start=1):
        s = text.strip()
        if not s or s.startswith("#"):
            continue
        row = [c.strip() for c in next(csv.reader([s]))]
        if not header_seen:
            if row != COLUMNS:
                raise CsvError(path, no, "header row must be: %s" % ",".join(COLUMNS))
            header_seen = True
            continue
        if len(row) != len(COLUMNS):
            raise CsvError(path, no, "%d columns, expected %d (%s)" % (len(row), len(COLUMNS), ",".join(COLUMNS)))
        regs.append(check_row(path, no, row))
    if not header_seen:
        raise CsvError(path, len(lines), "no header row")
    if not regs:
        raise CsvError(path, len(lines), "no registers")
    check_table(path, regs)
    return sorted(regs, key=lambda r: r.offset)


def check_row(path, no, row):
    r = Reg(no, row)
    if not re.fullmatch(r"[a-z][a-z0-9_]*", r.name):
        raise CsvError(path, no, "name '%s' must be a lower-case identifier" % r.name)
    r.offset = parse_int(path, no, "offset", r.raw_offset, hexa=True)
    if r.offset % 4:
        raise CsvError(path, no, "%s: offset 0x%X is not 32-bit word aligned" % (r.name, r.offset))
    if r.offset < FIRST_OFFSET:
        raise CsvError(path, no, "%s: offset 0x%X is below the first register offset 0x%X" % (r.name, r.offset, FIRST_OFFSET))
    r.width = parse_int(path, no, "width", r.raw_width)
    if r.raw_signed not in ("s", "u"):
        raise CsvError(path, no, "%s: signed must be s or u, not '%s'" % (r.name, r.raw_signed))
    r.signed = r.raw_signed == "s"
    if not 1 <= r.width <= 64:
        raise CsvError(path, no, "%s: width %d is outside 1..64" % (r.name, r.width))
    if r.width == 64 and not r.signed:
        raise CsvError(path, no, "%s: unsigned registers are at most 63 bits wide (the host table keeps values in int64)" % r.name)
    if r.width == 1 and r.signed:
        raise CsvError(path, no, "%s: a 1-bit register is a bool and must be unsigned" % r.name)

    def in_width(what, v):
        if v is not None and not r.lo <= v <= r.hi:
            raise CsvError(path, no, "%s: %s %d does not fit %s %d bits (%d .. %d)" %
                           (r.name, what, v, "signed" if r.signed else "unsigned", r.width, r.lo, r.hi))

    r.reset = parse_int(path, no, "reset", r.raw_reset)
    in_width("reset", r.reset)
    if r.raw_access not in ACCESS:
        raise CsvError(path, no, "%s: access must be one of %s, not '%s'" % (r.name, "|".join(ACCESS), r.raw_access))
    r.access = r.raw_access
    r.units = r.raw_units or "-"
    r.min = parse_int(path, no, "min", r.raw_min, allow_dash=True)
    r.max = parse_int(path, no, "max", r.raw_max, allow_dash=True)
    in_width("min", r.min)
    in_width("max", r.max)
    if r.eff_min > r.eff_max:
        raise CsvError(path, no, "%s: min %d > max %d" % (r.name, r.eff_min, r.eff_max))
    r.step = parse_int(path, no, "step", r.raw_step, allow_dash=True)
    if r.step is not None and r.step < 1:
        raise CsvError(path, no, "%s: step %d must be >= 1 (or '-')" % (r.name, r.step))
    r.step = r.step or 1
    for what, v in (("min", r.min), ("max", r.max)):
        if v is not None and v % r.step:
            raise CsvError(path, no, "%s: %s %d is not a multiple of the step %d" % (r.name, what, v, r.step))
    if not r.eff_min <= r.reset <= r.eff_max or r.reset % r.step:
        raise CsvError(path, no, "%s: reset %d is not legal (%d .. %d, step %d)" % (r.name, r.reset, r.eff_min, r.eff_max, r.step))
    if r.access == "pulse" and r.reset != 0:
        raise CsvError(path, no, "%s: a pulse register must reset to 0" % r.name)
    if r.raw_check not in CHECKS:
        raise CsvError(path, no, "%s: check must be one of %s, not '%s'" % (r.name, "|".join(CHECKS), r.raw_check))
    r.check = r.raw_check
    if r.check != "none" and r.any_range and r.step == 1:
        raise CsvError(path, no, "%s: check %s needs a min, max or step" % (r.name, r.check))
    if r.check == "none" and not (r.any_range and r.step == 1):
        raise CsvError(path, no, "%s: a range or step is given but check is none (nothing enforces it)" % r.name)
    r.rule = "" if r.raw_rule == "-" else r.raw_rule
    if not MEMBER_RE.fullmatch(r.raw_hls_member):
        raise CsvError(path, no, "%s: hls_member '%s' is not a member path" % (r.name, r.raw_hls_member))
    r.hls_member = r.raw_hls_member
    if r.raw_golden_member != "-" and not MEMBER_RE.fullmatch(r.raw_golden_member):
        raise CsvError(path, no, "%s: golden_member '%s' is not a member path or '-'" % (r.name, r.raw_golden_member))
    r.golden_member = "" if r.raw_golden_member == "-" else r.raw_golden_member
    r.description = r.raw_description
    if not r.description:
        raise CsvError(path, no, "%s: empty description" % r.name)
    return r


def check_table(path, regs):
    seen = {}
    members = {}
    for r in regs:
        if r.name in seen:
            raise CsvError(path, r.line, "duplicate name '%s' (first on line %d)" % (r.name, seen[r.name]))
        seen[r.name] = r.line
        for m in (r.hls_member, "golden:" + r.golden_member if r.golden_member else ""):
            if m and m in members:
                raise CsvError(path, r.line, "%s: member %s already used by %s" % (r.name, m, members[m]))
            if m:
                members[m] = r.name
    # the RTL slave names each data word A_<NAME> (A_<NAME>_<w> for wide registers): a register
    # "x_1" next to a wide "x" would give two words the same name
    words = {}
    for r in sorted(regs, key=lambda r: r.line):
        for w in range((r.width + 31) // 32):
            wn = "A_%s" % r.upper if r.width <= 32 else "A_%s_%d" % (r.upper, w)
            if wn in words:
                raise CsvError(path, r.line, "%s: its RTL word name %s clashes with a word of %s (rtl_ref/laserax_regs.v)" %
                               (r.name, wn, words[wn]))
            words[wn] = r.name
    by_off = sorted(regs, key=lambda r: (r.offset, r.line))
    for a, b in zip(by_off, by_off[1:]):
        if b.offset < a.offset + a.span:
            late = a if a.line > b.line else b
            raise CsvError(path, late.line, "%s (0x%X..0x%X) overlaps %s (0x%X..0x%X, incl. its reserved control word)" %
                           (b.name, b.offset, b.offset + b.span - 1, a.name, a.offset, a.offset + a.span - 1))


# ------------------------------------------------------------------------------------------------
# generators: each returns the file text
# ------------------------------------------------------------------------------------------------
def c_ll(v):
    """int64 literal (INT64_MIN cannot be written directly)."""
    if v == -(1 << 63):
        return "(-9223372036854775807LL - 1)"
    return "%dLL" % v


def member_path(base, path):
    return "%s.%s" % (base, path)


def word_ranges(r):
    """[(offset, lo_bit, hi_bit)] of the words of a register, low word first."""
    out = []
    for w in range(r.words):
        lo = 32 * w
        out.append((r.offset + 4 * w, lo, min(r.width, lo + 32) - 1))
    return out


# The debug taps of the HLS top (lx::axis_out members, the registered outputs of the blocks that
# only the testbenches compare): exactly the outputs that rtl_ref/laserax_top.v ties to 0 with
# DEBUG_TAPS = 0 (`assign o_<name> = TAPS ? ... : 0;`), read from that file so that the two columns
# drop the same outputs. The error-map outputs corr / map_delta stay in both.
RTL_TOP_REL = "rtl_ref/laserax_top.v"
RTL_TAP_RE = re.compile(r"^\s*assign\s+o_([a-z_][a-z0-9_]*)\s*=\s*TAPS\s*\?", re.M)


def debug_taps():
    path = os.path.join(ROOT, RTL_TOP_REL)
    try:
        with open(path, "r", encoding="utf-8") as f:
            text = f.read()
    except OSError as e:
        raise CsvError(RTL_TOP_REL, 0, "cannot read the debug taps: %s" % e)
    taps = RTL_TAP_RE.findall(text)
    if not taps or len(set(taps)) != len(taps):
        raise CsvError(RTL_TOP_REL, 0, "no (or a repeated) `assign o_<name> = TAPS ? ...` debug tap found")
    return taps


def gen_top_h(regs):
    args = ",\n".join("                 %s %s" % (r.lx_type, r.name) for r in regs)
    return """// laserax_axil.h — declaration of the synthesis top (see laserax_axil.cpp).
//
// %s
#ifndef LASERAX_HLS_LASERAX_AXIL_H
#define LASERAX_HLS_LASERAX_AXIL_H

#include "hls/laserax_top.h"

// LASERAX_HLS_DEBUG_TAPS, a compile-time switch (0 or 1; default 0, as DEBUG_TAPS = 0 of
// rtl_ref/laserax_top.v): 0 drops the debug taps from the top's outputs, the lx::axis_out members
//   %s
// are 0 in every call, so synthesis removes the logic that only feeds them (the deployed core);
// 1 drives them, for the testbenches that compare them (CTest tb_hls_csim_taps). The pins, the
// status and the error-map outputs (map_cfg_err, corr, map_delta) are the same for both values.
#ifndef LASERAX_HLS_DEBUG_TAPS
#define LASERAX_HLS_DEBUG_TAPS 0
#endif
#if LASERAX_HLS_DEBUG_TAPS != 0 && LASERAX_HLS_DEBUG_TAPS != 1
#error "LASERAX_HLS_DEBUG_TAPS must be 0 or 1"
#endif

// Pins a, b, sw, lerr and the outputs are wires; every other argument is one register of the
// s_axilite slave (bundle ctrl), in offset order (docs/REGISTERS.md).
void laserax_axil(bool a, bool b, bool sw, bool lerr,
%s,
                 lx::axis_out& out);

#endif  // LASERAX_HLS_LASERAX_AXIL_H
""" % (GENERATED_NOTE, wrap_list(debug_taps(), "//   ", 92), args)


def wrap_list(names, prefix, width):
    """names as `a`, `b`, ... wrapped into comment lines of at most width characters after the first."""
    words = ["%s%s" % (n, "," if i + 1 < len(names) else "") for i, n in enumerate(names)]
    lines, cur = [], ""
    for w in words:
        if cur and len(cur) + 1 + len(w) > width:
            lines.append(cur)
            cur = w
        else:
            cur = w if not cur else cur + " " + w
    lines.append(cur)
    return ("\n" + prefix).join(lines)


def gen_top_cpp(regs):
    params = ",\n".join("                 %s %s" % (r.lx_type, r.name) for r in regs)
    pragmas = "\n".join("#pragma HLS INTERFACE mode=s_axilite port=%s offset=0x%02X bundle=ctrl" % (r.name, r.offset)
                        for r in regs)
    assigns = "\n".join("    regs.%s = %s;" % (r.hls_member, r.name) for r in regs)
    taps = "\n".join("    out.%s = 0;" % t for t in debug_taps())
    return """// laserax_axil.cpp — Vitis HLS top function of the single-axis interface.
//
// %s
//
// One call = one clock (pipeline, II = 1). Pins are plain wires (ap_none); every register of docs/REGISTERS.md is one scalar argument on the s_axilite
// slave at its fixed offset (a register wider than 32 bits takes consecutive words, low word
// first); the outputs are wires. The state of the axis lives in one static laserax_top, so the
// function is the whole IP. The block-level control is on the same s_axilite slave (port=return:
// ap_start / ap_done / auto-restart in the control word at 0x00, the words 0x00..0x0F), as
// Vitis requires when arguments are s_axilite and as C/RTL co-simulation needs; software starts
// the IP once with ap_start = 1 and auto_restart = 1 (control word 0x81), after which the II = 1
// pipeline takes one call per clock. The registers start at 0, not at their reset values (an
// s_axilite argument has no initial value): software writes the whole image before the start
// (lxt::init_registers, host/ip_init.h). The debug taps of lx::axis_out are 0 unless
// LASERAX_HLS_DEBUG_TAPS = 1 (laserax_axil.h). Build for Vitis with -DLASERAX_USE_AP_TYPES (see
// scripts/run_hls.tcl); the default build uses lx_types' own classes.
#include "hls/laserax_axil.h"

#include "hls/laserax_regmap.h"

// Catapult HLS: this function is the design top (Vitis HLS ignores the pragma; its top is named
// by set_top in scripts/run_hls.tcl)
#pragma hls_design top
void laserax_axil(bool a, bool b, bool sw, bool lerr,
%s,
                 lx::axis_out& out) {
#pragma HLS INTERFACE mode=s_axilite port=return bundle=ctrl
#pragma HLS INTERFACE mode=ap_none port=a
#pragma HLS INTERFACE mode=ap_none port=b
#pragma HLS INTERFACE mode=ap_none port=sw
#pragma HLS INTERFACE mode=ap_none port=lerr
%s
#pragma HLS INTERFACE mode=ap_none port=out
#pragma HLS AGGREGATE variable=out
#pragma HLS PIPELINE II=1 style=frp
    static lx::laserax_top core;
    lx::axis_pins pins;
    pins.a = a;
    pins.b = b;
    pins.sw = sw;
    pins.lerr = lerr;
    lx::axis_regs regs;
%s
    out = core.step(pins, regs);
#if !LASERAX_HLS_DEBUG_TAPS
    // the debug taps dropped (laserax_axil.h): constant 0, as DEBUG_TAPS = 0 ties them in rtl_ref
%s
#endif
}
""" % (GENERATED_NOTE, params, pragmas, assigns, taps)


def gen_regmap_h(regs):
    end = max(r.offset + r.span for r in regs)
    consts = []
    for r in regs:
        u = r.upper
        consts.append("// %s: 0x%02X, %d bit%s %s, %s, reset %d" %
                      (r.name, r.offset, r.width, "" if r.width == 1 else "s", "signed" if r.signed else "unsigned",
                       r.access, r.reset))
        consts.append("constexpr unsigned %s_OFFSET = 0x%02X;" % (u, r.offset))
        consts.append("constexpr int %s_WIDTH = %d;" % (u, r.width))
        consts.append("constexpr int %s_WORDS = %d;" % (u, r.words))
        consts.append("constexpr bool %s_SIGNED = %s;" % (u, "true" if r.signed else "false"))
        consts.append("constexpr long long %s_RESET = %s;" % (u, c_ll(r.reset)))
    asserts = []
    for r in regs:
        asserts.append("static_assert(member_is<LX_REGMAP_MEMBER(%s)>(%s_WIDTH, %s_SIGNED),\n"
                       "              \"lx::axis_regs::%s is not %s (register %s)\");" %
                       (r.hls_member, r.upper, r.upper, r.hls_member, r.lx_type, r.name))
    return """// laserax_regmap.h — the s_axilite register map (docs/REGISTERS.md) as compile-time constants,
// for firmware authors and static checks, plus static_asserts that every register has the width
// and signedness of its member in lx::axis_regs.
//
// %s
#ifndef LASERAX_HLS_LASERAX_REGMAP_H
#define LASERAX_HLS_LASERAX_REGMAP_H

#include <type_traits>

#include "hls/laserax_top.h"

namespace lx {
namespace regmap {

constexpr unsigned FIRST_OFFSET = 0x%02X;  // first register
constexpr unsigned END_OFFSET = 0x%02X;    // one past the last word (the last reserved word)
constexpr int N_REGS = %d;

%s

// Width and signedness of a member type: lx::sint<W> / lx::uint<W> on both back ends (own classes
// and ap_int), bool = 1 bit unsigned; is_lx is false for any other type.
template <typename T>
struct member_bits {
    static constexpr int width = T::width;
    static constexpr bool is_signed = std::is_same<T, sint<T::width> >::value;
    static constexpr bool is_lx = is_signed || std::is_same<T, uint<T::width> >::value;
};
template <>
struct member_bits<bool> {
    static constexpr int width = 1;
    static constexpr bool is_signed = false;
    static constexpr bool is_lx = true;
};
template <typename T>
constexpr bool member_is(int width, bool is_signed) {
    return member_bits<T>::is_lx && member_bits<T>::width == width && member_bits<T>::is_signed == is_signed;
}

// The declared type of a member path of axis_regs (unevaluated).
#define LX_REGMAP_MEMBER(path) std::decay<decltype(static_cast<axis_regs*>(nullptr)->path)>::type
%s
#undef LX_REGMAP_MEMBER

}  // namespace regmap
}  // namespace lx

#endif  // LASERAX_HLS_LASERAX_REGMAP_H
""" % (GENERATED_NOTE, FIRST_OFFSET, end, len(regs), "\n".join(consts), "\n".join(asserts))


def c_str(s):
    return '"%s"' % s.replace("\\", "\\\\").replace('"', '\\"')


def settings_type(r):
    """C++ type of a register's member in the host settings struct lxt::axis_settings."""
    if r.width == 1:
        return "bool"
    if not r.signed and r.width >= 32:
        return "uint64_t"
    return "int64_t"


def settings_struct(regs):
    """The nested struct lxt::axis_settings built from the hls_member paths (the same member
    names as lx::axis_regs, plain integer types, reset values as default member initialisers)."""
    comp = re.compile(r"^([a-z_][a-z0-9_]*)(?:\[(\d+)\])?$")

    def new_node():
        return {"order": [], "kids": {}, "dims": {}, "leaf": {}}

    root = new_node()
    for r in regs:
        parts = r.hls_member.split(".")
        node = root
        for k, part in enumerate(parts):
            m = comp.match(part)
            name, index = m.group(1), m.group(2)
            if name not in node["order"]:
                node["order"].append(name)
            if index is not None:
                node["dims"][name] = max(node["dims"].get(name, 0), int(index) + 1)
            if k == len(parts) - 1:
                node["leaf"][name] = r
            else:
                node["kids"].setdefault(name, new_node())
                node = node["kids"][name]
    lines = []

    def emit(node, indent):
        pad = " " * indent
        for name in node["order"]:
            dim = "[%d]" % node["dims"][name] if name in node["dims"] else ""
            if name in node["leaf"]:
                r = node["leaf"][name]
                t = settings_type(r)
                if t == "bool":
                    init = "true" if r.reset else "false"
                elif t == "uint64_t":
                    init = "%dULL" % r.reset
                else:
                    init = c_ll(r.reset)
                if dim:
                    lines.append("%s%s %s%s = {};" % (pad, t, name, dim))
                else:
                    lines.append("%s%s %s = %s;  // %s" % (pad, t, name, init, r.name))
            else:
                lines.append("%sstruct %s_t {" % (pad, name))
                emit(node["kids"][name], indent + 4)
                lines.append("%s} %s%s;" % (pad, name, dim))

    emit(root, 4)
    return "\n".join(lines)


def gen_table_h(regs):
    idx = "\n".join("constexpr int %s = %d;" % (r.name, i) for i, r in enumerate(regs))
    rows = []
    for r in regs:
        rows.append("    {%s, 0x%02X, %d, %s, %s, access::%s, %s, %s, %s, %s, %s, check::%s, %s, %s, %s,\n     %s}," %
                    (c_str(r.name), r.offset, r.width, "true" if r.signed else "false", c_ll(r.reset), r.access,
                     c_str(r.units), "true" if r.any_range else "false", c_ll(r.eff_min), c_ll(r.eff_max), c_ll(r.step),
                     r.check, c_str(r.rule), c_str(r.hls_member), c_str(r.golden_member), c_str(r.description)))
    return """// regmap_table.h — the s_axilite register map (docs/REGISTERS.md) for host code: a constexpr
// table of every register, the host settings struct lxt::axis_settings (one member per register,
// plain integers, reset values) and accessors that read or write one register of it by index.
// Host code only: nothing from hls/ or golden/ (the model register structs are converted in
// sysmodel/regmap_models.h).
//
// %s
//
// Values are int64: the register's value (sign-extended for signed registers); the bits as they
// appear on the bus are to_bits(value). Hand-written users: host/regmap.h (register
// image, physical settings <-> registers).
#ifndef LASERAX_HOST_REGMAP_TABLE_H
#define LASERAX_HOST_REGMAP_TABLE_H

#include <cstdint>

namespace lxt {

// Every register of the map in plain integers, as a controller's software holds them: the member
// paths are those of the hls register struct (hls_member below), the defaults the reset values.
// A member may hold a value outside its register's width (image_from, host/regmap.h, reports it).
struct axis_settings {
%s
};

namespace regmap {

enum class access { rw, pulse, port };  // pulse: the host writes 1 then 0; port: table write port
enum class check { none, cfg, map };    // cfg: outside the range -> cfg_err; map: -> map_cfg_err

struct reg_info {
    const char* name;
    uint32_t offset;  // byte offset of the low word
    int width;        // bits (1..64)
    bool is_signed;
    int64_t reset;
    access acc;
    const char* units;
    bool any_range;   // every value of the width is legal as far as min/max go
    int64_t min, max; // legal range (the width's range when any_range)
    int64_t step;     // legal values are multiples of step (1: any)
    check chk;
    const char* rule;           // cross-register constraint, "" if none
    const char* hls_member;     // path inside lxt::axis_settings and lx::axis_regs
    const char* golden_member;  // path inside the golden model's register struct, "" if it has none
    const char* description;
    constexpr int words() const { return (width + 31) / 32; }
};

constexpr int kNumRegs = %d;
constexpr uint32_t kFirstOffset = 0x%02X;
constexpr uint32_t kEndOffset = 0x%02X;  // one past the last word (the last reserved word)

// Register indices (offset order).
namespace idx {
%s
}  // namespace idx

// One table for the program in C++17 (an inline variable); a C++14 translation unit (the Vitis
// C simulation compiles its testbench files, host/ip_init.cpp among them, as C++14) has a copy of
// its own of the constant table.
#if __cplusplus >= 201703L
#define LXT_REGMAP_INLINE_VAR inline
#else
#define LXT_REGMAP_INLINE_VAR
#endif
LXT_REGMAP_INLINE_VAR constexpr reg_info kRegs[kNumRegs] = {
%s
};
#undef LXT_REGMAP_INLINE_VAR

// Smallest / largest value of the register's width.
constexpr int64_t width_min(const reg_info& r) {
    return r.is_signed ? (r.width == 64 ? INT64_MIN : -(int64_t(1) << (r.width - 1))) : 0;
}
constexpr int64_t width_max(const reg_info& r) {
    return r.is_signed ? (r.width == 64 ? INT64_MAX : (int64_t(1) << (r.width - 1)) - 1)
                       : (int64_t(1) << r.width) - 1;  // unsigned registers have at most 63 bits
}
constexpr bool fits(const reg_info& r, int64_t v) { return v >= width_min(r) && v <= width_max(r); }
// min..max and the step (cross-register rules are not evaluated here).
constexpr bool legal(const reg_info& r, int64_t v) { return v >= r.min && v <= r.max && v %% r.step == 0; }
// value -> the register's bits (two's complement, width bits) and back.
constexpr uint64_t to_bits(const reg_info& r, int64_t v) {
    return r.width == 64 ? static_cast<uint64_t>(v) : static_cast<uint64_t>(v) & ((uint64_t(1) << r.width) - 1);
}
constexpr int64_t from_bits(const reg_info& r, uint64_t bits) {
    if (r.width == 64) return static_cast<int64_t>(bits);
    const uint64_t m = (uint64_t(1) << r.width) - 1;
    const uint64_t u = bits & m;
    if (!r.is_signed) return static_cast<int64_t>(u);
    const uint64_t sign = uint64_t(1) << (r.width - 1);
    return static_cast<int64_t>(u ^ sign) - static_cast<int64_t>(sign);
}

// Index of a register by name, -1 if there is none.
int find(const char* name);

// lxt::axis_settings: every register. get() returns the member as it is (it may lie outside the
// register's width); set() is false (s unchanged) if the value does not fit the width.
int64_t get(const axis_settings& s, int i);
bool set(axis_settings& s, int i, int64_t value);

}  // namespace regmap
}  // namespace lxt

#endif  // LASERAX_HOST_REGMAP_TABLE_H
""" % (GENERATED_NOTE, settings_struct(regs), len(regs), FIRST_OFFSET, max(r.offset + r.span for r in regs), idx,
       "\n".join(rows))


def gen_table_cpp(regs):
    get_s, set_s = [], []
    for r in regs:
        m = "s." + r.hls_member
        if r.width == 1:
            get_s.append("        case idx::%s: return %s ? 1 : 0;" % (r.name, m))
        else:
            get_s.append("        case idx::%s: return static_cast<int64_t>(%s);" % (r.name, m))
        set_s.append("        case idx::%s: assign(%s, value); return true;" % (r.name, m))
    return """// regmap_table.cpp — see regmap_table.h.
//
// %s
#include "host/regmap_table.h"

#include <cstring>

namespace lxt {
namespace regmap {

namespace {
template <typename T>
void assign(T& dst, int64_t v) {
    dst = static_cast<T>(v);
}
void assign(bool& dst, int64_t v) { dst = v != 0; }
}  // namespace

int find(const char* name) {
    for (int i = 0; i < kNumRegs; ++i)
        if (std::strcmp(kRegs[i].name, name) == 0) return i;
    return -1;
}

int64_t get(const axis_settings& s, int i) {
    switch (i) {
%s
        default: return 0;
    }
}

bool set(axis_settings& s, int i, int64_t value) {
    if (i < 0 || i >= kNumRegs || !fits(kRegs[i], value)) return false;
    switch (i) {
%s
        default: return false;
    }
}

}  // namespace regmap
}  // namespace lxt
""" % (GENERATED_NOTE, "\n".join(get_s), "\n".join(set_s))


def gen_models_h(regs):
    return """// regmap_models.h — the register map (host/regmap_table.h) applied to the model register
// structs: accessors that read or write one register of lx::axis_regs or golden::axis_regs by
// index, and the conversions between them and the host settings struct lxt::axis_settings.
// System-model / testbench code: it joins host/, hls/ and golden/, which never include each other.
//
// %s
#ifndef LASERAX_SYSMODEL_REGMAP_MODELS_H
#define LASERAX_SYSMODEL_REGMAP_MODELS_H

#include <cstdint>

#include "golden/laserax_top.h"
#include "hls/laserax_top.h"
#include "host/regmap_table.h"

namespace lxt {
namespace regmap {

// lx::axis_regs: every register.
int64_t get(const lx::axis_regs& r, int i);
bool set(lx::axis_regs& r, int i, int64_t value);  // false (r unchanged) if value does not fit
// golden::axis_regs: false for registers golden has no member for (golden_member == "").
// get() returns the member as it is (it may lie outside the register's width).
bool get(const golden::axis_regs& r, int i, int64_t* value);
bool set(golden::axis_regs& r, int i, int64_t value);

}  // namespace regmap

// The hls register struct for a golden one (registers golden lacks keep their reset values) or for
// the host settings; member values are truncated to the register widths, as a register write would.
lx::axis_regs to_hls(const golden::axis_regs& s);
lx::axis_regs to_hls(const axis_settings& s);
// The golden register struct for the host settings (members golden lacks are dropped) and back
// (registers golden lacks keep their reset values); members are copied as they are.
golden::axis_regs to_golden(const axis_settings& s);
axis_settings settings_from(const golden::axis_regs& g);

}  // namespace lxt

#endif  // LASERAX_SYSMODEL_REGMAP_MODELS_H
""" % (GENERATED_NOTE,)


def gen_models_cpp(regs):
    get_h, set_h, get_g, set_g, to_hls, to_hls_s, to_golden, from_golden = [], [], [], [], [], [], [], []
    for r in regs:
        m = "r." + r.hls_member
        if r.width == 1:
            get_h.append("        case idx::%s: return %s ? 1 : 0;" % (r.name, m))
            set_h.append("        case idx::%s: %s = value != 0; return true;" % (r.name, m))
        elif r.signed:
            get_h.append("        case idx::%s: return %s.to_int64();" % (r.name, m))
            set_h.append("        case idx::%s: %s = %s(value); return true;" % (r.name, m, r.lx_type))
        else:
            get_h.append("        case idx::%s: return static_cast<int64_t>(%s.to_uint64());" % (r.name, m))
            set_h.append("        case idx::%s: %s = %s(value); return true;" % (r.name, m, r.lx_type))
        if r.width == 1:
            to_hls_s.append("    r.%s = s.%s;" % (r.hls_member, r.hls_member))
        else:
            to_hls_s.append("    r.%s = %s(s.%s);" % (r.hls_member, r.lx_type, r.hls_member))
        if r.golden_member:
            g = "r." + r.golden_member
            get_g.append("        case idx::%s: *value = static_cast<int64_t>(%s); return true;" % (r.name, g))
            set_g.append("        case idx::%s: assign(%s, value); return true;" % (r.name, g))
            to_hls.append("    r.%s = s.%s;" % (r.hls_member, r.golden_member))
            to_golden.append("    convert(g.%s, s.%s);" % (r.golden_member, r.hls_member))
            from_golden.append("    convert(s.%s, g.%s);" % (r.hls_member, r.golden_member))
    return """// regmap_models.cpp — see regmap_models.h.
//
// %s
#include "sysmodel/regmap_models.h"

namespace lxt {

namespace {
template <typename T>
void assign(T& dst, int64_t v) {
    dst = static_cast<T>(v);
}
void assign(bool& dst, int64_t v) { dst = v != 0; }
template <typename D, typename S>
void convert(D& dst, const S& src) {
    dst = static_cast<D>(src);
}
}  // namespace

namespace regmap {

int64_t get(const lx::axis_regs& r, int i) {
    switch (i) {
%s
        default: return 0;
    }
}

bool set(lx::axis_regs& r, int i, int64_t value) {
    if (i < 0 || i >= kNumRegs || !fits(kRegs[i], value)) return false;
    switch (i) {
%s
        default: return false;
    }
}

bool get(const golden::axis_regs& r, int i, int64_t* value) {
    switch (i) {
%s
        default: return false;
    }
}

bool set(golden::axis_regs& r, int i, int64_t value) {
    if (i < 0 || i >= kNumRegs || !fits(kRegs[i], value)) return false;
    switch (i) {
%s
        default: return false;
    }
}

}  // namespace regmap

lx::axis_regs to_hls(const golden::axis_regs& s) {
    lx::axis_regs r;
%s
    return r;
}

lx::axis_regs to_hls(const axis_settings& s) {
    lx::axis_regs r;
%s
    return r;
}

golden::axis_regs to_golden(const axis_settings& s) {
    golden::axis_regs g;
%s
    return g;
}

axis_settings settings_from(const golden::axis_regs& g) {
    axis_settings s;
%s
    return s;
}

}  // namespace lxt
""" % (GENERATED_NOTE, "\n".join(get_h), "\n".join(set_h), "\n".join(get_g), "\n".join(set_g), "\n".join(to_hls),
       "\n".join(to_hls_s), "\n".join(to_golden), "\n".join(from_golden))


def gen_top_call_h(regs):
    end = max(r.offset + r.span for r in regs)
    masks = []
    for r in regs:
        for off, lo, hi in word_ranges(r):
            n = hi - lo + 1
            what = r.name if r.words == 1 else "%s bits %d..%d" % (r.name, hi, lo)
            masks.append("            case 0x%02X: return 0x%Xu;  // %s" % (off, (1 << n) - 1, what))
    args = []
    for r in regs:
        if r.width == 1:
            a = "at(0x%02X) != 0" % r.offset
        elif r.words == 1:
            a = "%s(at(0x%02X))" % (r.lx_type, r.offset)
        else:
            a = "%s(pair(0x%02X))" % (r.lx_type, r.offset)
        args.append("                     %s,  // %s" % (a, r.name))
    return """// laserax_axil_call.h — the synthesis top laserax_axil() behind a model of the HLS IP's
// s_axilite slave, for C simulation (testbench glue): the registers are 32-bit words at their
// offsets of docs/REGISTERS.md, all 0 at power-up as in the IP Vitis HLS makes (an s_axilite
// argument has no initial value), written one bus word at a time (host/ip_init.h writes the whole
// image), and every clock calls the top with the arguments the words hold. Header-only and built
// on hls/ and the standard library only, so it compiles in the Vitis C simulation too.
//
// %s
#ifndef LASERAX_SYSMODEL_LASERAX_AXIL_CALL_H
#define LASERAX_SYSMODEL_LASERAX_AXIL_CALL_H

#include <cstdint>

#include "hls/laserax_axil.h"

namespace lxt {

// The HLS IP's s_axilite slave (bundle ctrl) and its block control, as the C simulation sees
// them. A register word holds the bits of its register only (the bits above the width dropped,
// as the Vitis slave keeps W bits; a register wider than 32 bits takes consecutive words, low
// word first); the block-control word 0x00 keeps ap_start (bit 0) and auto_restart (bit 7). The
// model knows only the free-running mode the IP is used in: the core runs (one call of
// laserax_axil() per clock()) while 0x00 holds 0x81, i.e. from lxt::start_core on; a write of 0 to
// 0x00 stops it after the current call. The state of the core (the static laserax_top of
// hls/laserax_axil.cpp) is kept while it is stopped. Writes to 0x04..0x0F, to the reserved word
// after each register and past the map are ignored.
class laserax_axil_slave {
public:
    // One bus write (all four byte lanes); false when the word is ignored.
    bool write(uint32_t offset, uint32_t value) {
        if (offset == 0x00) {
            ctrl_ = value & 0x81u;
            return true;
        }
        const uint32_t m = mask(offset);
        if (m == 0) return false;
        w_[(offset - 0x%02Xu) / 4] = value & m;
        return true;
    }
    // The word a register holds (0x00: the block control; 0 for every other offset).
    uint32_t word(uint32_t offset) const {
        if (offset == 0x00) return ctrl_;
        return mask(offset) != 0 ? at(offset) : 0u;
    }
    bool running() const { return ctrl_ == 0x81u; }

    // One clock: while the core runs, one call of laserax_axil() on the registers the words hold
    // (true, outputs in out); else no call (false, out unchanged).
    bool clock(bool a, bool b, bool sw, bool lerr, lx::axis_out& out) {
        if (!running()) return false;
        laserax_axil(a, b, sw, lerr,
%s
                     out);
        return true;
    }

private:
    // the bits a register word holds; 0 for a word that is not a register word
    static uint32_t mask(uint32_t offset) {
        switch (offset) {
%s
            default: return 0u;
        }
    }
    uint32_t at(uint32_t offset) const { return w_[(offset - 0x%02Xu) / 4]; }
    uint64_t pair(uint32_t offset) const { return (uint64_t(at(offset + 4)) << 32) | at(offset); }

    uint32_t w_[(0x%02Xu - 0x%02Xu) / 4] = {};  // the words 0x%02X .. 0x%02X, 0 at power-up
    uint32_t ctrl_ = 0;                    // block control: stopped at power-up
};

}  // namespace lxt

#endif  // LASERAX_SYSMODEL_LASERAX_AXIL_CALL_H
""" % (GENERATED_NOTE, FIRST_OFFSET, "\n".join(args), "\n".join(masks), FIRST_OFFSET, end, FIRST_OFFSET,
       FIRST_OFFSET, end - 4)


def gen_c_h(regs):
    end = max(r.offset + r.span for r in regs)
    defs = []
    xs = []
    for r in regs:
        u = "LASERAX_REG_" + r.upper
        defs.append("/* %s: %s */" % (r.name, r.description.replace("*/", "* /")))
        defs.append("#define %s_OFFSET 0x%02Xu" % (u, r.offset))
        defs.append("#define %s_WIDTH %d" % (u, r.width))
        defs.append("#define %s_WORDS %d" % (u, r.words))
        defs.append("#define %s_SIGNED %d" % (u, 1 if r.signed else 0))
        defs.append("#define %s_RESET %s" % (u, c_ll(r.reset)))
        if not r.any_range:
            defs.append("#define %s_MIN %s" % (u, c_ll(r.eff_min)))
            defs.append("#define %s_MAX %s" % (u, c_ll(r.eff_max)))
        if r.step != 1:
            defs.append("#define %s_STEP %d" % (u, r.step))
        xs.append("    X(%s, 0x%02Xu, %d, %d, %s)" % (r.upper, r.offset, r.width, 1 if r.signed else 0, c_ll(r.reset)))
    return """/* laserax_regs_c.h — the laserax s_axilite register map for C firmware (docs/REGISTERS.md).
 *
 * %s
 *
 * Byte offsets on the AXI-lite slave (bundle ctrl). A register wider than 32 bits takes WORDS
 * consecutive 32-bit words, low word first; the word after them is reserved (Vitis HLS control
 * word). Pulse registers: write 1, then 0. RESET is the value
 * (sign-extended for SIGNED registers); MIN/MAX/STEP are given where the range is restricted.
 */
#ifndef LASERAX_REGS_C_H
#define LASERAX_REGS_C_H

#define LASERAX_REG_FIRST_OFFSET 0x%02Xu
#define LASERAX_REG_END_OFFSET 0x%02Xu
#define LASERAX_REG_COUNT %d

%s

/* X-macro over every register: X(NAME, OFFSET, WIDTH, SIGNED, RESET) */
#define LASERAX_REGS(X) \\
%s

#endif /* LASERAX_REGS_C_H */
""" % (GENERATED_NOTE, FIRST_OFFSET, end, len(regs), "\n".join(defs), " \\\n".join(xs))


# ---- rtl_ref/laserax_regs.v: the AXI4-Lite slave ------------------------------------------------
RTL_ADDR_W = 12  # default of the slave's ADDR_W parameter (byte address bits)


def rtl_map_addr_w(regs):
    """Byte address bits needed to reach every word of the map (the last reserved word)."""
    end = max(r.offset + r.span for r in regs)
    return max(3, (end - 1).bit_length())


def v_range(width):
    return "" if width == 1 else "[%d:0]" % (width - 1)


def v_const(r, v):
    """Sized Verilog literal of value v in the register's width (two's complement bits)."""
    if v >= 0:
        return "%d'd%d" % (r.width, v)
    return "%d'h%X" % (r.width, r.bits(v))


def rtl_words(r):
    """[(localparam, byte offset, reg lo bit, reg hi bit)] of the register's data words."""
    out = []
    for w, (off, lo, hi) in enumerate(word_ranges(r)):
        name = "A_%s" % r.upper if r.words == 1 else "A_%s_%d" % (r.upper, w)
        out.append((name, off, lo, hi))
    return out


def gen_rtl_regs(regs):
    end = max(r.offset + r.span for r in regs)
    map_aw = rtl_map_addr_w(regs)
    q = lambda r: "reg_%s_q" % r.name
    d = lambda r: "reg_%s_d" % r.name
    wen = lambda a: "wen_" + a[2:].lower()  # A_RATIO_1 -> wen_ratio_1: write of that word now
    rdw = lambda a: "rdw_" + a[2:].lower()  # the word as read

    ports = []
    for i, r in enumerate(regs):
        decl = "output wire %s%s" % ("signed " if r.signed else "", v_range(r.width))
        sep = "," if i + 1 < len(regs) else ""
        ports.append("    %-25s %-18s // 0x%02X %s, reset %d" % (decl, "o_%s%s" % (r.name, sep), r.offset, r.access, r.reset))
    params = []
    for r in regs:
        for name, off, lo, hi in rtl_words(r):
            what = r.name if r.words == 1 else "%s bits %d..%d" % (r.name, hi, lo)
            params.append("    localparam [WA_W-1:0] %-16s = %-4s // 0x%02X: %s" % (name, "%d;" % (off // 4), off, what))
    decls = []
    for r in regs:
        sg = "signed " if r.signed else "       "
        decls.append("    reg  %s%-7s %s;" % (sg, v_range(r.width), q(r)))
    nexts = []
    for r in regs:
        words = rtl_words(r)
        for name, off, lo, hi in words:
            nexts.append("    wire %s = wr_fire && wr_word == %s;" % (wen(name), name))
        slices = []  # high bits first
        for name, off, lo, hi in reversed(words):
            for lane in reversed(range(4)):
                blo, bhi = lo + 8 * lane, min(hi, lo + 8 * lane + 7)
                if blo > bhi:
                    continue
                dlo, dhi = blo - lo, bhi - lo
                cur = q(r) if r.width == 1 else "%s[%d]" % (q(r), blo) if blo == bhi else "%s[%d:%d]" % (q(r), bhi, blo)
                src = "wr_data[%d]" % dlo if dlo == dhi else "wr_data[%d:%d]" % (dhi, dlo)
                slices.append("(%s && wr_strb[%d]) ? %s : %s" % (wen(name), lane, src, cur))
        sg = "signed " if r.signed else ""
        if len(slices) == 1:
            nexts.append("    wire %s%s%s = %s;" % (sg, v_range(r.width) + " " if r.width > 1 else "", d(r), slices[0]))
        else:
            nexts.append("    wire %s%s %s = {" % (sg, v_range(r.width), d(r)))
            nexts.extend("        %s%s" % (x, "," if i + 1 < len(slices) else "};") for i, x in enumerate(slices))
    reads = []
    rdws = []
    for r in regs:
        for name, off, lo, hi in rtl_words(r):
            n = hi - lo + 1
            src = q(r) if r.words == 1 else "%s[%d:%d]" % (q(r), hi, lo)
            val = src if n == 32 else "{%d'd0, %s}" % (32 - n, src)
            rdws.append("    wire [31:0] %-20s = %s;" % (rdw(name), val))
            reads.append("            %-18s rd_word = %s;" % (name + ":", rdw(name)))
    resets = ["            %s <= %s;   // %d" % (q(r), v_const(r, r.reset), r.reset) if r.reset < 0 else
              "            %s <= %s;" % (q(r), v_const(r, r.reset)) for r in regs]
    updates = ["            %s <= %s;" % (q(r), d(r)) for r in regs]
    assigns = ["    assign o_%s = %s;" % (r.name, q(r)) for r in regs]
    return """// %s
// laserax_regs.v — the laserax register map (docs/REGISTERS.md) as an AXI4-Lite slave: every
// register of regmap/laserax_regs.csv at its byte offset, with its width and reset value, drives
// one output port o_<name> (the i_<name> input of laserax_top; rtl_ref/laserax_axil.v wires the two).
//
// Bus: AXI4-Lite, 32-bit data, ADDR_W-bit byte addresses (AWPROT/ARPROT are not used).
//   write   AW and W are accepted independently, in the same cycle or in different ones (AWREADY =
//           no address held and no response pending, WREADY likewise). The write takes effect at
//           the rising edge at which the later of the two handshakes completes; BVALID rises at
//           that same edge (BRESP = OKAY) and AWREADY/WREADY stay 0 until the B handshake (one
//           write outstanding). o_<name> has the new value after that edge, so laserax_top uses
//           it from the following edge on (a write completing at edge t acts in call t+1).
//   strobe  WSTRB[i] writes byte i of the word; bits above a register's width are dropped; a
//           register wider than 32 bits takes consecutive words, low word first.
//   read    ARREADY = !RVALID. At the edge of the AR handshake RDATA is registered from the
//           registers before that edge (a write completing at the same edge is not seen) and
//           RVALID rises; it stays until the R handshake (RRESP = OKAY). A register word reads
//           its bits with 0 above the register's width, signed registers too (as the Vitis HLS
//           slave: sign-extend from the width in software).
//   other   0x00..0x%02X, the reserved word after each register and every address from 0x%02X on
//           read 0 and ignore writes, with an OKAY response (no SLVERR). Address bits [1:0] are
//           ignored. Pulse and table-port registers hold what the host wrote (the core acts on
//           the level; nothing clears them).
// i_rst (synchronous, active high): every register at its reset value, no transaction held.
`timescale 1ns / 1ps
`default_nettype none

module laserax_regs #(
    // ADDR_W: byte address width, %d..32 (the map ends at 0x%02X); addresses past the map read 0
    parameter integer ADDR_W = %d
) (
    input  wire              i_clk,
    input  wire              i_rst,            // synchronous, active high: reset values
    // AXI4-Lite slave
    input  wire [ADDR_W-1:0] s_axil_awaddr,
    input  wire              s_axil_awvalid,
    output wire              s_axil_awready,
    input  wire [31:0]       s_axil_wdata,
    input  wire [3:0]        s_axil_wstrb,
    input  wire              s_axil_wvalid,
    output wire              s_axil_wready,
    output wire [1:0]        s_axil_bresp,
    output wire              s_axil_bvalid,
    input  wire              s_axil_bready,
    input  wire [ADDR_W-1:0] s_axil_araddr,
    input  wire              s_axil_arvalid,
    output wire              s_axil_arready,
    output wire [31:0]       s_axil_rdata,
    output wire [1:0]        s_axil_rresp,
    output wire              s_axil_rvalid,
    input  wire              s_axil_rready,
    // registers, offset order
%s
);

    localparam integer MAP_ADDR_W = %d;       // byte address bits of the map (0x00 .. 0x%02X)
    localparam integer WA_W       = ADDR_W - 2;  // word address bits
    localparam [1:0]   RESP_OKAY  = 2'b00;

    generate
        if (ADDR_W < MAP_ADDR_W || ADDR_W > 32) begin : g_bad_addr_w
            laserax_regs_PARAMETER_ADDR_W_must_be_%d_to_32 u_param_error ();
        end
    endgenerate

    // ---- word addresses (byte offset / 4) of the register words --------------------------------
%s

    // ---- write channel: address and data held until both are there -----------------------------
    reg              aw_full_q;                  // address accepted, data not yet
    reg [WA_W-1:0]   aw_word_q;
    reg              w_full_q;                   // data accepted, address not yet
    reg [31:0]       w_data_q;
    reg [3:0]        w_strb_q;
    reg              bvalid_q;
    wire             aw_hs     = s_axil_awvalid && s_axil_awready;
    wire             w_hs      = s_axil_wvalid && s_axil_wready;
    wire             wr_fire   = (aw_full_q || aw_hs) && (w_full_q || w_hs);   // the write edge
    wire [WA_W-1:0]  wr_word   = aw_full_q ? aw_word_q : s_axil_awaddr[ADDR_W-1:2];
    wire [31:0]      wr_data   = w_full_q ? w_data_q : s_axil_wdata;
    wire [3:0]       wr_strb   = w_full_q ? w_strb_q : s_axil_wstrb;
    wire             aw_full_d = (aw_full_q || aw_hs) && !wr_fire;
    wire             w_full_d  = (w_full_q || w_hs) && !wr_fire;
    wire             bvalid_d  = wr_fire || (bvalid_q && !s_axil_bready);

    assign s_axil_awready = !aw_full_q && !bvalid_q;
    assign s_axil_wready  = !w_full_q && !bvalid_q;
    assign s_axil_bvalid  = bvalid_q;
    assign s_axil_bresp   = RESP_OKAY;

    // ---- read channel ----------------------------------------------------------------------------
    reg              rvalid_q;
    reg [31:0]       rdata_q;
    wire             ar_hs    = s_axil_arvalid && s_axil_arready;
    wire [WA_W-1:0]  rd_addr  = s_axil_araddr[ADDR_W-1:2];
    wire             rvalid_d = ar_hs || (rvalid_q && !s_axil_rready);

    assign s_axil_arready = !rvalid_q;
    assign s_axil_rvalid  = rvalid_q;
    assign s_axil_rdata   = rdata_q;
    assign s_axil_rresp   = RESP_OKAY;

    // ---- registers -------------------------------------------------------------------------------
%s

    // next state: the bytes of the addressed word that WSTRB selects, at the write edge; a write
    // to a reserved or unmapped word enables nothing
%s

    // read data: the addressed word, 0 above the register's width; 0 for any other address
%s
    reg [31:0] rd_word;
    always @* begin
        case (rd_addr)
%s
            default:           rd_word = 32'd0;
        endcase
    end

    always @(posedge i_clk) begin
        if (i_rst) begin
            aw_full_q <= 1'b0;
            aw_word_q <= {WA_W{1'b0}};
            w_full_q  <= 1'b0;
            w_data_q  <= 32'd0;
            w_strb_q  <= 4'd0;
            bvalid_q  <= 1'b0;
            rvalid_q  <= 1'b0;
            rdata_q   <= 32'd0;
%s
        end else begin
            aw_full_q <= aw_full_d;
            if (aw_hs) aw_word_q <= s_axil_awaddr[ADDR_W-1:2];
            w_full_q  <= w_full_d;
            if (w_hs) begin
                w_data_q <= s_axil_wdata;
                w_strb_q <= s_axil_wstrb;
            end
            bvalid_q  <= bvalid_d;
            rvalid_q  <= rvalid_d;
            if (ar_hs) rdata_q <= rd_word;
%s
        end
    end

%s

endmodule

`default_nettype wire
""" % (GENERATED_NOTE, FIRST_OFFSET - 1, end, map_aw, end, RTL_ADDR_W, "\n".join(ports), map_aw, end - 1, map_aw,
       "\n".join(params), "\n".join(decls), "\n".join(nexts), "\n".join(rdws), "\n".join(reads),
       "\n".join(resets), "\n".join(updates), "\n".join(assigns))


def md_escape(s):
    return s.replace("|", "\\|")


def legal_text(r):
    if r.any_range and r.step == 1:
        parts = ["any"]
    elif r.any_range:
        parts = ["multiple of %d" % r.step]
    else:
        parts = ["%d .. %d" % (r.eff_min, r.eff_max)]
        if r.step != 1:
            parts[0] += ", step %d" % r.step
    if r.rule:
        parts.append(r.rule)
    text = "; ".join(parts)
    if r.check == "cfg":
        text += " (else cfg_err)"
    elif r.check == "map":
        text += " (else map_cfg_err)"
    return md_escape(text)


def gen_md(regs):
    rows = []
    for r in regs:
        off = "0x%02X" % r.offset if r.words == 1 else "0x%02X..0x%02X" % (r.offset, r.reserved - 1)
        w = "%d%s" % (r.width, " signed" if r.signed else "")
        hexv = "0x%X" % r.bits(r.reset)
        rows.append("| %s | `%s` | %s | %s | %d (%s) | %s | %s | %s |" %
                    (off, r.name, w, r.access, r.reset, hexv, md_escape(r.units), legal_text(r), md_escape(r.description)))
    wide = [r for r in regs if r.words > 1]
    words = []
    for r in wide:
        words.append("  * `%s`: %s" % (r.name, ", ".join("0x%02X = bits %d..%d" % (o, lo, hi) for o, lo, hi in word_ranges(r))))
    pulses = ", ".join("`%s`" % r.name for r in regs if r.access == "pulse")
    ports = ", ".join("`%s`" % r.name for r in regs if r.access == "port")
    end = max(r.offset + r.span for r in regs)
    used = set()
    for r in regs:
        for w in range(r.words + 1):
            used.add(r.offset + 4 * w)
    gaps = ["0x%02X" % o for o in range(FIRST_OFFSET, end, 4) if o not in used]
    return """<!-- %s -->
# laserax register map (s_axilite)

Generated from [`regmap/laserax_regs.csv`](../regmap/laserax_regs.csv), the single source of the
register map: the Vitis HLS top (`hls/laserax_axil.cpp`, one s_axilite scalar per register at the
offsets below), the constants in `hls/laserax_regmap.h` and `host/laserax_regs_c.h`, the
host table and accessors (`host/regmap_table.h`, used by the register image and the
physical <-> register helper in `host/regmap.h`) and this page are all written by
`%s`.
Edit the CSV, never the generated files; CTest `regmap_generated` fails until they are regenerated.

Conventions:

* Byte offsets on the AXI4-lite slave `s_axi_ctrl` (bundle `ctrl`); the first register is at 0x%02X
  (Vitis HLS reserves 0x00..0x0F of an s_axilite slave for its block-control registers: the
  top's return is on this slave; software writes 0x81 = ap_start | auto_restart to 0x00 once,
  then the II = 1 pipeline runs one call per clock; the reference RTL `laserax_regs.v` has no
  such word). The word after each register's data words is reserved: Vitis
  HLS keeps one control word per s_axilite scalar, even with `ap_none` (UG1399, "S_AXILITE Offset
  Option"), so a register of W bits occupies ceil(W/32) + 1 words. Other unused words: %s.
  Write 0 to reserved words.
* A register wider than 32 bits takes consecutive 32-bit words, **low word first**; write the low
  word, then the high word. The core reads the registers every clock (a value presented in one
  clock is in force in the chain from the next: the register stage of DESIGN 4.7), so between
  the two writes it would see a mixed value. For `ratio` and `comp_offset`, which change while the axis moves,
  set `comp_sync` = 1 once: the multiplier then keeps the pair in force until a clock with
  `comp_commit` = 1, which loads both together (write the words of both, then pulse
  `comp_commit`; `lxt::compensation_writes` does exactly this). The map origins change through
  the bank flip (`bank_sel`), which is atomic already. The wide registers:
%s
* Signed registers are two's complement in their width; the bits above the width in the high
  word are ignored (write the sign extension or 0).
* `access`:
  * `rw` — a setting, read every clock;
  * `pulse` — the host writes 1, then 0; the action happens in every clock the register is 1 (the
    core acts on the level): %s;
  * `port` — fields of a table write port: set address and data, then write enable 1, then 0;
    the word is written in every clock the enable is 1: %s.
* Legal range: a `cfg` register outside its range (or its rule) puts the whole chain in the safe
  state with status `cfg_err` (DESIGN §4.7); a `map` register outside its range gives the status
  bit `map_cfg_err` while `map_en` and that bank is selected, and the map is inactive
  ([ERROR_MAP.md](ERROR_MAP.md) §4.5); `any` is every value of the width.
* Reset: the values after power-up; they are the default member values of `lx::axis_regs`,
  `golden::axis_regs` and the host settings `lxt::axis_settings` (checked by `tb_regmap`).
  These are the reset values of the **RTL IP** (`rtl_ref/laserax_regs.v`, `rtl_ref/laserax_axil.v`)
  and of the C++ models. The **HLS IP** made from `hls/laserax_axil.cpp` cannot have them: an
  s_axilite scalar argument has no initial value in Vitis HLS, so its registers start at **0**
  after power-up. With those zeros the configuration check fails (`period`, `ratio` and others
  are 0), so the core sits in the safe state with `cfg_err` set (no count is taken), until software
  writes the whole register image, then starts the block (0x81 to 0x00). A host driving the HLS
  IP must therefore write every register once before the start, not only those it changes:
  `lxt::init_registers(image, write)` (`host/ip_init.h`; `image` e.g. `lxt::axis_settings{}`, the
  reset values, or a `reg_image`) writes it through the caller's register-write function, in this
  order: `comp_sync` = 1; every other register but `comp_commit` in offset order, low word first
  (the reserved words are not written); `comp_commit` = 1, then 0; `comp_sync` = 0 last, whatever
  the image holds (a core that has not run yet loads `ratio` / `comp_offset` into its pair in
  force only in a call with `comp_sync` = 0: it cannot see a commit made before the start). Then
  `lxt::start_core(write)` writes 0x81 to 0x00; writes that need a running core come after it
  (`comp_sync` = 1 with `lxt::compensation_writes`, `lxt::program_dds` for a table other than the
  power-up one, `lxt::program_map`). An image with a pulse register or a table write enable at 1
  is refused. The same sequence is correct for the RTL IP (its slave ignores the write to 0x00).
  `tb_hls_csim` (the Vitis C-simulation testbench) brings the HLS top up this way through a model
  of its slave whose registers start at 0 (`sysmodel/laserax_axil_call.h`) and checks that the core
  stays in the safe state without the call and leaves it in the call after the register stage
  with it.

| offset | name | width | access | reset | units | legal | description |
|---|---|---|---|---|---|---|---|
%s

Cross-register rules (checked by the configuration check every clock, DESIGN §4.7):
`tbl_period == period`, `period/4 <= mark_len <= period`, `amplitude <= 2^(dac_width-1) - 1`,
`max(glitch_n, 1) < min_spacing` (count integrity, DESIGN §4.2: a pulse that passes the glitch
filter and would change the count is always caught by the edge spacing check, `ovs_edge_st`).
Table load (DESIGN §4.6, §4.7; `lxt::program_dds` writes exactly this sequence): `tbl_period` = 0
first (the configuration is invalid from the next call on: safe state, `cfg_err`, so the DDS
never reads a half-written table), then per word k = 0 .. P/4-1 `tbl_addr` = k, `tbl_data` =
rha(amplitude * sin(2 pi k / P)), `tbl_we` = 1, `tbl_we` = 0, then `period`, `mark_len`,
`dac_width`, `amplitude`, and `tbl_period` = P last (P + 6 writes). The chain is in the safe
state from the call after the first write up to the call of the last one, one window whatever the
old and new values, and then restarts from reset with the new period: un-homed until the next
rising edge of the switch. The same sequence loads a new amplitude at the same period.
Error-map reload (docs/ERROR_MAP.md §4.4): write the geometry (`map_originB`, `map_kB`,
`map_nB`) of the bank B not selected by `bank_sel` and its words through
`map_we/map_addr/map_data`, then flip `bank_sel`.

Status and taps are not registers of this map: they are output wires of the top (`lx::axis_out`,
DESIGN §5).

Host helper: `host/regmap.h` keeps a register image (32-bit words by offset) with
write/read by name, converts it to and from the host settings `lxt::axis_settings`
(`sysmodel/model_regs.h`: to and from `lx::axis_regs` / `golden::axis_regs`), and converts
physical settings (air temperature, pressure, humidity, CO2, expansion coefficient, material
temperature, thermal origin, error-map table) to register values and back; `laserax compensate`
prints the resulting register writes (`--regs-out FILE` writes them as `offset name value`).
It also writes the bus sequences that change registers the core must not see half-updated: the
compensation pair (`compensation_writes`), an error-map bank (`program_map`) and the DDS table
with its period (`program_dds`, the table load above), and the whole image before the core is
started (`init_registers`, `host/ip_init.h`: see Reset above).

## RTL slave (`rtl_ref/laserax_regs.v`)

The Verilog reference of this map, generated from the CSV with the other files: an AXI4-Lite
slave (32-bit data, parameter `ADDR_W` = %d byte-address bits by default, %d .. 32 allowed: the map
ends at 0x%02X) that holds every register at its reset value and drives one output `o_<name>` per
register (its width, `signed` where the table says so). `rtl_ref/laserax_axil.v` wires it to the
`i_<name>` inputs of `laserax_top` (the IP top).

* Write: AW and W are accepted independently, in the same cycle or in either order (`AWREADY` =
  no address held and no response pending, `WREADY` likewise; one write outstanding). The write
  takes effect at the rising edge at which the later of the two handshakes completes; `BVALID`
  rises at that edge and the next write is accepted after the B handshake (back to back with
  `BREADY` = 1: one write every 2 clocks). **Latency**: with `AWVALID` and `WVALID` raised
  together on an idle slave, the register (and `o_<name>`) changes at the first rising edge, and
  the core uses the new value from the next edge on: a write whose handshake completes at edge t
  acts in call t+1 of `laserax_top::step()` (CTest `rtl_laserax_axil` checks exactly this).
* `WSTRB` writes the selected bytes of the word; bits above a register's width are dropped; a
  register wider than 32 bits takes its words low word first at its offsets (each word on its own:
  the core sees the mixed value between two word writes, hence `comp_sync` / `comp_commit`).
* Read: `ARREADY` = not `RVALID`; `RDATA` is registered at the AR handshake edge from the registers
  before that edge (a write completing at the same edge is not seen); `RVALID` holds until the R
  handshake (one read every 2 clocks). A register word reads its bits, **zero above the register's
  width**, signed registers too (as the Vitis HLS slave; sign-extend from the width in software,
  `lxt::regmap::from_bits`).
* Reserved words (the word after each register), 0x00 .. 0x%02X and addresses from 0x%02X on
  read 0; writes to them are ignored. Every response is OKAY (no SLVERR), as the Vitis HLS
  s_axilite slave. Address bits [1:0] are ignored (AXI4-Lite transfers are word aligned).
* The pulse registers (`%s`) and the table-port fields hold
  what the host wrote; the slave clears nothing (the core acts on the level, see `access` above).
* `i_rst` (synchronous, active high): every register at its reset value, no transaction held.
""" % (GENERATED_NOTE, COMMAND, FIRST_OFFSET, ", ".join(gaps) if gaps else "none",
       "\n".join(words), pulses, ports, "\n".join(rows), RTL_ADDR_W, rtl_map_addr_w(regs), end,
       FIRST_OFFSET - 1, end, "`, `".join(r.name for r in regs if r.access == "pulse"))


def generate(regs):
    files = {
        "hls/laserax_axil.h": gen_top_h(regs),
        "hls/laserax_axil.cpp": gen_top_cpp(regs),
        "hls/laserax_regmap.h": gen_regmap_h(regs),
        "host/regmap_table.h": gen_table_h(regs),
        "host/regmap_table.cpp": gen_table_cpp(regs),
        "sysmodel/regmap_models.h": gen_models_h(regs),
        "sysmodel/regmap_models.cpp": gen_models_cpp(regs),
        "sysmodel/laserax_axil_call.h": gen_top_call_h(regs),
        "host/laserax_regs_c.h": gen_c_h(regs),
        "docs/REGISTERS.md": gen_md(regs),
        "rtl_ref/laserax_regs.v": gen_rtl_regs(regs),
    }
    for rel, text in files.items():
        if rel.startswith("hls/"):
            for no, line in enumerate(text.split("\n"), start=1):
                m = HLS_FORBIDDEN.search(line)
                if m:
                    raise CsvError(rel, no, "generated hls text contains '%s' (hls lint); reword the CSV" % m.group(1))
    return files


# ------------------------------------------------------------------------------------------------
# self-test: malformed CSVs must be rejected with FILE:LINE: message
# ------------------------------------------------------------------------------------------------
def selftest():
    with open(os.path.join(ROOT, CSV_REL), "r", encoding="utf-8") as f:
        good = f.read().split("\n")
    data = [i for i, l in enumerate(good) if l.strip() and not l.startswith("#")]
    hdr, first, second = data[0], data[1], data[2]

    def edit(row_i, col, value):
        lines = list(good)
        row = next(csv.reader([lines[row_i]]))
        row[COLUMNS.index(col)] = value
        lines[row_i] = ",".join('"%s"' % c if "," in c else c for c in row)
        return lines

    def field(row_i, col):
        return next(csv.reader([good[row_i]]))[COLUMNS.index(col)]

    second_off = int(field(second, "offset"), 16)
    ranged = next(i for i in data[1:] if field(i, "min") not in ("-", "0"))  # a row with a lower bound
    dup = list(good)
    dup.insert(second + 1, good[second])
    wide = next(i for i in data[1:] if int(field(i, "width")) > 32)  # a register of two words
    clash = list(good)  # a one-word register named <wide>_1 at a free offset after the map
    end_off = max(int(field(i, "offset"), 16) + 4 * ((int(field(i, "width")) + 31) // 32 + 1) for i in data[1:])
    row = next(csv.reader([good[first]]))
    row[COLUMNS.index("name")] = field(wide, "name") + "_1"
    row[COLUMNS.index("offset")] = "0x%X" % end_off
    row[COLUMNS.index("hls_member")] = "clash_member"
    row[COLUMNS.index("golden_member")] = "-"
    clash.insert(data[-1] + 1, ",".join('"%s"' % c if "," in c else c for c in row))
    cases = [  # (name, lines, line number expected in the message, word expected)
        ("overlap", edit(second, "offset", "0x%X" % int(field(first, "offset"), 16)), second + 1, "overlaps"),
        ("misaligned", edit(second, "offset", "0x%X" % (second_off + 2)), second + 1, "aligned"),
        ("on_reserved_word", edit(second, "offset", "0x%X" % (int(field(first, "offset"), 16) + 4)), second + 1, "reserved"),
        ("below_first", edit(first, "offset", "0x0C"), first + 1, "below"),
        ("reset_out_of_width", edit(first, "reset", "999999"), first + 1, "does not fit"),
        ("reset_illegal", edit(ranged, "reset", str(int(field(ranged, "min")) - 1)), ranged + 1, "not legal"),
        ("duplicate_name", dup, second + 2, "duplicate"),
        ("rtl_word_clash", clash, data[-1] + 2, "clashes"),
        ("width_zero", edit(first, "width", "0"), first + 1, "width"),
        ("width_65", edit(first, "width", "65"), first + 1, "width"),
        ("bad_check", edit(first, "check", "maybe"), first + 1, "check"),
        ("bad_access", edit(first, "access", "wo"), first + 1, "access"),
        ("bad_signed", edit(first, "signed", "x"), first + 1, "signed"),
        ("bad_offset", edit(first, "offset", "16"), first + 1, "hex"),
        ("min_gt_max", edit(first, "min", "5000"), first + 1, "min"),
        ("bad_header", [l if i != hdr else l.replace("reset", "rst") for i, l in enumerate(good)], hdr + 1, "header"),
        ("few_columns", [l if i != first else l.rsplit(",", 3)[0] for i, l in enumerate(good)], first + 1, "columns"),
    ]
    fails = 0
    with tempfile.TemporaryDirectory(prefix="gen_regmap_selftest_") as tmp:
        def run(lines, name):
            path = os.path.join(tmp, name + ".csv")
            with open(path, "w", encoding="utf-8") as f:
                f.write("\n".join(lines))
            out = os.path.join(tmp, "out_" + name)
            p = subprocess.run([sys.executable, os.path.abspath(__file__), "--csv", path, "--out-dir", out],
                               capture_output=True, text=True)
            return p.returncode, p.stdout + p.stderr, path, out

        rc, msg, _, out = run(good, "good")
        if rc != 0 or not os.path.exists(os.path.join(out, "hls/laserax_axil.cpp")):
            fails += 1
            print("selftest: the committed CSV is rejected (exit %d): %s" % (rc, msg.strip()))
        for name, lines, line, word in cases:
            rc, msg, path, out = run(lines, name)
            want = "%s:%d:" % (path, line)
            ok = rc == 1 and want in msg and word in msg and not os.path.exists(out)
            if not ok:
                fails += 1
                print("selftest: case %s: expected exit 1 with '%s ... %s', got exit %d: %s" % (name, want, word, rc, msg.strip()))
            else:
                print("selftest: %-20s rejected: %s" % (name, msg.strip().replace(tmp + "/", "")))
    n = len(cases) + 1
    if fails:
        print("regmap_generator_selftest: FAIL (%d of %d cases)" % (fails, n))
        return 1
    print("regmap_generator_selftest: PASS (%d cases)" % n)
    return 0


# ------------------------------------------------------------------------------------------------
def main():
    ap = argparse.ArgumentParser(description="laserax register map generator", add_help=True)
    ap.add_argument("--csv", default=None, help="register map CSV (default %s)" % CSV_REL)
    ap.add_argument("--out-dir", default=None, help="root of the generated files (default: the repository root)")
    ap.add_argument("--check", action="store_true", help="compare with the files on disk, write nothing")
    ap.add_argument("--selftest", action="store_true", help="run the malformed-CSV self-test")
    a = ap.parse_args()
    if a.selftest:
        return selftest()
    csv_path = a.csv if a.csv is not None else os.path.join(ROOT, CSV_REL)
    shown = os.path.relpath(csv_path, ROOT) if a.csv is None else csv_path
    out_dir = a.out_dir if a.out_dir is not None else ROOT
    try:
        regs = load(csv_path)
        files = generate(regs)
    except CsvError as e:
        msg = str(e)
        if a.csv is None and msg.startswith(csv_path):
            msg = shown + msg[len(csv_path):]
        print("gen_regmap.py: error: %s" % msg, file=sys.stderr)
        return 1
    if a.check:
        bad = 0
        for rel, text in sorted(files.items()):
            path = os.path.join(out_dir, rel)
            try:
                with open(path, "r", encoding="utf-8", newline="") as f:
                    disk = f.read()
            except OSError:
                disk = None
            if disk == text:
                continue
            bad += 1
            if disk is None:
                print("gen_regmap.py --check: %s is missing" % rel)
                continue
            print("gen_regmap.py --check: %s differs from what %s generates:" % (rel, shown))
            diff = list(difflib.unified_diff(disk.split("\n"), text.split("\n"), "committed/" + rel, "generated/" + rel,
                                             n=1, lineterm=""))
            for line in diff[:40]:
                print("    " + line)
            if len(diff) > 40:
                print("    ... (%d more diff lines)" % (len(diff) - 40))
        if bad:
            print("regmap_generated: FAIL (%d of %d files differ; run %s)" % (bad, len(files), COMMAND))
            return 1
        print("regmap_generated: PASS (%d registers, %d generated files up to date)" % (len(regs), len(files)))
        return 0
    written = 0
    for rel, text in sorted(files.items()):
        path = os.path.join(out_dir, rel)
        try:
            with open(path, "r", encoding="utf-8", newline="") as f:
                if f.read() == text:
                    continue
        except OSError:
            pass
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
        written += 1
        print("gen_regmap.py: wrote %s" % rel)
    print("gen_regmap.py: %d registers, %d files (%d changed)" % (len(regs), len(files), written))
    return 0


if __name__ == "__main__":
    sys.exit(main())
