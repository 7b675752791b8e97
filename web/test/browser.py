#!/usr/bin/env python3
"""The page in a real browser: headless Chromium loads web/dist (built by web/build.sh) from a
local server, runs the cases below through the page's own form (index.html#test), and posts
what the page showed. Each case is run by the `gdsmc` command too (target/release/gdsmc):
observables.csv, every histogram table and summary.json (its timing aside) must be the
command's byte for byte, the summary's verdict lines the same, and bad input must get the
command's error words. Prints the page's speed beside the command's (one thread each).

Usage: python3 web/test/browser.py [--chromium PATH] [--keep DIR]
"""
import argparse
import http.server
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import threading

ROOT = pathlib.Path(__file__).resolve().parents[2]
DIST = ROOT / "web" / "dist"
GDSMC = ROOT / "target" / "release" / "gdsmc"

# GRW Example 3 at a small n (the heated Maxwell gas, exact T(t) and a2(t)), cooling hard
# spheres (a second loop and the distribution's references), a rough disk mixture (rough
# particles, species, d = 2; its inertia and a species' mass set in the form's fields), a run stopped by the page's Stop (its statistics must be those
# of a run of the ensembles it finished), and bad input: a key's rule, a scene's schema, a
# kernel's declared parameter. Each run's address is opened again and must set the page up
# for the same keys.
CASES = [
    {"name": "grw-example3", "scene": "grw-example3",
     "fields": {"n": "256", "ensembles": "24"}},
    {"name": "hcs-hard-spheres", "scene": "hcs-hard-spheres",
     "fields": {"n": "200", "ensembles": "10", "seed": "7"}},
    {"name": "rough-disk-mixture", "scene": "rough-disk-mixture-white-noise",
     "fields": {"n": "96", "ensembles": "6", "kappa": "0.4", "mass0": "3"},
     "distribution": False},
    {"name": "stopped", "scene": "grw-example3", "fields": {"n": "1024", "ensembles": "500"},
     "stop": 2},
    {"name": "bad n", "scene": "grw-example3", "fields": {"n": "1"}},
    {"name": "bad key", "scene": "grw-example3", "sets": ["collisions.alpha=0.5"]},
    {"name": "bad kernel parameter", "scene": "grw-example3",
     "fields": {"kernel": "vhs"}, "sets": ["collisions.lambda=2"]},
]

# The speed figures (docs/web.md): GRW Example 3 as shipped (n = 1024, 1000 ensembles) and
# cooling hard spheres, each a few seconds: long enough for the browser's optimizing compiler.
SPEED = [
    {"name": "grw-example3 speed", "scene": "grw-example3", "fields": {}, "distribution": False},
    {"name": "hcs-hard-spheres speed", "scene": "hcs-hard-spheres",
     "fields": {"n": "4096", "ensembles": "40"}, "distribution": False},
]


