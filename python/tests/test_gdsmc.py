"""The Python package against the command: the same numbers for the same scene and seed, the
same validation, Ctrl-C keeping the finished ensembles (charts, samples and notebooks: test_analysis.py).

The command is GDSMC_BIN or target/release/gdsmc (built by `cargo build --release -p gdsmc`).
"""

import csv
import json
import os
import signal
import subprocess
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import gdsmc

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"
GDSMC = Path(os.environ.get("GDSMC_BIN", ROOT / "target" / "release" / "gdsmc"))


def command(tmp_path, scene, *args):
    """Runs `gdsmc run` and returns its output directory."""
    if not GDSMC.exists():
        pytest.fail(f"{GDSMC} missing: cargo build --release -p gdsmc, or set GDSMC_BIN")
    out = tmp_path / "cmd"
    subprocess.run(
        [str(GDSMC), "run", str(scene), *args, "--out", str(out)],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    return out


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) if x != "" else np.nan for x in r] for r in rows[1:]]


def assert_table_equals_file(table, path):
    header, rows = read_csv(path)
    assert list(table) == header
    for j, name in enumerate(header):
        col = np.array([r[j] for r in rows])
        # Exactly equal (NaN where the file has NaN): the file holds round-trip decimals.
        assert np.array_equal(table[name], col, equal_nan=True), name


def strip_timing(v):
    if isinstance(v, dict):
        return {
            k: strip_timing(x)
            for k, x in v.items()
            if k not in ("wall_seconds", "cpu_seconds", "threads", "collisions_per_second")
        }
    if isinstance(v, list):
        return [strip_timing(x) for x in v]
    return v


@pytest.mark.parametrize(
    "name,args",
    [
        ("grw-example3", ["--n", "300", "--ensembles", "25", "--seed", "7"]),
        (
            "ms-constant-force",
            ["--n", "256", "--ensembles", "6", "--set", "observe.collisional_pairs=500"],
        ),
        # The Langevin thermostat (a drive declared by its type in the core): its keys read,
        # its exact finite-n temperature attached.
        ("langevin-maxwell", ["--n", "200", "--ensembles", "8", "--seed", "11"]),
        # A granular mixture: the species' columns (T_s0, T_s0_ratio, ...) and references.
        ("mixture-maxwell", ["--n", "200", "--ensembles", "8", "--seed", "3"]),
        # Rough particles: the rotation's columns (T_rot, theta, ...) and references.
        ("rough-hcs", ["--n", "200", "--ensembles", "6", "--seed", "5"]),
        # Rough disks (d = 2): the same columns, the references for disks.
        ("rough-disks-hcs", ["--n", "200", "--ensembles", "6", "--seed", "5"]),
        # Rough mixtures: each species' rotation (T_rot_s0, theta_s0, ...) and its references,
        # spheres cooling and disks under white noise.
        ("rough-mixture-hcs", ["--n", "200", "--ensembles", "6", "--seed", "9"]),
        ("rough-disk-mixture-white-noise", ["--n", "200", "--ensembles", "6", "--seed", "9"]),
    ],
)
def test_same_numbers_as_the_command(tmp_path, name, args):
    out = command(tmp_path, SCENES / f"{name}.toml", *args)
    scene = gdsmc.Scene.from_file(SCENES / f"{name}.toml")
    opts = dict(zip(args[0::2], args[1::2]))
    if "--set" in opts:
        key, value = opts["--set"].split("=")
        scene = scene.set(key, int(value))
    r = gdsmc.run(
        scene,
        n=int(opts["--n"]),
        ensembles=int(opts["--ensembles"]),
        seed=int(opts.get("--seed", 1)),
    )
    assert r.ensembles == int(opts["--ensembles"])
    assert_table_equals_file(r.table, out / "observables.csv")
    for hist, table in r.histograms.items():
        assert_table_equals_file(table, out / f"{hist}.csv")
    expected = {p.stem for p in out.glob("*.csv")} - {"observables"}
    assert set(r.histograms) == expected
    with open(out / "summary.json") as f:
        written = json.load(f)
        assert strip_timing(r.summary) == strip_timing(written)
    # The streams the numbers were drawn from, stated alike.
    assert written["stream_version"] == gdsmc.STREAM_VERSION
    # The views agree with the table.
    assert np.array_equal(r.times, r.table["t"])
    assert np.array_equal(r.mean["T"], r.table["T"])
    assert np.array_equal(r.ci["T"], r.table["T_ci"])
    if "mixture" in name:
        assert np.array_equal(r.mean["T_s1_ratio"], r.table["T_s1_ratio"])
    if name.startswith("rough") and "mixture" in name:
        assert np.array_equal(r.mean["theta_s1"], r.table["theta_s1"])
        assert np.array_equal(r.ci["T_rot_s0"], r.table["T_rot_s0_ci"])
        assert "theta_s0_MA" in r.table
    elif name.startswith("rough"):
        assert np.array_equal(r.mean["theta"], r.table["theta"])
        assert "theta_MA" in r.table


