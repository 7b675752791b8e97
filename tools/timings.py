#!/usr/bin/env python3
"""Measures every duration the README states, from nothing, on this machine, and writes them.

    python3 tools/timings.py [--skip-reproduce]

On a fresh clone of HEAD (in a temporary directory, with ../shared beside it as CI has it), an
empty target directory and an empty cargo home (every crate downloaded, as a new user's first
build does), it runs the README's two commands literally, then the pieces a reader asks about:
the test build alone, the quick-start run alone, the release build with the PNG/PDF
renderers (`--features render`, its own target directory), `gdsmc reproduce --quick`, the
long suite (`-- --ignored`) and the Python package's install into a fresh virtualenv
(`pip install './python[notebook]'`, its own target directory, as a user's). For each: wall time, CPU time (user + system of the children), the crates compiled
and the load average before and after, with the machine (CPU model, cores, memory), rustc and
the commit. It writes docs/timings.md, and the block between the README's `<!-- timings -->`
markers; tests/tests/timings.rs checks in CI that the block is the one docs/timings.md holds
and that no other duration is written by hand in the README, the docs or `gdsmc --help`.

Run it on an idle machine: it states the load it saw, and a loaded machine's figures are
longer by about the load over the cores.
"""

import datetime
import os
import platform
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN, END = "<!-- timings -->", "<!-- /timings -->"


def load():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def machine():
    model = "unknown CPU"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    with open("/proc/meminfo") as f:
        mem_kb = int(f.readline().split()[1])
    return f"{model}, {os.cpu_count()} cores, {mem_kb / 2**20:.0f} GiB, {platform.system()} {platform.release()}"


def run(cmd, cwd, env=None):
    """Runs `cmd`; returns (wall s, CPU s, crates compiled, load before, load after)."""
    l0 = load()
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    p = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.monotonic() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        sys.stderr.write(p.stdout[-4000:])
        raise SystemExit(f"failed: {' '.join(cmd)} (exit {p.returncode})")
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    compiled = len(re.findall(r"^\s*Compiling ", p.stdout, re.M))
    return wall, cpu, compiled, l0, load()


def minutes(s):
    if s < 10:
        return f"{s:.2f} s"
    s = round(s)
    return f"{s // 60} min {s % 60:02d} s" if s >= 60 else f"{s} s"


