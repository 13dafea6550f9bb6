"""`Dissection.disassemble`: the plan of straight moves that takes each
figure apart (the search of `dissect disassemble`), replayed here by a
checker of its own."""

import json
import subprocess
from pathlib import Path
from typing import Any, Dict, List, Sequence, Set, Tuple

import pytest

import dissect
from dissect import Figure

from conftest import instance

Voxel = Tuple[int, int, int]


def shift(c: Voxel, axis: int, by: int) -> Voxel:
    x, y, z = c
    return (x + by, y, z) if axis == 0 else (x, y + by, z) if axis == 1 else (x, y, z + by)


def replay(pieces: Sequence[Sequence[Sequence[int]]], plan: dissect.FigurePlan) -> None:
    """Plays the plan on the pieces (cubic cells) and checks every move:
    one axis, every unit step free of the rest of the part, a removal's
    sweep clear of it for good; at the end every part holds one piece, and
    the level is the index of the first removal."""
    at: List[Set[Voxel]] = [{(c[0], c[1], c[2]) for c in p} for p in pieces]
    part = [0] * len(at)
    parts = 1
    first_removal = None
    for k, m in enumerate(plan.moves, start=1):
        axes = [j for j in range(3) if m.by[j] != 0]
        assert len(axes) == 1, m
        group = set(m.pieces)
        assert len({part[i] for i in group}) == 1, m
        rest: Set[Voxel] = set()
        for i in range(len(at)):
            if part[i] == part[m.pieces[0]] and i not in group:
                rest |= at[i]
        j = axes[0]
        unit = 1 if m.by[j] > 0 else -1
        cells: Set[Voxel] = set().union(*(at[i] for i in group))
        span = max(abs(c[j]) for c in cells | rest) * 2 + 2 if m.removed else abs(m.by[j])
        for step in range(1, span + 1):
            moved = {shift(c, j, unit * step) for c in cells}
            assert not moved & rest, (m, step)
        for i in group:
            at[i] = {shift(c, j, m.by[j]) for c in at[i]}
        if m.removed:
            first_removal = first_removal or k
            for i in group:
                part[i] = parts
            parts += 1
    assert sorted(part) == list(range(len(at))) or len(at) == 1
    assert plan.level == (first_removal or 0)


def test_a_cubic_answer_comes_apart_as_the_cli_says(dissect_bin: Path, tmp_path: Path) -> None:
    figures, files = instance("cube4-cavity-to-7x4x2", "cubic")
    d = dissect.solve(figures, seed=1)
    plans = d.disassemble(time_limit=60)
    assert plans.lattice == "cubic"
    assert [f.name for f in plans.figures] == d.names
    for f, plan in enumerate(plans.figures):
        assert plan.apart and plan.level is not None and plan.level >= 1, plan
        assert plan.line.startswith(f"{plan.name}: apart in {len(plan.moves)} move"), plan.line
        assert plan.line.endswith(f"(level {plan.level})")
        replay(d.pieces[f], plan)
    assert plans.apart and plans.levels == [p.level for p in plans.figures]
    # The same lines and the same plan file as the CLI.
    sol, out = tmp_path / "s.json", tmp_path / "plan.json"
    d.to_json(sol)
    r = subprocess.run(
        [str(dissect_bin), "disassemble", "--solution", str(sol), "-o", str(out),
         *map(str, files)],
        capture_output=True, text=True,
    )
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines() == plans.lines
    assert out.read_text() == plans.to_json()
    path = tmp_path / "py-plan.json"
    plans.to_json(path)
    assert json.loads(path.read_text())["format"] == "dissection-disassembly/1"
    assert plans.to_dict()["figures"][0]["level"] == plans.figures[0].level


def ring(cells2: Sequence[Tuple[int, int]], place: str) -> List[Voxel]:
    out: List[Voxel] = []
    for a, b in cells2:
        out.append((a, b, 1) if place == "xy" else (1, a, b))
    return out


