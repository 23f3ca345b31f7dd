#!/usr/bin/python3
"""plot_homing.py — draw the single-axis referencing sequence from a laserax trace.

Usage (always with Debian's interpreter, which has numpy and matplotlib):
    /usr/bin/python3 scripts/plot_homing.py [TRACE.csv] [OUT.png] [--events EVENTS.csv]
                                            [--period P] [--title TEXT] [--whole]
    /usr/bin/python3 scripts/plot_homing.py --selftest [DIR]

TRACE.csv (default out/trace.csv): lines starting with '#' are comments (a comment such as
`# period=256` or `# P: 256` gives the period); the first other line is the header, with at
least the columns cycle,true_nm,raw_count,comp_pos,paced_pos,out_pos,sin,cos,ref_mark,switch,
stage,alarm; then one numeric row per clock call.
EVENTS.csv (default: events.csv beside the trace, if present): columns event,cycle,paced_pos,
out_pos,true_nm with events A, B, Z, C. Without it, A, B and C are taken from the trace (stage
1->2, stage 2->3, last count of the first mark pulse) and Z = B + P/4 in the homing direction.

The figure follows 'Figure 4: single-axis referencing sequence': x = real position in output
counts (paced_pos); stacked panels for the sin/cos codes, the reference switch, the reference
mark and the stage; dashed lines at A, B, Z, C; stage 1/2/3 regions shaded. By default only the
first referencing sequence is drawn (from the last reversal before A to the first reversal, or
one period of travel, after C); --whole draws every row.
"""
import argparse
import csv
import os
import re
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

NM_PER_COUNT = 78.125
REQUIRED = ["cycle", "true_nm", "raw_count", "comp_pos", "paced_pos", "out_pos", "sin", "cos",
            "ref_mark", "switch", "stage", "alarm"]
STAGE_COLOURS = {1: "#f2f2f2", 2: "#fff1cc", 3: "#dff0d8"}
EVENT_ORDER = ["A", "B", "Z", "C"]


def read_trace(path):
    """Returns (columns dict name -> float64 array, comment lines)."""
    comments = []
    header = None
    with open(path, "r", encoding="utf-8") as f:
        while True:
            line = f.readline()
            if not line:
                break
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                comments.append(s.lstrip("#").strip())
                continue
            header = [h.strip() for h in s.split(",")]
            break
        if header is None:
            raise SystemExit(f"plot_homing: {path}: no header row")
        missing = [c for c in REQUIRED if c not in header]
        if missing:
            raise SystemExit(f"plot_homing: {path}: missing columns {', '.join(missing)}")
        want = [header.index(c) for c in REQUIRED]
        data = np.loadtxt(f, delimiter=",", comments="#", usecols=want, ndmin=2,
                          dtype=np.float64)
    cols = {c: data[:, i] for i, c in enumerate(REQUIRED)}
    return cols, comments


def read_events(path):
    events = []
    if not path or not os.path.exists(path):
        return events
    with open(path, "r", encoding="utf-8") as f:
        rows = [ln for ln in f if ln.strip() and not ln.lstrip().startswith("#")]
    for row in csv.DictReader(rows):
        row = {k.strip(): (v or "").strip() for k, v in row.items() if k is not None}
        try:
            events.append((row["event"], float(row["paced_pos"])))
        except (KeyError, ValueError):
            continue
    return events


def period_from_comments(comments):
    for c in comments:
        m = re.search(r"\b(?:period|P)\s*[=:]\s*(\d+)", c)
        if m:
            return int(m.group(1))
    return None


def period_from_signal(out_pos, sin):
    """Median distance in out_pos between rising zero crossings of sin (None if < 2)."""
    neg = sin[:-1] < 0
    rise = np.nonzero(neg & (sin[1:] >= 0))[0] + 1
    if rise.size < 3:
        return None
    d = np.abs(np.diff(out_pos[rise]))
    d = d[d > 0]
    return int(round(float(np.median(d)))) if d.size else None


