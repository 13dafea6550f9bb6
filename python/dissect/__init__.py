"""dissect: geometric dissection puzzles from Python.

Find few connected pieces that cut one lattice figure into others (squares,
``tri4`` right triangles, cubes, ``tri3`` triangles, hexagons), prove lower
bounds, check solutions, count assemblies and draw them::

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
from typing import (
    Any,
    Callable,
    Dict,
    List,
    Mapping,
    NamedTuple,
    Optional,
    Sequence,
    Tuple,
    Union,
)

from . import _dissect
from ._dissect import LATTICES, Figure
from ._errors import (
    DissectError,
    FigureError,
    InvalidSolution,
    NoDissectionFound,
    CertificateError,
    OptionError,
    ProblemError,
)

__all__ = [
    "Figure",
    "Dissection",
    "Assemblies",
    "Disassembly",
    "FigurePlan",
    "Move",
    "LowerBound",
    "solve",
    "bound",
    "enumerate",
    "Enumeration",
    "verify",
    "read_figure",
    "piece_colour",
    "LATTICES",
    "OPTIONS",
    "PALETTE",
    "RANKS",
    "DissectError",
    "FigureError",
    "ProblemError",
    "OptionError",
    "InvalidSolution",
    "NoDissectionFound",
    "CertificateError",
    "check_proof",
    "ProofCheck",
]

#: The piece colours (``#rrggbb``): piece ``i`` is ``PALETTE[i]`` in every
#: picture (terminal, SVG, PNG, the studio, the page, ``plot``); from
#: ``dissect_core::palette``, the one palette.
PALETTE: Tuple[str, ...] = tuple(_dissect.PALETTE)
#: How ``solve(..., solutions=N)`` ranks the dissections it found
#: (``dissect solve --rank``; the engine's criteria).
RANKS: Tuple[str, ...] = tuple(_dissect.RANKS)

#: The options ``solve`` takes as keywords besides seed, time_limit and
#: threads (the CLI's flags, with ``_`` for ``-``).
OPTIONS: Tuple[str, ...] = tuple(_dissect.option_names())

#: A cell: ``(x, y)`` on square, tri3 and hex, ``(x, y, t)`` on tri4,
#: ``(x, y, z)`` on cubic.
Cell = Tuple[int, ...]
#: Cells of a figure kept in one piece: a regions grid (the text of
#: ``dissect solve --keep N:REGIONS.txt``), a list of cell groups, or a dict
#: of letter to cells.
Regions = Union[str, Sequence[Sequence[Sequence[int]]], Mapping[str, Sequence[Sequence[int]]]]
#: ``progress(pieces, seconds, source)``, called for every improvement.
Progress = Callable[[int, float, str], object]


def read_figure(path: Union[str, "os.PathLike[str]"], lattice: str = "square") -> Figure:
    """A figure from a text file (FORMAT.md); its name is the file's name."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    return Figure.from_text(text, lattice=lattice, name=os.path.basename(os.fspath(path)))


def piece_colour(i: int) -> str:
    """The colour (``#rrggbb``) of piece ``i`` in every picture:
    ``PALETTE[i]``, and past the palette the engine's further hues."""
    return _dissect.piece_colour(i)


class Assemblies(NamedTuple):
    """In how many ways the pieces of a dissection tile one figure."""

    #: The figure's name.
    figure: str
    #: Distinct tilings (all of them when ``complete``).
    tilings: int
    #: Tilings up to the figure's symmetries.
    up_to_symmetry: int
    #: The figure's symmetries (allowed motions mapping it onto itself).
    figure_symmetries: int
    #: Whether the count finished (else the numbers are lower bounds).
    complete: bool
    #: Seconds the count took.
    seconds: float

    @property
    def unique(self) -> bool:
        """Whether the figure has exactly one tiling up to its symmetries."""
        return self.complete and self.up_to_symmetry == 1


class Move(NamedTuple):
    """One move of a disassembly plan: ``pieces`` (indices of the
    dissection) go together by ``by`` (lattice steps along one axis);
    ``removed``: the group goes away to infinity that way and is a part of
    its own from then on."""

    pieces: List[int]
    by: Tuple[int, int, int]
    removed: bool


