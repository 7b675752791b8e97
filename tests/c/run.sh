#!/usr/bin/env bash
# The C ABI checks: header up to date, C and C++ callers built with the system compilers
# exactly as the README shows, run, and run again under valgrind (no errors, no leaks).
set -euo pipefail
cd "$(dirname "$0")/../.."

if command -v cbindgen >/dev/null; then
    cbindgen --quiet --config ffi/cbindgen.toml --output target/gdsmc.h.generated ffi
    if ! diff -u include/gdsmc.h target/gdsmc.h.generated; then
        echo "include/gdsmc.h is out of date: regenerate it with" >&2
        echo "  cbindgen --quiet --config ffi/cbindgen.toml --output include/gdsmc.h ffi" >&2
        exit 1
    fi
    echo "include/gdsmc.h matches cbindgen's output"
else
    echo "cbindgen not installed: header comparison skipped (CI installs it)" >&2
    [ -n "${CI:-}" ] && exit 1
fi

cargo build --release -p gdsmc-ffi
# A fresh work directory each run: the command refuses to replace an output set that holds
# files it did not write (the C results written beside it by a previous run).
rm -rf target/c
mkdir -p target/c
LINK="target/release/libgdsmc.a -lm -lpthread -ldl"
cc -std=c11 -Wall -Wextra -Werror examples/c/grw_example3.c -Iinclude $LINK -o target/c/grw_example3
cc -std=c11 -Wall -Wextra -Werror tests/c/bad_args.c -Iinclude $LINK -o target/c/bad_args
cc -std=c11 -Wall -Wextra -Werror tests/c/same_as_command.c -Iinclude $LINK -o target/c/same_as_command
cc -std=c11 -Wall -Wextra -Werror tests/c/references_as_command.c -Iinclude $LINK -o target/c/references_as_command
c++ -std=c++17 -Wall -Wextra -Werror examples/cpp/grw_example3.cpp -Iinclude $LINK -o target/c/grw_example3_cpp
# The shared library links too.
cc -std=c11 examples/c/grw_example3.c -Iinclude -Ltarget/release -lgdsmc -lm -o target/c/grw_example3_shared

./target/c/grw_example3
./target/c/grw_example3_cpp
LD_LIBRARY_PATH=target/release ./target/c/grw_example3_shared > /dev/null
./target/c/bad_args

VG="valgrind --quiet --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect,possible"
$VG ./target/c/bad_args
$VG ./target/c/grw_example3 > /dev/null
echo "valgrind: no errors, no leaks"

# The same numbers as the command (MS time-stepped scheme, BRS impact-speed law), and the
# same references.
cargo build --release -p gdsmc
bash tests/c/same_as_command.sh
bash tests/c/references_as_command.sh
