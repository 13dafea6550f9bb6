"""``dissect.enumerate``: every dissection with the fewest pieces (or with
``pieces``), counted and proved complete, as ``dissect enumerate`` does."""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Sequence, Tuple

from . import _dissect


class Enumeration:
    """Every dissection with ``pieces`` pieces, as ``enumerate`` returns it.

    Two dissections are the same when they cut the first figure into the
    same pieces; ``classes`` groups them up to the first figure's symmetries
    (rotations, and reflections when ``mirror``), one ``Dissection`` per
    class (its first one found), ranked when ``rank`` was given."""

    def __init__(self, figures: Sequence[Any], result: Dict[str, Any]):
        from . import Dissection

        #: K, the piece count counted.
        self.pieces: int = result["pieces"]
        #: Whether K is the proved minimum.
        self.minimum: bool = result["minimum"]
        #: The lower bound proved.
        self.lower_bound: int = result["lower_bound"]
        #: Whether the list is complete (False when stopped early).
        self.complete: bool = result["complete"]
        #: Whether a time limit or Ctrl-C ended it early.
        self.stopped: bool = result["stopped"]
        #: Whether Ctrl-C (KeyboardInterrupt) ended it.
        self.interrupted: bool = result["interrupted"]
        self.seconds: float = result["seconds"]
        #: Every dissection's pieces (``[f][i]`` lists of cells), in the order found.
        self.dissections: List[List[List[Tuple[int, ...]]]] = result["dissections"]
        #: The size of each class, in the order of ``classes``.
        self.class_sizes: List[int] = [c["size"] for c in result["classes"]]
        #: One verified dissection per class.
        self.classes: List[Dissection] = [
            Dissection(
                figures,
                {
                    "lattice": result["lattice"],
                    "mirror": result["mirror"],
                    "names": result["names"],
                    "pieces": c["pieces"],
                    "solution_json": c["solution_json"],
                    "lower_bound": result["lower_bound"],
                    "optimal": result["minimum"],
                    "found_by": "sat",
                },
            )
            for c in result["classes"]
        ]

    @property
    def count(self) -> int:
        """N, the number of dissections found."""
        return len(self.dissections)

    def __len__(self) -> int:
        return self.count

    def summary(self) -> str:
        """The last line ``dissect enumerate`` prints."""
        head = "" if self.complete else "at least "
        s = "" if self.count == 1 else "s"
        tail = "complete" if self.complete else "stopped"
        return (
            f"{head}{self.count} dissection{s} with {self.pieces} pieces "
            f"({len(self.classes)} up to the first figure's symmetries), {tail}"
        )

    def __repr__(self) -> str:
        return f"<Enumeration {self.summary()}>"


def enumerate_dissections(
    figures: Sequence[Any],
    pieces: Optional[int] = None,
    time_limit: Optional[float] = None,
    mirror: bool = True,
    unique: bool = False,
    rank: Optional[str] = None,
) -> Enumeration:
    """Counts every dissection of ``figures`` with ``pieces`` pieces (the
    minimum, proved first, when None), as ``dissect enumerate``: each one
    verified, grouped into classes up to the first figure's symmetries.
    ``time_limit`` (seconds) and Ctrl-C stop it with what was found
    (``.complete`` is then False). ``unique`` keeps only dissections whose
    pieces tile every figure in one way up to its symmetries; ``rank``
    (variance, smallest, shapes, symmetry, unique) orders the classes."""
    from . import _figures

    figures = _figures(figures)
    result = _dissect.enumerate(
        figures, pieces=pieces, time_limit=time_limit, mirror=mirror, unique=unique, rank=rank
    )
    return Enumeration(figures, result)
