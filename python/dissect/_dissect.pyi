"""Type stubs of ``dissect._dissect``, the Rust half of ``dissect``
(python/src). ``dissect`` wraps most of it; ``Figure`` is used as is."""

from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, final

import numpy.typing as npt

#: The lattice names the core knows.
LATTICES: List[str]
#: The piece colours ``#rrggbb`` (``dissect_core::palette``).
PALETTE: List[str]
#: The ranking criteria of several solutions.
RANKS: List[str]

@final
class Figure:
    """A figure: a non-empty set of cells on one lattice."""

    @staticmethod
    def from_text(text: str, lattice: str = "square", name: Optional[str] = None) -> Figure: ...
    @staticmethod
    def from_cells(
        cells: Sequence[Sequence[int]], lattice: str = "square", name: Optional[str] = None
    ) -> Figure: ...
    @staticmethod
    def from_array(
        array: npt.ArrayLike, lattice: Optional[str] = None, name: Optional[str] = None
    ) -> Figure: ...
    @property
    def lattice(self) -> str: ...
    @property
    def name(self) -> Optional[str]: ...
    @property
    def cells(self) -> List[Tuple[int, ...]]: ...
    @property
    def area(self) -> int: ...
    @property
    def components(self) -> int: ...
    def with_name(self, name: Optional[str]) -> Figure: ...
    def to_text(self) -> str: ...
    def __len__(self) -> int: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, ...]: ...

@final
class Explorer:
    """Runs single explorations of one problem (the worker half of
    ``dissect.ray.solve``)."""

    def __init__(self, figures: Sequence[Figure], seed: int = 1, **options: Any) -> None: ...
    def explore(
        self,
        round: int,
        level: int,
        descent: bool,
        indices: Sequence[int],
        parents: Sequence[bytes],
    ) -> List[bytes]: ...

#: Pieces as Python holds them: ``pieces[f][i]`` the cells of piece ``i`` in
#: figure ``f``, each cell a coordinate list.
_Pieces = Sequence[Sequence[Sequence[Sequence[int]]]]

def solve(
    figures: Sequence[Figure],
    seed: int = 1,
    time_limit: Optional[float] = None,
    threads: int = 0,
    executor: Optional[
        Callable[[int, int, bool, int, int, List[bytes]], List[bytes]]
    ] = None,
    progress: Optional[Callable[[int, float, str], object]] = None,
    **options: Any,
) -> Dict[str, Any]: ...
def bound(
    figures: Sequence[Figure],
    time_limit: Optional[float] = None,
    max_pieces: Optional[int] = None,
    mirror: bool = True,
    solver: Optional[str] = None,
    certificate: Optional[str] = None,
) -> Dict[str, Any]: ...
def verify(figures: Sequence[Figure], solution: str) -> int: ...
def check_proof(
    dir: str, progress: Optional[Callable[[str], object]] = None
) -> Dict[str, Any]: ...
def solution_json(
    lattice: str, mirror: bool, names: Sequence[str], pieces: _Pieces, extra: str = "{}"
) -> str: ...
def option_names() -> List[str]: ...
def assemblies(
    figures: Sequence[Figure],
    lattice: str,
    mirror: bool,
    names: Sequence[str],
    pieces: _Pieces,
    time_limit: Optional[float] = None,
) -> List[Dict[str, Any]]: ...
def disassemble(
    figures: Sequence[Figure],
    lattice: str,
    mirror: bool,
    names: Sequence[str],
    pieces: _Pieces,
    time_limit: Optional[float] = None,
) -> Tuple[str, List[str]]: ...
def enumerate(
    figures: Sequence[Figure],
    pieces: Optional[int] = None,
    time_limit: Optional[float] = None,
    mirror: bool = True,
    unique: bool = False,
    rank: Optional[str] = None,
) -> Dict[str, Any]: ...
def piece_colour(i: int) -> str: ...
def render_svg(lattice: str, mirror: bool, names: Sequence[str], pieces: _Pieces) -> str: ...
def render_html(lattice: str, mirror: bool, names: Sequence[str], pieces: _Pieces) -> str: ...
def drawing(lattice: str, pieces: _Pieces) -> List[List[Dict[str, Any]]]: ...
