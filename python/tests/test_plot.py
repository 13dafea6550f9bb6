"""Pictures: `plot` (matplotlib, Agg), `to_svg`/`_repr_svg_` and `to_html`
draw with the one palette (`dissect.PALETTE`, the Rust side's) and the
Rust side's lattice geometry."""

import re
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import List, Set

import numpy as np
import pytest

import dissect

from conftest import instance

SVG = "{http://www.w3.org/2000/svg}"

CASES = [
    ("squares-3-4-split-to-5", "square"),
    ("tri-triangle8-to-rect4x8", "tri4"),
    ("cube4-cavity-to-7x4x2", "cubic"),
    ("tri3-hexagon2-to-parallelogram4x3", "tri3"),
    ("hex-hexagon6-to-rhombus13x7", "hex"),
]


def fills(svg: str) -> Set[str]:
    root = ET.fromstring(svg)
    return {e.attrib["fill"].lower() for e in root.iter() if "fill" in e.attrib}


def test_palette_is_the_rust_palette_and_the_svg_fills() -> None:
    assert len(dissect.PALETTE) == 20
    assert dissect.PALETTE[0] == "#e6615c"  # dissect_core::palette, piece A
    assert all(re.fullmatch(r"#[0-9a-f]{6}", c) for c in dissect.PALETTE)
    assert [dissect.piece_colour(i) for i in range(20)] == list(dissect.PALETTE)
    assert dissect.piece_colour(20) not in dissect.PALETTE
    figures, _ = instance("squares-3-4-split-to-5", "square")
    d = dissect.solve(figures, seed=1)
    svg = d.to_svg()
    assert svg == d._repr_svg_()
    used = fills(svg) - {"#ffffff", "#222222", "none"}
    assert used == set(dissect.PALETTE[: d.piece_count])


@pytest.mark.parametrize("name, lattice", CASES)
def test_plot_to_a_file_with_the_palette(name: str, lattice: str, tmp_path: Path) -> None:
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import to_hex

    figures, _ = instance(name, lattice)
    d = dissect.solve(figures, seed=1, time_limit=5)
    ax = d.plot()
    out = tmp_path / "d.png"
    ax.figure.savefig(out)
    polys = [c for c in ax.collections if isinstance(c, PolyCollection)]
    assert len(polys) == 1
    cells = sum(len(p) for fig in d.pieces for p in fig)
    assert len(polys[0].get_paths()) == cells
    rgba = np.asarray(polys[0].get_facecolor(), dtype=float)
    colours: List[str] = [to_hex((r, g, b)) for r, g, b, _ in rgba.tolist()]
    want = [dissect.PALETTE[i] for fig in d.pieces for i, p in enumerate(fig) for _ in p]
    assert sorted(colours) == sorted(want)
    labels = {t.get_text() for t in ax.texts}
    assert labels == {chr(ord("A") + i) for i in range(d.piece_count)}
    plt.close(ax.figure)
    data = out.read_bytes()
    assert data.startswith(b"\x89PNG") and len(data) > 2000
    # The SVG view and the page of the same dissection.
    assert set(dissect.PALETTE[: d.piece_count]) <= fills(d.to_svg())
    page = d.to_html(tmp_path / "d.html")
    assert page.startswith("<!doctype html>") and (tmp_path / "d.html").read_text() == page


def test_cell_polygons_come_from_the_rust_geometry() -> None:
    from dissect import _dissect

    # One hexagon: six corners at distance 1/sqrt(3) from its centre (0, 0).
    hexagon = _dissect.drawing("hex", [[[[0, 0]]]])[0][0]["layers"][0]["cells"][0]
    assert len(hexagon) == 6
    assert all(abs((x * x + y * y) ** 0.5 - 3 ** -0.5) < 1e-9 for x, y in hexagon)
    # A tri4 triangle t=0: the top side of its square and the centre.
    tri = _dissect.drawing("tri4", [[[[0, 0, 0]]]])[0][0]["layers"][0]["cells"][0]
    assert sorted(tri) == [(0.0, 0.0), (0.5, 0.5), (1.0, 0.0)]
    # A cubic piece: one layer per z, squares.
    piece = _dissect.drawing("cubic", [[[[0, 0, 0], [0, 0, 1]]]])[0][0]
    assert [layer["layer"] for layer in piece["layers"]] == [0, 1]
    assert piece["colour"] == dissect.PALETTE[0] and piece["label"] == "A"