def test_two_linked_rings_cannot_be_taken_apart() -> None:
    square_ring = [(0, 0), (1, 0), (2, 0), (0, 1), (2, 1), (0, 2), (1, 2), (2, 2)]
    a = ring(square_ring, "xy")
    b = ring([(y + 1, z) for y, z in square_ring], "yz")
    assert not set(a) & set(b)
    figure = Figure.from_cells(a + b, lattice="cubic", name="rings")
    d = dissect.Dissection([figure], dict(
        lattice="cubic", mirror=True, names=["rings"], pieces=[[a, b]]))
    d.verify()
    plans = d.disassemble()
    (plan,) = plans.figures
    assert (plan.level, plan.moves, plan.locked, plan.stopped) == (None, [], [0, 1], False)
    assert plan.line == "rings: cannot be taken apart by straight moves (pieces A, B locked)"
    assert not plans.apart
    assert plans.to_dict()["figures"][0]["locked"] == [0, 1]


def test_flat_pieces_lift_off_and_bad_input() -> None:
    square = Figure.from_text("##\n##\n", name="square")
    bar = Figure.from_text("####\n", name="bar")
    d = dissect.solve([square, bar], seed=1)
    plans = d.disassemble()
    assert plans.levels == [1, 1]
    assert all(len(p.moves) == d.piece_count - 1 or len(p.moves) == d.piece_count
               for p in plans.figures)
    with pytest.raises(dissect.OptionError, match="time_limit"):
        d.disassemble(time_limit=-1)
    bad = dissect.Dissection([square, bar], dict(
        lattice="square", mirror=True, names=["square", "bar"],
        pieces=[[[(0, 0), (1, 0)], [(0, 1), (1, 1)]], [[(0, 0), (1, 0)], [(2, 0), (5, 0)]]]))
    with pytest.raises(dissect.InvalidSolution):
        bad.disassemble()


def test_a_stopped_search_says_so() -> None:
    # Many small pieces: a zero time limit decides nothing.
    figures, _ = instance("cube4-cavity-to-7x4x2", "cubic")
    d = dissect.solve(figures, seed=1)
    plans = d.disassemble(time_limit=0)
    assert all(p.stopped and p.level is None for p in plans.figures), plans.lines
    assert all(p.line.endswith("not decided (stopped)") for p in plans.figures)
    data: Dict[str, object] = plans.to_dict()
    assert data["format"] == "dissection-disassembly/1"


CAVITY_CUBE = (
    "####\n####\n####\n####\n\n####\n#..#\n#..#\n####\n\n"
    "####\n#..#\n#..#\n####\n\n####\n####\n####\n####\n"
)


def test_min_level_two_gives_pieces_that_interlock() -> None:
    # The cube with a cavity, to itself: one piece is the plain answer, so
    # min_level=2 needs a cut into pieces that hold together.
    a = Figure.from_text(CAVITY_CUBE, lattice="cubic", name="a")
    b = Figure.from_text(CAVITY_CUBE, lattice="cubic", name="b")
    assert dissect.solve([a, b], seed=1).piece_count == 1
    d = dissect.solve([a, b], seed=1, time_limit=60, min_level=2)
    d.verify()
    assert 2 <= d.piece_count <= 3
    plans = d.disassemble(time_limit=60)
    assert plans.apart
    for f, plan in enumerate(plans.figures):
        assert plan.level is not None and plan.level >= 2, plan.line
        replay(d.pieces[f], plan)
    # assemblable alone accepts the one piece; a box never reaches level 2.
    assert dissect.solve([a, b], seed=1, assemblable=True).piece_count == 1
    box = Figure.from_text("####\n####\n", lattice="cubic", name="box")
    bar = Figure.from_text("########\n", lattice="cubic", name="bar")
    with pytest.raises(dissect.NoDissectionFound):
        dissect.solve([box, bar], seed=1, min_level=2)
    bad: Dict[str, Any] = {"assemblable": 1}
    with pytest.raises(dissect.OptionError, match="assemblable must be True or False"):
        dissect.solve([a, b], seed=1, **bad)
    bad = {"min_level": "2"}
    with pytest.raises(dissect.OptionError, match="min_level must be a whole number"):
        dissect.solve([a, b], seed=1, **bad)
