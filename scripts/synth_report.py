#!/usr/bin/python3
"""synth_report.py — synthesis and place-and-route table of rtl_ref/ (the body of `make synth`).

For every block of rtl_ref/ and for the top (laserax_top):
  * generic Yosys synthesis (`synth -flatten` up to the fine stage, techmap, `abc -lut 4`; memories
    are kept as $mem cells): generic 4-LUT and flip-flop count;
  * iCE40 synthesis (`synth_ice40`): SB_LUT4, SB_CARRY, flip-flops (SB_DFF*), block RAMs
    (SB_RAM40_4K) and DSPs (SB_MAC16, only with --dsp / UP5K);
  * place and route with nextpnr-ice40 (HX8K ct256 by default, or UP5K sg48) of a harness
    around the block: every block input comes from a serial-in shift register and every block
    output goes to a loadable shift register, so the block is timed register-to-register with
    three pins (the blocks have far more ports than the package has I/Os). The maximum clock
    frequency reported by nextpnr is that of the block inside the harness; the harness adds one
    flip-flop per input bit and one LUT + flip-flop per output bit to the device utilisation.
    A block that does not fit (or whose place-and-route fails) is listed as such; the script
    does not fail for it;
  * every timing endpoint of the routed harness (scripts/pnr_endpoints.py, from nextpnr's
    --report --detailed-timing-report and --write files): DIR/<block>.endpoints.txt, and the
    count of endpoints with less than 0.5 ns of slack in the table.

Usage: synth_report.py --build BUILD_DIR [--out DIR] [--device hx8k|up5k] [--freq MHZ]
                       [--jobs N] [--modules a,b,...] [--no-pnr] [--seed N] [--limits FILE]
                       [--seeds 1-8]
With --seeds (make synth-sweep, issue 39): after the table, each module's harness netlist is
placed and routed again at every seed of the list (the netlist of --seed, synthesised once) and a
second table gives min / median / max fmax, the number of seeds below the target and each seed's
figure; it is also written to DIR/synth_sweep.md. Not a check: it prints numbers.
With --limits (the CTest `synth_check`, label synth): after the table, every module named in FILE
(rtl_ref/synth_limits.csv) is checked against its limits — synthesis must succeed, SB_LUT4 and
block RAM at most the limit, and the P&R fmax at least the limit (where one is given) — and the
script exits 1 on any violation, or when the endpoint list's worst path is not nextpnr's critical
path. Static timing of a fixed seed is deterministic.
The table table is printed and written to DIR/synth_report.md; logs and netlists stay in DIR.
The table RAM image (P = 256, amp = 32767) is written by BUILD_DIR/lutgen into DIR.
"""
import argparse
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pnr_endpoints  # noqa: E402  (scripts/pnr_endpoints.py: every endpoint's slack)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RTL = os.path.join(ROOT, "rtl_ref")
MODULES = ["input_filter", "quad_decoder", "pulse_multiplier", "output_pacer", "rephase",
           "dds_sincos", "error_map", "laserax_top", "encoder_counter", "pso"]
# The files read for a module are found, not listed: the file that defines it and, transitively,
# every rtl_ref/ file defining a module it instantiates (found by name in the text), so a block
# instantiated by the top can never be missing from the design. Only those files are read, so a
# module's netlist (and its placement at a fixed seed) does not move when an unrelated file is
# added to rtl_ref/ (reading every file shifted Yosys' internal names and moved every fmax by
# several MHz).
SOURCES = sorted(os.path.join(RTL, f) for f in os.listdir(RTL) if f.endswith(".v"))


def _module_files():
    """{module name: defining file} over rtl_ref/*.v, and {file: text without comments}."""
    defs, texts = {}, {}
    for path in SOURCES:
        with open(path) as f:
            text = re.sub(r"/\*.*?\*/", "", re.sub(r"//[^\n]*", "", f.read()), flags=re.S)
        texts[path] = text
        for name in re.findall(r"^\s*module\s+(\w+)", text, flags=re.M):
            defs[name] = path
    return defs, texts


