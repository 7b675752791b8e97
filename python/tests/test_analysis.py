"""The Python package's analysis side: charts (Result.plot, Swept.plot), each ensemble's own
samples, integer columns, errors in Python's words, and the example notebooks run headless."""

from pathlib import Path

import numpy as np
import pytest

import gdsmc

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"


def execute_notebook(name):
    """Executes python/examples/NAME.ipynb headless; returns its code cells' outputs, none of
    them an error."""
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    pytest.importorskip("matplotlib")
    path = ROOT / "python" / "examples" / f"{name}.ipynb"
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}}
    )
    client.execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    return outputs


def test_the_notebook_runs_headless():
    outputs = execute_notebook("grw_example3")
    text = "".join(o.get("text", "") for o in outputs if o.get("output_type") == "stream")
    assert "inside the 99.9% interval" in text
    assert any("image/png" in o.get("data", {}) for o in outputs)


@pytest.mark.parametrize(
    "name, words",
    [
        ("sweep_white_noise", "half-widths"),
        ("cooling_state", "collisions per particle at the end"),
        ("mixture", "Garzó and Dufty"),
    ],
)
def test_the_other_notebooks_run_headless(name, words):
    """The sweep, cooling-state and mixture notebooks run without an error, draw, and print."""
    outputs = execute_notebook(name)
    text = "".join(o.get("text", "") for o in outputs if o.get("output_type") == "stream")
    assert words in text, text
    assert any("image/png" in o.get("data", {}) for o in outputs)


def test_plot_draws_the_mean_band_and_references():
    """r.plot draws the mean, its band and each reference of the observable (as summary.json
    pairs them), on log axes where the times and values span decades; s.plot a series per
    group with every reference; a bad name or axis is refused in Python's words."""
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    r = gdsmc.run(SCENES / "grw-example3.toml", n=64, ensembles=4, seed=2)
    ax = r.plot("T")
    refs = r.references_of("T")
    assert set(refs) == {"T_exact", "T_mean_n"}
    assert len(ax.lines) == 1 + len(refs)
    assert ax.get_xscale() == "linear" and ax.get_yscale() == "linear"
    assert "T_mean_n" in " ".join(t.get_text() for t in ax.get_legend().get_texts())
    ax = r.plot("T_bulk", axis="collisions")
    assert ax.get_xlabel().startswith("collisions per particle")
    assert np.array_equal(ax.lines[0].get_xdata(), r.mean["s"])
    with pytest.raises(KeyError, match="no observable 'nope'"):
        r.plot("nope")
    with pytest.raises(ValueError, match="axis must be"):
        r.plot("T", axis="t")
    # A cooling gas observed at log-spaced times: log t and log T, Haff's law beside.
    hcs = gdsmc.run(SCENES / "hcs-hard-spheres.toml", n=128, ensembles=2)
    ax = hcs.plot("T_bulk")
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    assert {"T_bulk_MA", "T_bulk_sonine"} <= set(hcs.references_of("T_bulk"))
    s = gdsmc.sweep(
        SCENES / "grw-example3.toml",
        {"collisions.restitution": [0.5, 0.8], "drive.beta": [1, 2]},
        n=64,
        ensembles=2,
    )
    ax = s.plot("T")
    assert len(ax.containers) == 2  # one error-bar series per drive.beta
    legend = " ".join(t.get_text().replace("\n", " ") for t in ax.get_legend().get_texts())
    # Each reference's source once, with the first group's curve, not once per series.
    assert legend.count("(GRW (13)-(14))") == 1, legend
    assert legend.count("(exact ensemble mean") == 1, legend
    assert legend.count("T_exact") == 2 and legend.count("T_mean_n") == 2, legend
    with pytest.raises(ValueError, match="numeric varied key"):
        s.plot("T", x="seed")