def _move(m: Dict[str, Any]) -> Move:
    dx, dy, dz = (int(v) for v in m["by"])
    return Move([int(i) for i in m["pieces"]], (dx, dy, dz), bool(m["removed"]))


class FigurePlan(NamedTuple):
    """How one figure comes apart (``level`` and ``moves``), or why not:
    ``locked`` (the pieces that hold together) or ``stopped`` (not decided
    within the time limit or before Ctrl-C)."""

    #: The figure's name.
    name: str
    #: How many moves until the first piece (or group) comes free; None
    #: when the figure does not come apart (or was not decided).
    level: Optional[int]
    #: The moves, in order (empty when there is no plan).
    moves: List[Move]
    #: The pieces that hold together when the figure cannot be taken apart.
    locked: Optional[List[int]]
    #: Whether the search ended before deciding.
    stopped: bool
    #: The line ``dissect disassemble`` prints for this figure.
    line: str

    @property
    def apart(self) -> bool:
        """Whether the figure comes apart (it has a plan)."""
        return self.level is not None


class Disassembly:
    """The disassembly plans of a dissection's figures (``Dissection.
    disassemble``): the plan file ``dissection-disassembly/1`` of ``dissect
    disassemble -o``, one ``FigurePlan`` per figure in the solution's
    order."""

    def __init__(self, text: str, lines: Sequence[str]):
        self._text = text
        data: Dict[str, Any] = json.loads(text)
        self.lattice: str = data["lattice"]
        self.figures: List[FigurePlan] = [
            FigurePlan(
                name=f["name"],
                level=f.get("level"),
                moves=[_move(m) for m in f["moves"]],
                locked=f.get("locked"),
                stopped=bool(f.get("stopped", False)),
                line=line,
            )
            for f, line in zip(data["figures"], lines)
        ]

    @property
    def apart(self) -> bool:
        """Whether every figure comes apart (``dissect disassemble`` exits 0)."""
        return all(f.apart for f in self.figures)

    @property
    def levels(self) -> List[Optional[int]]:
        """Every figure's level (None where it has no plan)."""
        return [f.level for f in self.figures]

    @property
    def lines(self) -> List[str]:
        """The lines ``dissect disassemble`` prints, one per figure."""
        return [f.line for f in self.figures]

    def to_dict(self) -> Dict[str, Any]:
        """The plan file as a dict."""
        value: Dict[str, Any] = json.loads(self._text)
        return value

    def to_json(self, path: Union[str, "os.PathLike[str]", None] = None) -> str:
        """The plan file's text (``dissection-disassembly/1``, as ``dissect
        disassemble -o`` writes it); also written to ``path`` if given."""
        if path is not None:
            _write(path, self._text)
        return self._text

    def __repr__(self) -> str:
        return f"<Disassembly {self.lattice}: levels {self.levels}>"


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
        self.pieces: List[List[List[Cell]]] = result["pieces"]
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
        #: Who found it: greedy, search, repair, sat, coarse or sectors.
        self.found_by: Optional[str] = result.get("found_by")
        #: Why the run ended: optimal, finished, time_limit or interrupted.
        self.end: Optional[str] = result.get("end")
        #: The engine's scores (pieces, variance, smallest, shapes,
        #: symmetry, objective, assemblies: the ``rank`` criteria).
        self.scores: Dict[str, Any] = dict(result.get("scores") or {})
        #: ``dissect.ray.solve``: Ray tasks per batch, and every batch sent
        #: to Ray (``dissect.ray.RayBatch``); None for a local run.
        self.ray_tasks: Optional[int] = None
        self.ray_batches: Optional[List[Any]] = None
        #: The ranking criterion of ``solutions``.
        self.rank: str = result.get("rank") or "variance"
        self._extra = {
            k: result[k]
            for k in ("area_variance", "level", "explorations", "found_by")
            if result.get(k) is not None
        }
        # The engine's solution file text (what `dissect solve -o` writes).
        self._json: Optional[str] = result.get("solution_json")
        #: The different dissections found with the fewest pieces, best
        #: first by ``rank`` (``solve(..., solutions=N)``: at most N); this
        #: one is the first.
        self.solutions: List[Dissection] = [self]
        for other in list(result.get("solutions") or [])[1:]:
            self.solutions.append(Dissection(figures, _other_solution(result, other)))

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
        value: Dict[str, Any] = json.loads(self.to_json())
        return value

    def to_json(self, path: Union[str, "os.PathLike[str]", None] = None) -> str:
        """The solution in FORMAT.md form (``dissection-solution/1``), with
        ``pieces``, ``areas``, ``seed``, ``lower_bound``, ``optimal`` (and
        with several solutions ``scores`` and ``rank``) keys as ``dissect
        solve`` writes them. Also written to ``path`` if given."""
        text = self._json if self._json is not None else self._build_json()
        if path is not None:
            _write(path, text)
        return text

    def _parts(self) -> Tuple[str, bool, List[str], List[List[List[List[int]]]]]:
        pieces = [[[list(c) for c in p] for p in fig] for fig in self.pieces]
        return self.lattice, self.mirror, self.names, pieces

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
        return _dissect.solution_json(*self._parts(), json.dumps(extra))

    def verify(self) -> bool:
        """Checks the dissection against its figures with the independent
        verifier; True, or raises ``InvalidSolution`` naming the problem."""
        verify(self.figures, self)
        return True

    def assemblies(self, time_limit: Optional[float] = None) -> List[Assemblies]:
        """In how many ways the pieces tile each figure (the engine's count,
        as ``dissect assemblies``): every placement the lattice allows,
        mirror images as the dissection allows them, identical pieces
        interchangeable; one ``Assemblies`` per figure. ``time_limit``
        (seconds) bounds each figure's count; Ctrl-C stops it too (then
        ``complete`` is False and the numbers are lower bounds)."""
        rows = _dissect.assemblies(self.figures, *self._parts(), time_limit=time_limit)
        return [Assemblies(**row) for row in rows]

    def disassemble(self, time_limit: Optional[float] = None) -> Disassembly:
        """A plan of straight moves that takes each figure apart, the
        lowest level there is (the search of ``dissect disassemble``): moves
        of one piece or a group, removals to infinity; a figure that cannot
        be taken apart names its locked pieces. Flat lattices: every piece
        lifts off (level 1). ``time_limit`` (seconds) bounds all figures
        together; Ctrl-C stops it too (undecided figures are ``stopped``)."""
        text, lines = _dissect.disassemble(self.figures, *self._parts(), time_limit=time_limit)
        return Disassembly(text, lines)

    def plot(self, ax: Any = None, **kwargs: Any) -> Any:
        """Draws the figures side by side with matplotlib (``pip install
        matplotlib``), pieces in the colours of every other picture
        (``PALETTE``), cells and outlines from the engine's lattice
        geometry; ``cubic`` figures layer by layer. Returns the axes."""
        from ._plot import plot

        return plot(self, ax=ax, **kwargs)

    def to_svg(self) -> str:
        """The SVG picture ``dissect render`` draws (pieces, labels, legend)."""
        return _dissect.render_svg(*self._parts())

    def to_html(self, path: Union[str, "os.PathLike[str]", None] = None) -> str:
        """The page to share (``dissect render --html``): one self-contained
        HTML file showing the pieces move from one figure to another. Also
        written to ``path`` if given."""
        text = _dissect.render_html(*self._parts())
        if path is not None:
            _write(path, text)
        return text

    def _repr_svg_(self) -> str:
        return self.to_svg()

    def __repr__(self) -> str:
        opt = ", optimal" if self.optimal else ""
        return f"<Dissection {self.lattice}: {len(self.names)} figures, {self.piece_count} pieces{opt}>"

    def __getstate__(self) -> Dict[str, Any]:
        return self.__dict__

    def __setstate__(self, state: Dict[str, Any]) -> None:
        self.__dict__.update(state)


