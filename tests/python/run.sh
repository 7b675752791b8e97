#!/usr/bin/env bash
# The Python package as a user installs it, both routes the README names:
# 1. a wheel (abi3: one file for every CPython >= 3.9 on this platform), built once with
#    `pip wheel ./python` (maturin builds the PyO3 extension), then installed into a clean
#    virtualenv on a PATH without cargo or rustc, so that nothing compiles and no toolchain is
#    fetched; pytest runs there: the command's numbers for the same scene and seed, scene
#    errors, Ctrl-C, and the example notebooks executed headless (nbclient);
# 2. `pip install ./python` from the source tree (needs Rust): checked to install and import.
set -euo pipefail
cd "$(dirname "$0")/../.."
(cd python && cargo fmt --all -- --check \
    && CARGO_TARGET_DIR=../target cargo clippy --release --all-targets -- -D warnings)
cargo build --release -q -p gdsmc

# The wheel, built with the workspace's target directory (its artifacts shared).
W=target/wheels
rm -rf "$W"
B=target/py-build-venv
python3 -m venv --clear "$B"
"$B/bin/pip" install --quiet --disable-pip-version-check --upgrade pip
CARGO_TARGET_DIR=$PWD/target "$B/bin/pip" wheel --disable-pip-version-check --no-deps -w "$W" ./python
ls "$W"/gdsmc-*-abi3-*.whl

# Installed and tested with no Rust on the PATH.
NORUST=/usr/local/bin:/usr/bin:/bin
V=target/py-venv
python3 -m venv --clear "$V"
if env PATH="$NORUST" sh -c 'command -v cargo || command -v rustc'; then
    echo "cargo or rustc is on the PATH the wheel is tested with" >&2
    exit 1
fi
env PATH="$NORUST" "$V/bin/pip" install --quiet --disable-pip-version-check --upgrade pip
env PATH="$NORUST" "$V/bin/pip" install --disable-pip-version-check "$W"/gdsmc-*.whl
env PATH="$NORUST" "$V/bin/pip" install --quiet --disable-pip-version-check \
    pytest nbclient nbformat ipykernel matplotlib pandas tqdm xarray
env PATH="$NORUST" "$V/bin/python" -c "import gdsmc; print('gdsmc', gdsmc.__version__, 'from the wheel, imported from', gdsmc.__file__)"
env PATH="$NORUST" GDSMC_BIN=$PWD/target/release/gdsmc "$V/bin/pytest" -q python/tests

# The source route: pip builds the extension itself (reusing the target directory's
# artifacts), then the package imports and runs a scene.
S=target/py-source-venv
python3 -m venv --clear "$S"
"$S/bin/pip" install --quiet --disable-pip-version-check --upgrade pip
CARGO_TARGET_DIR=$PWD/target "$S/bin/pip" install --quiet --disable-pip-version-check ./python
"$S/bin/python" -c "import gdsmc; r = gdsmc.run('scenes/grw-example3.toml', n=64, ensembles=4); print('gdsmc from source:', r.mean['T_bulk'][-1])"
