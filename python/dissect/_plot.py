"""``Dissection.plot``: the dissection drawn with matplotlib.

Everything about the lattice and the colours comes from the Rust side
(``_dissect.drawing``): every cell's polygon in the plane (FORMAT.md's
geometry, y downward), each piece's merged outline, its label and its
colour from the one palette (``dissect.PALETTE``). This module only places
the figures side by side (a ``cubic`` figure as its z layers, one under
the other) and hands the shapes to matplotlib.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, List, Tuple

from . import _dissect

if TYPE_CHECKING:
    from . import Dissection

Point = Tuple[float, float]
#: (figure, piece, layer, colour, cell polygons, outline loops, label, label point)
Shape = Tuple[int, int, int, str, List[List[Point]], List[List[Point]], str, Point]


def _bounds(polys: List[List[Point]]) -> Tuple[float, float, float, float]:
    xs = [x for p in polys for x, _ in p]
    ys = [y for p in polys for _, y in p]
    return min(xs), min(ys), max(xs), max(ys)


def shapes(d: "Dissection", gap: float = 1.5) -> List[Shape]:
    """Every layer of every piece, moved to its place in the picture."""
    drawing = _dissect.drawing(d.lattice, d._parts()[3])
    out: List[Shape] = []
    offset = 0.0
    for f, pieces in enumerate(drawing):
        cells = [c for p in pieces for layer in p["layers"] for c in layer["cells"]]
        x0, y0, x1, y1 = _bounds(cells)
        layers = sorted({layer["layer"] for p in pieces for layer in p["layers"]})
        row = {z: k for k, z in enumerate(layers)}
        for i, p in enumerate(pieces):
            for layer in p["layers"]:
                dy = row[layer["layer"]] * (y1 - y0 + 1.0) - y0
                dx = offset - x0

                def move(pts: List[Point], dx: float = dx, dy: float = dy) -> List[Point]:
                    return [(x + dx, y + dy) for x, y in pts]

                lx, ly = layer["label_at"]
                out.append(
                    (
                        f,
                        i,
                        layer["layer"],
                        p["colour"],
                        [move(c) for c in layer["cells"]],
                        [move(o) for o in layer["outline"]],
                        p["label"],
                        (lx + dx, ly + dy),
                    )
                )
        offset += x1 - x0 + gap
    return out


def plot(
    d: "Dissection",
    ax: Any = None,
    edgecolor: str = "black",
    linewidth: float = 1.5,
    labels: bool = True,
) -> Any:
    """Draws ``d`` on ``ax`` (a new figure's axes if None); returns ``ax``."""
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection, PolyCollection

    if ax is None:
        _, ax = plt.subplots(figsize=(2 + 2 * len(d.pieces), 3))
    drawn = shapes(d)
    polys = [c for s in drawn for c in s[4]]
    colours = [s[3] for s in drawn for _ in s[4]]
    ax.add_collection(
        PolyCollection(polys, facecolors=colours, edgecolors=colours, linewidths=0.3)
    )
    loops = [o + o[:1] for s in drawn for o in s[5]]
    ax.add_collection(LineCollection(loops, colors=edgecolor, linewidths=linewidth))
    if labels:
        for s in drawn:
            ax.text(s[7][0], s[7][1], s[6], ha="center", va="center", fontsize=8)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.invert_yaxis()
    ax.set_axis_off()
    ax.set_title(f"{d.piece_count} pieces" + (" (optimal)" if d.optimal else ""))
    return ax