def _other_solution(result: Dict[str, Any], other: Dict[str, Any]) -> Dict[str, Any]:
    """The result of solution 2, 3, ... of a run: the run's own keys, the
    solution's pieces, scores and file."""
    out = dict(result, solutions=[], history=[], level=None, explorations=None)
    out.update(other)
    return out


def _write(path: Union[str, "os.PathLike[str]"], text: str) -> None:
    """Writes ``text`` to ``path`` atomically (a temporary file renamed)."""
    tmp = f"{os.fspath(path)}.tmp{os.getpid()}"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


class LowerBound:
    """A proved lower bound on the number of pieces, as ``bound`` returns it."""

    def __init__(self, figures: Sequence[Figure], result: Dict[str, Any]):
        #: No dissection has fewer pieces than this.
        self.value: int = result["value"]
        #: Why (components, incompatible cells, or a SAT proof).
        self.reason: str = result["reason"]
        #: Whether a time limit or Ctrl-C ended the search before it was done.
        self.stopped: bool = result["stopped"]
        #: With ``certificate``: the piece counts refuted, each with its
        #: formula and proof in that folder (``check_proof`` replays them);
        #: empty otherwise.
        self.certificates: List[int] = list(result.get("certificates", []))
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


def _figures(figures: Any) -> List[Figure]:
    if isinstance(figures, (Figure, str, bytes)):
        raise ProblemError("figures must be a list of at least two dissect.Figure")
    out: List[Figure] = []
    for i, f in builtins.enumerate(figures):
        if not isinstance(f, Figure):
            raise ProblemError(
                f"figure {i + 1} is a {type(f).__name__}, not a dissect.Figure "
                "(use Figure.from_text, Figure.from_array or read_figure)"
            )
        out.append(f)
    return out


