#!/usr/bin/env python3
"""Work-precision of a tail probability: weighted particles against equal weights (issue 56).

Usage: python3 tools/tail_work_precision.py [--gdsmc BIN] [--rounds R] [--out DIR] [--quick]
       [--only LABEL,...]

Runs GRW Example 3's heated Maxwell gas (scenes/grw-example3-weighted.toml) under each
configuration of CONFIGS, one thread each, the configurations interleaved round by round
(round r runs every configuration once, with seed 1000 r + k, before round r + 1 starts), and
times each `gdsmc run` by its CPU time (user + system of the child, os.wait4). Each run's
reduced-speed histogram has 4 shells to `c = 8/sqrt(2)` (`c = |v - V|/sqrt(2 T)`), so its edges
are 2, 4, 6, 8 `sqrt(T)` and its last bin is the weight beyond 8
`sqrt(T)`, averaged over the steady observations (t >= 4) in each ensemble: `P(|c| > 8)` with
its 99.9% half-width over ensembles (Student-t; the runner's). `P(|c| > 6)` and `P(|c| > 4)`
are sums of bins; their half-widths are bounded by the sum of the bins' (the bins' covariance
is not in the output: a bound, wider than the interval, the same rule for both schemes).

The figure of merit is the variance of the mean times the CPU time it took, `(ci/q)^2 cpu`
with `q` the Student-t quantile of the run (a run twice as long halves the variance, so the
product is the cost of one unit of precision). Its median over the rounds is reported, with
the rounds' spread, per configuration and threshold, and the ratio of equal weights' to each
weighted configuration's. Writes DIR/work_precision.csv (one row per run) and
DIR/work_precision.svg (standard error against CPU seconds, log-log, one point per run).
"""
import argparse
import csv
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SCENE = os.path.join(ROOT, "scenes", "grw-example3-weighted.toml")
THERMAL = (4, 6, 8)
RADIUS = 8.0 / math.sqrt(2.0)

EQUAL = ['scheme={kind="no-splitting"}']
# The tail transfer without windows (the scene's settings before the windows), every key set
# here so that a change of the scene does not change what a label runs.
TAIL = ["scheme.tail_kappa=7", "scheme.tail_speed=2.5", "scheme.exponent=0.5", "scheme.floor=0",
        "scheme.split=0"]
# The weight windows (scenes/grw-example3-weighted.toml), likewise.
WINDOWS = ["scheme.tail_kappa=0", "scheme.exponent=0.25", "scheme.floor=0.25", "scheme.split=2"]


def over(base, *changes):
    """`base` with each `key=value` of `changes` in place of the same key's setting."""
    keys = {c.split("=")[0] for c in changes}
    return [b for b in base if b.split("=")[0] not in keys] + list(changes)


# label, particles, ensembles, --set values.
CONFIGS = [
    ("equal n=1024", 1024, 100000, EQUAL),
    ("equal n=4096", 4096, 25000, EQUAL),
    ("tail transfer n0=1024", 1024, 250, TAIL),
    ("windows n0=1024", 1024, 250, WINDOWS),
    ("windows no floor n0=1024", 1024, 250, over(WINDOWS, "scheme.floor=0")),
    ("windows n0=1024 q=0", 1024, 250, over(WINDOWS, "scheme.exponent=0", "scheme.floor=0")),
    ("windows n0=1024 target 4", 1024, 250,
     over(WINDOWS, "scheme.target=4", "scheme.capacity=8")),
    ("windows n0=1024 capacity 8", 1024, 250, over(WINDOWS, "scheme.capacity=8")),
    ("windows n0=1024 capacity 16", 1024, 250, over(WINDOWS, "scheme.capacity=16")),
    ("windows and tail transfer n0=1024 q=0", 1024, 250,
     over(TAIL, "scheme.split=2", "scheme.exponent=0")),
]


