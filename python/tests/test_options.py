"""Every option of `dissect solve` through `dissect.solve`, each answer
checked by `dissect.verify` and by the independent checkers; several
solutions; the progress callback."""

import time
from pathlib import Path
from typing import Any, Dict, List, Sequence, Tuple

import pytest

import dissect
from dissect import Figure

from conftest import check_independently, instance

RECT = Figure.from_text("###\n###\n", name="rect.txt")
BAR = Figure.from_text("######\n", name="bar.txt")
SQUARE3 = Figure.from_text("###\n###\n###\n", name="square3.txt")
BAR9 = Figure.from_text("#########\n", name="bar9.txt")
L = Figure.from_text("###\n#..\n", name="l.txt")
L_MOVED = Figure.from_text("##\n.#\n.#\n", name="l-turned.txt")


def piece_of(d: dissect.Dissection, figure: int, cell: Tuple[int, ...]) -> int:
    """The piece of `figure` that holds `cell`."""
    return next(i for i, p in enumerate(d.pieces[figure]) if tuple(cell) in p)


def test_keep_regions_as_text_and_as_cell_groups(tmp_path: Path) -> None:
    plain = dissect.solve([RECT, BAR], seed=1)
    assert plain.piece_count == 2
    keeps: List[Dict[int, dissect.Regions]] = [
        {0: "a..\na..\n"}, {0: [[(0, 0), (0, 1)]]}, {0: {"a": [(0, 0), (0, 1)]}}
    ]
    for k, keep in enumerate(keeps):
        d = dissect.solve([RECT, BAR], seed=1, keep=keep)
        # The left column in one piece: no 2-piece cut of bars does that.
        assert piece_of(d, 0, (0, 0)) == piece_of(d, 0, (0, 1))
        assert d.piece_count == 3
        check_independently(d, tmp_path / str(k))


def test_min_and_max_piece(tmp_path: Path) -> None:
    d = dissect.solve([SQUARE3, BAR9], seed=1, min_piece=2, max_piece=3)
    assert all(2 <= a <= 3 for a in d.areas), d.areas
    check_independently(d, tmp_path)


def test_checkerboard(tmp_path: Path) -> None:
    assert dissect.solve([L, L_MOVED], seed=1).piece_count == 1
    d = dissect.solve([L, L_MOVED], seed=1, checkerboard=True)
    assert d.piece_count == 2
    for i in range(d.piece_count):
        # A piece that keeps its cells' colours has as many black cells in
        # every figure.
        black = {sum((c[0] + c[1]) % 2 == 0 for c in fig[i]) for fig in d.pieces}
        assert len(black) == 1, d.pieces
    check_independently(d, tmp_path)


def test_several_solutions_ranked_each_with_scores(tmp_path: Path) -> None:
    figures, files = instance("squares-3-4-split-to-5", "square")
    d = dissect.solve(figures, seed=1, solutions=3, time_limit=20)
    assert 2 <= len(d.solutions) <= 3
    assert d.solutions[0] is d
    assert d.rank == "variance"
    counts = {s.piece_count for s in d.solutions}
    assert counts == {d.piece_count}
    variances = [s.scores["variance"] for s in d.solutions]
    assert variances == sorted(variances)
    assert len({str(s.pieces) for s in d.solutions}) == len(d.solutions)
    for k, s in enumerate(d.solutions):
        assert set(s.scores) >= {"pieces", "variance", "smallest", "shapes", "symmetry", "objective"}
        assert s.scores["pieces"] == s.piece_count
        sol = s.to_dict()
        assert sol["rank"] == {"by": "variance", "position": k + 1}
        check_independently(s, tmp_path / str(k))


def test_rank_smallest_and_symmetry_weight(tmp_path: Path) -> None:
    figures, _ = instance("squares-3-4-split-to-5", "square")
    d = dissect.solve(figures, seed=1, solutions=3, rank="smallest", time_limit=20)
    assert d.rank == "smallest"
    smallest = [s.scores["smallest"] for s in d.solutions]
    assert smallest == sorted(smallest, reverse=True)
    w = dissect.solve(figures, seed=1, solutions=3, symmetry_weight=1.0, time_limit=20)
    for s in w.solutions:
        sc = s.scores
        assert sc["objective"] == pytest.approx(sc["variance"] - sc["symmetry"])
    objectives = [s.scores["objective"] for s in w.solutions]
    assert objectives == sorted(objectives)
    for k, s in enumerate(d.solutions + w.solutions):
        check_independently(s, tmp_path / str(k))


def test_rank_unique_counts_assemblies(tmp_path: Path) -> None:
    d = dissect.solve([RECT, BAR], seed=1, solutions=2, rank="unique", time_limit=3)
    assert d.rank == "unique"
    assert all(s.scores["assemblies"] is not None for s in d.solutions)
    check_independently(d, tmp_path)


@pytest.mark.parametrize(
    "options",
    [
        {"mirror": False},
        {"prove": False},
        {"paper": True},
        {"exact": True},
        {"threads": 1, "seed": 3, "max_pieces": 4, "time_limit": 30.0},
        {"explorations": 40, "patience": 5, "keep": 10, "iterations": 50, "area_weight": 0.0,
         "split_penalty": 2.0, "split_tries": 2, "full_level": True, "extra_rounds": 1,
         "rounds": 1, "repair": False},
    ],
)
def test_run_options(options: Dict[str, Any], tmp_path: Path) -> None:
    figures, files = instance("squares-3-4-split-to-5", "square")
    d = dissect.solve(figures, **options)
    assert d.piece_count == 4
    if options.get("mirror") is False:
        assert d.mirror is False and d.to_dict()["mirror"] is False
    if options.get("exact"):
        assert d.found_by == "sat" and d.optimal
    if options.get("prove") is False:
        # No SAT bound: the lower bound is the components' and cells' one.
        assert "SAT" not in (d.lower_bound_reason or "")
    check_independently(d, tmp_path)


