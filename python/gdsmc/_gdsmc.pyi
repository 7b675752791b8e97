"""Type hints of the Rust extension (gdsmc._gdsmc); the public API is gdsmc/__init__.py."""

from os import PathLike
from typing import Any, Callable, List, Optional, Tuple, Union

__version__: str
# The version of the random streams: a run is a pure function of (scene, seed, STREAM_VERSION).
STREAM_VERSION: int

class SceneError(ValueError):
    """A scene that cannot be read, parsed or validated (file, line and key named)."""

class RunError(RuntimeError):
    """A run that stopped (an engine error, a refused size, an unwritable output place)."""

class Scene:
    """A validated scene: a scene file's text and the overrides applied to it."""

    @staticmethod
    def from_file(path: Union[str, PathLike[str]]) -> Scene: ...
    @staticmethod
    def from_toml(text: str, name: str = "<string>") -> Scene: ...
    def set(self, key: str, value: Any) -> Scene:
        """A copy with ``key`` (dotted, e.g. "collisions.restitution") set to ``value`` (a
        number, bool, string or list; None removes the key), validated."""
    @property
    def name(self) -> str: ...
    @property
    def description(self) -> str: ...
    @property
    def n(self) -> int: ...
    @property
    def ensembles(self) -> int: ...
    @property
    def seed(self) -> int: ...
    @property
    def times(self) -> List[float]: ...
    @property
    def text(self) -> str: ...
    @property
    def overrides(self) -> List[str]: ...

class RunResult:
    """A run's statistics (wrapped by gdsmc.Result)."""

    @property
    def scene(self) -> Scene: ...
    @property
    def ensembles(self) -> int: ...
    @property
    def wall(self) -> float: ...
    @property
    def cpu(self) -> float: ...
    def tables(self) -> List[Tuple[str, str]]: ...
    def summary_text(self) -> str: ...
    def samples(self) -> Optional[Tuple[bytes, Tuple[int, int, int], List[str]]]: ...
    def snapshot_files(self) -> List[Tuple[float, str]]: ...
    def write(self, dir: Union[str, PathLike[str]], formats: str = "svg") -> List[str]: ...

def run(
    scene: Scene,
    n: Optional[int] = None,
    ensembles: Optional[int] = None,
    seed: Optional[int] = None,
    threads: int = 0,
    progress: Optional[Callable[[int], Any]] = None,
    allow_long: bool = False,
    samples: bool = False,
    initial_state: Optional[str] = None,
    save_state: Optional[str] = None,
) -> Tuple[RunResult, bool]: ...
def read_state(path: Union[str, PathLike[str]]) -> Tuple[str, bytes, Tuple[int, int]]: ...
def sweep(
    scene: Scene,
    vary: List[str],
    zip: bool = False,
    n: Optional[int] = None,
    ensembles: Optional[int] = None,
    seed: Optional[int] = None,
    threads: int = 0,
    progress: Optional[Callable[[int], Any]] = None,
    allow_long: bool = False,
    total: Optional[Callable[[int], Any]] = None,
) -> Tuple[str, str, int, bool]: ...
def references(
    scene: Scene, times: Optional[List[float]] = None, n: Optional[int] = None
) -> Tuple[List[float], List[Tuple[str, str, str, str, List[float]]]]: ...
def reproduce(
    names: List[str], quick: bool = True, threads: int = 0, seed: int = 1
) -> Tuple[str, List[str], List[str]]: ...
