"""Results as xarray Datasets (``to_xarray``): what other tools read, NetCDF through xarray."""

from __future__ import annotations

import numpy as np


def module():
    """The xarray module (needs xarray: ``pip install xarray``, or the ``xarray`` extra)."""
    try:
        import xarray as xr
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("to_xarray() needs xarray: pip install xarray") from e
    return xr


def result(r):
    """A run (``Result``) over ``t``: means, their half-widths, the references with sources."""
    xr = module()
    data = {}
    for c in r.columns:
        data[c] = ("t", r.mean[c], {"ci": f"{c}_ci", "level": "99.9% (3.2 sigma)"})
        data[f"{c}_ci"] = ("t", r.ci[c], {"half_width_of": c})
    sources = {}
    for c in r.columns:
        sources.update(r.references_of(c))
    for name, v in r.references.items():
        data[name] = ("t", v, {"source": sources.get(name, "")})
    attrs = {
        k: r.summary[k]
        for k in ("n", "ensembles", "seed", "stream_version", "gdsmc_version")
        if k in r.summary
    }
    attrs["scene"] = str(r.summary.get("scene", ""))
    return xr.Dataset(data, coords={"t": r.times}, attrs=attrs)


def swept(s):
    """A sweep (``Swept``) over ``point``, the varied keys its coordinates."""
    xr = module()
    point = np.arange(len(s.table.get("point", [])))
    coords = {"point": point}
    coords.update({k: ("point", s.table[k]) for k in s.keys if k in s.table})
    data = {c: ("point", v) for c, v in s.table.items() if c not in coords}
    return xr.Dataset(data, coords=coords, attrs={"scene": str(s.json.get("scene", ""))})
