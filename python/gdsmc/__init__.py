"""gdsmc: direct simulation Monte Carlo for the spatially homogeneous inelastic (granular)
Boltzmann equation, with ensemble statistics and exact references.

The same engine, scenes and numbers as the ``gdsmc`` command: a scene file (TOML, every key in
docs/scenes.md; the shipped scenes reproduce the examples of GRW, RW, BRS and MS), run as
independent ensembles; every observable comes back as the ensemble mean with the half-width of
its 99.9% confidence interval, beside the exact or hydrodynamic reference where one is known.

>>> import gdsmc
>>> scene = gdsmc.Scene.from_file("scenes/grw-example3.toml").set("collisions.restitution", 0.4)
>>> r = gdsmc.run(scene, n=1024, ensembles=100, seed=1)
>>> r.times, r.mean["T"], r.ci["T"], r.references["T_exact"]    # numpy arrays
>>> r.to_pandas()                                               # observables.csv as a DataFrame
>>> gdsmc.theory.references(scene, n=1024)["T_mean_n"]           # the references, without a run

A run releases the GIL; Ctrl-C (KeyboardInterrupt) lets the running ensembles finish and
raises :class:`Interrupted`, whose ``result`` holds the finished ones (exactly the result of a
run with that many ensembles).
"""

from __future__ import annotations

import csv
import io
import json
import os
from typing import Callable, Dict, List, Optional, Sequence, Union

import numpy as np

from . import _gdsmc, _plot, _state, _xr, theory
from ._progress import _progress, _set_total, _TextBar  # noqa: F401 (the tests use them)
from ._gdsmc import STREAM_VERSION, RunError, Scene, SceneError, __version__
from ._state import State, read_state

__all__ = [
    "Scene",
    "SceneError",
    "RunError",
    "Interrupted",
    "Result",
    "State",
    "read_state",
    "Reproduced",
    "run",
    "sweep",
    "Swept",
    "reproduce",
    "theory",
    "__version__",
    "STREAM_VERSION",
]


class Interrupted(KeyboardInterrupt):
    """A run stopped by Ctrl-C. ``result`` holds the ensembles that finished (the statistics
    of a run with that many ensembles)."""

    def __init__(self, result: "Result", asked: int):
        super().__init__(f"interrupted: kept {result.ensembles} of {asked} ensembles")
        self.result = result


def _parse_csv(text: str) -> Dict[str, np.ndarray]:
    """A CSV table as columns of floats (empty cells are NaN). The command writes every number
    with round-trip precision, so the arrays hold exactly the values of its files."""
    rows = list(csv.reader(io.StringIO(text)))
    header, body = rows[0], rows[1:]
    cols = {}
    for j, name in enumerate(header):
        cols[name] = np.array(
            [float(r[j]) if r[j] != "" else np.nan for r in body], dtype=np.float64
        )
    return cols


def _data_frame(table):
    """A table of columns as a pandas DataFrame (needs pandas)."""
    try:
        import pandas as pd
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("to_pandas() needs pandas: pip install pandas") from e
    return pd.DataFrame(table)


