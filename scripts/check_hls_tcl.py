#!/usr/bin/python3
"""check_hls_tcl.py — the C-simulation file lists of scripts/run_hls.tcl must be the files that the
CMake target tb_hls_csim really compiles (CTest hls_tcl_files), so the Vitis flow cannot drift
from the tested build.

  check_hls_tcl.py --tcl scripts/run_hls.tcl --sources <build>/hls_csim_sources.txt [--root .]
  check_hls_tcl.py --selftest

hls_csim_sources.txt is written by CMake (file(GENERATE) of the SOURCES of tb_hls_csim, one
absolute path a line). The Tcl must hold `set design_files { ... }` (the hls/ files: the design)
and `set tb_files { ... }` (everything else: testbench and golden chain), add files only through
these two lists (no glob), and every listed file must exist. Exit 0 on a match, 1 otherwise, with
one line per difference. --selftest: a matching pair passes; a missing file, an extra file, a file
in the wrong list, a glob and a missing list each fail.
"""
import argparse
import os
import re
import sys
import tempfile


def tcl_list(text, name):
    m = re.search(r"^\s*set\s+%s\s+\{([^}]*)\}" % name, text, re.M)
    if not m:
        return None
    return [w for w in m.group(1).split() if w]


def check(tcl_path, sources_path, root):
    errors = []
    text = open(tcl_path, encoding="utf-8").read()
    code = "\n".join(line.split("#", 1)[0] if line.lstrip().startswith("#") else line
                     for line in text.splitlines())
    design = tcl_list(code, "design_files")
    tb = tcl_list(code, "tb_files")
    if design is None:
        errors.append("%s: no `set design_files { ... }` list" % tcl_path)
    if tb is None:
        errors.append("%s: no `set tb_files { ... }` list" % tcl_path)
    if re.search(r"\bglob\b", code):
        errors.append("%s: uses glob (the C-simulation files must be listed)" % tcl_path)
    for line in code.splitlines():
        if re.search(r"\badd_files\b", line) and not re.search(r"\$(design_files|tb_files)|\$f\b", line):
            errors.append("%s: add_files outside the two lists: %s" % (tcl_path, line.strip()))
    if errors:
        return errors
    built = []
    for line in open(sources_path, encoding="utf-8"):
        line = line.strip()
        if line:
            built.append(os.path.relpath(os.path.realpath(line), os.path.realpath(root)))
    want_design = sorted(f for f in built if f.startswith("hls/"))
    want_tb = sorted(f for f in built if not f.startswith("hls/"))
    for label, have, want in (("design_files", design, want_design), ("tb_files", tb, want_tb)):
        for f in sorted(set(want) - set(have)):
            errors.append("%s: %s lacks %s (compiled by tb_hls_csim)" % (tcl_path, label, f))
        for f in sorted(set(have) - set(want)):
            errors.append("%s: %s has %s (not compiled by tb_hls_csim)" % (tcl_path, label, f))
        if len(have) != len(set(have)):
            errors.append("%s: %s lists a file twice" % (tcl_path, label))
    for f in design + tb:
        if not os.path.isfile(os.path.join(root, f)):
            errors.append("%s: %s does not exist" % (tcl_path, f))
    return errors


GOOD = """set design_files {
    hls/top.cpp
}
set tb_files {
    tb/tb_x.cpp
    golden/a.cpp
}
foreach f $design_files { add_files $f -cflags $cflags }
foreach f $tb_files { add_files -tb $f -cflags $cflags }
"""


def selftest():
    failures = 0
    with tempfile.TemporaryDirectory() as d:
        for f in ("hls/top.cpp", "tb/tb_x.cpp", "golden/a.cpp", "golden/b.cpp"):
            os.makedirs(os.path.join(d, os.path.dirname(f)), exist_ok=True)
            open(os.path.join(d, f), "w").close()
        src = os.path.join(d, "sources.txt")
        with open(src, "w") as fh:
            for f in ("tb/tb_x.cpp", "golden/a.cpp", "hls/top.cpp"):
                fh.write(os.path.join(d, f) + "\n")
        cases = [
            ("matching lists", GOOD, True),
            ("missing file", GOOD.replace("    golden/a.cpp\n", ""), False),
            ("extra file", GOOD.replace("    golden/a.cpp\n", "    golden/a.cpp\n    golden/b.cpp\n"), False),
            ("file in the wrong list", GOOD.replace("    hls/top.cpp\n", "").replace(
                "    golden/a.cpp\n", "    golden/a.cpp\n    hls/top.cpp\n"), False),
            ("glob", GOOD + "foreach f [glob golden/*.cpp] { add_files -tb $f }\n", False),
            ("no tb list", GOOD.replace("set tb_files", "set other_files"), False),
            ("file that does not exist", GOOD.replace("golden/a.cpp", "golden/zz.cpp"), False),
        ]
        for name, text, ok in cases:
            tcl = os.path.join(d, "run.tcl")
            with open(tcl, "w") as fh:
                fh.write(text)
            errs = check(tcl, src, d)
            if (not errs) != ok:
                failures += 1
                print("selftest FAIL: %s: expected %s, got %s" % (name, "pass" if ok else "fail", errs or "pass"))
    print("hls_tcl_files_selftest: %s (%d cases)" % ("PASS" if failures == 0 else "FAIL", 7))
    return 1 if failures else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tcl")
    ap.add_argument("--sources")
    ap.add_argument("--root", default=".")
    ap.add_argument("--selftest", action="store_true")
    a = ap.parse_args()
    if a.selftest:
        return selftest()
    if not a.tcl or not a.sources:
        ap.error("--tcl and --sources are required")
    errs = check(a.tcl, a.sources, a.root)
    for e in errs:
        print(e)
    print("hls_tcl_files: %s" % ("PASS" if not errs else "FAIL (%d differences)" % len(errs)))
    return 1 if errs else 0


if __name__ == "__main__":
    sys.exit(main())
