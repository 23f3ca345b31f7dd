#!/usr/bin/env python3
"""check_hls_pins.py - the asynchronous pins of hls/ reach only the two-flop synchroniser.

Usage: scripts/check_hls_pins.py [ROOT]      check ROOT/hls (default: the repository root)
       scripts/check_hls_pins.py --selftest  break each rule in a copy of hls/ and expect a FAIL

DESIGN 4.1: every asynchronous input (laser A, B, LERR and the reference switch) passes a
two-flop synchroniser before any logic reads it. In the generated RTL a pin that fans out to
logic ahead of the synchroniser is a metastability fault that neither C simulation nor
co-simulation shows, so the rule is checked on the source. The pins enter hls/ as the struct
axis_pins; the rules follow them to the one flip-flop they may reach:

  1. laserax_top.h: a member of `pins` is read only as a whole argument of the decoder's step
     (pins.a, pins.b, pins.lerr) and of the switch filter's step (pins.sw), once each; nothing
     else in hls/ reads a member of an axis_pins (laserax_axil.cpp only assigns them).
  2. quad_decoder.h, step(): the parameters a, b, lerr are used only as the first argument of
     fa_.step, fb_.step, fe_.step (one use each).
  3. input_filter.h, step(): the parameter pin is used only in `s1_ = pin;` (one use).

Comments are ignored. Prints every violation as `path:line: reason`, then one PASS/FAIL line;
exit status 0 pass, 1 violations, 2 usage error.
"""
import os
import re
import shutil
import sys
import tempfile

IDENT = r"[A-Za-z_]\w*"


