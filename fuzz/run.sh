#!/usr/bin/env bash
# Every fuzz target for SECONDS (default 20) on its corpus under AddressSanitizer, with a fixed
# seed (default 1), so that a run is the same mutations every time (a slower machine runs a
# prefix): `bash fuzz/run.sh [SECONDS] [SEED]`. Installs the nightly toolchain and cargo-fuzz
# when missing. Not a CI stage (CI replays the corpora and regressions as plain tests on
# stable and checks that the targets build): run it before a change to a map, a sampler, the
# scene reader, the state reader or the C ABI lands, and longer with other seeds to explore (fuzz/README.md).
set -euo pipefail
cd "$(dirname "$0")"
SECONDS_EACH=${1:-20}
SEED=${2:-1}
rustup toolchain install nightly --profile minimal
command -v cargo-fuzz >/dev/null || cargo install cargo-fuzz --version 0.13.2 --locked
for t in collision_maps rough_maps samplers scene_reader scene_structured state_reader c_abi; do
    mkdir -p "target/run-corpus/$t" && cp -r "corpus/$t/." "target/run-corpus/$t/"
    cargo +nightly fuzz run "$t" "target/run-corpus/$t" -- -max_total_time="$SECONDS_EACH" \
        -timeout=10 -seed="$SEED" > "target/run-$t.log" 2>&1 || { tail -40 "target/run-$t.log"; exit 1; }
    grep -E "^Done" "target/run-$t.log"
done