def student_q(dof):
    """The two-sided 99.9% Student-t quantile (Cornish-Fisher to 1e-4 for dof >= 10)."""
    z = 3.2905267314919255
    g1 = (z**3 + z) / 4
    g2 = (5 * z**5 + 16 * z**3 + 3 * z) / 96
    g3 = (3 * z**7 + 19 * z**5 + 17 * z**3 - 15 * z) / 384
    g4 = (79 * z**9 + 776 * z**7 + 1482 * z**5 - 1920 * z**3 - 945 * z) / 92160
    return z + g1 / dof + g2 / dof**2 + g3 / dof**3 + g4 / dof**4


def run_one(gdsmc, label, n, m, sets, seed, workdir):
    """One `gdsmc run`: its CPU seconds and the tail probabilities (mean, half-width)."""
    out = os.path.join(workdir, "run")
    shutil.rmtree(out, ignore_errors=True)
    cmd = [gdsmc, "run", SCENE, "--threads", "1", "--fresh", "--out", out,
           "--n", str(n), "--ensembles", str(m), "--seed", str(seed),
           "--set", "reduced_histogram.shells=4", "--set", f"reduced_histogram.radius={RADIUS!r}"]
    for s in sets:
        cmd += ["--set", s]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, cwd=workdir)
    _, status, usage = os.wait4(proc.pid, 0)
    err = proc.stderr.read().decode()
    proc.stderr.close()
    if status != 0:
        sys.exit(f"{label}: gdsmc run failed ({status}): {err}")
    cpu = usage.ru_utime + usage.ru_stime
    return cpu, tails_of(list(csv.DictReader(open(os.path.join(out, "reduced.csv")))))


def tails_of(rows):
    """`{c: (P(|v - V| > c sqrt(T)), its half-width or a bound, exact)}` from the rows of a
    reduced.csv with 4 shells to `8/sqrt(2)` and the bin beyond: the bins from the one that
    starts at `c/sqrt(2)` on (the half-widths summed: a bound unless it is the last bin)."""
    edges = [float(r["c_lo"]) for r in rows]
    f = [float(r["f"]) for r in rows]
    ci = [float(r["f_ci"]) for r in rows]
    tails = {}
    for c in THERMAL:
        first = min(range(len(edges)), key=lambda k: abs(edges[k] - c / math.sqrt(2.0)))
        if abs(edges[first] - c / math.sqrt(2.0)) > 1e-9 * c:
            sys.exit(f"no bin starts at {c} sqrt(T): {edges}")
        tails[c] = (sum(f[first:]), sum(ci[first:]), first == len(f) - 1)
    return tails


