#!/usr/bin/env python3
"""The full-size tail table of docs/tails-full.md from `gdsmc run` outputs.

Usage: python3 tools/tails_table.py DIR6 DIR7 DIR8
Each DIR is the output directory of `gdsmc run scenes/grw-exampleK.toml --n 10000000
--ensembles 100` (summary.json, observables.csv, histograms.csv: the shells' width is the
run's own). Prints one Markdown row per example that
has finished: the fitted exponent (GRW Section 4.3, k0 = 1) with its 99.9% interval, the
slopes of the fit's inner and outer halves, GRW (16)'s asymptote 1 + lambda/2, the final
temperature, the speed range of the fitted shells in thermal units, and the cost.
"""
import csv
import json
import math
import os
import sys

LAMBDA = {"6": 0.0, "7": 1.0, "8": 0.5}


def row(ex, d):
    s = json.load(open(os.path.join(d, "summary.json")))
    t = s["tail"]
    obs = list(csv.DictReader(open(os.path.join(d, "observables.csv"))))
    temp = float(obs[-1]["T"])
    # The run's own shells (a run may set histogram.radius or shells): the finite edges.
    edges = [float(r["r_hi"]) for r in csv.DictReader(open(os.path.join(d, "histograms.csv")))
             if math.isfinite(float(r["r_hi"]))]
    h = max(edges) / len(edges)
    inner, outer = t["halves"]["inner"], t["halves"]["outer"]
    k_lo, k_hi = inner["shells"][0], outer["shells"][1]
    # Shell k (1-based, GRW (31)) ends at r_k = k h.
    v_lo, v_hi = (k_lo - 1) * h / math.sqrt(temp), k_hi * h / math.sqrt(temp)
    c = s["counts"]
    return (
        f"| {ex} | {LAMBDA[ex]:g} | {1 + LAMBDA[ex] / 2:g} "
        f"| {t['slope']:.3f} +- {t['slope_ci']:.3f} "
        f"| {inner['slope']:.3f} +- {inner['slope_ci']:.3f} "
        f"| {outer['slope']:.3f} +- {outer['slope_ci']:.3f} "
        f"| {k_lo}-{k_hi} | {v_lo:.1f}-{v_hi:.1f} | {temp:.3f} "
        f"| {c['collisions']:.3e} | {c['fictitious']:.3e} "
        f"| {s['cpu_seconds']:.0f} | {s['wall_seconds']:.0f} |"
    )


def main():
    print(
        "| GRW example | lambda | GRW (16): 1 + lambda/2 | fitted exponent | inner half "
        "| outer half | shells | \\|v\\| / sqrt(T) | T at t_end | collisions | fictitious "
        "| CPU s | wall s |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for ex, d in zip(["6", "7", "8"], sys.argv[1:]):
        if os.path.exists(os.path.join(d, "summary.json")):
            print(row(ex, d))


if __name__ == "__main__":
    main()
