"""State files (docs/state.md) as numpy arrays: what ``gdsmc run --save-state``,
``run(save_state=...)`` and the velocity snapshots (``observe.snapshots``) write."""

from __future__ import annotations

import json
import os
from typing import Any, Dict, Optional, Union

import numpy as np

from . import _gdsmc, _xr


class State:
    """Every ensemble's particles at one time, read from a state file.

    Attributes:
        time: the time of the state (an observation time of the run that wrote it).
        s: collisions per particle so far, one per ensemble (``(ensembles,)``).
        velocities: the physical velocities, ``(ensembles, n, d)`` in the scene's units
            (``d`` the scene's dimension; a mixture's particles in species order, see
            ``header["species"]``).
        spins: the rim velocities of rough particles, ``(ensembles, n, 3)`` (the components
            the rotation has: ``z`` alone for disks), or ``None`` for smooth ones.
        header: the file's JSON header (scene, seed, segment, n, dimension, species, origin).
    """

    def __init__(self, header: Dict[str, Any], data: bytes, shape):
        self.header = header
        self.time: float = float(header["time"])
        n, d = int(header["n"]), int(header["dimension"])
        rows = np.frombuffer(data, dtype="<f8").reshape(shape)
        self.s: np.ndarray = rows[:, 0]
        self.velocities: np.ndarray = rows[:, 1 : 1 + 3 * n].reshape(-1, n, 3)[:, :, :d]
        self.spins: Optional[np.ndarray] = (
            rows[:, 1 + 3 * n :].reshape(-1, n, 3) if header["spins"] else None
        )

    @property
    def ensembles(self) -> int:
        """Ensembles (records) in the file."""
        return self.velocities.shape[0]

    def to_xarray(self):
        """The state as an xarray Dataset (needs xarray): ``velocities`` over ``(ensemble,
        particle, component)``, ``s`` over ``ensemble``, ``spins`` for rough particles, the
        time and the header's scalars as attributes; ``ds.to_netcdf(path)`` writes it where a
        NetCDF backend is installed."""
        xr = _xr.module()
        comps = ["x", "y", "z"][: self.velocities.shape[2]]
        data = {
            "velocities": (("ensemble", "particle", "component"), self.velocities),
            "s": (("ensemble",), self.s),
        }
        coords = {"component": comps}
        if self.spins is not None:
            data["spins"] = (("ensemble", "particle", "spin_component"), self.spins)
            coords["spin_component"] = ["x", "y", "z"]
        attrs = {"time": self.time}
        attrs.update(
            {k: v for k, v in self.header.items() if isinstance(v, (int, float, str, bool))}
        )
        attrs = {k: (int(v) if isinstance(v, bool) else v) for k, v in attrs.items()}
        return xr.Dataset(data, coords=coords, attrs=attrs)

    def __repr__(self) -> str:
        return (
            f"State({self.header['scene']!r} at t={self.time}: "
            f"{self.ensembles} ensembles of {self.velocities.shape[1]} particles)"
        )


def read_state(path: Union[str, os.PathLike]) -> State:
    """Reads a state file whole (checked as ``--initial-state`` is: magic, version, size)."""
    header, data, shape = _gdsmc.read_state(os.fspath(path))
    return State(json.loads(header), data, shape)


def snapshot_at(files, t: float) -> State:
    """The snapshot of ``files`` (``(time, path)`` pairs) at time ``t`` (to 1e-9 relative);
    a ``KeyError`` naming the times there are otherwise."""
    for time, path in files:
        if abs(time - t) <= 1e-9 * max(1.0, abs(t)):
            return read_state(path)
    times = ", ".join(repr(time) for time, _ in files) or "none (observe.snapshots is empty)"
    raise KeyError(f"no velocity snapshot at t = {t}; the run has snapshots at {times}")
