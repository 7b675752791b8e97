"""Progress bars of a run and a sweep: tqdm's when it is installed (one updating widget in
Jupyter), else a text bar on stderr; a sweep's bar learns its total once its points are
checked."""

import contextlib
import sys
from typing import Optional


class _TextBar:
    """A progress bar on stderr when tqdm is not installed."""

    def __init__(self, total: Optional[int]):
        self.total, self.n = total, 0

    def set_total(self, total: int) -> None:
        self.total = total

    def update(self, k: int) -> None:
        self.n += k
        if not self.total:
            sys.stderr.write(f"\r{self.n} ensembles")
            sys.stderr.flush()
            return
        width = 40
        full = int(width * self.n / max(self.total, 1))
        sys.stderr.write(f"\r[{'#' * full}{'.' * (width - full)}] {self.n}/{self.total} ensembles")
        sys.stderr.flush()

    def close(self) -> None:
        sys.stderr.write("\n")


def _bar(total: Optional[int]):
    try:
        from tqdm.auto import tqdm

        return tqdm(total=total, unit="ensembles")
    except ImportError:
        return _TextBar(total)


def _set_total(bar, total: int) -> None:
    """Sets a bar's total once it is known (a sweep's, after its points are checked)."""
    if isinstance(bar, _TextBar):
        bar.set_total(total)
    else:
        bar.total = total
        bar.refresh()


@contextlib.contextmanager
def _progress(progress, total: Optional[int]):
    """``(callback, set_total)`` for ``progress``: a callable as it is, ``True`` a bar over
    ``total`` ensembles (unknown: None, until ``set_total`` says) closed at the end, ``False``
    none."""
    if callable(progress):
        yield progress, None
    elif progress:
        bar = _bar(total)
        try:
            yield bar.update, (lambda t: _set_total(bar, t))
        finally:
            bar.close()
    else:
        yield None, None
