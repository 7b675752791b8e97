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

A run releases the GIL; Ctrl-C (KeyboardInterrupt) lets the running ensembles finish and
raises :class:`Interrupted`, whose ``result`` holds the finished ones (exactly the result of a
run with that many ensembles).
"""

from __future__ import annotations

import csv
import io
import json
import os
import sys
from typing import Callable, Dict, List, Optional, Sequence, Union

import numpy as np

from . import _gdsmc
from ._gdsmc import RunError, Scene, SceneError, __version__

__all__ = [
    "Scene",
    "SceneError",
    "RunError",
    "Interrupted",
    "Result",
    "Reproduced",
    "run",
    "reproduce",
    "__version__",
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
        histograms: the other tables the scene asks for (``histograms``, ``reduced``,
            ``marginal``), each a dict of columns.
        summary: summary.json as a dict (sizes, seed, timing, counts, errors against the
            references, steady averages, the tail exponent, warnings).
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
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("to_pandas() needs pandas: pip install pandas") from e
        return pd.DataFrame(self.table)

    def write(self, directory: Union[str, os.PathLike], formats: str = "svg") -> List[str]:
        """Writes the command's whole output set (tables, summary.json, charts in ``formats``:
        "svg", "png", "pdf", comma-separated) into ``directory``. Returns the files written."""
        return self._raw.write(os.fspath(directory), formats)

    def __repr__(self) -> str:
        return repr(self._raw)


class _TextBar:
    """A progress bar on stderr when tqdm is not installed."""

    def __init__(self, total: int):
        self.total, self.n = total, 0

    def update(self, k: int) -> None:
        self.n += k
        width = 40
        full = int(width * self.n / max(self.total, 1))
        sys.stderr.write(f"\r[{'#' * full}{'.' * (width - full)}] {self.n}/{self.total} ensembles")
        sys.stderr.flush()

    def close(self) -> None:
        sys.stderr.write("\n")


def _bar(total: int):
    try:
        from tqdm.auto import tqdm

        return tqdm(total=total, unit="ensembles")
    except ImportError:
        return _TextBar(total)


def run(
    scene: Union[Scene, str, os.PathLike],
    *,
    n: Optional[int] = None,
    ensembles: Optional[int] = None,
    seed: Optional[int] = None,
    threads: int = 0,
    progress: Union[bool, Callable[[int], None]] = False,
    allow_long: bool = False,
) -> Result:
    """Runs a scene (a :class:`Scene` or a scene file's path).

    ``n``, ``ensembles`` and ``seed`` override the scene's ``particles.n``, ``run.ensembles``
    and ``run.seed`` (validated as the command's flags). ``threads=0`` uses every core; the
    numbers are the same for any value, and equal to ``gdsmc run``'s for the same scene and
    seed. ``progress=True`` shows a bar (tqdm in notebooks when installed); a callable is
    called with the ensembles finished since its last call. A run whose estimated work is
    above the command's limit is refused unless ``allow_long``.

    Raises :class:`SceneError` (file, line and key named), :class:`RunError`, and
    :class:`Interrupted` on Ctrl-C (with the finished ensembles' result).
    """
    if not isinstance(scene, Scene):
        scene = Scene.from_file(os.fspath(scene))
    bar = None
    callback = None
    if callable(progress):
        callback = progress
    elif progress:
        bar = _bar(ensembles if ensembles is not None else scene.ensembles)
        callback = bar.update
    try:
        raw, interrupted = _gdsmc.run(scene, n, ensembles, seed, threads, callback, allow_long)
    finally:
        if bar is not None:
            bar.close()
    if interrupted:
        asked = ensembles if ensembles is not None else scene.ensembles
        if raw.ensembles == 0:
            raise KeyboardInterrupt("interrupted before any ensemble finished")
        raise Interrupted(Result(raw), asked)
    return Result(raw)


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