def solve(
    figures: Sequence[Figure],
    *,
    seed: int = 1,
    time_limit: Optional[float] = None,
    threads: int = 0,
    solutions: int = 1,
    rank: str = "variance",
    min_piece: Optional[int] = None,
    max_piece: Optional[int] = None,
    checkerboard: bool = False,
    symmetry_weight: Optional[float] = None,
    keep: Union[int, Mapping[int, Regions], None] = None,
    assemblable: bool = False,
    min_level: Optional[int] = None,
    mirror: bool = True,
    prove: bool = True,
    exact: bool = False,
    paper: bool = False,
    max_pieces: Optional[int] = None,
    progress: Optional[Progress] = None,
    **options: Any,
) -> Dissection:
    """Finds a dissection of ``figures`` into as few connected pieces as it
    can: the run ``dissect solve`` makes, with its options under their
    Python names, and the same answer for the same seed (whatever
    ``threads`` is). Every option is checked by the engine's rules.

    * ``seed``, ``threads`` (0: one per core), ``time_limit`` (seconds; it
      and Ctrl-C return the best dissection found so far, ``.stopped`` /
      ``.interrupted`` say so), ``max_pieces``.
    * ``solutions=N``: up to N different dissections with the fewest
      pieces, ranked by ``rank`` (one of ``RANKS``); ``d.solutions`` lists
      them best first (``d`` is the first), each with its ``scores``.
    * The designer's constraints: ``min_piece`` / ``max_piece`` (cells per
      piece), ``checkerboard=True`` (every piece keeps its cells' colours;
      square and cubic), ``symmetry_weight`` (favour symmetric pieces) and
      ``keep={figure_index: regions}``: cells of figure ``figure_index``
      (0-based) that end in one piece, as a regions grid (letters a-z over
      the figure's text), a list of cell groups, or a dict of letter to
      cells. ``keep=NB`` (a number) is the candidates kept per level.
    * 3D puzzles that can be built: ``assemblable=True`` accepts only
      dissections whose every figure comes apart by straight moves, and
      ``min_level=L`` those whose every figure needs at least L moves
      before its first piece comes free (it interlocks); ``d.disassemble()``
      gives the plans. A figure that is a box (every line along an axis
      meets it in one run) always comes apart at level 1, so ``min_level``
      of 2 or more raises ``NoDissectionFound`` there at once.
    * ``mirror=False``: pieces are not turned over; ``prove=False``: no
      exact lower bound beside the search; ``exact=True``: SAT alone;
      ``paper=True``: the paper's schedule.
    * ``progress(pieces, seconds, source)`` is called with every
      improvement as the run finds it (e.g. to move a tqdm bar); an
      exception it raises stops the run and is raised.
    * The solver's tuning: see ``OPTIONS`` (``explorations=100``, ...).

    Raises ``NoDissectionFound`` when the search ends without one (or the
    constraints cannot hold), ``ProblemError`` for figures that cannot be
    dissected together, ``OptionError`` for a bad option.
    """
    figures = _figures(figures)
    given: Dict[str, Any] = dict(
        solutions=solutions,
        rank=rank,
        min_piece=min_piece,
        max_piece=max_piece,
        checkerboard=checkerboard,
        symmetry_weight=symmetry_weight,
        keep=keep,
        assemblable=assemblable,
        min_level=min_level,
        mirror=mirror,
        prove=prove,
        exact=exact,
        paper=paper,
        max_pieces=max_pieces,
    )
    options.update({k: v for k, v in given.items() if v is not None})
    result = _dissect.solve(
        figures, seed=seed, time_limit=time_limit, threads=threads, progress=progress, **options
    )
    return Dissection(figures, result)


