#!/usr/bin/python3
"""check_hls_loops.py — every loop on the synthesis path of the HLS top carries the unroll
directives of both HLS tools (CTest hls_loops; issue 37 finding 7).

  check_hls_loops.py [--root DIR] [--cxx CXX]
  check_hls_loops.py --selftest

The top laserax_axil() is a pipeline at II = 1: a loop inside it must be fully unrolled. Vitis HLS
unrolls loops inside a pipelined function by itself (the project still writes `#pragma HLS
UNROLL` as the first line of the body), Catapult HLS only with `#pragma hls_unroll yes` on the line
before the loop (before its LX_LOOP label). The check preprocesses hls/laserax_axil.cpp as the
synthesis front ends see it (`-E -D__SYNTHESIS__`, the project's own integer types: the code under
`#ifndef __SYNTHESIS__` is gone), takes every `for`, `while` and `do` loop that comes from a file
under hls/ and requires both pragmas, except the loops of ALLOWED: (file, function) pairs of loops
that are never hardware (a constexpr function evaluated only at compile time), each with its
reason. Exit 0 when every loop passes, 1 with one line per loop otherwise (file:line, function).
--selftest: the tree as it is passes; a loop added to a copy of an hls/ header without pragmas,
with only the Vitis one and with only the Catapult one fails, with both passes; the allowed loop
fails once its entry is removed from ALLOWED.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TOP = "hls/laserax_axil.cpp"

# Loops on the path that are not hardware: (file, function) -> why no unroll directive is needed.
ALLOWED = {
    ("hls/lx_types.h", "clog2p1"): "constexpr bit count used only for widths (template arguments): compile time",
}

LOOP_RE = re.compile(r"\b(for|while)\s*\(|\bdo\s*\{")
LINE_MARK_RE = re.compile(r'^#\s+(\d+)\s+"([^"]*)"')
CATAPULT = "#pragma hls_unroll yes"
VITIS = "#pragma HLS UNROLL"


def preprocess(root, cxx):
    cmd = [cxx, "-std=c++14", "-E", "-D__SYNTHESIS__", "-I" + root, os.path.join(root, TOP)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("check_hls_loops: the preprocessor failed: %s\n%s" % (" ".join(cmd), p.stderr[-2000:]))
    return p.stdout


def lines_with_origin(text, root):
    """[(file relative to root or None, line number, text)] of the preprocessed output."""
    out = []
    cur, no = None, 0
    for line in text.split("\n"):
        m = LINE_MARK_RE.match(line)
        if m:
            no = int(m.group(1))
            path = m.group(2)
            full = os.path.normpath(path if os.path.isabs(path) else os.path.join(root, path))
            rel = os.path.relpath(full, root)
            cur = rel if rel.startswith("hls" + os.sep) and not rel.startswith("..") else None
            continue
        out.append((cur, no, line))
        no += 1
    return out


def enclosing_function(code, pos):
    """Name of the innermost function whose body holds code[pos] ('' if none found)."""
    depth = 0
    i = pos
    while i > 0:
        i -= 1
        c = code[i]
        if c == "}":
            depth += 1
        elif c == "{":
            if depth > 0:
                depth -= 1
                continue
            # the header of this block: back to the previous ; { or }
            j = i
            while j > 0 and code[j - 1] not in ";{}":
                j -= 1
            header = code[j:i].strip()
            # a function (or constructor, with its initialiser list): the name before the first
            # parenthesis; control statements and other blocks are skipped
            m = re.search(r"([A-Za-z_]\w*)\s*\(", header)
            if m and ")" in header and m.group(1) not in ("for", "while", "if", "switch", "catch", "do"):
                return m.group(1)
    return ""


def check(root, cxx="c++"):
    rows = lines_with_origin(preprocess(root, cxx), root)
    code = "\n".join(r[2] for r in rows)
    starts = []
    off = 0
    for r in rows:
        starts.append(off)
        off += len(r[2]) + 1
    errors, n_loops = [], 0
    for k, (origin, no, line) in enumerate(rows):
        if origin is None or line.lstrip().startswith("#"):
            continue
        for m in LOOP_RE.finditer(line):
            n_loops += 1
            func = enclosing_function(code, starts[k] + m.start())
            if (origin, func) in ALLOWED:
                continue
            # the line before the loop (labels such as `name:` of LX_LOOP are on the loop's line)
            prev = next((rows[p][2].strip() for p in range(k - 1, -1, -1)
                         if rows[p][2].strip() and not LINE_MARK_RE.match(rows[p][2])), "")
            # the first line of the body
            body_open = code.find("{", starts[k] + m.start())
            after = code[body_open + 1:body_open + 400].lstrip().split("\n", 1)[0].strip()
            missing = []
            if prev != CATAPULT:
                missing.append("`%s` on the line before it (Catapult)" % CATAPULT)
            if after != VITIS:
                missing.append("`%s` as the first line of its body (Vitis)" % VITIS)
            if missing:
                errors.append("%s:%d: loop in %s() on the synthesis path of %s lacks %s" %
                              (origin, no, func or "?", TOP, " and ".join(missing)))
    return errors, n_loops


def selftest(cxx):
    fails = 0
    errs, n = check(ROOT, cxx)
    if errs:
        fails += 1
        print("selftest: the tree fails: " + "; ".join(errs))
    else:
        print("selftest: the tree passes (%d loop(s) on the path, all allowed or directed)" % n)
    loop = """
