#!/usr/bin/env bash
# Builds libgdsmc and installs it for C and C++ builds:
#   PREFIX/include/gdsmc.h, gdsmc.hpp
#   PREFIX/lib/libgdsmc.a, libgdsmc.so
#   PREFIX/lib/pkgconfig/gdsmc.pc             (pkg-config --cflags --libs gdsmc)
#   PREFIX/lib/cmake/gdsmc/gdsmcConfig.cmake  (find_package(gdsmc): gdsmc::gdsmc, gdsmc::static)
# Usage: bash ffi/install.sh [PREFIX]   (default: $HOME/.local)
set -euo pipefail
cd "$(dirname "$0")/.."

PREFIX="${1:-$HOME/.local}"
case "$PREFIX" in /*) ;; *) PREFIX="$PWD/$PREFIX" ;; esac
VERSION="$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -1)"
[ -n "$VERSION" ] || { echo "install.sh: no version in Cargo.toml" >&2; exit 1; }

cargo build --release -p gdsmc-ffi
install -d "$PREFIX/include" "$PREFIX/lib/pkgconfig" "$PREFIX/lib/cmake/gdsmc"
install -m 644 include/gdsmc.h include/gdsmc.hpp "$PREFIX/include/"
install -m 644 target/release/libgdsmc.a "$PREFIX/lib/"
install -m 755 target/release/libgdsmc.so "$PREFIX/lib/"
for f in gdsmc.pc:pkgconfig gdsmcConfig.cmake:cmake/gdsmc gdsmcConfigVersion.cmake:cmake/gdsmc; do
    name="${f%%:*}"
    sed -e "s|@PREFIX@|$PREFIX|g" -e "s|@VERSION@|$VERSION|g" "ffi/package/$name.in" \
        > "$PREFIX/lib/${f#*:}/$name"
done
echo "installed gdsmc $VERSION into $PREFIX"