def sources_for(top):
    """The rtl_ref/ files the module top needs (its own file first, then the instantiated ones)."""
    defs, texts = _module_files()
    if top not in defs:
        return list(SOURCES)   # unknown: read everything, hierarchy -check reports what is missing
    need, todo = [], [defs[top]]
    while todo:
        path = todo.pop(0)
        if path in need:
            continue
        need.append(path)
        for name, dpath in defs.items():
            if dpath not in need and re.search(r"^\s*" + name + r"\s*(#|\w)", texts[path], flags=re.M):
                todo.append(dpath)
    return need
DEVICES = {
    "hx8k": {"nextpnr": ["--hx8k", "--package", "ct256"], "synth": [], "lcs": 7680,
             "icetime": ["-d", "hx8k", "-P", "ct256"]},
    "up5k": {"nextpnr": ["--up5k", "--package", "sg48"], "synth": ["-dsp"], "lcs": 5280,
             "icetime": ["-d", "up5k", "-P", "sg48"]},
}
TABLE_FILE = "dds_table_p256.hex"
# Debug taps of laserax_top (axis_out taps of the C++ model). The top is measured at its default
# DEBUG_TAPS = 0 (the deployed core: the taps tied to 0, the logic behind them removed) and its
# P&R harness leaves them open; --keep-taps measures it with DEBUG_TAPS = 1 and taps in the harness.
TOP_TAPS = {"o_raw_count", "o_step", "o_comp_pos", "o_delta", "o_backlog", "o_pstep", "o_paced_pos",
            "o_ostep", "o_out_pos", "o_adj", "o_a_pos", "o_b_pos", "o_c_pos", "o_z_pos", "o_d",
            "o_rep_mark"}