class Result:
    """A run's statistics, as the command's files hold them.

    Attributes:
        times: observation times.
        columns: the observables (T, T_bulk, V_x, ..., a2, ...), in the order of
            observables.csv.
        mean, ci: per observable, the ensemble mean and the half-width of its 99.9% interval
            (Student-t quantile for the ensembles run; 3.2 sigma for many).
        references: the reference columns (e.g. ``T_exact``, ``T_mean_n``), per name.
        table: every column of observables.csv in order (``t``, ``NAME``, ``NAME_ci``, ...).
        histograms: the other tables the scene asks for (``histograms``, ``reduced`` with
            ``power_tail``, ``marginal``), each a dict of columns.
        summary: summary.json as a dict (sizes, seed, timing, counts, errors against the
            references, steady averages, the tail exponent, warnings).
        samples: with ``run(..., samples=True)``, per observable every ensemble's own values,
            an array of shape ``(ensembles, times)`` (their mean is ``mean``); else None.
    """

    def __init__(self, raw: "_gdsmc.RunResult"):
        self._raw = raw
        files = dict(raw.tables())
        self.summary: dict = json.loads(files.pop("summary.json"))
        self.table: Dict[str, np.ndarray] = _parse_csv(files.pop("observables.csv"))
        names = list(self.table)
        self.times: np.ndarray = self.table["t"]
        self.columns: List[str] = [c for c in names if c + "_ci" in self.table]
        self.mean: Dict[str, np.ndarray] = {c: self.table[c] for c in self.columns}
        self.ci: Dict[str, np.ndarray] = {c: self.table[c + "_ci"] for c in self.columns}
        observed = set(self.columns) | {c + "_ci" for c in self.columns} | {"t"}
        self.references: Dict[str, np.ndarray] = {
            c: self.table[c] for c in names if c not in observed
        }
        self.histograms: Dict[str, Dict[str, np.ndarray]] = {
            name[: -len(".csv")]: _parse_csv(text) for name, text in files.items()
        }
        kept = raw.samples()
        self.samples: Optional[Dict[str, np.ndarray]] = None
        if kept is not None:
            data, shape, names = kept
            cube = np.frombuffer(data, dtype="<f8").reshape(shape)
            self.samples = {c: cube[:, :, j] for j, c in enumerate(names)}

    @property
    def scene(self) -> Scene:
        """The scene that ran, with the call's overrides."""
        return self._raw.scene

    @property
    def ensembles(self) -> int:
        """Ensembles in the statistics."""
        return self._raw.ensembles

    @property
    def wall(self) -> float:
        """Wall seconds."""
        return self._raw.wall

    @property
    def cpu(self) -> float:
        """CPU seconds (all threads)."""
        return self._raw.cpu

    def summary_text(self) -> str:
        """The summary ``gdsmc run`` prints."""
        return self._raw.summary_text()

    def to_pandas(self):
        """observables.csv as a pandas DataFrame (needs pandas)."""
        return _data_frame(self.table)

    def to_xarray(self):
        """The run as an xarray Dataset over the coordinate ``t``: per observable its mean
        (attribute ``ci``: the variable ``NAME_ci`` with the 99.9% half-width), every reference
        column (attribute ``source``), the scene, n, ensembles, seed and versions as attributes
        (``ds.to_netcdf(path)`` writes NetCDF where a backend is installed). Needs xarray."""
        return _xr.result(self)

    def references_of(self, name: str) -> Dict[str, str]:
        """The references of observable ``name`` that the run attached, with their sources
        (from summary.json)."""
        out: Dict[str, str] = {}
        for e in self.summary.get("errors", []):
            if e["observable"] == name and e["reference"] in self.references:
                out.setdefault(e["reference"], e["source"])
        return out

    def plot(self, name: str = "T", ax=None, axis: str = "time"):
        """Draws observable ``name`` as the command's chart does (needs matplotlib): the
        ensemble mean, its 99.9% band and every reference of it dashed, against time or, with
        ``axis="collisions"``, collisions per particle (the ``s`` column); log axes where the
        times or the values span decades. Returns the matplotlib Axes."""
        return _plot.result(self, name, ax, axis)

    @property
    def snapshot_times(self) -> List[float]:
        """The times of the velocity snapshots (``observe.snapshots``, or ``run(snapshots=)``)."""
        return [t for t, _ in self._raw.snapshot_files()]

    def snapshot(self, t: float) -> State:
        """Every ensemble's particles at snapshot time ``t`` (a :class:`State`)."""
        return _state.snapshot_at(self._raw.snapshot_files(), t)

    def velocities(self, t: float) -> np.ndarray:
        """The velocities at snapshot time ``t``: ``(ensembles, n, d)``, scene units."""
        return self.snapshot(t).velocities

    def write(self, directory: Union[str, os.PathLike], formats: str = "svg") -> List[str]:
        """Writes the command's whole output set (tables, summary.json, charts in ``formats``:
        "svg", "png", "pdf", comma-separated; png and pdf when the extension was built with its
        ``render`` feature) into ``directory``. Returns the files written."""
        return self._raw.write(os.fspath(directory), formats)

    def __repr__(self) -> str:
        return repr(self._raw)


