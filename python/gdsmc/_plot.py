"""Charts of a run and of a sweep with matplotlib, drawn as the command draws them: the mean,
its 99.9% band or interval, and every reference of the observable (``Result.plot``,
``Swept.plot``)."""

import textwrap
from typing import Optional

import numpy as np


def _pyplot():
    """matplotlib's pyplot (needs matplotlib)."""
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(
            "plot() needs matplotlib: pip install matplotlib (or 'gdsmc[notebook]')"
        ) from e
    return plt


def _legend_below(ax):
    """The legend under the plotting area, each entry wrapped to 60 characters, as the
    command's charts put theirs in a band below the data: never over the data, and inside the
    figure once laid out (a reference's whole description once ran past the figure)."""
    handles, labels = ax.get_legend_handles_labels()
    labels = [textwrap.fill(label, 60) for label in labels]
    ax.legend(
        handles,
        labels,
        fontsize="small",
        loc="upper center",
        bbox_to_anchor=(0.5, -0.16),
        frameon=False,
    )
    ax.figure.tight_layout()


def _log_steps(x: np.ndarray) -> bool:
    """Whether abscissae call for a log axis, as the command's charts decide: their steps grow
    tenfold or more and they span two decades (``observe.spacing = "log"``)."""
    p = x[np.isfinite(x) & (x > 0)]
    return len(p) >= 4 and (p[-1] - p[-2]) > 10 * (p[1] - p[0]) and p[-1] / p[0] >= 100


def _log_values(*arrays: np.ndarray) -> bool:
    """Whether values call for a log axis: all positive over three decades or more."""
    v = np.concatenate([a[np.isfinite(a)] for a in arrays])
    return len(v) > 0 and v.min() > 0 and v.max() / v.min() >= 1e3


def result(r, name: str, ax=None, axis: str = "time"):
    """``Result.plot``: observable ``name`` of run ``r`` against time or collisions."""
    if name not in r.mean:
        raise KeyError(f"no observable {name!r}; the run has {', '.join(r.columns)}")
    if axis not in ("time", "collisions"):
        raise ValueError(f'axis must be "time" or "collisions", got {axis!r}')
    plt = _pyplot()
    if ax is None:
        _, ax = plt.subplots()
    x = r.mean["s"] if axis == "collisions" else r.times
    mean, ci = r.mean[name], r.ci[name]
    ax.plot(x, mean, color="C0", label=f"mean of {r.ensembles} ensembles")
    ax.fill_between(
        x, mean - ci, mean + ci, color="C0", alpha=0.25, linewidth=0, label="99.9% interval"
    )
    refs = r.references_of(name)
    for k, (ref, source) in enumerate(refs.items()):
        ax.plot(x, r.references[ref], "--", color=f"C{k + 1}", label=f"{ref} ({source})")
    if _log_steps(x):
        ax.set_xscale("log")
    if _log_values(mean, *(r.references[k] for k in refs)):
        ax.set_yscale("log")
    ax.set_xlabel(
        "collisions per particle s" if axis == "collisions" else "time t (scene units)"
    )
    ax.set_ylabel(name)
    _legend_below(ax)
    return ax


def swept(s, name: str, x: Optional[str] = None, ax=None):
    """``Swept.plot``: observable ``name`` of sweep ``s`` against the varied key ``x``."""
    if name not in s.mean:
        raise KeyError(f"no observable {name!r}; the sweep has {', '.join(s.columns)}")
    numeric = [k for k in s.keys if isinstance(s.table[k], np.ndarray)]
    if x is None:
        if not numeric:
            raise ValueError("no varied key is numeric: name one with x=")
        x = numeric[0]
    if x not in numeric:
        raise ValueError(f"x must be a numeric varied key ({', '.join(numeric)}), got {x!r}")
    plt = _pyplot()
    if ax is None:
        _, ax = plt.subplots()
    others = [k for k in s.keys if k != x]
    labels = [
        ", ".join(f"{k} = {s.table[k][i]}" for k in others)
        for i in range(len(s.table["point"]))
    ]
    groups = list(dict.fromkeys(labels))
    points = {p["point"]: p for p in s.json["points"]}
    cited = set()
    for g, group in enumerate(groups):
        rows = [i for i, lab in enumerate(labels) if lab == group]
        rows.sort(key=lambda i: s.table[x][i])
        xs = s.table[x][rows]
        suffix = f", {group}" if group else ""
        ax.errorbar(
            xs,
            s.mean[name][rows],
            yerr=s.ci[name][rows],
            fmt="o",
            color=f"C{g}",
            capsize=3,
            label=f"mean and 99.9% interval{suffix}",
        )
        refs = {}
        for i in rows:
            for ref, r in points[int(s.table["point"][i])]["references"].items():
                if r["of"] == name:
                    refs.setdefault(ref, r["source"])
        for k, (ref, source) in enumerate(refs.items()):
            words = ref if ref in cited else f"{ref} ({source})"
            cited.add(ref)
            ax.plot(
                xs,
                s.references[ref][rows],
                ["--", ":", "-."][k % 3],
                color=f"C{g}",
                label=f"{words}{suffix}",
            )
    ax.set_xlabel(x)
    ax.set_ylabel(name)
    _legend_below(ax)
    return ax