def main():
    skip_reproduce = "--skip-reproduce" in sys.argv
    commit = subprocess.check_output(["git", "rev-parse", "--short", "HEAD"], cwd=REPO, text=True).strip()
    rustc = subprocess.check_output(["rustc", "-V"], text=True).strip()
    work = tempfile.mkdtemp(prefix="gdsmc-timings-")
    clone = os.path.join(work, "gdsmc")
    subprocess.run(["git", "clone", "-q", REPO, clone], check=True)
    shared = os.path.join(os.path.dirname(REPO), "shared")
    if os.path.isdir(shared):
        os.symlink(shared, os.path.join(work, "shared"))
    env = dict(os.environ)
    env.pop("CARGO_TARGET_DIR", None)
    # A new user's cargo home: nothing downloaded yet (the toolchain is rustup's, elsewhere).
    env["CARGO_HOME"] = os.path.join(work, "cargo-home")
    # The clone's README block is the previous measurement (or none): its test skips itself.
    env["GDSMC_TIMINGS_RUN"] = "1"
    rows = []

    def settle():
        """Waits (at most 150 s) for the previous step's load to fall below one core's, so a
        step from nothing is measured on a machine as idle as the first one's."""
        t0 = time.monotonic()
        while load() > 1.0 and time.monotonic() - t0 < 150:
            time.sleep(5)

    def step(key, what, cmd, e=env, idle=False):
        if idle:
            settle()
        print(f"timings: {what} ...", flush=True)
        w, c, n, l0, l1 = run(cmd, clone, e)
        rows.append((key, what, " ".join(cmd), w, c, n, l0, l1))
        print(f"timings: {what}: {minutes(w)} wall, {minutes(c)} CPU, {n} crates compiled", flush=True)
        return w, n

    try:
        first, first_n = step(
            "first-command",
            "the README's first command, from nothing",
            ["cargo", "run", "--release", "-p", "gdsmc", "--", "run", "scenes/grw-example3.toml"],
        )
        run_alone, _ = step(
            "quick-start-run",
            "its run alone (GRW Example 3, built)",
            ["target/release/gdsmc", "run", "scenes/grw-example3.toml", "--out", "target/timings-out"],
        )
        test_build, test_n = step(
            "test-build",
            "the test build after it (`--no-run`)",
            ["cargo", "test", "--workspace", "--release", "--no-run"],
        )
        tests, _ = step(
            "tests",
            "the README's second command after the test build",
            ["cargo", "test", "--workspace", "--release"],
        )
        render_env = dict(env, CARGO_TARGET_DIR=os.path.join(work, "target-render"))
        render, render_n = step(
            "build-with-renderers",
            "the release build with the PNG/PDF renderers, from nothing",
            ["cargo", "build", "--release", "-p", "gdsmc", "--features", "render"],
            render_env,
            idle=True,
        )
        if not skip_reproduce:
            step(
                "reproduce-quick",
                "`gdsmc reproduce --quick`",
                ["target/release/gdsmc", "reproduce", "--quick", "--out", "target/timings-reproduce"],
            )
        long_suite, _ = step(
            "long-suite",
            "the long suite after the tests (`-- --ignored`)",
            ["cargo", "test", "--workspace", "--release", "--", "--ignored"],
        )
        venv = os.path.join(work, "venv")
        subprocess.run([sys.executable, "-m", "venv", venv], check=True)
        python, _ = step(
            "python-install",
            "the Python package into a fresh virtualenv",
            [os.path.join(venv, "bin", "pip"), "install", "--disable-pip-version-check", "./python[notebook]"],
            idle=True,
        )
    finally:
        shutil.rmtree(work, ignore_errors=True)

    today = datetime.date.today().isoformat()
    cores = os.cpu_count()
    block = (
        f"Measured by `tools/timings.py` on {today} (commit {commit}; {cores} cores, load "
        f"{rows[0][6]:.2f} at the start; docs/timings.md): the first command took "
        f"{minutes(first)} from nothing ({first_n} crates compiled; the run itself "
        f"{minutes(run_alone)}), the second {minutes(test_build + tests)} after it (it compiled "
        f"{test_n} crates, the test harnesses and the test-only dependencies, in "
        f"{minutes(test_build)}, and reused the rest; the tests ran {minutes(tests)}). With "
        f"the PNG/PDF renderers (`--features render`) the release build compiles "
        f"{render_n} crates instead of {first_n} and took {minutes(render)} from nothing. The long suite "
        f"(`cargo test --workspace --release -- --include-ignored` runs both) took "
        f"{minutes(long_suite)} after them; `pip install './python[notebook]'` into a fresh "
        f"virtualenv took {minutes(python)} (it builds the extension in its own target)."
    )
    md = [
        "# Timings",
        "",
        "Generated by `python3 tools/timings.py` on a fresh clone with an empty target directory;",
        "do not edit by hand. Every duration the README states comes from here (checked by",
        "`tests/tests/timings.rs`). Wall and CPU time (user + system of every process), and the",
        "one-minute load average before and after each step. The load before the first step is",
        "the other work on the machine (figures taken under a load L on C cores are longer by",
        "about L/C); after it, the load is mostly the previous step's own (a build on 2 cores",
        "holds it near 2), so the first figure is the one that says whether the machine was idle.",
        "",
        f"- Date: {today}; commit {commit}; {rustc}",
        f"- Machine: {machine()}",
        "",
        "| step | command | wall | CPU | crates compiled | load before | load after |",
        "|---|---|---|---|---|---|---|",
    ]
    for key, what, cmd, w, c, n, l0, l1 in rows:
        cmd = cmd.replace(work + os.sep, "")
        md.append(f"| {what} (`{key}`) | `{cmd}` | {minutes(w)} | {minutes(c)} | {n} | {l0:.2f} | {l1:.2f} |")
    md += ["", "The README's block:", "", BEGIN, block, END, ""]
    with open(os.path.join(REPO, "docs", "timings.md"), "w") as f:
        f.write("\n".join(md))
    readme = os.path.join(REPO, "README.md")
    text = open(readme).read()
    i, j = text.index(BEGIN), text.index(END)
    with open(readme, "w") as f:
        f.write(text[:i] + BEGIN + "\n" + block + "\n" + text[j:])
    print("timings: wrote docs/timings.md and the README's block")


if __name__ == "__main__":
    main()