def run(cmd, cwd, log):
    """Runs cmd in cwd, output to log; returns (returncode, seconds)."""
    t0 = time.time()
    with open(log, "w") as f:
        rc = subprocess.call(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    return rc, time.time() - t0


def read_verilog_cmd(top):
    return "read_verilog " + " ".join(sources_for(top))


def cell_counts(json_path, top):
    with open(json_path) as f:
        nl = json.load(f)
    counts = {}
    for cell in nl["modules"][top]["cells"].values():
        counts[cell["type"]] = counts.get(cell["type"], 0) + 1
    return nl, counts


def ports_of(nl, top):
    """[(name, direction, width)] of module top in a Yosys JSON netlist, in declaration order."""
    return [(n, p["direction"], len(p["bits"])) for n, p in nl["modules"][top]["ports"].items()]


def harness(module, ports, skip_outputs=()):
    """Verilog of a serial-in / serial-out register harness around module."""
    ins = [(n, w) for n, d, w in ports if d == "input" and n != "i_clk"]
    outs = [(n, w) for n, d, w in ports if d == "output" and n not in skip_outputs]
    nin = sum(w for _, w in ins)
    nout = sum(w for _, w in outs)
    v = ["`default_nettype none",
         f"// generated by scripts/synth_report.py: P&R harness of {module}",
         f"module wrap_{module} (input wire i_clk, input wire i_sdi, input wire i_load, output wire o_sdo);",
         f"    reg  [{nin - 1}:0] in_sr;",
         f"    wire [{nout - 1}:0] outs;",
         f"    reg  [{nout - 1}:0] out_sr;",
         "    always @(posedge i_clk) begin",
         f"        in_sr  <= {{in_sr[{nin - 2}:0], i_sdi}};" if nin > 1 else "        in_sr  <= i_sdi;",
         f"        out_sr <= i_load ? outs : {{out_sr[{nout - 2}:0], 1'b0}};" if nout > 1
         else "        out_sr <= outs;",
         "    end",
         f"    assign o_sdo = out_sr[{nout - 1}];"]
    conns = [".i_clk(i_clk)"]
    lo = 0
    for n, w in ins:
        conns.append(f".{n}(in_sr[{lo + w - 1}:{lo}])")
        lo += w
    lo = 0
    for n, w in outs:
        conns.append(f".{n}(outs[{lo + w - 1}:{lo}])")
        lo += w
    v.append(f"    {module} dut (")
    v.append(",\n".join("        " + c for c in conns))
    v.append("    );")
    v.append("endmodule")
    v.append("`default_nettype wire")
    return "\n".join(v) + "\n", nin, nout


def do_module(m, a):
    out = a.out
    dev = DEVICES[a.device]
    r = {"module": m}
    # generic
    if a.no_generic:
        r["g_lut"] = r["g_ff"] = "-"
    gjson = os.path.join(out, f"{m}.generic.json")
    script = (f"{read_verilog_cmd(m)}; hierarchy -check -top {m}; "
              f"synth -flatten -top {m} -run begin:fine; opt -fast -full; techmap; opt -fast; "
              f"abc -lut 4; opt -fast; check -assert; write_json {gjson}")
    rc = 0 if a.no_generic else run(["yosys", "-q", "-p", script], out, os.path.join(out, f"{m}.generic.log"))[0]
    if a.no_generic:
        pass
    elif rc == 0:
        _, c = cell_counts(gjson, m)
        r["g_lut"] = c.get("$lut", 0)
        r["g_ff"] = sum(n for t, n in c.items() if re.match(r"^\$_(S?DFF|DFFE|SDFFE|SDFFCE|ALDFF|DFFSR)", t))
        r["g_mem"] = sum(n for t, n in c.items() if t.startswith("$mem"))
    else:
        r["g_err"] = "generic synth failed"
    # iCE40, block alone
    ijson = os.path.join(out, f"{m}.ice40.json")
    taps = "chparam -set DEBUG_TAPS 1 laserax_top; " if (m == "laserax_top" and a.keep_taps) else ""
    script = f"{read_verilog_cmd(m)}; {taps}synth_ice40 {' '.join(dev['synth'] + a.synth_opts.split())} -top {m} -json {ijson}"
    rc, _ = run(["yosys", "-q", "-p", script], out, os.path.join(out, f"{m}.ice40.log"))
    if rc != 0:
        r["i_err"] = "synth_ice40 failed"
        return r
    nl, c = cell_counts(ijson, m)
    r["lut"] = c.get("SB_LUT4", 0)
    r["carry"] = c.get("SB_CARRY", 0)
    r["ff"] = sum(n for t, n in c.items() if t.startswith("SB_DFF"))
    r["bram"] = c.get("SB_RAM40_4K", 0)
    r["dsp"] = c.get("SB_MAC16", 0)
    if a.no_pnr:
        return r
    # harness P&R
    skip = TOP_TAPS if (m == "laserax_top" and not a.keep_taps) else ()
    text, nin, nout = harness(m, ports_of(nl, m), skip)
    r["h_in"], r["h_out"] = nin, nout
    wv = os.path.join(out, f"wrap_{m}.v")
    with open(wv, "w") as f:
        f.write(text)
    wjson = os.path.join(out, f"wrap_{m}.json")
    script = f"{read_verilog_cmd(m)} {wv}; {taps}synth_ice40 {' '.join(dev['synth'] + a.synth_opts.split())} -top wrap_{m} -json {wjson}"
    rc, _ = run(["yosys", "-q", "-p", script], out, os.path.join(out, f"wrap_{m}.ice40.log"))
    if rc != 0:
        r["fmax"] = "harness synth failed"
        return r
    plog = os.path.join(out, f"{m}.nextpnr.log")
    prep = os.path.join(out, f"wrap_{m}.timing.json")
    ppost = os.path.join(out, f"wrap_{m}.routed.json")
    cmd = (["nextpnr-ice40"] + dev["nextpnr"] +
           ["--json", wjson, "--pcf-allow-unconstrained", "--timing-allow-fail", "--freq", str(a.freq),
            "--seed", str(a.seed),
            "--asc", os.path.join(out, f"wrap_{m}.asc"),
            "--report", prep, "--detailed-timing-report", "--write", ppost])
    rc, secs = run(cmd, out, plog)
    r["wjson"] = wjson
    with open(plog, errors="replace") as f:
        log = f.read()
    util = re.findall(r"ICESTORM_LC:\s+(\d+)/\s*(\d+)", log)
    if util:
        r["lc"] = f"{util[-1][0]}/{util[-1][1]}"
    if rc != 0:
        too_big = re.search(r"(Unable to place|exceeds|[Tt]oo many|is full|not enough|failed to place)", log)
        over = util and int(util[-1][0]) > int(util[-1][1])
        r["fmax"] = "does not fit" if (too_big or over) else "P&R failed"
        return r
    # the harness clock (nextpnr also lists pseudo-clocks, e.g. the constant clock of a
    # combinational SB_MAC16); the last report is the one after routing
    fmx = fmax_of_log(log)
    r["fmax"] = f"{fmx:.1f}" if fmx is not None else "n/a"
    r["pnr_s"] = round(secs)
    r["icetime"] = icetime_of(m, dev, out)
    # every endpoint's slack (scripts/pnr_endpoints.py) into DIR/<m>.endpoints.txt; the count of
    # endpoints with less than 0.5 ns of slack goes into the table, and the analysis must agree
    # with nextpnr's own critical path (checked with --limits)
    period = 1000.0 / a.freq
    try:
        res = pnr_endpoints.analyse(ppost, prep)
        if not res["rows"]:
            raise ValueError("no clocked endpoint")
        with open(os.path.join(out, f"{m}.endpoints.txt"), "w") as f:
            f.write(pnr_endpoints.report(res, period, 60) + "\n")
        over, near, worst = pnr_endpoints.summary(res, period)
        r["near"] = str(near)
        r["ep_ok"] = pnr_endpoints.agrees(res)
        r["ep_why"] = (f"the endpoint list's worst path {worst:.3f} ns is not nextpnr's critical path "
                       f"({res['ref']} ns)")
        os.remove(ppost)  # (large: the routed netlist is only needed for the analysis)
    except (OSError, ValueError, KeyError) as e:
        r["near"] = "n/a"
        r["ep_ok"] = False
        r["ep_why"] = f"endpoint analysis failed: {e}"
    return r


def icetime_of(m, dev, out):
    """Independent timing cross-check (issue 39): the placed harness packed to a bitstream
    (icepack), read back from it (iceunpack) and analysed by IceStorm's icetime (topological,
    its own delay tables). Returns "fmax MHz / logic levels", or why there is none; the full
    report (its critical path by tile) is DIR/<m>.icetime.txt."""
    tools = ("icepack", "iceunpack", "icetime")
    if not all(shutil.which(t) for t in tools):
        return "n/a (no fpga-icestorm)"
    asc = os.path.join(out, f"wrap_{m}.asc")
    binf = os.path.join(out, f"wrap_{m}.bin")
    back = os.path.join(out, f"wrap_{m}.unpacked.asc")
    rep = os.path.join(out, f"{m}.icetime.txt")
    if (run(["icepack", asc, binf], out, os.path.join(out, f"{m}.icepack.log"))[0] != 0 or
            run(["iceunpack", binf, back], out, os.path.join(out, f"{m}.iceunpack.log"))[0] != 0):
        return "icepack failed"
    rc, _ = run(["icetime"] + dev["icetime"] + ["-t", back], out, rep)
    with open(rep, errors="replace") as f:
        text = f.read()
    for path in (binf, back):
        os.remove(path)
    mt = re.search(r"Total path delay: ([0-9.]+) ns \(([0-9.]+) MHz\)", text)
    lv = re.search(r"Total number of logic levels: (\d+)", text)
    if rc != 0 or not mt:
        return "icetime failed"
    return f"{float(mt.group(2)):.1f} / {lv.group(1) if lv else '?'}"


def md_table(head, rows):
    """Markdown table lines: the first column left-aligned, the others right-aligned."""
    widths = [max(len(h), *(len(x[i]) for x in rows)) for i, h in enumerate(head)]
    lines = ["| " + " | ".join(h.ljust(widths[i]) for i, h in enumerate(head)) + " |",
             "|" + "|".join("-" * (w + 2) for w in widths) + "|"]
    for x in rows:
        lines.append("| " + " | ".join(v.rjust(widths[i]) if i else v.ljust(widths[i])
                                        for i, v in enumerate(x)) + " |")
    return lines


def fmax_of_log(log):
    """The harness clock's fmax after routing from a nextpnr log, or None."""
    fm = [f for c, f in re.findall(r"Max frequency for clock\s+'([^']*)':\s*([0-9.]+) MHz", log)
          if c.startswith("i_clk")]
    return float(fm[-1]) if fm else None


def sweep_seed(m, wjson, seed, a):
    """(seed, fmax or None): nextpnr of the module's harness netlist at another seed."""
    dev = DEVICES[a.device]
    plog = os.path.join(a.out, f"{m}.seed{seed}.nextpnr.log")
    cmd = (["nextpnr-ice40"] + dev["nextpnr"] +
           ["--json", wjson, "--pcf-allow-unconstrained", "--timing-allow-fail", "--freq", str(a.freq),
            "--seed", str(seed)])
    rc, _ = run(cmd, a.out, plog)
    with open(plog, errors="replace") as f:
        log = f.read()
    return seed, (fmax_of_log(log) if rc == 0 else None)


def parse_seeds(text):
    """'1-8' or '1,3,5' (or a mix) -> sorted list of distinct seeds >= 1."""
    seeds = set()
    for part in text.split(","):
        part = part.strip()
        if not part:
            continue
        if "-" in part:
            lo, hi = part.split("-", 1)
            if not (lo.isdigit() and hi.isdigit()) or int(lo) < 1 or int(hi) < int(lo) or int(hi) - int(lo) > 99:
                raise ValueError(f"bad seed range '{part}'")
            seeds.update(range(int(lo), int(hi) + 1))
        elif part.isdigit() and int(part) >= 1:
            seeds.add(int(part))
        else:
            raise ValueError(f"bad seed '{part}'")
    if not seeds:
        raise ValueError("no seed")
    return sorted(seeds)


def sweep_table(mods, results, seeds, a):
    """P&R of every module's harness at each seed (the synthesised netlist of --seed reused):
    min / median / max fmax per module, and every seed's figure."""
    jobs = []
    fm = {m: {} for m in mods}
    for m in mods:
        r = results[m]
        for sd in seeds:
            if sd == a.seed and isinstance(r.get("fmax"), str) and re.match(r"^[0-9.]+$", r["fmax"]):
                fm[m][sd] = float(r["fmax"])
            elif r.get("wjson"):
                jobs.append((m, sd))
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
        futs = {ex.submit(sweep_seed, m, results[m]["wjson"], sd, a): m for m, sd in jobs}
        for fu in concurrent.futures.as_completed(futs):
            sd, f = fu.result()
            fm[futs[fu]][sd] = f
    head = ["block", "seeds", "min MHz", "median MHz", "max MHz", f"below {a.freq:g} MHz"] + [f"s{sd}" for sd in seeds]
    rows = []
    for m in mods:
        vals = [fm[m].get(sd) for sd in seeds]
        ok = sorted(v for v in vals if v is not None)
        if ok:
            med = ok[len(ok) // 2] if len(ok) % 2 else (ok[len(ok) // 2 - 1] + ok[len(ok) // 2]) / 2
            stats = [f"{ok[0]:.1f}", f"{med:.1f}", f"{ok[-1]:.1f}", str(sum(1 for v in ok if v < a.freq))]
        else:
            stats = ["n/a"] * 4
        rows.append([m, str(len(seeds))] + stats + [("n/a" if v is None else f"{v:.1f}") for v in vals])
    lines = md_table(head, rows)
    lines.append("")
    lines.append(f"Seed sweep: nextpnr-ice40 of each block's harness netlist at seeds {seeds[0]}..{seeds[-1]}"
                 f" ({len(seeds)} seeds), --freq {a.freq:g}; the netlist is synthesised once.")
    return "\n".join(lines), fm


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build", help="build directory holding lutgen")
    ap.add_argument("--out", default="out/synth")
    ap.add_argument("--device", choices=sorted(DEVICES), default="hx8k")
    ap.add_argument("--freq", type=float, default=100.0, help="nextpnr target clock, MHz")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--modules", default=",".join(MODULES))
    ap.add_argument("--no-pnr", action="store_true", help="synthesis only")
    ap.add_argument("--synth-opts", default="",
                    help="extra synth_ice40 options (e.g. '-abc9'); the judge (make synth, synth_check) uses none")
    ap.add_argument("--no-generic", action="store_true", help="skip the generic (technology-free) synthesis")
    ap.add_argument("--limits", help="CSV of limits per module (rtl_ref/synth_limits.csv); exit 1 on a violation")
    ap.add_argument("--seeds", help="seed sweep after the report: e.g. 1-8 or 1,3,5 (P&R of the same netlist at each)")
    ap.add_argument("--keep-taps", action="store_true",
                    help="laserax_top with DEBUG_TAPS = 1, its debug taps connected to the P&R harness")
    a = ap.parse_args()
    seeds = None
    if a.seeds is not None:
        try:
            seeds = parse_seeds(a.seeds)
        except ValueError as e:
            sys.exit(f"synth_report: --seeds: {e}")
        if a.no_pnr:
            sys.exit("synth_report: --seeds needs place and route (not with --no-pnr)")
    a.out = os.path.abspath(a.out)
    os.makedirs(a.out, exist_ok=True)
    lutgen = os.path.join(os.path.abspath(a.build), "lutgen")
    if not os.access(lutgen, os.X_OK):
        sys.exit(f"synth_report: {lutgen} not found (run `make build` first)")
    if subprocess.call([lutgen, "--period", "256", "--amplitude", "32767", "--hex",
                        os.path.join(a.out, TABLE_FILE)], stdout=subprocess.DEVNULL) != 0:
        sys.exit("synth_report: lutgen failed")
    mods = [m for m in a.modules.split(",") if m]
    for m in mods:
        if m not in MODULES:
            sys.exit(f"synth_report: unknown module {m}")
    print(f"synth_report: {len(mods)} modules, device {a.device}, target {a.freq:g} MHz, logs in {a.out}",
          flush=True)
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
        futs = {ex.submit(do_module, m, a): m for m in mods}
        for fu in concurrent.futures.as_completed(futs):
            r = fu.result()
            results[r["module"]] = r
            print(f"  done: {r['module']}", flush=True)

    dev = a.device.upper()
    head = ["block", "generic LUT4", "generic FF", f"{dev} SB_LUT4", "SB_CARRY", "FF (SB_DFF*)",
            "BRAM (SB_RAM40_4K)", "DSP (SB_MAC16)", f"fmax MHz ({dev}, P&R)", "icetime MHz / levels",
            "slack < 0.5 ns", "harness LCs"]
    rows = []
    for m in mods:
        r = results[m]
        g = r.get("g_err")
        rows.append([m,
                     str(r.get("g_lut", g or "")), str(r.get("g_ff", "")),
                     str(r.get("lut", r.get("i_err", ""))), str(r.get("carry", "")), str(r.get("ff", "")),
                     str(r.get("bram", "")), str(r.get("dsp", "")),
                     str(r.get("fmax", "not run" if a.no_pnr else "")), str(r.get("icetime", "")),
                     str(r.get("near", "")),
                     str(r.get("lc", ""))])
    lines = md_table(head, rows)
    notes = [
        "",
        f"yosys synth_ice40 / nextpnr-ice40 {' '.join(DEVICES[a.device]['nextpnr'])}, --freq {a.freq:g}, seed {a.seed}.",
        "Generic: synth -flatten, abc -lut 4, memories kept as $mem (the 1024x17 table RAM counts 0 LUT/FF).",
        "LUT/FF/BRAM/DSP: the block alone. fmax and harness LCs: the block inside a shift-register I/O",
        "harness (one FF per input bit, one LUT+FF per output bit), register to register.",
        "slack < 0.5 ns: the timing endpoints (flip-flop and block RAM inputs) whose longest path leaves",
        f"less than 0.5 ns at {a.freq:g} MHz (scripts/pnr_endpoints.py; the list: DIR/<block>.endpoints.txt).",
        "icetime: the same placement packed to a bitstream (icepack), read back (iceunpack) and timed by",
        "IceStorm's icetime -t (its own delay tables, topological: every path incl. the harness I/O",
        "registers), fmax and logic levels of its critical path (by tile: DIR/<block>.icetime.txt).",
    ]
    if "laserax_top" in mods and not a.keep_taps:
        notes.append("laserax_top: DEBUG_TAPS = 0 (default: the debug taps raw_count .. rep_mark tied to 0 and")
        notes.append("left open in the harness; --keep-taps: DEBUG_TAPS = 1, taps in the harness).")
    elif "laserax_top" in mods:
        notes.append("laserax_top: DEBUG_TAPS = 1 (--keep-taps), the debug taps in the harness.")
    text = "\n".join(lines + notes)
    print()
    print(text)
    with open(os.path.join(a.out, "synth_report.md"), "w") as f:
        f.write(text + "\n")
    if seeds:
        stext, _ = sweep_table(mods, results, seeds, a)
        print()
        print(stext)
        with open(os.path.join(a.out, "synth_sweep.md"), "w") as f:
            f.write(stext + "\n")
    if a.limits:
        sys.exit(check_limits(a.limits, results))


def read_limits(path):
    """{module: (max_lut, min_fmax or None, max_bram)} from a CSV with # comments."""
    lim = {}
    with open(path) as f:
        for ln, line in enumerate(f, 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            cols = [c.strip() for c in line.split(",")]
            if len(cols) != 4:
                sys.exit(f"{path}:{ln}: expected 'module, max_lut, min_fmax|-, max_bram'")
            try:
                lim[cols[0]] = (int(cols[1]), None if cols[2] == "-" else float(cols[2]), int(cols[3]))
            except ValueError:
                sys.exit(f"{path}:{ln}: bad number in '{line}'")
    return lim


def check_limits(path, results):
    """Prints one line per checked module; returns the exit code (0 all within limits)."""
    lim = read_limits(path)
    bad = 0
    print()
    for m, (max_lut, min_fmax, max_bram) in lim.items():
        r = results.get(m)
        why = []
        if r is None:
            why.append("not run")
        elif "i_err" in r or "g_err" in r:
            why.append(r.get("i_err") or r.get("g_err"))
        else:
            if r["lut"] > max_lut:
                why.append(f"SB_LUT4 {r['lut']} > {max_lut}")
            if r["bram"] > max_bram:
                why.append(f"BRAM {r['bram']} > {max_bram}")
            if min_fmax is not None:
                try:
                    fm = float(r.get("fmax", ""))
                except ValueError:
                    fm = None
                if fm is None:
                    why.append(f"no fmax ({r.get('fmax', 'not run')})")
                elif fm < min_fmax:
                    why.append(f"fmax {fm:.1f} MHz < {min_fmax:g}")
            if "ep_ok" in r and not r["ep_ok"]:
                why.append(r["ep_why"])
        if why:
            bad += 1
            print(f"synth_check: FAIL {m}: " + "; ".join(why))
        else:
            f = r.get("fmax", "-")
            print(f"synth_check: ok   {m}: SB_LUT4 {r['lut']} <= {max_lut}, BRAM {r['bram']} <= {max_bram}" +
                  (f", fmax {f} >= {min_fmax:g} MHz" if min_fmax is not None else f" (fmax {f}, not limited)"))
    print(f"synth_check: {len(lim) - bad} passed, {bad} failed")
    return 1 if bad else 0


if __name__ == "__main__":
    main()
