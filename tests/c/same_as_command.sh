#!/usr/bin/env bash
# The C ABI gives the command's numbers: for each scene in tests/c/scenes, `gdsmc run` (one
# ensemble) and the C program same_as_command (stream 0 of the same seed, under valgrind too)
# must agree to the last bit in every observable both print.
set -euo pipefail
cd "$(dirname "$0")/../.."
GDSMC=target/release/gdsmc
PROG=target/c/same_as_command
VG="valgrind --quiet --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect,possible"
for scene in tests/c/scenes/*.toml; do
    name=$(basename "$scene" .toml)
    out=target/c/cmd-$name
    $GDSMC run "$scene" --out "$out" > /dev/null
    python3 - "$out/observables.csv" > "$out/times.txt" <<'PY'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    print(row["t"])
PY
    $PROG "$scene" < "$out/times.txt" > "$out/c.csv"
    $VG $PROG "$scene" < "$out/times.txt" > "$out/c-valgrind.csv"
    python3 - "$out/observables.csv" "$out/c.csv" "$out/c-valgrind.csv" "$name" <<'PY'
import csv, sys
cmd = list(csv.DictReader(open(sys.argv[1])))
for path in sys.argv[2:4]:
    c = list(csv.DictReader(open(path)))
    assert len(c) == len(cmd) > 1, (path, len(c), len(cmd))
    cols = [k for k in c[0] if k != "t"]
    for a, b in zip(cmd, c):
        for k in ["t"] + cols:
            x, y = float(a[k]), float(b[k])
            if not (x == y or (x != x and y != y)):
                sys.exit(f"{sys.argv[4]}: {path} differs from gdsmc run at t = {a['t']}, {k}: {x!r} vs {y!r}")
print(f"{sys.argv[4]}: {len(cmd)} times x {len(cols)} observables equal to the last bit (C, C under valgrind, gdsmc run)")
PY
done