def test_threads_do_not_change_the_numbers():
    s = SCENES / "grw-example3.toml"
    a = gdsmc.run(s, n=200, ensembles=12, threads=1)
    b = gdsmc.run(s, n=200, ensembles=12, threads=2)
    for k in a.table:
        assert np.array_equal(a.table[k], b.table[k], equal_nan=True), k


def test_write_gives_the_command_files(tmp_path):
    out = command(tmp_path, SCENES / "grw-example3.toml", "--n", "200", "--ensembles", "9")
    r = gdsmc.run(SCENES / "grw-example3.toml", n=200, ensembles=9)
    files = r.write(tmp_path / "py", formats="svg")
    assert "observables.csv" in files and "T.svg" in files
    assert (tmp_path / "py" / "observables.csv").read_bytes() == (
        out / "observables.csv"
    ).read_bytes()


def test_bad_scenes_name_the_key():
    text = (SCENES / "grw-example3.toml").read_text()
    bad = text.replace("restitution = 0.5", "restitution = 1.5")
    assert bad != text
    with pytest.raises(gdsmc.SceneError, match=r"collisions\.restitution.*\(0, 1\].*1\.5"):
        gdsmc.Scene.from_toml(bad, name="bad.toml")
    with pytest.raises(gdsmc.SceneError, match=r"bad\.toml:\d+"):
        gdsmc.Scene.from_toml(bad, name="bad.toml")
    s = gdsmc.Scene.from_file(SCENES / "grw-example3.toml")
    with pytest.raises(gdsmc.SceneError, match=r"collisions\.restitution"):
        s.set("collisions.restitution", 1.5)
    with pytest.raises(gdsmc.SceneError, match=r"collisions\.no_such_key|no_such_key"):
        s.set("collisions.no_such_key", 1)
    # A typo in a later set names that key alone, in Python's words (not the command's --set).
    with pytest.raises(gdsmc.SceneError) as e:
        s.set("collisions.restitution", 0.4).set("collisions.restitutoin", 0.3)
    message = str(e.value)
    assert message.startswith('set("collisions.restitutoin")'), message
    assert "--set" not in message and "collisions.restitution," not in message, message
    with pytest.raises(gdsmc.SceneError, match=r"particles\.n"):
        gdsmc.run(s, n=0)
    with pytest.raises(gdsmc.SceneError, match="cannot read"):
        gdsmc.Scene.from_file("no/such/scene.toml")
    with pytest.raises(TypeError):
        s.set("collisions.restitution", object())
    # SceneError is a ValueError; the scene itself is unchanged by a refused set.
    assert issubclass(gdsmc.SceneError, ValueError)
    assert s.overrides == []


def test_the_langevin_thermostat_runs_and_meets_its_exact_temperature():
    s = gdsmc.Scene.from_file(SCENES / "langevin-maxwell.toml")
    with pytest.raises(gdsmc.SceneError, match=r"drive\.friction.*> 0.*-1"):
        s.set("drive.friction", -1.0)
    with pytest.raises(gdsmc.SceneError, match=r"drive\.zeta.*not a key.*langevin"):
        s.set("drive.zeta", 0.5)
    r = gdsmc.run(s, n=100, ensembles=400, seed=3)
    exact = r.references["T_bulk_mean_n"]
    # Jointly at 99.9% over the 21 times (Bonferroni): each 99.9% half-width (z 3.29, 400
    # ensembles) widened to z(1 - 0.0005/21) = 4.07.
    assert (abs(r.mean["T_bulk"] - exact) <= 4.07 / 3.29 * r.ci["T_bulk"]).all()


