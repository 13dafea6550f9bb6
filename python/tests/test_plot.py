import xml.etree.ElementTree as ET

import pytest

import dissect

from conftest import instance


@pytest.mark.parametrize(
    "name, lattice",
    [("squares-3-4-split-to-5", "square"), ("tri-triangle8-to-rect4x8", "tri4"),
     ("cube4-cavity-to-7x4x2", "cubic")],
)
def test_plot_to_a_file_and_svg(name, lattice, tmp_path):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figures, _ = instance(name, lattice)
    d = dissect.solve(figures, seed=1)
    ax = d.plot()
    out = tmp_path / "d.png"
    ax.figure.savefig(out)
    plt.close(ax.figure)
    data = out.read_bytes()
    assert data.startswith(b"\x89PNG") and len(data) > 2000
    root = ET.fromstring(d._repr_svg_())
    polygons = root.findall("{http://www.w3.org/2000/svg}polygon")
    cells = sum(len(p) for fig in d.pieces for p in fig)
    assert len(polygons) == cells
