"""`Dissection.assemblies`: the engine's count of tilings per figure, the
same as `dissect assemblies`."""

import subprocess
from pathlib import Path
from typing import Any, Dict, List, Tuple

import pytest

import dissect
from dissect import Figure

from conftest import instance


def test_two_squares_cut_into_dominoes() -> None:
    # A 2x2 square and a 1x4 bar from two dominoes.
    square = Figure.from_text("##\n##\n")
    bar = Figure.from_text("####\n")
    d = dissect.solve([square, bar], seed=1)
    assert d.piece_count == 2
    counts = d.assemblies()
    assert [c.figure for c in counts] == d.names
    # Two identical dominoes tile the square in 2 ways (both vertical or both
    # horizontal), one up to its symmetries; the bar in 1.
    assert (counts[0].tilings, counts[0].up_to_symmetry) == (2, 1)
    assert (counts[1].tilings, counts[1].up_to_symmetry) == (1, 1)
    assert all(c.complete and c.unique for c in counts)
    assert counts[0].figure_symmetries == 8


def test_same_counts_as_the_cli(dissect_bin: Path, tmp_path: Path) -> None:
    figures, files = instance("squares-3-4-split-to-5", "square")
    d = dissect.solve(figures, seed=1)
    sol = tmp_path / "s.json"
    d.to_json(sol)
    r = subprocess.run(
        [str(dissect_bin), "assemblies", "--solution", str(sol), *map(str, files)],
        capture_output=True, text=True,
    )
    assert r.returncode == 0, r.stderr
    counts = d.assemblies(time_limit=60)
    for c, line in zip(counts, r.stdout.strip().splitlines()):
        assert line.startswith(f"{c.figure}: {c.tilings} tiling"), (line, c)
        assert f"({c.up_to_symmetry} up to" in line, (line, c)


def dominoes(width: int, height: int) -> List[List[Tuple[int, ...]]]:
    """A width x height rectangle (width even) cut into horizontal dominoes."""
    return [[(x, y), (x + 1, y)] for y in range(height) for x in range(0, width, 2)]


def test_time_limit_and_a_bad_dissection() -> None:
    # An 8x8 square and a 16x4 bar as 32 dominoes: millions of tilings.
    square = Figure.from_text("########\n" * 8, name="square.txt")
    bar = Figure.from_text("################\n" * 4, name="bar.txt")
    result: Dict[str, Any] = dict(
        lattice="square", mirror=True, names=["square.txt", "bar.txt"],
        pieces=[dominoes(8, 8), dominoes(16, 4)],
    )
    d = dissect.Dissection([square, bar], result)
    assert d.verify() and d.piece_count == 32
    quick = d.assemblies(time_limit=0.2)
    assert len(quick) == 2 and not any(c.complete for c in quick)
    # Cut short at its limit (how many tilings came first depends on the
    # machine's load: the limit is also checked while the board is built).
    assert all(c.tilings >= 0 and c.seconds < 5 for c in quick)
    with pytest.raises(dissect.OptionError):
        d.assemblies(time_limit=-1)
    # Piece 0 made 3 cells: not a dissection, counted never.
    pieces = dominoes(8, 8)
    pieces[0].append(pieces[1].pop())
    broken = dissect.Dissection([square, bar], dict(result, pieces=[pieces, dominoes(16, 4)]))
    with pytest.raises(dissect.InvalidSolution) as e:
        broken.assemblies()
    assert "not a valid dissection" in str(e.value)