def bound(
    figures: Sequence[Figure],
    time_limit: Optional[float] = None,
    max_pieces: Optional[int] = None,
    mirror: bool = True,
    solver: Optional[str] = None,
    certificate: Union[str, "os.PathLike[str]", None] = None,
) -> LowerBound:
    """Proves a lower bound on the number of pieces (``dissect bound``):
    components, incompatible cells, then SAT for 1, 2, ... pieces until a
    dissection is met, ``max_pieces``, ``time_limit`` or Ctrl-C.

    With ``certificate`` (a folder) every "no K-piece dissection" the SAT
    search proves is written there as ``kK.cnf`` (the formula) and
    ``kK.drat`` (its DRAT proof), with ``README.txt``
    (``dissect bound --certificate``), listed in
    ``LowerBound.certificates``; ``check_proof`` replays them. With
    ``solver`` (a command such as ``"cadical --no-binary"``, run as ``CMD
    kK.cnf kK.drat``) another SAT solver answers each K instead
    (``dissect bound --solver``), its refutations and proofs kept the same
    way."""
    figures = _figures(figures)
    result = _dissect.bound(
        figures,
        time_limit=time_limit,
        max_pieces=max_pieces,
        mirror=mirror,
        solver=solver,
        certificate=None if certificate is None else os.fspath(certificate),
    )
    return LowerBound(figures, result)


class ProofCheck:
    """What ``check_proof`` found: one entry per certificate of the folder.
    True when every certificate verified."""

    def __init__(self, result: Dict[str, Any]):
        #: Whether every certificate verified.
        self.verified: bool = result["verified"]
        #: The last line ``dissect check-proof`` prints: ``verified: 2
        #: certificates (k3, k4)`` or ``failed: 1 of 2 certificates do not
        #: verify``.
        self.verdict: str = result["verdict"]
        #: Per certificate, by K: ``k``, ``verified``, ``line`` (as
        #: ``check-proof`` prints it), and ``clauses``, ``cubes``, ``lemmas``,
        #: ``rat_lemmas``, ``deletions`` when verified, or ``failure`` (the
        #: file and line where the replay failed).
        self.certificates: List[Dict[str, Any]] = list(result["certificates"])

    def __bool__(self) -> bool:
        return self.verified

    def __repr__(self) -> str:
        return f"<ProofCheck {self.verdict}>"


def check_proof(
    dir: Union[str, "os.PathLike[str]"],
    progress: Optional[Callable[[str], object]] = None,
) -> ProofCheck:
    """Replays every certificate of ``dir`` (written by ``bound(...,
    certificate=dir)`` or ``dissect bound --certificate``) with the
    project's independent DRAT checker, as ``dissect check-proof`` does: a
    proof is read a line at a time (it may be a named pipe that a solver is
    writing). ``progress(line)`` is called as each certificate ends. A
    proof that does not refute its formula is reported in the result (not
    raised); a folder without certificates or a malformed file raises
    ``CertificateError``; Ctrl-C stops the check."""
    return ProofCheck(_dissect.check_proof(os.fspath(dir), progress=progress))


def verify(
    figures: Sequence[Figure],
    solution: Union[Dissection, Dict[str, Any], str, "os.PathLike[str]"],
) -> int:
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
