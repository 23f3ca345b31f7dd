#!/usr/bin/env python3
"""check_rtl_widths.py — the rtl_ref/ port widths come from rtl_ref/laserax_widths.vh.

Every rtl_ref/*.v block declares its ports with the width macros (`LX_*) of the generated header
rtl_ref/laserax_widths.vh (tools/rtl_widths.cpp writes it from the configuration structs of hls/;
tb_generated_files checks that it is up to date), or with its own parameters. This check fails on:
  * a port whose range holds a number other than the 0 of [..:0] (a retyped width),
  * a block that uses `LX_ macros without `include "laserax_widths.vh",
  * a macro that the header does not define.
Not checked: formal-only ports (inside `ifdef FORMAL), the AXI4-Lite protocol ports s_axil_* (their
widths are the protocol's: 32-bit data, 4 strobes, 2-bit responses), and rtl_ref/laserax_regs.v,
which scripts/gen_regmap.py generates from the register map regmap/laserax_regs.csv.

Usage: check_rtl_widths.py [--selftest] [ROOT]
"""
import os
import re
import sys
import tempfile

EXEMPT_FILES = {"laserax_regs.v"}   # generated from regmap/laserax_regs.csv (its own single source)
PORT_RE = re.compile(r"^\s*(input|output)\s+wire\s+(?:signed\s+)?\[([^\]]+)\]\s*(\w+)", re.M)


def module_headers(text):
    """The text of every `module NAME ... );` header, comments and `ifdef FORMAL parts removed."""
    out = []
    for m in re.finditer(r"^module\s+(\w+)\b.*?^\);", text, re.M | re.S):
        h = re.sub(r"//[^\n]*", "", m.group(0))
        h = re.sub(r"^\s*`ifdef\s+FORMAL\b.*?^\s*`endif", "", h, flags=re.M | re.S)
        out.append((m.group(1), h))
    return out


def check(root):
    rtl = os.path.join(root, "rtl_ref")
    with open(os.path.join(rtl, "laserax_widths.vh"), encoding="utf-8") as fh:
        macros = set(re.findall(r"^`define\s+(LX_\w+)\s+[0-9]+", fh.read(), re.M))
    errors, checked = [], 0
    for name in sorted(os.listdir(rtl)):
        if not name.endswith(".v") or name in EXEMPT_FILES:
            continue
        with open(os.path.join(rtl, name), encoding="utf-8") as fh:
            text = fh.read()
        used = set(re.findall(r"`(LX_\w+)", re.sub(r"//[^\n]*", "", text)))
        if used and '`include "laserax_widths.vh"' not in text:
            errors.append("%s: uses `LX_ macros without `include \"laserax_widths.vh\"" % name)
        for u in sorted(used - macros):
            errors.append("%s: `%s is not defined in rtl_ref/laserax_widths.vh" % (name, u))
        for module, header in module_headers(text):
            for _, rng, port in PORT_RE.findall(header):
                checked += 1
                if port.startswith("s_axil_"):
                    continue
                hi, _, lo = rng.partition(":")
                if re.search(r"\b[0-9]+\b", hi) and not re.search(r"[`A-Za-z_]", hi) or lo.strip() != "0":
                    errors.append("%s: module %s, port %s [%s]: a literal width; use a `LX_ macro of "
                                  "laserax_widths.vh (or a parameter)" % (name, module, port, rng))
    return errors, checked


def selftest():
    ok = True
    good = ('`default_nettype none\n`include "laserax_widths.vh"\nmodule good (\n'
            '    input  wire [`LX_W_POS-1:0] i_p,\n    input  wire [W-1:0] i_q,\n'
            '`ifdef FORMAL\n    , output wire [41:0] f_o\n`endif\n'
            '    input  wire [31:0] s_axil_wdata\n);\nendmodule\n')
    cases = [("clean block", good, True),
             ("literal width", good.replace("[`LX_W_POS-1:0]", "[37:0]"), False),
             ("missing include", good.replace('`include "laserax_widths.vh"\n', ""), False),
             ("unknown macro", good.replace("LX_W_POS", "LX_W_NOPE"), False),
             ("literal lsb", good.replace("[W-1:0]", "[W-1:1]"), False)]
    for what, text, want in cases:
        with tempfile.TemporaryDirectory() as d:
            os.mkdir(os.path.join(d, "rtl_ref"))
            with open(os.path.join(d, "rtl_ref", "laserax_widths.vh"), "w") as fh:
                fh.write("`define LX_W_POS 38\n")
            with open(os.path.join(d, "rtl_ref", "good.v"), "w") as fh:
                fh.write(text)
            errors, _ = check(d)
            got = not errors
            print("selftest: %-16s %s -> %s" % (what, "pass" if got else "fail", "ok" if got == want else "WRONG"))
            ok = ok and got == want
    print("selftest: %s" % ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


def main():
    args = sys.argv[1:]
    if args and args[0] == "--selftest":
        return selftest()
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    errors, checked = check(root)
    for e in errors:
        print("check_rtl_widths: " + e)
    if errors:
        print("check_rtl_widths: FAIL (%d problems)" % len(errors))
        return 1
    print("check_rtl_widths: PASS (%d vector ports of rtl_ref/*.v, widths from laserax_widths.vh)" % checked)
    return 0


if __name__ == "__main__":
    sys.exit(main())
