#!/usr/bin/python3
"""plot_gantry.py — draw the twin-axis (gantry) referencing sequence written by `laserax gantry`.

Usage (with Debian's interpreter, which has numpy and matplotlib):
    /usr/bin/python3 scripts/plot_gantry.py [--trace out/gantry_trace.csv]
                                            [--sequence-png out/gantry_sequence.png]
                                            [--map out/gantry_skew_map.csv]
                                            [--map-png out/gantry_skew_map.png]
    /usr/bin/python3 scripts/plot_gantry.py --selftest [DIR]

gantry_trace.csv: comment lines start with '#' (the first gives period=, offset=, skew_limit=;
`# step N = NAME` lines name the sequence steps); then a header and one row per traced clock with
at least cycle,step,x1_nm,x2_nm,ctrl1,ctrl2,homed1,homed2,rack,skew_valid,skew,stage1,stage2,
mark1,mark2,sw1,sw2.
gantry_skew_map.csv: comment line with period=, offset=, skew_limit=; header; one row per
power-up phase pair with at least phase1,phase2,skew_error,alarm.

gantry_sequence.png: the sequence over time (us of machine time): physical positions of X1 and
X2 (um from X1's switch) with the sequence steps shaded and named; the rack x1 - x2 and the skew
the controller measures minus the offset (output counts) with the +-P bound and the skew limit;
the compensator stages and reference marks of both axes.
gantry_skew_map.png: heat map of skew - offset at the check over the power-up phases of X1 and X2,
alarm cells marked.
Exit status: 0 done, 1 bad input, 3 numpy/matplotlib missing.
"""
import argparse
import os
import re
import sys
import tempfile

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
    import numpy as np  # noqa: E402
except ImportError as exc:  # pragma: no cover
    print("plot_gantry.py: numpy/matplotlib not available (%s); run `make deps` or "
          "apt-get install python3-matplotlib; plots skipped" % exc)
    sys.exit(3)

NM_PER_COUNT = 78.125
CLOCK_NS = 10.0
TRACE_REQUIRED = ["cycle", "step", "x1_nm", "x2_nm", "ctrl1", "ctrl2", "homed1", "homed2", "rack",
                  "skew_valid", "skew", "stage1", "stage2", "mark1", "mark2", "sw1", "sw2"]
MAP_REQUIRED = ["phase1", "phase2", "skew_error", "alarm"]
STEP_COLOURS = ["#f2f2f2", "#e8f0fb", "#fff1cc", "#dff0d8", "#fde2e2", "#ece2f7", "#d9f2f2"]


def read_csv(path, required):
    """Returns (dict column -> float array, list of comment lines)."""
    comments, header, rows = [], None, []
    with open(path, "r", encoding="utf-8") as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                comments.append(s.lstrip("#").strip())
                continue
            if header is None:
                header = [h.strip() for h in s.split(",")]
                continue
            rows.append([float(v) for v in s.split(",")])
    if header is None or not rows:
        raise ValueError("%s: no header or no rows" % path)
    missing = [c for c in required if c not in header]
    if missing:
        raise ValueError("%s: missing columns %s" % (path, ", ".join(missing)))
    data = np.array(rows, dtype=float)
    return {h: data[:, i] for i, h in enumerate(header)}, comments


def header_value(comments, key, default=None):
    for c in comments:
        m = re.search(r"\b%s=([-\w.]+)" % re.escape(key), c)
        if m:
            return m.group(1)
    return default


def step_names(comments):
    names = {}
    for c in comments:
        m = re.match(r"step (\d+) = (.*)$", c)
        if m:
            names[int(m.group(1))] = m.group(2)
    return names


