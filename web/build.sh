#!/usr/bin/env bash
# Builds the browser page into web/dist (README, "In the browser"): the runner as WebAssembly
# (crate gdsmc-web as a cdylib for wasm32-wasip1, its 128-bit SIMD on: every browser since 2021 has it),
# the page's own files from web/www, and scenes.json, the shipped scenes the page offers.
# Serve web/dist with any static file server (`python3 -m http.server -d web/dist`); nothing
# is fetched from elsewhere, so the page works offline once loaded.
set -euo pipefail
cd "$(dirname "$0")/.."
rustup target add wasm32-wasip1 >/dev/null 2>&1 || rustup target list --installed | grep -qx wasm32-wasip1
CARGO_TARGET_WASM32_WASIP1_RUSTFLAGS="-C target-feature=+simd128" \
    CARGO_PROFILE_RELEASE_STRIP=symbols \
    cargo rustc --release --target wasm32-wasip1 -p gdsmc-web --lib --crate-type cdylib
mkdir -p web/dist
cp target/wasm32-wasip1/release/gdsmc_web.wasm web/dist/gdsmc_web.wasm
cp web/www/* web/dist/
python3 - <<'PY'
import json, pathlib
scenes = [
    {"name": p.stem, "path": f"scenes/{p.name}", "text": p.read_text()}
    for p in sorted(pathlib.Path("scenes").glob("*.toml"))
    if not p.stem.startswith("sweep-")
]
pathlib.Path("web/dist/scenes.json").write_text(json.dumps(scenes))
PY
echo "web/dist: $(du -b web/dist/gdsmc_web.wasm | cut -f1) bytes of WebAssembly, $(ls web/dist | wc -l) files"
