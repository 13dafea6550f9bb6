"""dissect: geometric dissection puzzles from Python.

Find few connected pieces that cut one lattice figure into others (squares,
``tri4`` right triangles, cubes), prove lower bounds, check solutions::

    import numpy as np
    import dissect

    a = dissect.Figure.from_array(np.ones((3, 4), bool))
    b = dissect.Figure.from_array(np.ones((2, 6), bool))
    d = dissect.solve([a, b], seed=1)
    d.piece_count, d.verify(), d.to_json()

The search runs in Rust with the GIL released; Ctrl-C stops it and returns
the best dissection found so far. ``dissect.ray`` runs many problems, or one
search's explorations, on a Ray cluster.
"""

from __future__ import annotations

import builtins
import json
import os
from typing import Any, Dict, List, Optional, Sequence, Union

from . import _dissect
from ._dissect import LATTICES, Figure
from ._errors import (
    DissectError,
    FigureError,
    InvalidSolution,
    NoDissectionFound,
    OptionError,
    ProblemError,
)

__all__ = [
    "Figure",
    "Dissection",
    "LowerBound",
    "solve",
    "bound",
    "enumerate",
    "Enumeration",
    "verify",
    "read_figure",
    "LATTICES",
    "OPTIONS",
    "DissectError",
    "FigureError",
    "ProblemError",
    "OptionError",
    "InvalidSolution",
    "NoDissectionFound",
]

#: The solver options ``solve`` takes as keywords (the CLI's flags, with
#: ``_`` for ``-``): mirror, max_pieces, area_weight, explorations, keep,
#: iterations, split_penalty, split_tries, full_level, extra_rounds, patience.
OPTIONS = tuple(_dissect.option_names())