def plot_sequence(trace_path, png_path):
    t, comments = read_csv(trace_path, TRACE_REQUIRED)
    period = int(header_value(comments, "period", "256"))
    offset = float(header_value(comments, "offset", "0"))
    limit = float(header_value(comments, "skew_limit", str(period)))
    names = step_names(comments)
    us = t["cycle"] * CLOCK_NS / 1000.0

    fig, axes = plt.subplots(3, 1, figsize=(12, 9.5), sharex=True,
                             gridspec_kw={"height_ratios": [2.2, 2.2, 1.3]})
    title = "gantry referencing: P = %d counts (%.2f um), offset %g, skew limit %g" % (
        period, period * NM_PER_COUNT / 1000.0, offset, limit)
    if header_value(comments, "phase1") is not None:
        title += ", power-up phases %s / %s" % (header_value(comments, "phase1"), header_value(comments, "phase2"))
    fig.suptitle(title)

    # shaded sequence steps
    steps = t["step"].astype(int)
    change = np.flatnonzero(np.diff(steps)) + 1
    starts = np.concatenate([[0], change])
    ends = np.concatenate([change, [len(steps) - 1]])
    for k, (a, b) in enumerate(zip(starts, ends)):
        for ax in axes:
            ax.axvspan(us[a], us[b], color=STEP_COLOURS[steps[a] % len(STEP_COLOURS)], alpha=0.6, lw=0)
        if us[b] - us[a] > 0.04 * (us[-1] - us[0] + 1e-9):
            axes[0].text(0.5 * (us[a] + us[b]), 1.0, names.get(steps[a], str(steps[a])), rotation=0,
                         ha="center", va="bottom", fontsize=7, transform=axes[0].get_xaxis_transform())

    ax = axes[0]
    ax.plot(us, t["x1_nm"] / 1000.0, label="X1 real position", color="tab:blue")
    ax.plot(us, t["x2_nm"] / 1000.0, label="X2 real position", color="tab:orange", ls="--")
    ax.set_ylabel("position [um from X1's switch]")
    ax.legend(loc="lower right", fontsize=8)
    ax.grid(alpha=0.3)

    ax = axes[1]
    ax.plot(us, t["rack"], label="rack x1 - x2 (physical)", color="tab:purple")
    valid = t["skew_valid"] > 0
    skew_err = np.where(valid, t["skew"] - offset, np.nan)
    ax.plot(us, skew_err, label="controller skew - offset (both homed)", color="tab:green", lw=2)
    for s in (1, -1):
        ax.axhline(s * period, color="k", ls=":", lw=1, label="+-P (seed bound)" if s > 0 else None)
        ax.axhline(s * limit, color="tab:red", ls="--", lw=1, label="skew limit" if s > 0 else None)
    ax.set_ylabel("output counts")
    ax.legend(loc="lower right", fontsize=8)
    ax.grid(alpha=0.3)

    ax = axes[2]
    ax.step(us, t["stage1"] + 0.05, where="post", label="X1 compensator stage", color="tab:blue")
    ax.step(us, t["stage2"] - 0.05, where="post", label="X2 compensator stage", color="tab:orange")
    ax.fill_between(us, 0, 0.5 * t["mark1"], step="post", color="tab:blue", alpha=0.4, label="X1 ref mark")
    ax.fill_between(us, 0, -0.5 * t["mark2"], step="post", color="tab:orange", alpha=0.4, label="X2 ref mark")
    ax.set_yticks([-0.5, 0, 1, 2, 3])
    ax.set_yticklabels(["mark2", "", "1", "2", "3"])
    ax.set_ylim(-0.8, 3.4)
    ax.set_ylabel("stage / mark")
    ax.set_xlabel("machine time [us] (one clock = 10 ns)")
    ax.legend(loc="upper left", fontsize=7, ncol=4)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)
    plt.close(fig)


