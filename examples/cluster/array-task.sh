#!/usr/bin/env bash
# One task of an array job: shard K of S of a gdsmc run, or of one point of a parameter sweep.
#
#   array-task.sh SCENE SHARD_ROOT [gdsmc run options ...]
#
# The task number comes from the scheduler: Slurm (SLURM_ARRAY_TASK_ID), PBS Pro
# (PBS_ARRAY_INDEX), Torque (PBS_ARRAYID), SGE/UGE (SGE_TASK_ID, from 1), LSF (LSB_JOBINDEX,
# from 1), or GDSMC_TASK set by hand (from 0). The shard count is GDSMC_SHARDS (default: the
# Slurm array's task count, SLURM_ARRAY_TASK_COUNT, when there is no sweep; else 1).
#
# A sweep: GDSMC_SWEEP names a file with one point per line, each line the `--set` assignments
# of that point (e.g. `collisions.restitution=0.5`; several separated by spaces; `#` comments).
# Task t runs shard (t mod S) of point (t div S), so an array of (points x S) tasks covers the
# sweep; shards go to SHARD_ROOT/point-P (P the line's number among the points, from 0),
# without a sweep to SHARD_ROOT. Worker threads: SLURM_CPUS_PER_TASK, NCPUS (PBS), NSLOTS
# (SGE), LSB_DJOB_NUMPROC (LSF), else all cores. A task killed (preempted, node lost) continues
# from its shard file when it runs again. Then merge-all.sh merges every point.
set -euo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 SCENE SHARD_ROOT [gdsmc run options ...]" >&2
    exit 2
fi
scene=$1
root=$2
shift 2
gdsmc=${GDSMC:-gdsmc}

if [ -n "${GDSMC_TASK:-}" ]; then task=$GDSMC_TASK
elif [ -n "${SLURM_ARRAY_TASK_ID:-}" ]; then task=$SLURM_ARRAY_TASK_ID
elif [ -n "${PBS_ARRAY_INDEX:-}" ]; then task=$PBS_ARRAY_INDEX
elif [ -n "${PBS_ARRAYID:-}" ]; then task=$PBS_ARRAYID
elif [ -n "${SGE_TASK_ID:-}" ]; then task=$((SGE_TASK_ID - 1))
elif [ -n "${LSB_JOBINDEX:-}" ]; then task=$((LSB_JOBINDEX - 1))
else
    echo "$0: no task number (not in an array job, and GDSMC_TASK is not set)" >&2
    exit 2
fi

points=()
if [ -n "${GDSMC_SWEEP:-}" ]; then
    while IFS= read -r line || [ -n "$line" ]; do
        line=${line%%#*}
        line=$(echo "$line" | xargs)
        [ -n "$line" ] && points+=("$line")
    done < "$GDSMC_SWEEP"
    if [ ${#points[@]} -eq 0 ]; then
        echo "$0: $GDSMC_SWEEP has no points" >&2
        exit 2
    fi
    shards=${GDSMC_SHARDS:-1}
else
    shards=${GDSMC_SHARDS:-${SLURM_ARRAY_TASK_COUNT:-1}}
fi
threads=${SLURM_CPUS_PER_TASK:-${NCPUS:-${NSLOTS:-${LSB_DJOB_NUMPROC:-0}}}}

shard=$((task % shards))
point=$((task / shards))
sets=()
out=$root
if [ ${#points[@]} -gt 0 ]; then
    if [ "$point" -ge ${#points[@]} ]; then
        echo "$0: task $task is beyond ${#points[@]} points x $shards shards" >&2
        exit 2
    fi
    for a in ${points[$point]}; do sets+=(--set "$a"); done
    out=$root/point-$point
fi
exec "$gdsmc" run "$scene" "$@" "${sets[@]}" --shard "$shard/$shards" --threads "$threads" --out "$out"
