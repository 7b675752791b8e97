#!/usr/bin/env python3
"""The weighted scheme's own bias in the far tail against `n0` (issue 80).

Usage: python3 tools/weighted_bias.py [--gdsmc BIN] [--rounds R] [--out DIR] [--n0 N,...]

Runs GRW Example 3's heated Maxwell gas on the shipped weight windows
(scenes/grw-example3-weighted.toml) at each `n0` and, beside each, equal weights at the same
`n` (the finite gas's own bias is then the same on both sides: their difference is the
weights'), round by round (round r runs every configuration once, seed 1000 r + k, one
thread). Each run's tail probabilities `P(|v - V| > c sqrt(T))`, `c` = 4, 6, 8, averaged over
the steady observations (t >= 4), come from `tail_work_precision.py`'s reader. Per
configuration the rounds' mean and its standard error (over rounds: each round is an
independent estimate), and per `n0` the weighted-over-equal ratio minus one with its standard
error and `z`. Writes DIR/weighted_bias.csv (one row per run and threshold) and prints the
table docs/weighted.md quotes. Every configuration's ensembles are chosen so that a run costs
about the same CPU (the weighted runs scale with `n0`, the equal-weight ones with `n`).
"""
import argparse
import csv
import math
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tail_work_precision as twp  # noqa: E402

# (n0, weighted ensembles, equal-weight ensembles): about 6 CPU s and 15 CPU s a run.
SIZES = {512: (500, 60000), 1024: (250, 30000), 2048: (125, 15000), 4096: (64, 7500),
         8192: (32, 3750)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--gdsmc", default=os.path.join(twp.ROOT, "target", "release", "gdsmc"))
    ap.add_argument("--rounds", type=int, default=6)
    ap.add_argument("--out", default="weighted-bias")
    ap.add_argument("--n0", default="512,1024,2048,4096,8192")
    a = ap.parse_args()
    n0s = [int(x) for x in a.n0.split(",")]
    configs = []
    for n0 in n0s:
        mw, me = SIZES[n0]
        configs.append((f"windows n0={n0}", n0, mw, twp.WINDOWS))
        configs.append((f"equal n={n0}", n0, me, twp.EQUAL))
    os.makedirs(a.out, exist_ok=True)
    rows = []
    path = os.path.join(a.out, "weighted_bias.csv")
    with tempfile.TemporaryDirectory() as work, open(path, "w", newline="") as fh:
        wr = csv.writer(fh)
        wr.writerow(["config", "round", "seed", "n", "ensembles", "cpu_s", "sqrt_t", "p",
                     "p_ci"])
        for r in range(a.rounds):
            for k, (label, n, m, sets) in enumerate(configs):
                seed = 1000 * r + k
                cpu, tails = twp.run_one(a.gdsmc, label, n, m, sets, seed, work)
                for c, (p, ci, _) in tails.items():
                    row = (label, r, seed, n, m, round(cpu, 2), c, p, ci)
                    rows.append(row)
                    wr.writerow(row)
                fh.flush()
                print(f"round {r} {label}: {cpu:.1f} s CPU, " + ", ".join(
                    f"P(>{c}) {p:.4e}" for c, (p, _, _) in tails.items()), flush=True)
    stat = {}
    for label, *_ in configs:
        for c in twp.THERMAL:
            ps = [x[7] for x in rows if x[0] == label and x[6] == c]
            se = statistics.stdev(ps) / math.sqrt(len(ps)) if len(ps) > 1 else float("nan")
            stat[(label, c)] = (statistics.mean(ps), se)
    print("\n| n0 = n | c | windows | equal weights | windows / equal - 1 | z |")
    print("|---|---|---|---|---|---|")
    for n0 in n0s:
        for c in twp.THERMAL:
            (w, sw), (e, se) = stat[(f"windows n0={n0}", c)], stat[(f"equal n={n0}", c)]
            if e <= 0:
                continue
            d = w / e - 1.0
            sd = (w / e) * math.hypot(sw / w if w else 0.0, se / e)
            z = d / sd if sd > 0 else float("nan")
            print(f"| {n0} | {c} | {w:.4e} +- {sw:.1e} | {e:.4e} +- {se:.1e} | "
                  f"{100 * d:+.2f}% +- {100 * sd:.2f}% | {z:+.1f} |")


if __name__ == "__main__":
    main()