def events_from_trace(cols, period):
    paced, stage, mark = cols["paced_pos"], cols["stage"], cols["ref_mark"]
    ev = []
    up = np.nonzero((stage[:-1] == 1) & (stage[1:] == 2))[0]
    if up.size:
        ev.append(("A", paced[up[0] + 1]))
    up3 = np.nonzero((stage[:-1] == 2) & (stage[1:] == 3))[0]
    if up3.size:
        i = up3[0] + 1
        b = paced[i]
        a = ev[0][1] if ev else None
        direction = 1.0 if a is None or b >= a else -1.0
        ev.append(("B", b))
        if period:
            ev.append(("Z", b + direction * period / 4))
        fall = np.nonzero((mark[i:-1] > 0) & (mark[i + 1:] == 0))[0]
        if fall.size:
            ev.append(("C", paced[i + fall[0]]))
    return ev


def homing_window(cols, period):
    """Row range [lo, hi) of the first referencing sequence: from the last reversal (or 2P of
    travel) before A to the first reversal (or P of travel) after C. None if never homed."""
    paced, stage = cols["paced_pos"], cols["stage"]
    a_idx = np.nonzero((stage[:-1] == 1) & (stage[1:] == 2))[0]
    b_idx = np.nonzero((stage[:-1] == 2) & (stage[1:] == 3))[0]
    if a_idx.size == 0 or b_idx.size == 0:
        return None
    ia = int(a_idx[a_idx < b_idx[0]][-1]) + 1 if np.any(a_idx < b_idx[0]) else int(a_idx[0]) + 1
    ib = int(b_idx[0]) + 1
    direction = 1.0 if paced[ib] >= paced[ia] else -1.0
    span = float(period or 256)
    step = np.sign(np.diff(paced))
    moving = np.nonzero(step != 0)[0]
    rev = moving[1:][step[moving[1:]] != step[moving[:-1]]]   # index of first step of a new run
    before = rev[rev < ia]
    lo = int(before[-1]) + 1 if before.size else 0
    far = np.nonzero(direction * (paced[ia] - paced[:ia]) > 2 * span)[0]
    if far.size:
        lo = max(lo, int(far[-1]) + 1)
    after = rev[rev > ib]
    hi = int(after[0]) + 1 if after.size else paced.size
    c_guess = paced[ib] + direction * span / 4
    beyond = np.nonzero(direction * (paced[ib:] - c_guess) > span)[0]
    if beyond.size:
        hi = min(hi, ib + int(beyond[0]) + 1)
    return lo, hi


def reduce_rows(cols, keys):
    """Keeps the rows where a plotted value changes (and the row before each change), so a trace
    of 1e5+ calls with a slow pacer plots quickly and still exactly as steps."""
    n = cols["cycle"].size
    if n <= 2:
        return np.arange(n)
    change = np.zeros(n, dtype=bool)
    for k in keys:
        change[1:] |= cols[k][1:] != cols[k][:-1]
    keep = change.copy()
    keep[:-1] |= change[1:]
    keep[0] = keep[-1] = True
    return np.nonzero(keep)[0]


def stage_runs(stage):
    """[(stage, first index, last index)] of consecutive equal stage values."""
    if stage.size == 0:
        return []
    edges = np.nonzero(stage[1:] != stage[:-1])[0] + 1
    starts = np.concatenate(([0], edges))
    ends = np.concatenate((edges - 1, [stage.size - 1]))
    return [(int(stage[s]), int(s), int(e)) for s, e in zip(starts, ends)]


