#!/usr/bin/env bash
# The array-job scripts of examples/cluster/ run as a scheduler would run them (the task
# variables set by hand: Slurm's for a plain sharded run, SGE's 1-based ones for a sweep), and
# their merged outputs equal direct runs byte for byte.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release -q -p gdsmc
export GDSMC=$PWD/target/release/gdsmc
W=target/ci-cluster
rm -rf "$W" && mkdir -p "$W"
SCENE=scenes/grw-example3.toml
OPTS=(--n 400 --ensembles 31)

# Slurm array of 3 shards.
for k in 0 1 2; do
    SLURM_ARRAY_TASK_ID=$k SLURM_ARRAY_TASK_COUNT=3 SLURM_CPUS_PER_TASK=1 \
        examples/cluster/array-task.sh $SCENE "$W/shards" "${OPTS[@]}" > /dev/null
done
examples/cluster/merge-all.sh "$W/shards" "$W/merged" > /dev/null
$GDSMC run $SCENE "${OPTS[@]}" --out "$W/one" > /dev/null
cmp "$W/one/observables.csv" "$W/merged/observables.csv"
echo "slurm array of 3 shards merged: observables.csv identical to one run"

# SGE array (1-based) over a sweep of 2 points x 2 shards.
printf '# two points\ncollisions.restitution=0.9\n\ncollisions.restitution=0.7 # the second\n' \
    > "$W/sweep.txt"
for t in 1 2 3 4; do
    SGE_TASK_ID=$t GDSMC_SHARDS=2 GDSMC_SWEEP="$W/sweep.txt" NSLOTS=1 \
        examples/cluster/array-task.sh $SCENE "$W/sweep" "${OPTS[@]}" > /dev/null
done
examples/cluster/merge-all.sh "$W/sweep" "$W/sweep-out"
for p in 0:0.9 1:0.7; do
    $GDSMC run $SCENE "${OPTS[@]}" --set "collisions.restitution=${p#*:}" \
        --out "$W/direct-${p%%:*}" > /dev/null
    cmp "$W/direct-${p%%:*}/observables.csv" "$W/sweep-out/point-${p%%:*}/observables.csv"
done
echo "sge array over a 2-point sweep x 2 shards merged: identical to direct runs"

# A point with a shard missing is named, the others still merged, exit 1.
rm "$W"/sweep/point-1/*shard-1-of-2*
if examples/cluster/merge-all.sh "$W/sweep" "$W/sweep-out2" 2> "$W/err.txt"; then
    echo "merge-all succeeded with a shard missing"; exit 1
fi
grep -q "point-1: FAILED: error: 1 of 2 shards missing: 1/2" "$W/err.txt"
test -s "$W/sweep-out2/point-0/observables.csv"
echo "a missing shard is named and the other points are merged"
