"""A scene's references without a run: the exact solutions, the exact means at the scene's n,
the Boltzmann limits and the approximations that hold for its physics (the ``gdsmc-theory``
crate, which ``gdsmc run`` computes its reference columns with: the values equal the command's
to the bit).

>>> import gdsmc
>>> scene = gdsmc.Scene.from_file("scenes/grw-example3.toml")
>>> refs = gdsmc.theory.references(scene, n=4096)
>>> refs.times, refs["T_mean_n"], refs.kind["T_mean_n"]     # numpy arrays, "mean_at_n"

A reference whose arithmetic cannot hold at some times (its closed form leaves the range of
double there) holds NaN at them, is counted in ``not_computable`` and is named in a
``UserWarning``: never a wrong number.
"""

from __future__ import annotations

import os
import warnings
from typing import Dict, List, Optional, Sequence, Union

import numpy as np

from . import _gdsmc, _xr
from ._gdsmc import Scene

__all__ = ["References", "references"]


class References:
    """The references of a scene at its times.

    Attributes:
        times: the times they are evaluated at.
        names: the reference columns, in the order ``gdsmc run`` writes them.
        values: per name, the values at ``times`` (NaN where not computable).
        of: per name, the observable it is the reference of (``T``, ``T_bulk``, ``a2``).
        source: per name, its paper and equation.
        kind: per name, ``"mean_at_n"`` (the exact ensemble mean at the scene's n, which a
            run's mean must lie within its interval of), ``"limit"`` (the Boltzmann equation's
            solution, O(1/n) from a mean at finite n) or ``"approximation"``.
        not_computable: per name, how many times it cannot be computed at.
    """

    def __init__(self, times: Sequence[float], curves: List[tuple]):
        self.times: np.ndarray = np.asarray(times, dtype=np.float64)
        self.names: List[str] = [c[0] for c in curves]
        self.of: Dict[str, str] = {c[0]: c[1] for c in curves}
        self.source: Dict[str, str] = {c[0]: c[2] for c in curves}
        self.kind: Dict[str, str] = {c[0]: c[3] for c in curves}
        self.values: Dict[str, np.ndarray] = {
            c[0]: np.asarray(c[4], dtype=np.float64) for c in curves
        }
        self.not_computable: Dict[str, int] = {
            name: int(np.count_nonzero(~np.isfinite(v))) for name, v in self.values.items()
        }

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self.values:
            held = ", ".join(self.names) or "none"
            raise KeyError(f"no reference {name!r} holds for this scene (these do: {held})")
        return self.values[name]

    def __contains__(self, name: object) -> bool:
        return name in self.values

    def __iter__(self):
        return iter(self.names)

    def __len__(self) -> int:
        return len(self.names)

    def __repr__(self) -> str:
        return f"References({', '.join(self.names)} at {len(self.times)} times)"

    def to_xarray(self):
        """The references as an xarray Dataset over ``t``, each with its ``of``, ``source``,
        ``kind`` and ``not_computable`` as attributes (needs xarray)."""
        xr = _xr.module()
        data = {
            n: (
                "t",
                self.values[n],
                {
                    "of": self.of[n],
                    "source": self.source[n],
                    "kind": self.kind[n],
                    "not_computable": self.not_computable[n],
                },
            )
            for n in self.names
        }
        return xr.Dataset(data, coords={"t": self.times})

    def to_pandas(self):
        """The references as a DataFrame indexed by time (needs pandas)."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("to_pandas() needs pandas: pip install pandas") from e
        return pd.DataFrame(self.values, index=pd.Index(self.times, name="t"))


def references(
    scene: Union[Scene, str, os.PathLike],
    times: Optional[Sequence[float]] = None,
    *,
    n: Optional[int] = None,
) -> References:
    """The references of ``scene`` (a :class:`Scene` or a scene file's path) at ``times``
    (default: its observation times; finite, from 0 on, increasing), with ``n`` overriding
    ``particles.n`` as :func:`gdsmc.run`'s keyword does (the exact means at n depend on it).
    Nothing is run. Raises :class:`gdsmc.SceneError` for a bad scene or bad times."""
    if not isinstance(scene, Scene):
        scene = Scene.from_file(os.fspath(scene))
    t, curves = _gdsmc.references(scene, None if times is None else [float(x) for x in times], n)
    refs = References(t, curves)
    for name, k in refs.not_computable.items():
        if k:
            warnings.warn(
                f"{name} is not computable here at {k} of {len(refs.times)} times: its closed "
                "form leaves the range of double at these parameters (NaN there)",
                UserWarning,
                stacklevel=2,
            )
    return refs
