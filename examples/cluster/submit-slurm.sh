#!/usr/bin/env bash
# Submits a sharded gdsmc run (or sweep) to Slurm: the array of shard tasks, then the merge,
# which starts when every task has succeeded (afterok).
#
#   submit-slurm.sh SCENE SHARDS [SWEEP_FILE] [-- gdsmc run options ...]
#
# Examples (from the repository's root, gdsmc on PATH):
#   examples/cluster/submit-slurm.sh scenes/grw-example6.toml 16
#   examples/cluster/submit-slurm.sh scenes/ms-gaussian.toml 4 examples/cluster/alphas.txt
#   examples/cluster/submit-slurm.sh scenes/grw-example7.toml 20 -- --ensembles 200
set -euo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 SCENE SHARDS [SWEEP_FILE] [-- gdsmc run options ...]" >&2
    exit 2
fi
scene=$1
shards=$2
shift 2
sweep=""
if [ $# -gt 0 ] && [ "$1" != "--" ]; then sweep=$1; shift; fi
[ "${1:-}" = "--" ] && shift
name=$(basename "$scene" .toml)
points=1
if [ -n "$sweep" ]; then
    points=$(sed -e 's/#.*//' "$sweep" | grep -c '[^[:space:]]' || true)
fi
tasks=$((points * shards))
export SCENE=$scene SHARD_ROOT=shards/$name OUT_ROOT=out/$name GDSMC_SHARDS=$shards
export GDSMC_SWEEP=$sweep GDSMC_OPTIONS="$*"
job=$(sbatch --parsable --export=ALL --array=0-$((tasks - 1)) \
    examples/cluster/slurm-shards.sbatch)
sbatch --export=ALL --dependency=afterok:"$job" examples/cluster/slurm-merge.sbatch
echo "array job $job: $points point(s) x $shards shards; the merge writes $OUT_ROOT"
