#!/usr/bin/env bash
# gdsmc on microcontrollers, under QEMU: builds the firmware for a Cortex-M4F (mps2-an386;
# its FPU is single precision, so f64 runs in software) and for a Cortex-M7 with a
# double-precision FPU (mps2-an500, built with -C target-cpu=cortex-m7: f64 in hardware), runs
# both, runs the same code on the host, and fails unless the three print the same numbers to
# the last digit (the trajectories' checksums included). Then the Cortex-M0 build (the BBC
# micro:bit, `-M microbit`: 64 KiB of flash allowed by its memory layout, 16 KiB of RAM): GRW
# Example 3 alone, the core built with only the Maxwell kernel and white noise and its scalar
# paths (no SIMD lanes there), at opt-level z; compared with the host built the same way.
#
#   bash embedded/run.sh                 build, run, compare
#   bash embedded/run.sh --figures       also print the figures table (markdown)
#   bash embedded/run.sh --update-readme also write that table into docs/guide.md
#   bash embedded/run.sh --check-readme  fail when docs/guide.md's table is not the measured one
set -euo pipefail
cd "$(dirname "$0")"
MODE="${1:-}"
QEMU="qemu-system-arm -nographic -semihosting-config enable=on,target=native -icount shift=0"
TARGET=thumbv7em-none-eabihf
M4=target/$TARGET/release/gdsmc-firmware
M7=target/m7/$TARGET/release/gdsmc-firmware

# The sizes in docs/guide.md's table must not depend on where the repository or the cargo registry
# lie. Source paths end up in the binaries (panic locations): mapped to fixed names. And cargo
# hashes the absolute path of a path dependency outside this workspace (../core) into its
# symbol names, whose order moves code by tens of bytes (the same source gave 370,160 bytes
# of M4F flash in one checkout and 370,176 in another: 361 or 362 KiB): the firmware is built
# through one fixed path, a link to the repository.
ROOT="$(cd .. && pwd)"
FIXED=/tmp/gdsmc-embedded-root
ln -sfn "$ROOT" "$FIXED"
MANIFEST="--manifest-path $FIXED/embedded/Cargo.toml"
REMAP="--remap-path-prefix=$FIXED=/gdsmc --remap-path-prefix=$ROOT=/gdsmc"
REMAP="$REMAP --remap-path-prefix=${CARGO_HOME:-$HOME/.cargo}=/cargo"
RUSTFLAGS="$REMAP" cargo build $MANIFEST --quiet --release -p gdsmc-firmware --target $TARGET
RUSTFLAGS="$REMAP -C target-cpu=cortex-m7" cargo build $MANIFEST --quiet --release \
    -p gdsmc-firmware --target $TARGET --target-dir target/m7
M0=target/m0/thumbv6m-none-eabi/release/gdsmc-firmware
RUSTFLAGS="$REMAP" CARGO_PROFILE_RELEASE_OPT_LEVEL=z cargo build $MANIFEST --quiet --release \
    -p gdsmc-firmware --no-default-features --features gdsmc-core/scalar \
    --target thumbv6m-none-eabi --target-dir target/m0
cargo run --quiet --release -p gdsmc-demo-host > target/host.txt
cargo run --quiet --release -p gdsmc-demo-host --features gdsmc-core/scalar -- m0 > target/host-m0.txt

timeout 900 $QEMU -M mps2-an386 -cpu cortex-m4 -kernel $M4 > target/m4.txt
timeout 900 $QEMU -M mps2-an500 -kernel $M7 > target/m7.txt
for board in m4 m7; do
    if ! diff <(grep -v '^figure' target/$board.txt) target/host.txt > target/$board.diff; then
        echo "the $board firmware's numbers differ from the host's:" >&2
        head -20 target/$board.diff >&2
        exit 1
    fi
done
lines=$(wc -l < target/host.txt)
echo "firmware on mps2-an386 (Cortex-M4F) and mps2-an500 (Cortex-M7): $lines lines equal to the host's, checksums of every velocity included"
timeout 900 $QEMU -M microbit -kernel $M0 > target/m0.txt
if ! diff <(grep -v '^figure' target/m0.txt) target/host-m0.txt > target/m0.diff; then
    echo "the micro:bit firmware's numbers differ from the host's:" >&2
    head -20 target/m0.diff >&2
    exit 1
fi
echo "firmware on microbit (Cortex-M0, GRW Example 3 alone): $(wc -l < target/host-m0.txt) lines equal to the host's"

# The C firmware: the no_std libgdsmc (caller memory, panic = abort) with the engines of GRW
# Example 3 alone (gdsmc-core's `maxwell` and `white-noise`: a firmware names what it runs)
# linked into a C main with newlib's semihosting, on the Cortex-M4F; the same main.c on the host
# against the std build, which holds every engine. The firmware's library is built in the
# workspace's `dist` profile (thin LTO, one codegen unit: the smallest code; `release` is
# cargo's default for the sake of one shared build of the command and the tests).
(cd .. && RUSTFLAGS="$REMAP" cargo rustc --quiet -p gdsmc-ffi --no-default-features \
    --features gdsmc-core/maxwell,gdsmc-core/white-noise \
    --target $TARGET --profile dist --crate-type staticlib && cargo build --quiet --release -p gdsmc-ffi)