def plot(trace, out, events_path=None, period=None, title=None, whole=False):
    cols, comments = read_trace(trace)
    if cols["cycle"].size == 0:
        raise SystemExit(f"plot_homing: {trace}: no data rows")
    if period is None:
        period = period_from_comments(comments) or period_from_signal(cols["out_pos"], cols["sin"])
    if events_path is None:
        events_path = os.path.join(os.path.dirname(os.path.abspath(trace)), "events.csv")
    events = read_events(events_path)
    if not events:
        events = events_from_trace(cols, period)

    win = None if whole else homing_window(cols, period)
    if win is not None:
        cols = {k: v[win[0]:win[1]] for k, v in cols.items()}
    idx = reduce_rows(cols, ["paced_pos", "sin", "cos", "switch", "ref_mark", "stage"])
    x = cols["paced_pos"][idx]
    c = {k: v[idx] for k, v in cols.items()}

    fig, axes = plt.subplots(4, 1, sharex=True, figsize=(12, 7.5),
                             gridspec_kw={"height_ratios": [3, 1, 1, 1.2]})
    ax_sc, ax_sw, ax_mk, ax_st = axes

    # Stage regions (in real position): one span per run of equal stage in time.
    labelled = set()
    for st, s, e in stage_runs(c["stage"]):
        lo, hi = float(np.min(x[s:e + 1])), float(np.max(x[s:e + 1]))
        if e + 1 < x.size:
            hi = max(hi, float(x[e + 1]))
        if hi <= lo:
            hi = lo + 0.5
        for ax in axes:
            ax.axvspan(lo, hi, color=STAGE_COLOURS.get(st, "#eeeeee"), zorder=0, lw=0)
        if st not in labelled:
            ax_sc.text((lo + hi) / 2, 1.02, f"Stage {st}", transform=ax_sc.get_xaxis_transform(),
                       ha="center", va="bottom", fontsize=9, color="0.3")
            labelled.add(st)

    ax_sc.plot(x, c["sin"], drawstyle="steps-post", lw=1.0, color="tab:blue", label="sin")
    ax_sc.plot(x, c["cos"], drawstyle="steps-post", lw=1.0, color="tab:red", label="cos")
    ax_sc.axhline(0, color="0.5", lw=0.5)
    ax_sc.set_ylabel("DAC code")
    ax_sc.legend(loc="upper left", fontsize=8, ncol=2)

    for ax, key, name in ((ax_sw, "switch", "switch"), (ax_mk, "ref_mark", "ref mark")):
        ax.plot(x, c[key], drawstyle="steps-post", lw=1.2, color="k")
        ax.set_ylim(-0.2, 1.3)
        ax.set_yticks([0, 1])
        ax.set_ylabel(name)
    ax_st.plot(x, c["stage"], drawstyle="steps-post", lw=1.2, color="tab:green")
    ax_st.set_ylim(0.5, 3.5)
    ax_st.set_yticks([1, 2, 3])
    ax_st.set_ylabel("stage")
    if np.any(cols["alarm"] != 0):
        ax_st.text(0.99, 0.9, "alarm raised", transform=ax_st.transAxes, ha="right", va="top",
                   color="red", fontsize=9)

    # Event markers; coincident events (C = Z by default) share one label.
    by_pos = {}
    for name, pos in events:
        by_pos.setdefault(pos, []).append(name)
    for pos, names in sorted(by_pos.items()):
        names = sorted(set(names), key=lambda n: EVENT_ORDER.index(n) if n in EVENT_ORDER else 9)
        for ax in axes:
            ax.axvline(pos, color="0.2", ls="--", lw=0.9, zorder=3)
        ax_st.text(pos, -0.35, " = ".join(names), transform=ax_st.get_xaxis_transform(),
                   ha="center", va="top", fontsize=10, fontweight="bold")

    ax_st.set_xlabel("real position, output counts (paced_pos)", labelpad=18)
    if title is None:
        if period:
            title = (f"Single-axis referencing sequence, period P = {period} counts "
                     f"({period * NM_PER_COUNT / 1000:g} \u00b5m)")
        else:
            title = "Single-axis referencing sequence (period unknown)"
    fig.suptitle(title)
    fig.align_ylabels(axes)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return len(events), period