def svg(points, path):
    """Standard error against CPU seconds, log-log, a marker per run, one colour a config."""
    colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf"]
    labels = sorted({p[0] for p in points}, key=[c[0] for c in CONFIGS].index)
    pts = [p for p in points if p[2] > 0 and p[3] > 0]
    if not pts:
        return
    lx = [math.log10(p[2]) for p in pts]
    ly = [math.log10(p[3]) for p in pts]
    x0, x1 = math.floor(min(lx)), math.ceil(max(lx))
    y0, y1 = math.floor(min(ly)), math.ceil(max(ly))
    w, h, m, legend = 820, 420, 70, 240
    sx = lambda v: m + (v - x0) / max(x1 - x0, 1) * (w - legend - 2 * m)
    sy = lambda v: h - m - (v - y0) / max(y1 - y0, 1) * (h - 2 * m)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" '
           'font-family="sans-serif" font-size="12">',
           f'<rect width="{w}" height="{h}" fill="white"/>',
           f'<text x="{(w - legend) / 2}" y="20" text-anchor="middle">P(|v - V| &gt; 8 '
           'sqrt(T)), GRW Example 3: standard error against CPU time</text>']
    for e in range(x0, x1 + 1):
        out.append(f'<line x1="{sx(e)}" y1="{sy(y0)}" x2="{sx(e)}" y2="{sy(y1)}" stroke="#ddd"/>')
        out.append(f'<text x="{sx(e)}" y="{h - m + 18}" text-anchor="middle">1e{e}</text>')
    for e in range(y0, y1 + 1):
        out.append(f'<line x1="{sx(x0)}" y1="{sy(e)}" x2="{sx(x1)}" y2="{sy(e)}" stroke="#ddd"/>')
        out.append(f'<text x="{m - 6}" y="{sy(e) + 4}" text-anchor="end">1e{e}</text>')
    out.append(f'<text x="{(w - legend) / 2}" y="{h - 20}" text-anchor="middle">CPU seconds '
               '(one point a run; lower left is better)</text>')
    out.append(f'<text x="16" y="{h / 2}" transform="rotate(-90 16 {h / 2})" '
               'text-anchor="middle">standard error of the mean</text>')
    for k, lab in enumerate(labels):
        col = colours[k % len(colours)]
        for p in pts:
            if p[0] == lab:
                out.append(f'<circle cx="{sx(math.log10(p[2])):.1f}" '
                           f'cy="{sy(math.log10(p[3])):.1f}" r="4" fill="{col}"/>')
        out.append(f'<circle cx="{w - legend}" cy="{m + 16 * k}" r="4" fill="{col}"/>')
        out.append(f'<text x="{w - legend + 10}" y="{m + 16 * k + 4}">{lab}</text>')
    out.append("</svg>")
    open(path, "w").write("\n".join(out) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--gdsmc", default=os.path.join(ROOT, "target", "release", "gdsmc"))
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--out", default="work-precision")
    ap.add_argument("--quick", action="store_true", help="a tenth of the ensembles")
    ap.add_argument("--only", default="", help="comma-separated labels to run")
    a = ap.parse_args()
    configs = [c for c in CONFIGS if not a.only or c[0] in a.only.split(",")]
    os.makedirs(a.out, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for r in range(a.rounds):
            for k, (label, n, m, sets) in enumerate(configs):
                m = max(m // 10, 20) if a.quick else m
                cpu, tails = run_one(a.gdsmc, label, n, m, sets, 1000 * r + k, work)
                q = student_q(m - 1)
                for c, (p, ci, exact) in tails.items():
                    se = ci / q
                    rows.append((label, r, c, n, m, cpu, p, ci, exact, se * se * cpu))
                print(f"round {r} {label}: {cpu:.1f} s CPU, " + ", ".join(
                    f"P(>{c}) {p:.3e} +- {ci:.1e}" for c, (p, ci, _) in tails.items()),
                    flush=True)
    with open(os.path.join(a.out, "work_precision.csv"), "w", newline="") as fh:
        wr = csv.writer(fh)
        wr.writerow(["config", "round", "thermal_speeds", "n", "ensembles", "cpu_s", "p",
                     "p_ci", "ci_exact", "var_x_cpu"])
        wr.writerows(rows)
    svg([(x[0], x[1], x[5], x[7] / student_q(x[4] - 1)) for x in rows if x[2] == 8],
        os.path.join(a.out, "work_precision.svg"))
    print("\n| config | c | P(|c| > c) (pooled) | var x CPU (median; min-max over rounds) |")
    print("|---|---|---|---|")
    med = {}
    for label, *_ in configs:
        for c in THERMAL:
            sel = [x for x in rows if x[0] == label and x[2] == c]
            ps = [x[6] for x in sel]
            v = [x[9] for x in sel]
            med[(label, c)] = statistics.median(v)
            print(f"| {label} | {c} | {statistics.mean(ps):.3e} | {med[(label, c)]:.2e} "
                  f"({min(v):.1e}-{max(v):.1e}) |")
    for c in THERMAL:
        eq = [med[(l, c)] for l, *_ in configs if l.startswith("equal") and med[(l, c)] > 0]
        for l, *_ in configs:
            if not l.startswith("equal") and eq and med[(l, c)] > 0:
                print(f"c = {c}: best equal weights / {l}: {min(eq) / med[(l, c)]:.1f}x")


if __name__ == "__main__":
    main()