CFW=target/c-firmware.elf
arm-none-eabi-gcc -std=c11 -Wall -Wextra -Werror -O2 -mcpu=cortex-m4 -mthumb -mfloat-abi=hard \
    -mfpu=fpv4-sp-d16 -ffunction-sections -fdata-sections -I../include c/main.c c/startup.c \
    -T c/link.ld -nostartfiles --specs=rdimon.specs -Wl,--gc-sections -Wl,--no-warn-rwx-segments \
    ../target/$TARGET/dist/libgdsmc.a -lrdimon -lc -lm -o $CFW 2> target/c-firmware.log \
    || { cat target/c-firmware.log >&2; exit 1; }
cc -std=c11 -Wall -Wextra -Werror c/main.c -I../include ../target/release/libgdsmc.a -lm -lpthread \
    -ldl -o target/c-host
./target/c-host > target/c-host.txt
timeout 900 $QEMU -M mps2-an386 -cpu cortex-m4 -kernel $CFW > target/c-m4.txt
if ! diff target/c-m4.txt target/c-host.txt > target/c-m4.diff; then
    echo "the C firmware's numbers differ from the host's:" >&2
    head -20 target/c-m4.diff >&2
    exit 1
fi
grep -q '^ok$' target/c-m4.txt
echo "C firmware (no_std libgdsmc) on mps2-an386: $(wc -l < target/c-host.txt) lines equal to the host's"

[ -z "$MODE" ] && exit 0

figures() {
    python3 - "$M4" "$M7" target/m4.txt target/m7.txt "$CFW" "$M0" target/m0.txt <<'PY'
import re, subprocess, sys
m4, m7, o4, o7, cfw, m0, o0 = sys.argv[1:8]
def size(elf):
    out = subprocess.run(["arm-none-eabi-size", elf], capture_output=True, text=True, check=True).stdout
    text, data, bss = map(int, out.splitlines()[1].split()[:3])
    return text, data + bss
def figs(path):
    f = {}
    for line in open(path):
        if line.startswith("figure"):
            parts = line.split()
            key = parts[1] if "=" not in parts[1] else ""
            for kv in parts[1:]:
                if "=" in kv:
                    k, v = kv.split("=")
                    f[(key + "." if key else "") + k] = int(v)
    return f
rows = []
for name, elf, out, fp in [("mps2-an386, Cortex-M4F", m4, o4, "software (single-precision FPU)"),
                           ("mps2-an500, Cortex-M7", m7, o7, "hardware (double-precision FPU)")]:
    text, ram = size(elf)
    f = figs(out)
    rows.append(f"| {name} | {fp} | {text/1024:.0f} KiB | {ram/1024:.1f} KiB | {f['stack_peak_bytes']/1024:.1f} KiB "
                f"| {f['particles_per_kib']} | {f['grw3.per_collision']:,} | {f['hcs.per_collision']:,} | {f['rough.per_collision']:,} | {f['rough-mix.per_collision']:,} |")
print("| board (QEMU) | f64 | flash | static RAM | peak stack | particles per KiB | instructions per collision, GRW Ex. 3 | instructions per collision, cooling hard spheres | instructions per collision, cooling rough spheres | instructions per collision, heated rough disk mixture |")
text, ram = size(m0)
f = figs(o0)
rows.append(f"| microbit, Cortex-M0 (GRW Ex. 3 only, n = 64; core features `maxwell`, `white-noise`, `scalar`) | software (no FPU) | {text/1024:.0f} KiB | {ram/1024:.1f} KiB | {f['stack_peak_bytes']/1024:.1f} KiB "
            f"| {f['particles_per_kib']} | {f['grw3.per_collision']:,} | - | - | - |")
text, ram = size(cfw)
rows.append(f"| mps2-an386, Cortex-M4F, C firmware (GRW Ex. 3 only, newlib; core features `maxwell`, `white-noise`) | software (single-precision FPU) | {text/1024:.0f} KiB | {ram/1024:.1f} KiB | - | 32 | - | - | - | - |")
print("|---|---|---|---|---|---|---|---|---|---|")
print("\n".join(rows))
PY
}

TABLE=$(figures)
case "$MODE" in
    --figures) echo "$TABLE" ;;
    --update-readme|--check-readme)
        python3 - "$MODE" "$TABLE" <<'PY'
import sys
mode, table = sys.argv[1], sys.argv[2]
path = "../docs/guide.md"
text = open(path).read()
start, end = "<!-- embedded-figures:start -->\n", "<!-- embedded-figures:end -->"
a, b = text.index(start) + len(start), text.index(end)
if mode == "--update-readme":
    open(path, "w").write(text[:a] + table + "\n" + text[b:])
    print("docs/guide.md: figures table updated")
elif text[a:b].strip() != table.strip():
    print("docs/guide.md's embedded figures differ from the measured ones; run bash embedded/run.sh --update-readme", file=sys.stderr)
    print(table, file=sys.stderr)
    sys.exit(1)
else:
    print("docs/guide.md's embedded figures are the measured ones")
PY
        ;;
    *) echo "unknown option $MODE" >&2; exit 2 ;;
esac
