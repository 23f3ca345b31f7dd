#!/usr/bin/python3
"""pnr_endpoints.py — every timing endpoint of a placed and routed iCE40 design, worst first.

nextpnr prints one critical path per clock. A block near its timing goal has many paths close to
that one, and any change of the netlist moves the placement, so one path per run is a slow guide.
nextpnr-ice40 can write, besides the critical paths, the timing of every net to every sink
(`--report REP.json --detailed-timing-report`); for a sink that ends a path (an input of a logic
cell whose flip-flop is used, an input of a block RAM) the figure it gives is the delay of the
longest path that ends there, setup time included. With the routed netlist (`--write POST.json`),
which says which logic cells use their flip-flop, this tool lists those endpoints by slack:

  * the worst endpoints (delay, slack at the period, the cell and port, the net that feeds it),
  * the same grouped by register (the flip-flops of one HDL register share a name stem),
  * a slack histogram.

`--check` fails (exit 1) unless the worst endpoint equals nextpnr's reported critical path
(0.02 ns): the endpoint classification (or nextpnr's report format) is not what this tool assumes.

Usage: pnr_endpoints.py POST_JSON REPORT_JSON [--top N] [--period NS] [--check]
       pnr_endpoints.py --selftest   (synthetic netlists and reports: the endpoint rules, the
                                      counts, and --check failing on a disagreeing report)
(scripts/synth_report.py writes both files for every block it places.)
"""
import argparse
import collections
import json
import os
import re
import sys

CLOCK_PORTS = {"CLK", "RCLK", "WCLK", "RCLKE", "WCLKE"}


def load(post_path, rep_path):
    with open(post_path) as f:
        post = json.load(f)
    with open(rep_path) as f:
        rep = json.load(f)
    top = next(iter(post["modules"].values()))
    return top["cells"], rep


def flag(c, name):
    return str(c.get("parameters", {}).get(name, "0")).strip("0") != ""


def is_endpoint(c, port):
    """a sink that ends a timing path in nextpnr's ice40 model"""
    ty = c["type"]
    if port in CLOCK_PORTS:
        return False
    if ty == "ICESTORM_LC":
        return flag(c, "DFF_ENABLE") and port != "CIN"
    if ty in ("ICESTORM_RAM", "ICESTORM_DSP", "ICESTORM_SPRAM"):
        return True
    return False


def stem(cell):
    """the HDL register a flip-flop cell comes from: the name before Yosys's mapping suffixes"""
    return re.sub(r"_SB_(DFF|LUT4|CARRY).*$", "", cell)


def critical(rep):
    ref = None
    for p in rep.get("critical_paths", []):
        if p.get("from", "").startswith("posedge") and p.get("to", "").startswith("posedge"):
            ref = sum(s["delay"] for s in p["path"])
    return ref


def analyse(post_path, rep_path):
    """{"rows": [(delay, cell, port, net)] worst first, "ref": nextpnr's critical path (ns) or
    None}; raises ValueError when the report lacks the detailed net timings."""
    cells, rep = load(post_path, rep_path)
    if "detailed_net_timings" not in rep:
        raise ValueError("the report has no detailed net timings (run nextpnr with --detailed-timing-report)")
    eps = {}
    for n in rep["detailed_net_timings"]:
        if not str(n.get("event", "")).startswith("posedge"):
            continue
        for e in n.get("endpoints", []):
            c = cells.get(e["cell"])
            if c is None or not is_endpoint(c, e["port"]):
                continue
            if not str(e.get("event", "")).startswith("posedge"):
                continue
            key = (e["cell"], e["port"])
            if key not in eps or e["delay"] > eps[key][0]:
                eps[key] = (e["delay"], n["net"])
    rows = sorted(((d, cell, port, net) for (cell, port), (d, net) in eps.items()), reverse=True)
    return {"rows": rows, "ref": critical(rep)}


def summary(res, period, near=0.5):
    """(endpoints over the period, endpoints with slack below `near` ns, worst delay)"""
    rows = res["rows"]
    return (sum(1 for r in rows if r[0] > period), sum(1 for r in rows if period - r[0] < near),
            rows[0][0] if rows else None)


def report(res, period, top):
    """the text report: counts, slack histogram, worst endpoints, worst registers"""
    rows = res["rows"]
    worst = rows[0][0]
    over, near, _ = summary(res, period)
    out = [f"endpoints: {len(rows)}; worst {worst:.3f} ns ({1000.0 / worst:.1f} MHz); "
           f"over the {period:g} ns period: {over}; slack below 0.5 ns: {near}"]
    edges = [-2, -1, -0.5, -0.25, 0, 0.25, 0.5, 1, 2, float("inf")]
    counts = [0] * len(edges)
    for d, *_ in rows:
        s = period - d
        for i, e in enumerate(edges):
            if s < e:
                counts[i] += 1
                break
    out.append("slack histogram (ns):")
    lo = "-inf"
    for i, e in enumerate(edges):
        hi = "inf" if e == float("inf") else f"{e:g}"
        out.append(f"  [{lo:>5}, {hi:>5})  {counts[i]}")
        lo = hi
    out.append(f"worst {top} endpoints (path delay with setup, slack, endpoint, the net into it):")
    for d, cell, port, net in rows[:top]:
        out.append(f"  {d:7.3f} {period - d:+7.3f}  {cell}.{port}  <- {net}")
    groups = collections.OrderedDict()
    for d, cell, port, net in rows:
        g = groups.setdefault(stem(cell), [d, 0, 0])
        g[1] += 1
        if d > period:
            g[2] += 1
    out.append(f"worst {top} registers (worst delay, endpoints, endpoints over the period):")
    for name, (d, n, nover) in list(groups.items())[:top]:
        out.append(f"  {d:7.3f} {n:5d} {nover:5d}  {name}")
    return "\n".join(out)