def test_plot_legends_stay_off_the_data_and_inside_the_figure():
    """The legend sits below the plotting area, its entries wrapped: it overlaps neither the
    data nor the figure's edge, even with a reference's whole description (a2_exact's is 180
    characters; it once ran past the figure and over the curves)."""
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    r = gdsmc.run(SCENES / "grw-example3.toml", n=64, ensembles=4, seed=2)
    s = gdsmc.sweep(SCENES / "grw-example3.toml", {"collisions.restitution": [0.5, 0.8]},
                    n=64, ensembles=2)
    for ax in (r.plot("a2"), s.plot("T")):
        fig = ax.figure
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        legend = ax.get_legend().get_window_extent(renderer)
        plot = ax.get_window_extent(renderer)
        page = fig.bbox
        assert not legend.overlaps(plot), (legend, plot)
        assert page.x0 <= legend.x0 and legend.x1 <= page.x1, (legend, page)
        assert page.y0 <= legend.y0 and legend.y1 <= page.y1, (legend, page)
        assert all(len(line) <= 60 for t in ax.get_legend().get_texts()
                   for line in t.get_text().split("\n"))


def test_integers_errors_and_the_sweep_total_in_pythons_words():
    """sweep.csv's counts come back as integers; a bad keyword is named as the keyword (not
    the command's flag); a sweep tells its bar the total before it runs."""
    s = gdsmc.sweep(SCENES / "grw-example3.toml", "drive.beta=1,2", n=64, ensembles=2, seed=3)
    for c in ("point", "seed", "ensembles", "window_points"):
        assert s.table[c].dtype == np.int64, c
    assert list(s.table["seed"]) == [3, 4]
    with pytest.raises(gdsmc.SceneError) as e:
        gdsmc.run(SCENES / "grw-example3.toml", ensembles=0)
    assert "ensembles=0" in str(e.value) and "--ensembles" not in str(e.value)
    scene = gdsmc.Scene.from_file(str(SCENES / "grw-example3.toml"))
    totals = []
    gdsmc._gdsmc.sweep(scene, ["drive.beta=1,2,3"], False, 64, 2, None, 0, None, False, totals.append)
    assert totals == [6]
    bar = gdsmc._TextBar(None)
    gdsmc._set_total(bar, 6)
    assert bar.total == 6


def test_samples_are_every_ensembles_own_values():
    """run(samples=True) keeps each ensemble's observables: their mean over the ensembles is the
    result's mean (to rounding), the first ensemble is the same whatever the ensemble count,
    and a run without it keeps none."""
    r = gdsmc.run(SCENES / "grw-example3.toml", n=64, ensembles=5, seed=3, samples=True)
    assert r.samples["T"].shape == (5, len(r.times))
    for c in ("T", "a2", "s"):
        assert np.allclose(r.samples[c].mean(axis=0), r.mean[c], rtol=1e-12, atol=1e-15), c
    one = gdsmc.run(SCENES / "grw-example3.toml", n=64, ensembles=1, seed=3, samples=True)
    assert np.array_equal(one.samples["T"][0], r.samples["T"][0])
    assert gdsmc.run(SCENES / "grw-example3.toml", n=64, ensembles=2).samples is None


def test_a_saved_state_is_continued(tmp_path):
    """save_state and initial_state are the command's flags: the continuation's first
    observation is the saved run's last, its references kept; a state of other physics runs
    without references; a bad file is refused naming it."""
    scene = gdsmc.Scene.from_file(str(SCENES / "grw-example3.toml")).set("observe.t_end", 1.0)
    state = tmp_path / "s.gdsmc-state"
    a = gdsmc.run(scene, n=64, ensembles=3, seed=5, save_state=state)
    later = scene.set("observe.t_end", 2.0).set("observe.t_start", 1.0)
    b = gdsmc.run(later, n=64, ensembles=3, seed=5, initial_state=state)
    for c in ("T", "T_bulk", "a2", "s"):
        assert b.mean[c][0] == a.mean[c][-1], c
    assert "T_mean_n" in b.references
    other = gdsmc.run(
        later.set("collisions.restitution", 0.9), n=64, ensembles=3, initial_state=state
    )
    assert other.references == {}
    with pytest.raises(ValueError, match="observe.t_start is 0"):
        gdsmc.run(scene, n=64, ensembles=3, initial_state=state)
    bad = tmp_path / "bad"
    bad.write_text("x" * 5000)
    with pytest.raises(ValueError, match="not a gdsmc state file"):
        gdsmc.run(later, n=64, ensembles=3, initial_state=bad)