def synth_trace(path, events_path=None, period=256, a_pos=1000, pace=4, rows=100_000):
    """A plausible homing run for the self-test: forward sweep, switch at A, stage 2 over P
    counts with a rephase of d, stage 3 with a mark from B to C, then a return and a second pass."""
    amp = 32767
    n = rows
    cycle = np.arange(n)
    # Move forward 1 count per `pace` calls to a_pos + 3P, then back to a_pos - P/2, then forward.
    fwd = a_pos + 3 * period
    path_pos = []
    p = a_pos - 2 * period
    while len(path_pos) < n:
        for target in (fwd, a_pos - period // 2, fwd + period):
            while p != target and len(path_pos) < n:
                path_pos.extend([p] * pace)
                p += 1 if target > p else -1
        path_pos.extend([p] * (n - len(path_pos)))
    paced = np.array(path_pos[:n], dtype=np.int64)
    ph_a = a_pos % period
    d = (7 * period // 8 - ph_a) % period
    stage = np.ones(n, dtype=np.int64)
    adj = np.zeros(n, dtype=np.int64)
    state, b = 1, None
    for i in range(n):
        if state == 1 and paced[i] == a_pos and (i == 0 or paced[i - 1] == a_pos - 1):
            state = 2
        elif state == 2:
            tr = paced[i] - a_pos
            if tr < 0:
                state = 1
            elif tr >= period:
                state, b = 3, a_pos + period
        stage[i] = state
        if state == 2:
            adj[i] = (d * (paced[i] - a_pos)) // period
        elif state == 3:
            adj[i] = d
    out_pos = paced + adj
    ang = 2 * np.pi * (out_pos % period) / period
    sin = np.round(amp * np.sin(ang)).astype(np.int64)
    cos = np.round(amp * np.cos(ang)).astype(np.int64)
    switch = (paced >= a_pos).astype(np.int64)
    c_pos = (b if b is not None else 10**9) + period // 4
    ref = ((stage == 3) & (paced >= (b or 0)) & (paced <= c_pos)).astype(np.int64)
    true_nm = paced * NM_PER_COUNT
    raw = np.floor(true_nm / 78.125 / 8.1).astype(np.int64)
    with open(path, "w", encoding="utf-8") as f:
        f.write(f"# synthetic laserax trace for plot_homing.py --selftest\n# period={period}\n")
        f.write(",".join(REQUIRED) + "\n")
        arr = np.column_stack([cycle, true_nm, raw, paced, paced, out_pos, sin, cos, ref, switch,
                               stage, np.zeros(n, dtype=np.int64)])
        np.savetxt(f, arr, delimiter=",", fmt=["%d", "%.3f"] + ["%d"] * 10)
    if events_path:
        with open(events_path, "w", encoding="utf-8") as f:
            f.write("event,cycle,paced_pos,out_pos,true_nm\n")
            for name, pos in (("A", a_pos), ("B", b), ("Z", b + period // 4), ("C", c_pos)):
                i = int(np.argmax(paced == pos))
                f.write(f"{name},{i},{pos},{out_pos[i]},{true_nm[i]:.3f}\n")


def selftest(folder):
    import time
    folder = folder or tempfile.mkdtemp(prefix="laserax_plot_")
    os.makedirs(folder, exist_ok=True)
    trace = os.path.join(folder, "trace.csv")
    synth_trace(trace, os.path.join(folder, "events.csv"))
    t0 = time.time()
    nev, period = plot(trace, os.path.join(folder, "homing.png"))
    t1 = time.time()
    ok = nev == 4 and period == 256 and os.path.getsize(os.path.join(folder, "homing.png")) > 10000
    # Without the events file and the period comment: derived from the trace itself.
    trace2 = os.path.join(folder, "bare", "trace.csv")
    os.makedirs(os.path.dirname(trace2), exist_ok=True)
    with open(trace, encoding="utf-8") as fi, open(trace2, "w", encoding="utf-8") as fo:
        fo.writelines(ln for ln in fi if not ln.startswith("#"))
    nev2, period2 = plot(trace2, os.path.join(folder, "bare", "homing.png"), whole=True)
    ok = ok and nev2 == 4 and period2 == 256
    print(f"plot_homing selftest: {os.path.join(folder, 'homing.png')} "
          f"(1e5 rows in {t1 - t0:.2f} s; events {nev}/{nev2}, period {period}/{period2})")
    print("plot_homing_selftest: " + ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("trace", nargs="?", default="out/trace.csv")
    ap.add_argument("out", nargs="?", default="out/homing.png")
    ap.add_argument("--events", default=None, help="events CSV (default: events.csv beside trace)")
    ap.add_argument("--period", type=int, default=None, help="period P in output counts")
    ap.add_argument("--title", default=None)
    ap.add_argument("--whole", action="store_true",
                    help="plot the whole trace (default: only the first referencing sequence)")
    ap.add_argument("--selftest", action="store_true",
                    help="plot a synthetic trace; the optional positional argument is the folder")
    args = ap.parse_args(argv)
    if args.selftest:
        return selftest(args.trace if args.trace != "out/trace.csv" else None)
    if not os.path.exists(args.trace):
        print(f"plot_homing: {args.trace} not found (run `make run` first)", file=sys.stderr)
        return 1
    nev, period = plot(args.trace, args.out, args.events, args.period, args.title, args.whole)
    print(f"plot_homing: wrote {args.out} (period {period if period else '?'}, {nev} events)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