def run(
    scene: Union[Scene, str, os.PathLike],
    *,
    n: Optional[int] = None,
    ensembles: Optional[int] = None,
    seed: Optional[int] = None,
    threads: int = 0,
    progress: Union[bool, Callable[[int], None]] = False,
    allow_long: bool = False,
    samples: bool = False,
    initial_state: Optional[Union[str, os.PathLike]] = None,
    save_state: Optional[Union[str, os.PathLike]] = None,
    snapshots: Optional[Sequence[float]] = None,
) -> Result:
    """Runs a scene (a :class:`Scene` or a scene file's path).

    ``n``, ``ensembles`` and ``seed`` override the scene's ``particles.n``, ``run.ensembles``
    and ``run.seed`` (validated as the command's flags). ``threads=0`` uses every core; the
    numbers are the same for any value, and equal to ``gdsmc run``'s for the same scene and
    seed. ``progress=True`` shows a bar (tqdm in notebooks when installed); a callable is
    called with the ensembles finished since its last call. A run whose estimated work is
    above the command's limit is refused unless ``allow_long``. ``samples=True`` keeps every
    ensemble's own observables (``Result.samples``: per observable an ``(ensembles, times)``
    array), for analyses beyond the mean and its interval. ``save_state`` and
    ``initial_state`` are the command's ``--save-state`` and ``--initial-state``
    (docs/state.md): every ensemble's particles at the last observation saved to a file, and a
    run continued from one (the scene observing from its time on). ``snapshots`` sets
    ``observe.snapshots``: every ensemble's velocities at the first observation at or after
    each time (``Result.velocities(t)``, ``Result.snapshot(t)``).

    Raises :class:`SceneError` (file, line and key named), :class:`RunError`, and
    :class:`Interrupted` on Ctrl-C (with the finished ensembles' result).
    """
    if not isinstance(scene, Scene):
        scene = Scene.from_file(os.fspath(scene))
    if snapshots is not None:
        scene = scene.set("observe.snapshots", [float(t) for t in snapshots])
    total = ensembles if ensembles is not None else scene.ensembles
    with _progress(progress, total) as (callback, _):
        raw, interrupted = _gdsmc.run(
            scene,
            n,
            ensembles,
            seed,
            threads,
            callback,
            allow_long,
            samples,
            None if initial_state is None else os.fspath(initial_state),
            None if save_state is None else os.fspath(save_state),
        )
    if interrupted:
        asked = ensembles if ensembles is not None else scene.ensembles
        if raw.ensembles == 0:
            raise KeyboardInterrupt("interrupted before any ensemble finished")
        raise Interrupted(Result(raw), asked)
    return Result(raw)


def _vary_specs(vary) -> List[str]:
    """``vary`` as the command's ``KEY=VALUES`` strings: a string or a list of them as they
    are, a dict ``{key: values}`` with each value list written as scene values (a string
    value such as ``"0.3:0.9:7"`` is taken as the command's range syntax)."""
    if vary is None:
        return []
    if isinstance(vary, str):
        return [vary]
    if isinstance(vary, dict):
        specs = []
        for key, values in vary.items():
            if isinstance(values, str):
                specs.append(f"{key}={values}")
                continue
            texts = []
            for v in values:
                if isinstance(v, bool):
                    texts.append("true" if v else "false")
                elif isinstance(v, (int, np.integer)):
                    texts.append(str(int(v)))
                elif isinstance(v, (float, np.floating)):
                    texts.append(repr(float(v)))
                else:
                    texts.append(str(v))
            specs.append(f"{key}={','.join(texts)}")
        return specs
    return [str(v) for v in vary]


# sweep.csv's columns that count or number things: integers, never NaN.
_INTEGER_COLUMNS = ("point", "seed", "ensembles", "window_points")


class Swept:
    """A sweep's results, as ``gdsmc sweep`` writes them.

    Attributes:
        table: every column of sweep.csv (``point``, the varied keys, ``seed``,
            ``ensembles``, ``window_from``, ``window_points``, ``NAME`` and ``NAME_ci`` for every
            observable, the references): ``point``, ``seed``, ``ensembles`` and
            ``window_points`` as integer arrays, other numbers as float arrays (empty cells
            NaN), a varied key whose values are not numbers as a list of strings.
        keys: the varied keys.
        columns: the observables.
        mean, ci: per observable, each point's window mean and the half-width of its 99.9%
            interval.
        references: per reference, its value at each point (averaged over the same window).
        json: sweep.json as a dict (what each reference is, each point's window).
        complete: whether every point asked for ran.
    """

    def __init__(self, csv_text: str, json_text: str):
        rows = list(csv.reader(io.StringIO(csv_text)))
        header, body = rows[0], rows[1:]
        self.json: dict = json.loads(json_text)
        self.keys: List[str] = [v["key"] for v in self.json["vary"]]
        self.complete: bool = self.json["complete"]
        self.table: Dict[str, Union[np.ndarray, List[str]]] = {}
        for j, name in enumerate(header):
            cells = [r[j] for r in body]
            if name in _INTEGER_COLUMNS:
                self.table[name] = np.array([int(c) for c in cells], dtype=np.int64)
                continue
            try:
                self.table[name] = np.array(
                    [float(c) if c != "" else np.nan for c in cells], dtype=np.float64
                )
            except ValueError:
                self.table[name] = cells
        fixed = {"point", "seed", "ensembles", "window_from", "window_points", *self.keys}
        names = [c for c in header if c not in fixed]
        self.columns: List[str] = [c for c in names if c + "_ci" in self.table]
        self.mean = {c: self.table[c] for c in self.columns}
        self.ci = {c: self.table[c + "_ci"] for c in self.columns}
        observed = set(self.columns) | {c + "_ci" for c in self.columns}
        self.references = {c: self.table[c] for c in names if c not in observed}

    def to_pandas(self):
        """sweep.csv as a pandas DataFrame (needs pandas)."""
        return _data_frame(self.table)

    def to_xarray(self):
        """sweep.csv as an xarray Dataset over the dimension ``point``, the varied keys also
        its coordinates (needs xarray)."""
        return _xr.swept(self)

    def plot(self, name: str = "a2", x: Optional[str] = None, ax=None):
        """Draws observable ``name`` at every point as the command's sweep chart does (needs
        matplotlib): against the varied key ``x`` (default: the first numeric one), one series
        per combination of the other keys, each point's mean with its 99.9% interval, every
        reference of it dashed. Returns the matplotlib Axes."""
        return _plot.swept(self, name, x, ax)

    def __repr__(self) -> str:
        n = len(self.table.get("point", []))
        return f"Swept({self.json['scene']!r} over {', '.join(self.keys)}: {n} points)"


