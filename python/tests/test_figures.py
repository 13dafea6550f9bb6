import pickle
from pathlib import Path
from typing import Callable, List

import numpy as np
import pytest

import dissect
from dissect import Figure


def test_from_text_square() -> None:
    f = Figure.from_text("###\n#.#\n")
    assert f.lattice == "square"
    assert f.area == 5 == len(f)
    assert f.cells == [(0, 0), (0, 1), (1, 0), (2, 0), (2, 1)]
    assert f.to_text() == "###\n#.#\n"


def test_from_text_tri4_and_cubic() -> None:
    t = Figure.from_text("C3\n", lattice="tri4")
    assert t.area == 4
    assert sorted(t.cells) == [(0, 0, 2), (0, 0, 3), (1, 0, 0), (1, 0, 1)]
    c = Figure.from_text("##\n\n#.\n", lattice="cubic")
    assert c.lattice == "cubic"
    assert sorted(c.cells) == [(0, 0, 0), (0, 0, 1), (1, 0, 0)]


def test_from_array_2d_and_3d_match_text() -> None:
    a = np.array([[1, 1, 1], [1, 0, 1]], dtype=bool)
    assert Figure.from_array(a) == Figure.from_text("###\n#.#\n")
    cube = np.zeros((2, 1, 2), dtype=bool)  # [z, y, x]
    cube[0, 0, :] = True
    cube[1, 0, 0] = True
    assert Figure.from_array(cube) == Figure.from_text("##\n\n#.\n", lattice="cubic")
    tri = np.zeros((1, 2, 4), dtype=bool)  # [y, x, t]
    tri[0, 0, [2, 3]] = True
    tri[0, 1, [0, 1]] = True
    assert Figure.from_array(tri, lattice="tri4") == Figure.from_text("C3", lattice="tri4")
    # 0/1 integers are booleans too.
    assert Figure.from_array([[1, 0], [1, 1]]).area == 3


def test_from_cells_and_pickle() -> None:
    f = Figure.from_cells([(0, 0), (1, 0)], name="domino")
    assert f.name == "domino" and f.area == 2
    g = pickle.loads(pickle.dumps(f))
    assert g == f and g.name == "domino"
    assert hash(g) == hash(f)


def test_read_figure(tmp_path: Path) -> None:
    p = tmp_path / "l.txt"
    p.write_text("#.\n##\n")
    f = dissect.read_figure(p)
    assert f.name == "l.txt" and f.area == 3


@pytest.mark.parametrize(
    "make, words",
    [
        (lambda: Figure.from_text("##\n#x\n"), ["line 2", "column 2", "'x'"]),
        (lambda: Figure.from_text("..\n"), ["empty"]),
        (lambda: Figure.from_text("##", lattice="hexagonal"), ["unknown lattice", "hexagonal"]),
        (lambda: Figure.from_text("#G", lattice="tri4"), ["'G'"]),
        (lambda: Figure.from_array(np.zeros((2, 2), bool)), ["empty"]),
        (lambda: Figure.from_array(np.ones(4, bool)), ["2D or 3D"]),
        (lambda: Figure.from_array(np.array([[2, 1]])), ["booleans or 0/1"]),
        (lambda: Figure.from_array(np.ones((2, 2, 3), bool), lattice="tri4"), ["(rows, columns, 4)"]),
        (lambda: Figure.from_cells([(0, 0, 7)], lattice="tri4"), ["not a cell of the tri4 lattice"]),
        (lambda: Figure.from_cells([(0,)]), ["not a cell"]),
    ],
)
def test_bad_figures_raise_figure_error_naming_the_problem(
    make: Callable[[], object], words: List[str]
) -> None:
    with pytest.raises(dissect.FigureError) as e:
        make()
    assert isinstance(e.value, ValueError)
    for w in words:
        assert w in str(e.value)
