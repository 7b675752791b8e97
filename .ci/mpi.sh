#!/usr/bin/env bash
# MPI (issue 14): `mpirun -n 2 gdsmc run` gives the single process's outputs byte for byte, and
# a job killed in the middle continues to the same bytes when run again. Builds the `mpi`
# feature in its own target directory (OpenMPI and libclang from Debian).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! dpkg -s libopenmpi-dev openmpi-bin libclang-dev >/dev/null 2>&1; then
    apt-get update
    apt-get install -y libopenmpi-dev openmpi-bin libclang-dev
fi
# Built in the workspace's target directory (every dependency is the release build's: only the
# MPI crates and gdsmc itself compile); the MPI binary is copied aside and the plain one put
# back (a fresh build only links it again), so later users of target/release/gdsmc get it.
cargo build --release -p gdsmc --features mpi
mkdir -p target/mpi
cp target/release/gdsmc target/mpi/gdsmc
cargo build --release -p gdsmc
G=target/mpi/gdsmc
W=target/ci-mpi
rm -rf "$W" && mkdir -p "$W"
# OpenMPI refuses root unless told, and CI may have fewer cores than ranks.
MPIRUN=(mpirun --allow-run-as-root --oversubscribe -n 2)
export OMPI_MCA_rmaps_base_oversubscribe=1

same() { # same DIR_A DIR_B: every CSV byte-identical, summary.json equal but for timing
    for f in "$1"/*.csv; do cmp "$f" "$2/$(basename "$f")"; done
    python3 - "$1/summary.json" "$2/summary.json" <<'PY'
import json, sys
def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items()
                if k not in ("wall_seconds", "cpu_seconds", "threads", "collisions_per_second")}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v
a, b = (strip(json.load(open(p))) for p in sys.argv[1:])
assert a == b, "summary statistics differ"
PY
    echo "same: $1 $2"
}

# GRW Example 3 as shipped, and MS's constant-force thermostat (steady averages, histogram).
$G run scenes/grw-example3.toml --out "$W/grw-one" > /dev/null
"${MPIRUN[@]}" $G run scenes/grw-example3.toml --threads 1 --out "$W/grw-mpi" | tail -1
same "$W/grw-one" "$W/grw-mpi"
MS=(scenes/ms-constant-force.toml --n 512 --ensembles 30 --set observe.collisional_pairs=1000)
$G run "${MS[@]}" --out "$W/ms-one" > /dev/null
"${MPIRUN[@]}" $G run "${MS[@]}" --threads 1 --out "$W/ms-mpi" | tail -1
same "$W/ms-one" "$W/ms-mpi"
# The weighted scheme (issue 56): weights, reductions and the weighted tail, one per rank.
WT=(scenes/grw-example3-weighted.toml --ensembles 16)
$G run "${WT[@]}" --out "$W/wt-one" > /dev/null
"${MPIRUN[@]}" $G run "${WT[@]}" --threads 1 --out "$W/wt-mpi" | tail -1
same "$W/wt-one" "$W/wt-mpi"

# Killed in the middle (SIGTERM to mpirun, which ends the ranks), then run again.
BIG=(scenes/grw-example3.toml --n 40000 --ensembles 80)
$G run "${BIG[@]}" --out "$W/big-one" > /dev/null
timeout -s TERM 1 "${MPIRUN[@]}" $G run "${BIG[@]}" --threads 1 --out "$W/big-mpi" \
    > /dev/null 2>&1 || true
# The ranks can outlive mpirun for a moment; the rerun would find their journals locked.
for _ in $(seq 150); do pgrep -f "$G run .*big-mpi" > /dev/null || break; sleep 0.2; done
ls -la "$W"/.big-mpi.* 2>/dev/null || echo "(no journal left: the job was killed before its first ensemble or after its end)"
"${MPIRUN[@]}" $G run "${BIG[@]}" --threads 1 --out "$W/big-mpi" > "$W/rerun.log" 2>&1 \
    || { cat "$W/rerun.log"; exit 1; }
grep -E "continued|not continued|MPI ranks" "$W/rerun.log" || true
same "$W/big-one" "$W/big-mpi"
if ls "$W"/.big-mpi.* >/dev/null 2>&1; then echo "journals left after a finished run"; exit 1; fi
# A user's directory at --out: refused by rank 0 before any work, every rank told (no hang),
# the directory left as it was; more ranks than ensembles refused by every rank alike.
mkdir -p "$W/users" && echo draft > "$W/users/thesis.tex"
if timeout 120 "${MPIRUN[@]}" $G run scenes/grw-example3.toml --n 64 --ensembles 4 \
    --out "$W/users" > "$W/users.log" 2>&1; then
    echo "mpirun wrote into a user's directory"; exit 1
fi
grep -q "gdsmc did not write" "$W/users.log" || { cat "$W/users.log"; exit 1; }
[ "$(ls "$W/users")" = "thesis.tex" ] && [ "$(cat "$W/users/thesis.tex")" = "draft" ]
if timeout 120 mpirun --allow-run-as-root --oversubscribe -n 3 $G run scenes/grw-example3.toml \
    --n 64 --ensembles 2 --out "$W/few" > "$W/few.log" 2>&1; then
    echo "3 ranks ran 2 ensembles"; exit 1
fi
grep -q "3 ranks for 2 ensembles" "$W/few.log" || { cat "$W/few.log"; exit 1; }
echo "refused: a user's directory, more ranks than ensembles"

# A sweep under mpirun (issue 37): 2 ranks over 3 points, 5 ranks (each point's ensembles
# split in 2), and 2 ranks each in its own directory (no shared file system: rank 0 gets
# rank 1's journal as bytes) all write the single process's sweep, taking every ensemble
# from the ranks' journals, and leave no journal.
SW=(sweep "$PWD/scenes/grw-example3.toml" --vary collisions.restitution=0.5,0.7,0.9 --n 64 --ensembles 4)
$G "${SW[@]}" --out "$W/sweep-one" > /dev/null
"${MPIRUN[@]}" $G "${SW[@]}" --threads 1 --out "$W/sweep-two" > "$W/sweep-two.log"
mpirun --allow-run-as-root --oversubscribe -n 5 $G "${SW[@]}" --threads 1 --out "$W/sweep-five" \
    > "$W/sweep-five.log"
mkdir -p "$W/own/r0" "$W/own/r1"
cat > "$W/own-dir.sh" <<'SH'
#!/usr/bin/env bash
cd "$1/r$OMPI_COMM_WORLD_RANK" && shift && exec "$@"
SH
chmod +x "$W/own-dir.sh"
"${MPIRUN[@]}" "$W/own-dir.sh" "$PWD/$W/own" "$PWD/$G" "${SW[@]}" --threads 1 --out sweep \
    > "$W/sweep-own.log"
for d in sweep-two sweep-five own/r0/sweep; do
    for f in sweep.csv sweep.json sweep.md; do cmp "$W/sweep-one/$f" "$W/$d/$f"; done
done
for l in two five own; do
    grep -q "continued  12 ensembles taken" "$W/sweep-$l.log" || { cat "$W/sweep-$l.log"; exit 1; }
done
if ls -a "$W" "$W/own/r0" "$W/own/r1" | grep -q "gdsmc-ensembles"; then
    echo "journals left after a finished sweep"; exit 1
fi
echo "sweeps under mpirun: the single process's files"
# (Its lints: CI's lint stage, `cargo clippy -p gdsmc --features mpi --all-targets`.)
