#!/usr/bin/env bash
# The C ABI's references are the command's columns: for each one-species scene below,
# `gdsmc run` (a few ensembles) and the C program references_as_command (the same scene and n,
# the run's observation times, under valgrind too) must name the same reference columns and
# agree to the last bit in each (NaN where the reference is not computable, in both).
set -euo pipefail
cd "$(dirname "$0")/../.."
GDSMC=target/release/gdsmc
PROG=target/c/references_as_command
VG="valgrind --quiet --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect,possible"
# Scene and n: the exact means at n and the Boltzmann limits (GRW (13)-(14), Bobylev et
# al.'s a2(t)), Haff's law and MS's Sonine a2 with a drive, BRS's exact host-medium solution
# at n, the hydrodynamic closures, the Gaussian thermostat's zeta = 1e-300 (Haff's law there,
# once infinite) and a collision rate of 1e-300 (a2_exact not computable: NaN in both).
while read -r scene n; do
    name=$(basename "$scene" .toml)-$n
    out=target/c/refs-$name
    rm -rf "$out"  # the command keeps an output set holding files it did not write
    $GDSMC run "$scene" --n "$n" --ensembles 3 --out "$out" > /dev/null
    python3 - "$out/observables.csv" > "$out/times.txt" <<'PY'
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    print(row["t"])
PY
    $PROG "$scene" "$n" < "$out/times.txt" > "$out/c.csv" 2> "$out/c.err"
    $VG $PROG "$scene" "$n" < "$out/times.txt" > "$out/c-valgrind.csv" 2> /dev/null
    python3 - "$out/observables.csv" "$out/c.csv" "$out/c-valgrind.csv" "$name" <<'PY'
import csv, sys
cmd = list(csv.DictReader(open(sys.argv[1])))
for path in sys.argv[2:4]:
    c = list(csv.DictReader(open(path)))
    cols = [k for k in c[0] if k != "t"]
    assert cols, f"{sys.argv[4]}: no reference holds in C"
    missing = [k for k in cols if k not in cmd[0]]
    assert not missing, f"{sys.argv[4]}: C has {missing}, the command does not"
    assert len(c) == len(cmd) > 1, (path, len(c), len(cmd))
    for a, b in zip(cmd, c):
        for k in ["t"] + cols:
            x, y = float(a[k]), float(b[k])
            if not (x == y or (x != x and y != y)):
                sys.exit(f"{sys.argv[4]}: {path} differs from gdsmc run at t = {a['t']}, {k}: {x!r} vs {y!r}")
print(f"{sys.argv[4]}: {len(cmd)} times x {len(cols)} references equal to the last bit ({', '.join(cols)})")
PY
done <<'SCENES'
scenes/grw-example3.toml 64
scenes/grw-example3.toml 4096
scenes/ms-white-noise.toml 256
scenes/brs-example2.toml 128
scenes/brs-example5.toml 128
tests/c/reference-scenes/haff-tiny-thermostat.toml 256
tests/c/reference-scenes/grw3-tiny-rate.toml 64
SCENES