def serve(directory, cases, reports):
    """A static server of `directory` that also answers cases.json and takes POST /report."""

    class Handler(http.server.SimpleHTTPRequestHandler):
        def __init__(self, *a, **k):
            super().__init__(*a, directory=str(directory), **k)

        def log_message(self, *a):
            pass

        def do_GET(self):
            if self.path.split("?")[0] == "/cases.json":
                body = json.dumps(cases).encode()
                self.send_response(200)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)
            else:
                super().do_GET()

        def do_POST(self):
            n = int(self.headers.get("Content-Length", "0"))
            reports.append(json.loads(self.rfile.read(n)))
            self.send_response(204)
            self.end_headers()

    Handler.extensions_map[".wasm"] = "application/wasm"
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def browse(chromium, url, reports, timeout):
    """Runs headless Chromium on `url` until the page has reported (or `timeout` seconds)."""
    with tempfile.TemporaryDirectory() as profile:
        args = [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                "--no-first-run", "--disable-background-networking",
                "--disable-component-update", "--disable-sync", "--mute-audio",
                "--disable-dev-shm-usage", "--window-size=1280,900",
                f"--user-data-dir={profile}", "--remote-debugging-port=0", url]
        p = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        try:
            waited = 0.0
            while not reports and waited < timeout and p.poll() is None:
                threading.Event().wait(0.5)
                waited += 0.5
        finally:
            p.terminate()
            try:
                _, err = p.communicate(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
                _, err = p.communicate()
    if not reports:
        sys.exit(f"the page reported nothing in {timeout} s; Chromium said:\n{err[-3000:]}")
    return reports[0]


def native(case, scene_path, out, threads=1):
    """The command's run of a case: (exit code, stderr, stdout)."""
    args = [str(GDSMC), "run", scene_path, "--threads", str(threads), "--out", str(out),
            "--format", "svg"]
    for s in case["sets"]:
        args += ["--set", s]
    p = subprocess.run(args, cwd=ROOT, capture_output=True, text=True)
    return p.returncode, p.stderr, p.stdout


def without_timing(summary_json):
    """summary.json's statistics: everything but what the clocks say."""
    v = json.loads(summary_json)
    for k in ["wall_seconds", "cpu_seconds", "threads"]:
        v.pop(k, None)
    return v


def summary_lines(summary):
    """The summary's lines but those the clocks or the files written make (the run line's
    timing, the events line's rate, the files written) and blank ones."""
    skip = ("run ", "events ", "wrote ")
    return [l for l in summary.splitlines() if l.strip() and not l.startswith(skip)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    ap.add_argument("--keep", help="keep the command's outputs here")
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--speed", action="store_true",
                    help="longer runs for the speed figures (docs/web.md), compared as well")
    a = ap.parse_args()
    cases = SPEED if a.speed else CASES
    for need in [DIST / "gdsmc_web.wasm", GDSMC]:
        if not need.exists():
            sys.exit(f"{need} is missing: run web/build.sh and cargo build --release first")
    reports = []
    server = serve(DIST, cases, reports)
    url = f"http://127.0.0.1:{server.server_address[1]}/index.html#test"
    page = browse(a.chromium, url, reports, a.timeout)
    server.shutdown()
    scenes = {s["name"]: s["path"] for s in json.loads((DIST / "scenes.json").read_text())}
    if a.keep and pathlib.Path(a.keep).exists():
        sys.exit(f"--keep {a.keep}: choose a directory that does not exist yet")
    work = pathlib.Path(a.keep or tempfile.mkdtemp(prefix="gdsmc-browser-"))
    work.mkdir(parents=True, exist_ok=True)
    failures = []
    for case, got in zip(cases, page):
        name = case["name"]
        out = work / name.replace(" ", "-") / "run"
        if case.get("stop"):
            # The command's run of the ensembles the page finished.
            got["sets"] = [x for x in got["sets"] if not x.startswith("run.ensembles=")]
            got["sets"].append(f"run.ensembles={got['done']}")
        code, err, text = native(got, scenes[case["scene"]], out)
        if got["error"] is not None or code != 0:
            want = next((l for l in err.splitlines() if l.startswith("error:")), err.strip())
            if got["error"] is None or code == 0:
                failures.append(f"{name}: page error {got['error']!r}, command exit {code}: {err.strip()}")
            elif got["error"].strip() != want.strip():
                failures.append(f"{name}: the page said\n  {got['error']}\nthe command\n  {want}")
            else:
                print(f"ok   {name}: the same error: {want}")
            continue
        same = []
        for file, body in got["files"].items():
            mine = (out / file).read_text()
            if file == "summary.json" and case.get("stop"):
                # The stopped run asked for more ensembles than it finished, the command's not.
                drop = ["ensembles_requested", "interrupted"]
                ok = ({k: v for k, v in without_timing(body).items() if k not in drop}
                      == {k: v for k, v in without_timing(mine).items() if k not in drop})
            elif file == "summary.json":
                ok = without_timing(body) == without_timing(mine)
            else:
                ok = body == mine
            if not ok:
                (out.parent / f"page-{file}").write_text(body)
                failures.append(f"{name}: {file} differs from the command's ({out / file}, "
                                f"the page's beside it)")
            same.append(file)
        missing = {p.name for p in out.glob("*.csv")} - set(got["files"])
        if missing:
            failures.append(f"{name}: the page lacks {sorted(missing)}")
        if case.get("stop"):
            asked = int(case["fields"]["ensembles"])
            if not got["stopped"] or not 0 < got["done"] < asked or "stopped" not in got["status"]:
                failures.append(f"{name}: Stop did not stop the run ({got['done']} of {asked}: {got['status']})")
        elif summary_lines(got["summary"]) != summary_lines(text):
            (out.parent / "page-summary.txt").write_text(got["summary"])
            failures.append(f"{name}: the summary differs from the command's (page-summary.txt)")
        if not got["link_ok"]:
            failures.append(f"{name}: the run's address does not set the page up for the same keys")
        if not all(got["charts_live"][:2]):
            failures.append(f"{name}: the live charts were not drawn")
        # Readable at 1280 px: no sideways scrolling, every live chart's smallest text (its
        # ticks) at 9 px or more as drawn, and a Watch list of every chart of the run.
        lay = got["layout"]
        if lay["page"] > lay["window"]:
            failures.append(f"{name}: the page is {lay['page']} px wide in a {lay['window']} px window")
        for k, c in enumerate(lay["charts"]):
            if c["smallest_text"] < 9.0:
                failures.append(
                    f"{name}: live chart {k} drawn {c['drawn']:.0f} px wide, its smallest text "
                    f"{c['smallest_text']:.1f} px (unreadable under 9)")
        if lay["watch"] < 3:
            failures.append(f"{name}: the Watch list offers {lay['watch']} charts")
        # The command's merged scene file reproduces the page's run: parsed, it is the same.
        if not case.get("stop"):
            merged = out.parent / "merged.toml"
            merged.write_text(got["toml"])
            again = out.parent / "from-toml"
            code2, err2, _ = native({"sets": []}, str(merged), again)
            if code2 != 0 or (again / "observables.csv").read_text() != (out / "observables.csv").read_text():
                failures.append(f"{name}: the downloaded scene file does not reproduce the run: {err2}")
        theirs = json.loads((out / "summary.json").read_text())
        native_rate = theirs["counts"]["collisions"] / max(theirs["cpu_seconds"], 1e-9)
        page_rate = got["collisions"] / max(got["engine_seconds"], 1e-9)
        page_wall = got["collisions"] / max(got["wall_seconds"], 1e-9)
        if a.speed:
            # The command on every core, for the page's wall rate on every core.
            native(got, scenes[case["scene"]], out.parent / "all-cores", threads=0)
            every = json.loads((out.parent / "all-cores" / "summary.json").read_text())
            print(f"     {name}: page {page_wall:.3e}/s on {got['workers']} workers, command "
                  f"{every['counts']['collisions'] / every['wall_seconds']:.3e}/s on "
                  f"{every['threads']} threads (wall)")
        print(f"ok   {name}: {', '.join(same)} equal to the command's; the summary equal; "
              f"{got['collisions']} collisions; page {page_wall:.3e}/s on {got['workers']} "
              f"workers ({page_rate:.3e} per worker-second), command {native_rate:.3e} per CPU second")
    if len(page) != len(cases):
        failures.append(f"the page reported {len(page)} of {len(cases)} cases")
    if failures:
        print("\n".join("FAIL " + f for f in failures))
        sys.exit(1)
    if not a.keep:
        shutil.rmtree(work)
    print(f"browser: {len(cases)} cases as the command has them")


if __name__ == "__main__":
    main()