def sweep(
    scene: Union[Scene, str, os.PathLike],
    vary=None,
    *,
    zip: bool = False,
    n: Optional[int] = None,
    ensembles: Optional[int] = None,
    seed: Optional[int] = None,
    threads: int = 0,
    progress: Union[bool, Callable[[int], None]] = False,
    allow_long: bool = False,
) -> Swept:
    """A parameter study (``gdsmc sweep``): the scene at every value of the varied keys.

    ``vary`` is a dict ``{key: values}`` (a list of values, or the command's range text such
    as ``"0.3:0.9:7"`` or ``"log:0.1:10:5"``), a ``"KEY=VALUES"`` string or a list of them;
    None takes the scene's ``[sweep]`` table. Several keys make a grid (the last varies
    fastest), or are paired with ``zip=True``. Every point is validated before anything runs;
    point ``k`` runs with seed ``run.seed + k`` and gives the numbers of ``gdsmc run`` of its
    scene and seed. ``n``, ``ensembles``, ``seed``, ``threads``, ``progress``, ``allow_long``
    as for :func:`run` (the bar counts the ensembles of every point).

    Raises :class:`SceneError`, ``ValueError`` (a bad ``vary``), :class:`RunError`, and
    :class:`Interrupted` on Ctrl-C, whose ``result`` holds the points that finished.
    """
    if not isinstance(scene, Scene):
        scene = Scene.from_file(os.fspath(scene))
    specs = _vary_specs(vary)
    with _progress(progress, None) as (callback, set_total):
        csv_text, json_text, asked, interrupted = _gdsmc.sweep(
            scene, specs, zip, n, ensembles, seed, threads, callback, allow_long, set_total
        )
    result = Swept(csv_text, json_text)
    if interrupted:
        done = len(result.table.get("point", []))
        if done == 0:
            raise KeyboardInterrupt("interrupted before any point finished")
        err = Interrupted.__new__(Interrupted)
        KeyboardInterrupt.__init__(err, f"interrupted: kept {done} of {asked} points")
        err.result = result
        raise err
    return result


class Reproduced:
    """The papers' tables beside ours (``gdsmc reproduce``).

    Attributes:
        markdown: the report (report.md of the command).
        tables: one text block per table, as the command prints them.
        failures: figures of ours that miss their range (empty when the run passes).
    """

    def __init__(self, markdown: str, tables: List[str], failures: List[str]):
        self.markdown, self.tables, self.failures = markdown, tables, failures

    @property
    def passed(self) -> bool:
        """No disagreement of ours beyond the report-wide range."""
        return not self.failures

    def _repr_markdown_(self) -> str:
        return self.markdown

    def __repr__(self) -> str:
        return "\n".join(self.tables)


def reproduce(*names: str, quick: bool = True, threads: int = 0, seed: int = 1) -> Reproduced:
    """Runs the papers' tables (e.g. ``reproduce("grw-table1")``; none named: all), by default
    at the reduced sizes of ``gdsmc reproduce --quick``."""
    md, tables, failures = _gdsmc.reproduce(list(names), quick, threads, seed)
    return Reproduced(md, tables, failures)