@pytest.mark.parametrize(
    "options, cls, words",
    [
        ({"solutions": 0}, dissect.OptionError, ["solutions must be from 1"]),
        ({"rank": "prettiest"}, dissect.OptionError, ["unknown ranking", "prettiest"]),
        ({"min_piece": 0}, dissect.OptionError, ["min_piece must be at least 1"]),
        ({"min_piece": 5, "max_piece": 3}, dissect.NoDissectionFound,
         ["constraints cannot all hold", "min_piece 5 is larger than max_piece 3"]),
        ({"min_piece": 7}, dissect.NoDissectionFound, ["larger than the figures (6 cells)"]),
        ({"symmetry_weight": -1.0}, dissect.OptionError, ["symmetry_weight must be a number >= 0"]),
        ({"checkerboard": "yes"}, dissect.OptionError, ["checkerboard must be True or False"]),
        ({"keep": {2: "a"}}, dissect.OptionError, ["keep[2]", "figure 3 does not exist"]),
        ({"keep": {0: "a.\n?.\n"}}, dissect.OptionError, ["keep[0]", "line 2, column 1", "'?'"]),
        ({"keep": {0: "...\n...\n"}}, dissect.OptionError, ["no region is marked"]),
        ({"keep": {0: [[(9, 9)]]}}, dissect.OptionError, ["cell [9, 9] is not a cell of figure 1"]),
        ({"keep": {0: {"ab": [(0, 0)]}}}, dissect.OptionError, ["letter a-z", '"ab"']),
        ({"keep": {-1: "a"}}, dissect.OptionError, ["figure indices"]),
        ({"keep": {0: 5}}, dissect.OptionError, ["keep[0] must be a regions grid"]),
        ({"progress": 3}, dissect.OptionError, ["progress must be a callable"]),
    ],
)
def test_option_errors_come_from_the_engine_rules(
    options: Dict[str, Any], cls: type, words: List[str]
) -> None:
    with pytest.raises(cls) as e:
        dissect.solve([RECT, BAR], **options)
    for w in words:
        assert w in str(e.value), str(e.value)


def test_checkerboard_on_a_lattice_without_one() -> None:
    a = Figure.from_text("C3\n", lattice="tri4")
    b = Figure.from_text("3C\n", lattice="tri4")
    with pytest.raises(dissect.OptionError) as e:
        dissect.solve([a, b], checkerboard=True)
    assert "checkerboard" in str(e.value) and "tri4" in str(e.value)


def test_progress_receives_each_improvement_as_it_happens() -> None:
    figures, _ = instance("squares-3-4-split-to-5", "square")
    calls: List[Tuple[int, float, str]] = []

    def progress(pieces: int, seconds: float, source: str) -> None:
        calls.append((pieces, seconds, source))

    d = dissect.solve(figures, seed=1, progress=progress)
    assert calls, "no improvement reported"
    assert [(p, s) for p, _, s in calls] == [(h["pieces"], h["by"]) for h in d.history]
    pieces = [p for p, _, _ in calls]
    assert pieces == sorted(pieces, reverse=True) and pieces[-1] == d.piece_count
    seconds = [t for _, t, _ in calls]
    assert seconds == sorted(seconds)


def test_progress_is_called_during_the_run_not_after() -> None:
    # Three cubes into one (729 voxels): the first answer comes in well under
    # a second and nothing proves it optimal in 3 s (the corner bound is 8), so
    # the run goes on to its limit whatever the machine's speed.
    figures, _ = instance("cubes-1-6-8-to-9", "cubic")
    start = time.monotonic()
    seen: List[Tuple[float, float]] = []

    def progress(pieces: int, seconds: float, source: str) -> None:
        seen.append((time.monotonic() - start, seconds))

    d = dissect.solve(figures, seed=1, time_limit=3, progress=progress)
    took = time.monotonic() - start
    assert d.stopped and took >= 2.9
    assert seen
    # The first improvement reached Python within a moment of being found,
    # long before the run ended.
    wall, seconds = seen[0]
    assert wall - seconds < 0.5 and wall < took - 1.0, (seen, took)


def test_progress_exception_stops_the_run() -> None:
    figures, _ = instance("squares-6-6-7-split-to-11", "square")

    class Enough(Exception):
        pass

    def progress(pieces: int, seconds: float, source: str) -> None:
        raise Enough(f"{pieces} pieces")

    with pytest.raises(Enough):
        dissect.solve(figures, seed=1, time_limit=60, progress=progress)


def test_progress_moves_a_tqdm_bar() -> None:
    tqdm = pytest.importorskip("tqdm")
    figures, _ = instance("squares-3-4-split-to-5", "square")
    with tqdm.tqdm(desc="pieces", disable=False) as bar:

        def progress(pieces: int, seconds: float, source: str) -> None:
            bar.set_postfix(pieces=pieces, by=source)
            bar.update(1)

        d = dissect.solve(figures, seed=1, progress=progress)
        assert bar.n == len(d.history)


def _same(a: Sequence[Any], b: Sequence[Any]) -> bool:
    return list(a) == list(b)


def test_options_lists_every_puzzle_option() -> None:
    for name in ("solutions", "rank", "min_piece", "max_piece", "checkerboard",
                 "symmetry_weight", "keep", "assemblable", "min_level", "mirror", "prove",
                 "exact", "paper"):
        assert name in dissect.OPTIONS
    assert _same(dissect.RANKS, ["variance", "smallest", "shapes", "symmetry", "unique", "level"])
