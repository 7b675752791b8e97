#!/usr/bin/env bash
# The Python package from a clean virtualenv: `pip install ./python` (maturin builds the PyO3
# extension), then pytest: the command's numbers for the same scene and seed, scene errors,
# Ctrl-C, and the example notebook executed headless (nbclient).
set -euo pipefail
cd "$(dirname "$0")/../.."
(cd python && cargo fmt --all -- --check \
    && CARGO_TARGET_DIR=../target cargo clippy --release --all-targets -- -D warnings)
cargo build --release -q -p gdsmc
V=target/py-venv
python3 -m venv --clear "$V"
"$V/bin/pip" install --quiet --disable-pip-version-check --upgrade pip
# The extension's Rust build shares the workspace's target directory (its artifacts).
CARGO_TARGET_DIR=$PWD/target "$V/bin/pip" install --disable-pip-version-check ./python
"$V/bin/pip" install --quiet --disable-pip-version-check \
    pytest nbclient nbformat ipykernel matplotlib pandas tqdm xarray
"$V/bin/python" -c "import gdsmc; print('gdsmc', gdsmc.__version__, 'imported from', gdsmc.__file__)"
GDSMC_BIN=$PWD/target/release/gdsmc "$V/bin/pytest" -q python/tests
