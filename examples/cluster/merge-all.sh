#!/usr/bin/env bash
# Merges the shards an array job wrote: SHARD_ROOT/point-P for each point of a sweep into
# OUT_ROOT/point-P, or SHARD_ROOT itself (no sweep) into OUT_ROOT. A point whose shards are
# not all there (or damaged) is named and the others are still merged; exits 1 if any failed.
#
#   merge-all.sh SHARD_ROOT OUT_ROOT [gdsmc merge options ...]
set -uo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 SHARD_ROOT OUT_ROOT [gdsmc merge options ...]" >&2
    exit 2
fi
root=$1
outs=$2
shift 2
gdsmc=${GDSMC:-gdsmc}
mkdir -p "$outs"
failed=0
if compgen -G "$root/point-*" > /dev/null; then
    for d in "$root"/point-*; do
        p=$(basename "$d")
        if "$gdsmc" merge "$d" --out "$outs/$p" "$@" > "$outs.$p.log" 2>&1; then
            echo "$p: $(grep -m1 '^merged' "$outs.$p.log")"
        else
            echo "$p: FAILED: $(tail -1 "$outs.$p.log")" >&2
            failed=1
        fi
    done
else
    "$gdsmc" merge "$root" --out "$outs" "$@" || failed=1
fi
exit $failed