def agrees(res, tol=0.02):
    """the worst endpoint equals nextpnr's critical path"""
    return bool(res["rows"]) and res["ref"] is not None and abs(res["ref"] - res["rows"][0][0]) <= tol


def selftest():
    """synthetic routed netlists and reports: which sinks are endpoints, the counts, the register
    groups, and the agreement check passing and failing; 0 if every case gives what it should"""
    import tempfile
    lc = lambda dff: {"type": "ICESTORM_LC", "parameters": {"DFF_ENABLE": "1" if dff else "0"}}
    cells = {"a_SB_DFF_Q_DFFLC": lc(True), "a_SB_DFF_Q_1_DFFLC": lc(True),
             "b_SB_LUT4_O_LC": lc(False), "c_SB_CARRY_CO_LC": lc(True),
             "ram_SB_RAM40_4K": {"type": "ICESTORM_RAM", "parameters": {}}}
    sinks = [("a_SB_DFF_Q_DFFLC", "I0", 10.4),     # endpoint, over 10 ns
             ("a_SB_DFF_Q_DFFLC", "I1", 10.1),     # the same endpoint cell, another port
             ("a_SB_DFF_Q_1_DFFLC", "I2", 9.7),    # endpoint, within 0.5 ns
             ("a_SB_DFF_Q_1_DFFLC", "CLK", 30.0),  # clock port: not an endpoint
             ("b_SB_LUT4_O_LC", "I0", 12.0),       # no flip-flop: not an endpoint
             ("c_SB_CARRY_CO_LC", "CIN", 11.0),    # carry input: not an endpoint
             ("c_SB_CARRY_CO_LC", "I3", 8.0),      # endpoint, 2 ns of slack
             ("ram_SB_RAM40_4K", "WADDR_0", 9.9)]  # block RAM input: endpoint
    nets = [{"net": "n%d" % i, "event": "posedge clk",
             "endpoints": [{"cell": c, "port": p, "event": "posedge clk", "delay": d}]}
            for i, (c, p, d) in enumerate(sinks)]
    post = {"modules": {"top": {"cells": cells}}}
    fails = 0
    with tempfile.TemporaryDirectory() as tmp:
        pp, rp = os.path.join(tmp, "post.json"), os.path.join(tmp, "rep.json")
        with open(pp, "w") as f:
            json.dump(post, f)
        for crit, want_ok in ((10.4, True), (10.41, True), (12.0, False), (10.0, False)):
            rep = {"critical_paths": [{"from": "posedge clk", "to": "posedge clk",
                                       "path": [{"delay": crit / 2}, {"delay": crit / 2}]}],
                   "detailed_net_timings": nets}
            with open(rp, "w") as f:
                json.dump(rep, f)
            res = analyse(pp, rp)
            got = [(c, p) for _, c, p, _ in res["rows"]]
            want = [("a_SB_DFF_Q_DFFLC", "I0"), ("a_SB_DFF_Q_DFFLC", "I1"), ("ram_SB_RAM40_4K", "WADDR_0"),
                    ("a_SB_DFF_Q_1_DFFLC", "I2"), ("c_SB_CARRY_CO_LC", "I3")]
            if got != want:
                print(f"pnr_endpoints selftest: endpoints {got}, expected {want}"); fails += 1
            if summary(res, 10.0) != (2, 4, 10.4):
                print(f"pnr_endpoints selftest: summary {summary(res, 10.0)}, expected (2, 4, 10.4)"); fails += 1
            groups = [ln.split()[-1] for ln in report(res, 10.0, 10).split("\n")
                      if ln.startswith("  ") and ln.split()[-1] in ("a", "ram_SB_RAM40_4K", "c")]
            if groups != ["a", "ram_SB_RAM40_4K", "c"]:
                print(f"pnr_endpoints selftest: register groups {groups}, expected a, ram_SB_RAM40_4K, c")
                fails += 1
            if agrees(res) != want_ok:
                print(f"pnr_endpoints selftest: critical path {crit} ns: agrees = {agrees(res)}, expected {want_ok}")
                fails += 1
        rep = {"critical_paths": []}
        with open(rp, "w") as f:
            json.dump(rep, f)
        try:
            analyse(pp, rp)
            print("pnr_endpoints selftest: a report without net timings was accepted"); fails += 1
        except ValueError:
            pass
    print("pnr_endpoints selftest: " + ("PASS" if fails == 0 else f"FAIL ({fails})"))
    return 0 if fails == 0 else 1


def main():
    if sys.argv[1:] == ["--selftest"]:
        return selftest()
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("post")
    ap.add_argument("report")
    ap.add_argument("--top", type=int, default=30, help="endpoints (and registers) to list")
    ap.add_argument("--period", type=float, default=10.0, help="clock period, ns")
    ap.add_argument("--check", action="store_true",
                    help="fail unless the worst endpoint equals nextpnr's critical path (0.02 ns)")
    a = ap.parse_args()
    try:
        res = analyse(a.post, a.report)
    except (OSError, ValueError, KeyError) as e:
        print(f"pnr_endpoints: {e}", file=sys.stderr)
        return 1
    if not res["rows"]:
        print("pnr_endpoints: no clocked endpoint found", file=sys.stderr)
        return 1
    print(report(res, a.period, a.top))
    if a.check:
        if res["ref"] is None:
            print("pnr_endpoints --check: no posedge-to-posedge critical path in the report", file=sys.stderr)
            return 1
        print(f"nextpnr critical path {res['ref']:.3f} ns, worst endpoint {res['rows'][0][0]:.3f} ns")
        if not agrees(res):
            print("pnr_endpoints --check: FAIL (the worst endpoint is not nextpnr's critical path)",
                  file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