def plot_map(map_path, png_path):
    m, comments = read_csv(map_path, MAP_REQUIRED)
    period = int(header_value(comments, "period", "256"))
    limit = float(header_value(comments, "skew_limit", str(period)))
    p1 = np.unique(m["phase1"])
    p2 = np.unique(m["phase2"])
    grid = np.full((len(p2), len(p1)), np.nan)
    alarm = np.zeros_like(grid)
    i1 = {v: i for i, v in enumerate(p1)}
    i2 = {v: i for i, v in enumerate(p2)}
    for a, b, e, al in zip(m["phase1"], m["phase2"], m["skew_error"], m["alarm"]):
        grid[i2[b], i1[a]] = e
        alarm[i2[b], i1[a]] = al
    step1 = p1[1] - p1[0] if len(p1) > 1 else 1.0
    step2 = p2[1] - p2[0] if len(p2) > 1 else 1.0
    fig, ax = plt.subplots(figsize=(7.5, 6.2))
    im = ax.imshow(grid, origin="lower", cmap="RdBu_r", vmin=-period, vmax=period, aspect="auto",
                   extent=[p1[0] - step1 / 2, p1[-1] + step1 / 2, p2[0] - step2 / 2, p2[-1] + step2 / 2])
    cb = fig.colorbar(im, ax=ax)
    cb.set_label("skew - offset at the check [output counts]")
    ya, xa = np.nonzero(alarm > 0)
    if len(xa):
        ax.scatter(p1[xa], p2[ya], marker="x", color="k", s=18, label="alarm (|skew - offset| > %g)" % limit)
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.11), fontsize=8, frameon=False)
    worst = np.nanmax(np.abs(grid))
    ax.set_title("temporary skew over power-up phases, P = %d (worst %d counts = %.2f um)" % (
        period, worst, worst * NM_PER_COUNT / 1000.0), fontsize=10)
    ax.set_xlabel("X1 power-up phase (output phase at A) [counts]")
    ax.set_ylabel("X2 power-up phase [counts]")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)
    plt.close(fig)


def selftest(folder):
    os.makedirs(folder, exist_ok=True)
    trace = os.path.join(folder, "gantry_trace.csv")
    smap = os.path.join(folder, "gantry_skew_map.csv")
    period = 16
    with open(trace, "w", encoding="utf-8") as f:
        f.write("# laserax gantry trace: period=%d offset=2 switch_offset=2 skew_limit=%d\n" % (period, period))
        f.write("# step 3 = X1 search\n# step 4 = X1 clearance\n")
        f.write(",".join(TRACE_REQUIRED) + "\n")
        for c in range(0, 400):
            step = 3 if c < 200 else 4
            x = 0.1 * c
            row = [c * 8, step, x * 78.125, (x + 0.02 * c) * 78.125, x, x, 0, 0, 1.0 if c > 150 else 0.0,
                   1 if c > 300 else 0, 5, 1 if c < 100 else 3, 1, 1 if 120 < c < 140 else 0, 0, 1, 1]
            f.write(",".join(str(v) for v in row) + "\n")
    with open(smap, "w", encoding="utf-8") as f:
        f.write("# laserax gantry skew map: period=%d offset=0 skew_limit=9\n" % period)
        f.write("phase1,phase2,skew_error,alarm\n")
        for a in range(period):
            for b in range(period):
                d1 = (14 - a) % period
                d2 = (14 - b) % period
                f.write("%d,%d,%d,%d\n" % (a, b, d2 - d1, 1 if abs(d2 - d1) > 9 else 0))
    plot_sequence(trace, os.path.join(folder, "gantry_sequence.png"))
    plot_map(smap, os.path.join(folder, "gantry_skew_map.png"))
    for name in ("gantry_sequence.png", "gantry_skew_map.png"):
        if os.path.getsize(os.path.join(folder, name)) < 1000:
            print("plot_gantry.py selftest: %s too small" % name)
            return 1
    print("plot_gantry.py selftest: PASS (%s)" % folder)
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--trace", default="out/gantry_trace.csv")
    ap.add_argument("--sequence-png", default=None)
    ap.add_argument("--map", default=None)
    ap.add_argument("--map-png", default=None)
    ap.add_argument("--selftest", nargs="?", const="", default=None, metavar="DIR")
    a = ap.parse_args()
    if a.selftest is not None:
        return selftest(a.selftest or tempfile.mkdtemp(prefix="plot_gantry_"))
    try:
        if a.trace:
            png = a.sequence_png or os.path.join(os.path.dirname(a.trace) or ".", "gantry_sequence.png")
            plot_sequence(a.trace, png)
        if a.map:
            png = a.map_png or os.path.join(os.path.dirname(a.map) or ".", "gantry_skew_map.png")
            plot_map(a.map, png)
    except (OSError, ValueError) as exc:
        print("plot_gantry.py: %s" % exc)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
