#!/usr/bin/env python3
"""Tests tools/tail_work_precision.py's arithmetic without running gdsmc: the bins a tail
probability sums (a first version summed from the bin one shell too early, so P(|c| > 4) came
out as P(|c| > 2)), the bound on the summed half-widths, and the 99.9% Student-t quantile
against published values, and that no configuration sets a key twice. Run by CI beside the module-cycle tool's test."""
import math, os, sys

sys.dont_write_bytecode = True  # no __pycache__ in the tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tail_work_precision as t

r = 8.0 / math.sqrt(2.0)
rows = [{"c_lo": repr(r * k / 4), "f": repr(10.0 ** -k), "f_ci": repr(0.1 * 10.0 ** -k)}
        for k in range(5)]  # bins [0,2), [2,4), [4,6), [6,8) sqrt(T) and beyond 8
tails = t.tails_of(rows)
assert abs(tails[8][0] - 1e-4) < 1e-18 and tails[8][2], tails[8]
assert abs(tails[6][0] - (1e-3 + 1e-4)) < 1e-15 and not tails[6][2], tails[6]
assert abs(tails[4][0] - (1e-2 + 1e-3 + 1e-4)) < 1e-15, tails[4]
assert abs(tails[4][1] - 0.1 * (1e-2 + 1e-3 + 1e-4)) < 1e-15, tails[4]
for dof, want in [(10, 4.587), (20, 3.850), (100, 3.390)]:
    assert abs(t.student_q(dof) - want) < 2e-3, (dof, t.student_q(dof))
# Every configuration sets each key once (gdsmc refuses a key set twice: a configuration that
# added to a list holding the same key stopped a measurement), and `over` replaces a key.
for label, _, _, sets in t.CONFIGS:
    keys = [x.split("=")[0] for x in sets]
    assert len(keys) == len(set(keys)), (label, sets)
assert t.over(["a=1", "b=2"], "a=3") == ["b=2", "a=3"]
print("tail_work_precision: ok")