namespace lx {
inline int lx_selftest_sum(const int (&v)[4]) {
    int s = 0;
%s    LX_LOOP(selftest_sum) for (int i = 0; i < 4; ++i) {
%s        s += v[i];
    }
    return s;
}
}  // namespace lx
"""
    cases = [  # (name, Catapult line, Vitis line, should pass)
        ("no_pragma", "", "", False),
        ("vitis_only", "", "#pragma HLS UNROLL\n", False),
        ("catapult_only", "#pragma hls_unroll yes\n", "", False),
        ("both", "#pragma hls_unroll yes\n", "#pragma HLS UNROLL\n", True),
    ]
    with tempfile.TemporaryDirectory(prefix="check_hls_loops_") as tmp:
        shutil.copytree(os.path.join(ROOT, "hls"), os.path.join(tmp, "hls"))
        target = os.path.join(tmp, "hls", "input_filter.h")
        orig = open(target, encoding="utf-8").read()
        guard_end = orig.rstrip().rfind("#endif")
        for name, cat, vit, want in cases:
            with open(target, "w", encoding="utf-8") as f:
                f.write(orig[:guard_end] + loop % (cat, vit) + orig[guard_end:])
            errs, _ = check(tmp, cxx)
            ok = (not errs) if want else any("lx_selftest_sum" in e for e in errs)
            print("selftest: %-14s %s: %s" % (name, "passes" if not errs else "fails",
                                              errs[0] if errs else "no finding"))
            if not ok:
                fails += 1
                print("selftest: case %s: expected %s" % (name, "a pass" if want else "a finding"))
        with open(target, "w", encoding="utf-8") as f:
            f.write(orig)
        saved = dict(ALLOWED)
        ALLOWED.clear()
        try:
            errs, _ = check(tmp, cxx)
        finally:
            ALLOWED.update(saved)
        if not any("clog2p1" in e for e in errs):
            fails += 1
            print("selftest: without its ALLOWED entry the loop of clog2p1 was not reported")
        else:
            print("selftest: no_allowed       fails: %s" % next(e for e in errs if "clog2p1" in e))
    print("hls_loops_selftest: %s" % ("PASS" if fails == 0 else "FAIL (%d cases)" % fails))
    return 1 if fails else 0


def main():
    ap = argparse.ArgumentParser(description="unroll directives of the loops on the HLS top's synthesis path")
    ap.add_argument("--root", default=ROOT)
    ap.add_argument("--cxx", default=os.environ.get("CXX", "c++"))
    ap.add_argument("--selftest", action="store_true")
    a = ap.parse_args()
    if a.selftest:
        return selftest(a.cxx)
    errs, n = check(a.root, a.cxx)
    for e in errs:
        print(e)
    if errs:
        print("hls_loops: FAIL (%d of %d loop(s) on the synthesis path without both unroll directives)" % (len(errs), n))
        return 1
    print("hls_loops: PASS (%d loop(s) on the synthesis path of %s: every one directed or allowed: %s)" %
          (n, TOP, "; ".join("%s %s(): %s" % (f, fn, why) for (f, fn), why in sorted(ALLOWED.items()))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
