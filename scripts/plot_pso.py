#!/usr/bin/python3
"""plot_pso.py — figures for `laserax pso` and `laserax counters`.

Usage (Debian's interpreter, with numpy and matplotlib):
    /usr/bin/python3 scripts/plot_pso.py pso [TRACE.csv] [FIRES.csv] [OUT.png]
    /usr/bin/python3 scripts/plot_pso.py counters [TRACE.csv] [OUT.png]
    /usr/bin/python3 scripts/plot_pso.py --selftest [DIR]

pso: TRACE (default out/pso_trace.csv) has the columns cycle,x_nm,y_nm,pos_x,pos_y,... (lines
starting with '#' are comments); FIRES (default out/pso_fires.csv) has k,cycle,x_nm,y_nm,
ideal_x_nm,ideal_y_nm,err_nm,along_nm,emitted. Left: the path in um with the firing positions
(filled: pulse emitted, hollow: suppressed by the window) and the ideal points; right: the firing
position error in nm against the fire number.
counters: TRACE (default out/counters_trace.csv) has cycle,cnt0,cnt1,corr0,corr1,tick,waiting,
reached,rst_pending0,rst_done0,event. Panels: both counters, the corrected outputs, with the
events marked.
"""
import csv
import os
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_csv(path):
    """Returns (header list, rows as lists of strings), skipping '#' comments."""
    rows, header = [], None
    with open(path, "r", encoding="utf-8") as f:
        for line in f:
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            if header is None:
                header = [h.strip() for h in s.split(",")]
                continue
            rows.append(next(csv.reader([s])))
    if header is None:
        raise SystemExit("plot_pso.py: %s: no header line" % path)
    return header, rows


def column(header, rows, name, conv=float):
    i = header.index(name)
    return np.array([conv(r[i]) for r in rows])