def strip_comments(text):
    """The text with // and /* */ comments blanked (newlines kept, so line numbers stay)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("".join(c if c == "\n" else " " for c in text[i:j]))
            i = j
        else:
            out.append(text[i])
            i += 1
    return "".join(out)


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


def function_body(text, signature_re):
    """(start, end) of the body of the first function whose signature matches, or None."""
    m = re.search(signature_re, text)
    if not m:
        return None
    i = text.find("{", m.end())
    if i < 0:
        return None
    depth = 0
    for j in range(i, len(text)):
        if text[j] == "{":
            depth += 1
        elif text[j] == "}":
            depth -= 1
            if depth == 0:
                return (i, j + 1)
    return None


def check_param_uses(path, text, errors, signature_re, what, allowed):
    """Every use of each parameter in `allowed` (name -> regex of its one allowed use) inside the
    body of the function matched by signature_re is that use, exactly once."""
    body = function_body(text, signature_re)
    if body is None:
        errors.append(f"{path}:1: {what} not found (the rule cannot be checked)")
        return
    b0, b1 = body
    seg = text[b0:b1]
    for name, use_re in allowed.items():
        ok_spans = [(m.start(), m.end()) for m in re.finditer(use_re, seg)]
        uses = [m.start() for m in re.finditer(r"(?<![\w.])" + name + r"\b", seg)]
        bad = [u for u in uses if not any(s <= u < e for s, e in ok_spans)]
        for u in bad:
            errors.append(f"{path}:{line_of(text, b0 + u)}: {what}: pin `{name}` read outside the synchroniser")
        if len(uses) - len(bad) != 1:
            errors.append(f"{path}:{line_of(text, b0)}: {what}: pin `{name}` must reach the synchroniser exactly "
                          f"once (found {len(uses) - len(bad)} such uses)")


def check(root):
    hls = os.path.join(root, "hls")
    errors = []
    files = sorted(f for f in os.listdir(hls) if f.endswith((".h", ".cpp")))
    texts = {}
    for f in files:
        with open(os.path.join(hls, f), encoding="utf-8") as fh:
            texts[f] = strip_comments(fh.read())

    # 1. members of an axis_pins: read only in the two synchroniser calls of laserax_top.h
    allowed_top = {
        "a": r"dec_\.step\(\s*pins\.a\s*,\s*pins\.b\s*,\s*pins\.lerr\s*,",
        "b": r"dec_\.step\(\s*pins\.a\s*,\s*pins\.b\s*,\s*pins\.lerr\s*,",
        "lerr": r"dec_\.step\(\s*pins\.a\s*,\s*pins\.b\s*,\s*pins\.lerr\s*,",
        "sw": r"swf_\.step\(\s*pins\.sw\s*,",
    }
    seen = {k: 0 for k in allowed_top}
    for f, t in texts.items():
        path = os.path.join("hls", f)
        for m in re.finditer(r"\bpins\s*\.\s*(" + IDENT + r")", t):
            member = m.group(1)
            # an assignment to a member (the HLS top wrapper fills the struct) is not a read
            after = t[m.end():m.end() + 3]
            if re.match(r"\s*=(?!=)", after):
                continue
            use_re = allowed_top.get(member) if f == "laserax_top.h" else None
            ok = use_re is not None and any(s.start() <= m.start() < s.end() for s in re.finditer(use_re, t))
            if ok:
                seen[member] += 1
            else:
                errors.append(f"{path}:{line_of(t, m.start())}: pin `pins.{member}` read outside the synchroniser")
    for member, n in seen.items():
        if n != 1:
            errors.append(f"hls/laserax_top.h:1: pin `pins.{member}` must reach its synchroniser exactly once "
                          f"(found {n})")

    # 2. the decoder passes its three pins straight into its input filters
    if "quad_decoder.h" in texts:
        check_param_uses("hls/quad_decoder.h", texts["quad_decoder.h"], errors,
                         r"out_t\s+step\s*\(\s*bool\s+a\s*,\s*bool\s+b\s*,\s*bool\s+lerr\b",
                         "quad_decoder::step",
                         {"a": r"fa_\.step\(\s*a\s*,", "b": r"fb_\.step\(\s*b\s*,",
                          "lerr": r"fe_\.step\(\s*lerr\s*,"})
    else:
        errors.append("hls/quad_decoder.h:1: missing")
    # 3. the filter's pin reaches the first synchroniser flop only
    if "input_filter.h" in texts:
        check_param_uses("hls/input_filter.h", texts["input_filter.h"], errors,
                         r"out_t\s+step\s*\(\s*bool\s+pin\b", "input_filter::step",
                         {"pin": r"\bs1_\s*=\s*pin\s*;"})
    else:
        errors.append("hls/input_filter.h:1: missing")
    return errors


def report(root):
    errors = check(root)
    for e in errors:
        print(e)
    print(f"check_hls_pins: {'PASS' if not errors else 'FAIL'} ({len(errors)} violation(s))")
    return 0 if not errors else 1


def selftest(root):
    """Each mutation breaks one rule in a copy of hls/; each must be reported."""
    mutations = [
        ("input_filter.h", "        const bool glitch = valid_ && s2_ == f_ && cnt_ != 0;",
         "        const bool glitch = valid_ && s2_ == f_ && cnt_ != 0 && pin;"),
        ("input_filter.h", "        s1_ = pin;", "        s1_ = !s2_;"),
        ("quad_decoder.h", "        if (clear) {", "        if (clear || a) {"),
        ("quad_decoder.h", "fb_.step(b, glitch_n)", "fb_.step(a, glitch_n)"),
        ("laserax_top.h", "        const dig_tap dig = dig_q3_;", "        dig_tap dig = dig_q3_;\n        dig.mark = dig.mark || pins.a;"),
        ("laserax_top.h", "swf_.step(pins.sw, ", "swf_.step(false, "),
    ]
    if check(root):
        print("check_hls_pins --selftest: FAIL (the tree itself has violations)")
        return 1
    failures = 0
    for f, old, new in mutations:
        with tempfile.TemporaryDirectory() as tmp:
            shutil.copytree(os.path.join(root, "hls"), os.path.join(tmp, "hls"))
            p = os.path.join(tmp, "hls", f)
            with open(p, encoding="utf-8") as fh:
                t = fh.read()
            if old not in t:
                print(f"selftest: mutation anchor not found in hls/{f}: {old.strip()}")
                failures += 1
                continue
            with open(p, "w", encoding="utf-8") as fh:
                fh.write(t.replace(old, new, 1))
            errs = check(tmp)
            status = "caught" if errs else "MISSED"
            print(f"selftest: hls/{f}: {new.strip()[:60]} -> {status}")
            if not errs:
                failures += 1
    print(f"check_hls_pins --selftest: {'PASS' if failures == 0 else 'FAIL'} "
          f"({len(mutations) - failures} of {len(mutations)} mutations caught)")
    return 0 if failures == 0 else 1


def main(argv):
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    if len(argv) > 2:
        print("usage: check_hls_pins.py [--selftest | ROOT]", file=sys.stderr)
        return 2
    if len(argv) == 2 and argv[1] == "--selftest":
        return selftest(here)
    root = argv[1] if len(argv) == 2 else here
    if not os.path.isdir(os.path.join(root, "hls")):
        print(f"check_hls_pins: no hls/ under {root}", file=sys.stderr)
        return 2
    return report(root)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