def test_set_and_properties():
    s = gdsmc.Scene.from_file(SCENES / "grw-example3.toml")
    t = s.set("collisions.restitution", 0.4).set("particles.n", 64)
    assert t.n == 64 and s.n == 1024
    assert t.overrides == ["collisions.restitution=0.4", "particles.n=64"]
    assert "overrides" in repr(t)
    assert len(t.times) == len(gdsmc.run(t, ensembles=3).times)


def test_setting_a_key_again_changes_it():
    # Each set is validated when made; setting the key again replaces it (the command refuses
    # a key given twice, where the first value would never be checked).
    s = gdsmc.Scene.from_file(SCENES / "grw-example3.toml").set("particles.n", 64)
    t = s.set("particles.n", 32).set("collisions.restitution", 0.4)
    assert t.n == 32
    assert t.overrides == ["particles.n=32", "collisions.restitution=0.4"]
    assert gdsmc.run(t, n=16, ensembles=2).scene.n == 16


def test_progress_callback_counts_every_ensemble():
    seen = []
    r = gdsmc.run(SCENES / "grw-example3.toml", n=200, ensembles=30, progress=seen.append)
    assert sum(seen) == r.ensembles == 30


def test_ctrl_c_keeps_the_finished_ensembles():
    s = SCENES / "grw-example3.toml"
    # A run far longer than the signal's delay on any machine (about 30 s of work here, and
    # stopped after 1 s), not sized from a timed first run.
    full = 4000
    # Python's own Ctrl-C handler, whatever this process inherited: a shell that starts a job in
    # the background starts it with SIGINT ignored, and Python then installs no handler, so the
    # signal below did nothing (CI run from such a shell: "DID NOT RAISE").
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    # SIGINT to this process during the run, as Ctrl-C or a notebook's interrupt sends it; 1 s
    # leaves the wrapper's start far behind.
    timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(gdsmc.Interrupted) as e:
            gdsmc.run(s, n=20000, ensembles=full)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    kept = e.value.result
    assert isinstance(e.value, KeyboardInterrupt)
    assert 0 < kept.ensembles < full, kept.ensembles
    # Exactly the statistics of a run with that many ensembles.
    short = gdsmc.run(s, n=20000, ensembles=kept.ensembles)
    for k in short.table:
        assert np.array_equal(kept.table[k], short.table[k], equal_nan=True), k


def test_to_pandas():
    pd = pytest.importorskip("pandas")
    r = gdsmc.run(SCENES / "grw-example3.toml", n=100, ensembles=4)
    df = r.to_pandas()
    assert isinstance(df, pd.DataFrame)
    assert list(df.columns) == list(r.table)
    assert len(df) == len(r.times)


def test_reproduce_a_table():
    rep = gdsmc.reproduce("grw-table1")
    assert rep.tables and "GRW" in rep.markdown
    assert rep.passed, rep.failures


def test_the_gil_is_released_while_running():
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.time())
            time.sleep(0.005)

    t = threading.Thread(target=tick)
    t.start()
    t0 = time.time()
    gdsmc.run(SCENES / "grw-example3.toml", n=20000, ensembles=60, threads=1)
    t1 = time.time()
    stop.set()
    t.join()
    during = [x for x in ticks if t0 < x < t1]
    # A thread that sleeps 5 ms per tick ticks about (t1 - t0) / 5 ms times when it can run;
    # with the GIL held through the run it could not tick at all. At least a quarter of that.
    assert len(during) >= 0.25 * (t1 - t0) / 0.005, (len(during), t1 - t0)


def test_a_raising_progress_callback_stops_the_run():
    calls = []

    def progress(k):
        calls.append(k)
        raise ValueError("stop here")

    t0 = time.time()
    with pytest.raises(ValueError, match="stop here"):
        gdsmc.run(SCENES / "grw-example3.toml", n=20000, ensembles=2000, threads=1, progress=progress)
    # Stopped after the first report, far before 2000 ensembles (about 30 s on one core).
    assert len(calls) == 1
    assert time.time() - t0 < 10