def plot_pso(trace, fires, out):
    th, tr = read_csv(trace)
    x = column(th, tr, "x_nm") / 1000.0
    y = column(th, tr, "y_nm") / 1000.0
    fig, (ax, ae) = plt.subplots(1, 2, figsize=(13, 5.5), gridspec_kw={"width_ratios": [3, 2]})
    ax.plot(x, y, "-", color="#999999", lw=1.0, label="path")
    if os.path.exists(fires):
        fh, fr = read_csv(fires)
        if fr:
            fx = column(fh, fr, "x_nm") / 1000.0
            fy = column(fh, fr, "y_nm") / 1000.0
            ix = column(fh, fr, "ideal_x_nm") / 1000.0
            iy = column(fh, fr, "ideal_y_nm") / 1000.0
            err = column(fh, fr, "err_nm")
            emitted = column(fh, fr, "emitted", int) != 0
            k = column(fh, fr, "k", int)
            ax.plot(ix, iy, "x", color="#2c7fb8", ms=6, label="ideal (k x distance)")
            ax.plot(fx[emitted], fy[emitted], "o", color="#d95f02", ms=4, label="fired, pulse emitted")
            if (~emitted).any():
                ax.plot(fx[~emitted], fy[~emitted], "o", mfc="none", color="#d95f02", ms=4,
                        label="fired, outside window")
            ae.plot(k, err, ".-", color="#d95f02")
            ae.set_title("firing position error: max %.1f nm, mean %.1f nm" % (err.max(), err.mean()))
    ae.set_xlabel("fire number")
    ae.set_ylabel("error vs ideal [nm]")
    ae.grid(True, alpha=0.3)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [um]")
    ax.set_ylabel("y [um]")
    ax.set_title("PSO firing positions along the path")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_counters(trace, out):
    th, tr = read_csv(trace)
    t_us = column(th, tr, "cycle") / 100.0
    fig, axes = plt.subplots(3, 1, figsize=(11, 8), sharex=True)
    axes[0].plot(t_us, column(th, tr, "cnt0"), ".-", ms=2, label="counter 0 (simulation)")
    axes[0].set_ylabel("counter 0")
    axes[1].plot(t_us, column(th, tr, "cnt1"), ".-", ms=2, color="#d95f02", label="counter 1 (quadrature)")
    axes[1].set_ylabel("counter 1")
    axes[2].plot(t_us, column(th, tr, "corr0"), ".-", ms=2, label="output 0")
    axes[2].plot(t_us, column(th, tr, "corr1"), ".-", ms=2, color="#d95f02", label="output 1")
    axes[2].set_ylabel("corrected output [bits]")
    axes[2].set_xlabel("time [us]")
    ev = th.index("event")
    for r, t in zip(tr, t_us):
        if len(r) > ev and r[ev]:
            for a in axes:
                a.axvline(t, color="#888888", lw=0.8, ls="--")
            axes[0].annotate(r[ev], (t, axes[0].get_ylim()[1]), rotation=90, fontsize=7, va="top", ha="right")
    for a in axes:
        a.grid(True, alpha=0.3)
        a.legend(loc="best", fontsize=8)
    axes[0].set_title("encoder counters, correction every 10 us")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def selftest(d):
    os.makedirs(d, exist_ok=True)
    tr, fi, ct = os.path.join(d, "pso_trace.csv"), os.path.join(d, "pso_fires.csv"), os.path.join(d, "ct.csv")
    with open(tr, "w") as f:
        f.write("# synthetic\ncycle,x_nm,y_nm,pos_x,pos_y,dist_counts,fire,emit,pulse,in_win,fire_cnt\n")
        for i in range(200):
            a = i / 200 * np.pi
            f.write("%d,%.3f,%.3f,0,0,0,0,0,0,1,0\n" % (i, 1e4 * np.cos(a), 1e4 * np.sin(a)))
    with open(fi, "w") as f:
        f.write("k,cycle,x_nm,y_nm,ideal_x_nm,ideal_y_nm,err_nm,along_nm,emitted\n")
        for k in range(1, 10):
            a = k / 10 * np.pi
            f.write("%d,%d,%.3f,%.3f,%.3f,%.3f,%.3f,0,%d\n" % (k, k * 20, 1e4 * np.cos(a) + 30, 1e4 * np.sin(a),
                                                            1e4 * np.cos(a), 1e4 * np.sin(a), 30.0, k % 3 != 0))
    with open(ct, "w") as f:
        f.write("cycle,cnt0,cnt1,corr0,corr1,tick,waiting,reached,rst_pending0,rst_done0,event\n")
        for i in range(0, 20000, 1000):
            f.write("%d,%d,%d,%d,%d,1,0,0,0,0,%s\n" % (i, i // 100, 2147483000 + i if i < 5000 else -2147483000 + i,
                                                     i // 100, 2 * i, "reset" if i == 5000 else ""))
    plot_pso(tr, fi, os.path.join(d, "pso.png"))
    plot_counters(ct, os.path.join(d, "counters.png"))
    ok = all(os.path.getsize(os.path.join(d, n)) > 1000 for n in ("pso.png", "counters.png"))
    print("plot_pso selftest: %s (%s)" % ("PASS" if ok else "FAIL", d))
    return 0 if ok else 1


def main(argv):
    if len(argv) >= 1 and argv[0] == "--selftest":
        return selftest(argv[1] if len(argv) > 1 else tempfile.mkdtemp(prefix="plot_pso_"))
    if not argv or argv[0] not in ("pso", "counters"):
        print(__doc__)
        return 2
    if argv[0] == "pso":
        trace = argv[1] if len(argv) > 1 else "out/pso_trace.csv"
        fires = argv[2] if len(argv) > 2 else os.path.join(os.path.dirname(trace), "pso_fires.csv")
        out = argv[3] if len(argv) > 3 else os.path.join(os.path.dirname(trace), "pso.png")
        plot_pso(trace, fires, out)
    else:
        trace = argv[1] if len(argv) > 1 else "out/counters_trace.csv"
        out = argv[2] if len(argv) > 2 else os.path.join(os.path.dirname(trace), "counters.png")
        plot_counters(trace, out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
