#!/usr/bin/env bash
# Installs gdsmc into a scratch prefix with ffi/install.sh, then builds and runs GRW Example 3
# from a CMake project (find_package(gdsmc), shared and static targets) and from a pkg-config
# compile line, the shared library found through the rpath (no LD_LIBRARY_PATH).
set -euo pipefail
cd "$(dirname "$0")/../.."

PREFIX="$PWD/target/cmake-prefix"
rm -rf "$PREFIX" target/cmake-build
bash ffi/install.sh "$PREFIX"

cmake -S tests/cmake -B target/cmake-build -DCMAKE_PREFIX_PATH="$PREFIX" -DCMAKE_BUILD_TYPE=Release
cmake --build target/cmake-build -j 2
(cd target/cmake-build && ctest --output-on-failure)

export PKG_CONFIG_PATH="$PREFIX/lib/pkgconfig"
# shellcheck disable=SC2046
cc -std=c11 -Wall -Wextra -Werror examples/c/grw_example3.c $(pkg-config --cflags gdsmc) \
    $(pkg-config --libs gdsmc) -lm -o target/cmake-build/grw_example3_pkgconfig
env -u LD_LIBRARY_PATH target/cmake-build/grw_example3_pkgconfig > /dev/null
echo "pkg-config: $(pkg-config --modversion gdsmc), rpath $(pkg-config --variable=libdir gdsmc)"