def test_sweep_gives_the_command_sweep(tmp_path):
    """gdsmc.sweep equals `gdsmc sweep` of the same scene, values and seed, cell for cell, and
    a dict of values is the command's list."""
    scene = SCENES / "grw-example3.toml"
    s = gdsmc.sweep(
        scene,
        {"collisions.restitution": [0.5, 0.8], "drive.beta": "1:2:2"},
        n=64,
        ensembles=3,
        seed=4,
        threads=1,
    )
    out = tmp_path / "sweep"
    subprocess.run(
        [
            str(GDSMC), "sweep", str(scene),
            "--vary", "collisions.restitution=0.5,0.8", "--vary", "drive.beta=1:2:2",
            "--n", "64", "--ensembles", "3", "--seed", "4", "--out", str(out),
        ],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    assert_table_equals_file(s.table, out / "sweep.csv")
    assert s.keys == ["collisions.restitution", "drive.beta"]
    assert s.complete and len(s.table["point"]) == 4
    assert list(s.table["seed"]) == [4, 5, 6, 7]
    assert "T" in s.columns and "T_exact" in s.references
    assert s.to_pandas().shape[0] == 4


def test_sweep_point_is_the_run_of_its_seed():
    """Point k of a sweep is gdsmc.run of its scene with seed + k: the last observation's
    means and intervals, to the last bit."""
    scene = gdsmc.Scene.from_file(str(SCENES / "grw-example3.toml"))
    s = gdsmc.sweep(scene, "drive.beta=0.5,2", n=64, ensembles=3, seed=9)
    r = gdsmc.run(scene.set("drive.beta", 2.0), n=64, ensembles=3, seed=10)
    for c in ["T", "a2", "T_bulk"]:
        assert s.mean[c][1] == r.mean[c][-1], c
        assert s.ci[c][1] == r.ci[c][-1], c


def test_sweep_takes_the_scene_table_and_refuses_bad_values():
    """A scene's [sweep] table is taken when no values are given; a bad range or a bad point
    is refused before anything runs, naming the rule or the point."""
    scene = gdsmc.Scene.from_toml(
        (SCENES / "grw-example3.toml").read_text()
        + '\n[sweep]\nvary = ["collisions.restitution=0.5,0.9"]\n'
    )
    s = gdsmc.sweep(scene, n=64, ensembles=2)
    assert list(s.table["collisions.restitution"]) == [0.5, 0.9]
    with pytest.raises(ValueError, match="count must be an integer"):
        gdsmc.sweep(scene, "collisions.restitution=0:1:x", n=64, ensembles=2)
    with pytest.raises(gdsmc.SceneError, match="point 1"):
        gdsmc.sweep(scene, {"collisions.restitution": [0.5, 1.5]}, n=64, ensembles=2)


@pytest.mark.parametrize(
    "name,n",
    [("grw-example3", 300), ("ms-white-noise", 256), ("brs-example2", 128), ("mixture-maxwell", 200)],
)
def test_theory_gives_the_commands_reference_columns_without_a_run(tmp_path, name, n):
    """gdsmc.theory.references: every reference column of `gdsmc run`, to the bit, with
    nothing run (the exact means at n, the limits, the approximations)."""
    out = command(tmp_path, SCENES / f"{name}.toml", "--n", str(n), "--ensembles", "2")
    with open(out / "observables.csv") as f:
        table = list(csv.DictReader(f))
    refs = gdsmc.theory.references(SCENES / f"{name}.toml", n=n)
    assert len(refs) > 0
    assert np.array_equal(refs.times, [float(r["t"]) for r in table])
    for name_ in refs:
        written = np.array([float(r[name_]) for r in table])
        assert np.array_equal(refs[name_], written, equal_nan=True), name_
        assert refs.kind[name_] in ("mean_at_n", "limit", "approximation")
        assert refs.of[name_] in table[0]


def test_theory_flags_what_it_cannot_compute_and_refuses_bad_times():
    scene = gdsmc.Scene.from_file(SCENES / "grw-example3.toml").set("collisions.gamma", 1e-300)
    with pytest.warns(UserWarning, match="a2_exact is not computable here"):
        refs = gdsmc.theory.references(scene, times=[0.0, 1.0, 8.0], n=64)
    assert refs.not_computable["a2_exact"] == 3
    assert np.all(np.isnan(refs["a2_exact"]))
    assert np.array_equal(refs["T_exact"], [1.0, 3.0, 17.0])
    with pytest.raises(KeyError, match="T_bulk_sonine"):
        refs["T_bulk_sonine"]
    with pytest.raises(gdsmc.SceneError, match="times"):
        gdsmc.theory.references(scene, times=[0.0, 2.0, 1.0])