def test_snapshots_are_the_particles_the_observables_come_from(tmp_path):
    """run(snapshots=...) takes every ensemble's velocities at the first observation at or
    after each time: each ensemble's T from its snapshot is that ensemble's T at the
    observation (samples=True), the snapshot equals the state a run saves there, a missing
    time is named, and the files go with the result."""
    scene = gdsmc.Scene.from_file(str(SCENES / "grw-example3.toml")).set("observe.t_end", 2.0)
    r = gdsmc.run(scene, n=64, ensembles=3, seed=5, samples=True, snapshots=[0.9, 2.0])
    i = int(np.searchsorted(r.times, 0.9))
    assert r.snapshot_times == [float(r.times[i]), 2.0]
    snap = r.snapshot(r.times[i])
    v = r.velocities(r.times[i])
    assert v.shape == (3, 64, 3) and snap.spins is None
    bulk = v.mean(axis=1, keepdims=True)
    t_bulk = ((v - bulk) ** 2).sum(axis=2).mean(axis=1) / 3
    np.testing.assert_allclose(t_bulk, r.samples["T_bulk"][:, i], rtol=1e-12)
    np.testing.assert_array_equal(snap.s, r.samples["s"][:, i])
    saved = tmp_path / "s.gdsmc-state"
    short = scene.set("observe.t_end", float(r.times[i])).set("observe.intervals", i)
    gdsmc.run(short, n=64, ensembles=3, seed=5, save_state=saved)
    np.testing.assert_array_equal(gdsmc.read_state(saved).velocities, v)
    with pytest.raises(KeyError, match="snapshots at"):
        r.velocities(0.3)
    files = [p for _, p in r._raw.snapshot_files()]
    del r, snap
    assert not any(Path(p).exists() for p in files)


def test_to_xarray_holds_the_tables_and_the_state(tmp_path):
    """Result, Swept, References and State as xarray Datasets: the same numbers as the
    tables, the intervals and sources named, a NetCDF round trip where a backend exists."""
    xr = pytest.importorskip("xarray")
    r = gdsmc.run(SCENES / "grw-example3.toml", n=200, ensembles=6, seed=3,
                  snapshots=[8.0])
    ds = r.to_xarray()
    assert np.array_equal(ds["t"].values, r.times)
    assert np.array_equal(ds["T_bulk"].values, r.mean["T_bulk"])
    assert np.array_equal(ds["T_bulk_ci"].values, r.ci["T_bulk"])
    assert ds["T_bulk"].attrs["ci"] == "T_bulk_ci"
    assert np.array_equal(ds["T_mean_n"].values, r.references["T_mean_n"])
    assert "GRW" in ds["T_exact"].attrs["source"]
    assert ds.attrs["ensembles"] == 6 and ds.attrs["scene"] == "grw-example3"
    refs = gdsmc.theory.references(SCENES / "grw-example3.toml", n=200).to_xarray()
    assert np.array_equal(refs["T_mean_n"].values, r.references["T_mean_n"])
    assert refs["T_mean_n"].attrs["kind"] == "mean_at_n"
    st = r.snapshot(8.0).to_xarray()
    assert st["velocities"].shape == (6, 200, 3)
    assert np.array_equal(st["velocities"].values, r.velocities(8.0))
    assert st.attrs["time"] == 8.0
    s = gdsmc.sweep(SCENES / "grw-example3.toml", {"collisions.restitution": [0.4, 0.6]},
                    n=100, ensembles=3)
    sw = s.to_xarray()
    assert np.array_equal(sw["collisions.restitution"].values, [0.4, 0.6])
    assert np.array_equal(sw["a2"].values, s.mean["a2"])