def read_figure(path: Union[str, os.PathLike], lattice: str = "square") -> Figure:
    """A figure from a text file (FORMAT.md); its name is the file's name."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    return Figure.from_text(text, lattice=lattice, name=os.path.basename(os.fspath(path)))


class Dissection:
    """A dissection of figures into pieces, as ``solve`` returns it.

    ``pieces[f][i]`` lists the cells of piece ``i`` in figure ``f`` (tuples,
    in the figure's own coordinates); piece ``i`` is the same piece in every
    figure.
    """

    def __init__(self, figures: Sequence[Figure], result: Dict[str, Any]):
        self.figures: List[Figure] = list(figures)
        self.lattice: str = result["lattice"]
        self.mirror: bool = result["mirror"]
        self.names: List[str] = list(result["names"])
        self.pieces: List[List[List[tuple]]] = result["pieces"]
        #: A proved lower bound on the piece count, and why it holds.
        self.lower_bound: Optional[int] = result.get("lower_bound")
        self.lower_bound_reason: Optional[str] = result.get("lower_bound_reason")
        #: Whether the piece count is proved minimal (equals the lower bound).
        self.optimal: bool = bool(result.get("optimal", False))
        #: Every improvement: dicts of pieces, seconds and by (who found it).
        self.history: List[Dict[str, Any]] = list(result.get("history", []))
        self.seed: Optional[int] = result.get("seed")
        self.seconds: Optional[float] = result.get("seconds")
        #: Whether a time limit or Ctrl-C ended the search early.
        self.stopped: bool = bool(result.get("stopped", False))
        #: Whether Ctrl-C (KeyboardInterrupt) ended the search.
        self.interrupted: bool = bool(result.get("interrupted", False))
        #: Who found it: greedy, search, repair or sat.
        self.found_by: Optional[str] = result.get("found_by")
        #: Why the run ended: optimal, finished, time_limit or interrupted.
        self.end: Optional[str] = result.get("end")
        self._extra = {
            k: result[k]
            for k in ("area_variance", "level", "explorations", "found_by")
            if result.get(k) is not None
        }
        # The engine's solution file text (what `dissect solve -o` writes).
        self._json: Optional[str] = result.get("solution_json")

    @property
    def piece_count(self) -> int:
        """The number of pieces."""
        return len(self.pieces[0]) if self.pieces else 0

    @property
    def areas(self) -> List[int]:
        """The area (cell count) of every piece."""
        return [len(p) for p in self.pieces[0]] if self.pieces else []

    def to_dict(self) -> Dict[str, Any]:
        """The solution as FORMAT.md's JSON object (a dict)."""
        return json.loads(self.to_json())

    def to_json(self, path: Union[str, os.PathLike, None] = None) -> str:
        """The solution in FORMAT.md form (``dissection-solution/1``), with
        ``pieces``, ``areas``, ``seed``, ``lower_bound`` and ``optimal`` keys
        as ``dissect solve`` writes them. Also written to ``path`` if given."""
        if self._json is not None:
            text = self._json
        else:
            text = self._build_json()
        if path is not None:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        return text

    def _build_json(self) -> str:
        extra: Dict[str, Any] = {"pieces": self.piece_count, "areas": self.areas}
        if "area_variance" in self._extra:
            extra["area_variance"] = self._extra["area_variance"]
        if self.seed is not None:
            extra["seed"] = self.seed
        if self.seconds is not None:
            extra["seconds"] = round(self.seconds, 3)
        for k in ("level", "explorations", "found_by"):
            if k in self._extra:
                extra[k] = self._extra[k]
        extra["stopped_early"] = self.stopped
        if self.lower_bound is not None:
            extra["lower_bound"] = self.lower_bound
            extra["lower_bound_reason"] = self.lower_bound_reason
            extra["optimal"] = self.optimal
        text = _dissect.solution_json(
            self.lattice,
            self.mirror,
            self.names,
            [[list(map(list, p)) for p in fig] for fig in self.pieces],
            json.dumps(extra),
        )
        return text

    def verify(self) -> bool:
        """Checks the dissection against its figures with the independent
        verifier; True, or raises ``InvalidSolution`` naming the problem."""
        verify(self.figures, self)
        return True

    def plot(self, ax=None, **kwargs):
        """Draws the figures side by side, pieces coloured alike in every
        figure (matplotlib; ``pip install matplotlib``). Returns the axes.
        ``cubic`` figures are drawn layer by layer."""
        from ._plot import plot

        return plot(self, ax=ax, **kwargs)

    def to_svg(self) -> str:
        """An SVG picture of the pieces (no dependency)."""
        from ._plot import svg

        return svg(self)

    def _repr_svg_(self) -> str:
        return self.to_svg()

    def __repr__(self) -> str:
        opt = ", optimal" if self.optimal else ""
        return f"<Dissection {self.lattice}: {len(self.names)} figures, {self.piece_count} pieces{opt}>"

    def __getstate__(self):
        return self.__dict__

    def __setstate__(self, state):
        self.__dict__.update(state)


class LowerBound:
    """A proved lower bound on the number of pieces, as ``bound`` returns it."""

    def __init__(self, figures: Sequence[Figure], result: Dict[str, Any]):
        #: No dissection has fewer pieces than this.
        self.value: int = result["value"]
        #: Why (components, incompatible cells, or a SAT proof).
        self.reason: str = result["reason"]
        #: Whether a time limit or Ctrl-C ended the search before it was done.
        self.stopped: bool = result["stopped"]
        #: A dissection with ``value`` pieces found by the SAT search (then
        #: the bound is optimal), or None.
        self.dissection: Optional[Dissection] = None
        if result.get("pieces") is not None:
            self.dissection = Dissection(
                figures, dict(result, lower_bound=result["value"], optimal=True, found_by="sat")
            )

    def __int__(self) -> int:
        return self.value

    def __repr__(self) -> str:
        return f"<LowerBound {self.value} ({self.reason})>"


def _figures(figures) -> List[Figure]:
    if isinstance(figures, (Figure, str, bytes)):
        raise ProblemError("figures must be a list of at least two dissect.Figure")
    figures = list(figures)
    for i, f in builtins.enumerate(figures):
        if not isinstance(f, Figure):
            raise ProblemError(
                f"figure {i + 1} is a {type(f).__name__}, not a dissect.Figure "
                "(use Figure.from_text, Figure.from_array or read_figure)"
            )
    return figures


def solve(
    figures: Sequence[Figure],
    seed: int = 1,
    time_limit: Optional[float] = None,
    threads: int = 0,
    **options: Any,
) -> Dissection:
    """Finds a dissection of ``figures`` into as few connected pieces as it
    can: the same search, options and results as ``dissect solve`` for the
    same seed (whatever ``threads`` is).

    ``time_limit`` (seconds) and Ctrl-C stop the search and return the best
    dissection found so far (``.stopped`` / ``.interrupted`` say so). The
    options are the CLI's flags: see ``dissect.OPTIONS``. Raises
    ``NoDissectionFound`` when the search ends without one, ``ProblemError``
    for figures that cannot be dissected together, ``OptionError`` for a bad
    option.
    """
    figures = _figures(figures)
    result = _dissect.solve(figures, seed=seed, time_limit=time_limit, threads=threads, **options)
    return Dissection(figures, result)


def bound(
    figures: Sequence[Figure],
    time_limit: Optional[float] = None,
    max_pieces: Optional[int] = None,
    mirror: bool = True,
) -> LowerBound:
    """Proves a lower bound on the number of pieces (``dissect bound``):
    components, incompatible cells, then SAT for 1, 2, ... pieces until a
    dissection is met, ``max_pieces``, ``time_limit`` or Ctrl-C."""
    figures = _figures(figures)
    result = _dissect.bound(figures, time_limit=time_limit, max_pieces=max_pieces, mirror=mirror)
    return LowerBound(figures, result)


def verify(figures: Sequence[Figure], solution) -> int:
    """Checks ``solution`` (a ``Dissection``, a FORMAT.md dict, JSON text, or
    the path of a solution file) against ``figures`` with the independent
    verifier. Returns the piece count; raises ``InvalidSolution`` listing
    every violation."""
    figures = list(figures)
    if isinstance(solution, Dissection):
        text = solution.to_json()
    elif isinstance(solution, dict):
        text = json.dumps(solution)
    elif isinstance(solution, os.PathLike) or (
        isinstance(solution, str) and not solution.lstrip().startswith("{")
    ):
        with open(solution, encoding="utf-8") as f:
            text = f.read()
    elif isinstance(solution, str):
        text = solution
    else:
        raise InvalidSolution(
            f"a solution is a Dissection, a dict, JSON text or a path, not {type(solution).__name__}"
        )
    return _dissect.verify(figures, text)


# ``dissect.enumerate`` (the builtin stays ``builtins.enumerate`` in here).
from ._enumerate import Enumeration, enumerate_dissections as enumerate  # noqa: E402,A001
