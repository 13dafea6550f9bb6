"""Pictures of dissections: matplotlib (``Dissection.plot``) and plain SVG
(``Dissection.to_svg``, shown by notebooks through ``_repr_svg_``).

Cells are drawn as polygons in FORMAT.md's geometry (y grows downward), each
filled with its piece's colour; piece outlines are the polygon edges not
shared by two cells of the same piece. Figures stand side by side; a
``cubic`` figure is drawn as its z layers, one under the other.
"""

from __future__ import annotations

import math
from collections import Counter
from typing import Dict, List, Tuple

Point = Tuple[float, float]

#: Piece colours (the first piece gets the first colour, and so on).
PALETTE = [
    "#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f", "#edc948", "#b07aa1",
    "#ff9da7", "#9c755f", "#bab0ac", "#1f77b4", "#aec7e8", "#ffbb78", "#98df8a",
    "#ff9896", "#c5b0d5", "#c49c94", "#f7b6d2", "#dbdb8d", "#9edae5",
]

_H = math.sqrt(3) / 2


def colour(i: int) -> str:
    """The colour of piece ``i``."""
    return PALETTE[i % len(PALETTE)]


def cell_polygon(lattice: str, cell: tuple) -> List[Point]:
    """The corners of a cell in the plane (FORMAT.md geometry; cubic cells
    as the unit square of their layer)."""
    x, y = cell[0], cell[1]
    if lattice in ("square", "cubic"):
        return [(x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1)]
    if lattice == "tri4":
        c = (x + 0.5, y + 0.5)
        corners = [(x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1)]
        t = cell[2]
        return [corners[t], corners[(t + 1) % 4], c]
    if lattice == "tri3":
        if (x + y) % 2 == 0:  # up
            return [(x / 2, (y + 1) * _H), ((x + 2) / 2, (y + 1) * _H), ((x + 1) / 2, y * _H)]
        return [(x / 2, y * _H), ((x + 2) / 2, y * _H), ((x + 1) / 2, (y + 1) * _H)]
    if lattice == "hex":
        cx, cy = x + (y % 2) / 2, y * _H
        r = 1 / math.sqrt(3)
        return [
            (cx + r * math.cos(math.radians(a)), cy + r * math.sin(math.radians(a)))
            for a in (-90, -30, 30, 90, 150, 210)
        ]
    raise ValueError(f"cannot draw cells of the {lattice} lattice")


def _layout(d) -> List[Tuple[int, int, List[Point], int]]:
    """(figure, piece, polygon, layer) for every cell, each figure moved to
    its place in the picture (layer: z on cubic, else 0)."""
    out = []
    offset = 0.0
    for f, pieces in enumerate(d.pieces):
        cells = [(i, c) for i, p in enumerate(pieces) for c in p]
        polys = [(i, cell_polygon(d.lattice, c), c) for i, c in cells]
        xs = [x for _, poly, _ in polys for x, _ in poly]
        ys = [y for _, poly, _ in polys for _, y in poly]
        x0, y0 = min(xs), min(ys)
        height = max(ys) - y0
        z0 = min(c[2] for _, c in cells) if d.lattice == "cubic" else 0
        for i, poly, c in polys:
            dy = (c[2] - z0) * (height + 1) if d.lattice == "cubic" else 0.0
            layer = c[2] - z0 if d.lattice == "cubic" else 0
            out.append((f, i, [(px - x0 + offset, py - y0 + dy) for px, py in poly], layer))
        offset += max(xs) - x0 + 1.5
    return out


def _outline(cells) -> List[Tuple[Point, Point]]:
    """Edges between cells of different pieces (or on the outside)."""
    count: Counter = Counter()
    owner: Dict = {}
    for f, i, poly, _ in cells:
        for a, b in zip(poly, poly[1:] + poly[:1]):
            key = tuple(sorted([(round(a[0], 6), round(a[1], 6)), (round(b[0], 6), round(b[1], 6))]))
            count[(f, i, key)] += 1
            owner[(f, i, key)] = (a, b)
    return [owner[k] for k, n in count.items() if n == 1]


def plot(d, ax=None, edgecolor="black", linewidth=1.5, labels=True):
    """Draws ``d`` on ``ax`` (a new figure's axes if None); returns ``ax``."""
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection, PolyCollection

    if ax is None:
        _, ax = plt.subplots(figsize=(2 + 2 * len(d.pieces), 3))
    cells = _layout(d)
    ax.add_collection(
        PolyCollection(
            [poly for _, _, poly, _ in cells],
            facecolors=[colour(i) for _, i, _, _ in cells],
            edgecolors=[colour(i) for _, i, _, _ in cells],
            linewidths=0.3,
        )
    )
    ax.add_collection(LineCollection(_outline(cells), colors=edgecolor, linewidths=linewidth))
    if labels:
        sums: Dict = {}
        for f, i, poly, layer in cells:
            s = sums.setdefault((f, i, layer), [0.0, 0.0, 0])
            s[0] += sum(p[0] for p in poly) / len(poly)
            s[1] += sum(p[1] for p in poly) / len(poly)
            s[2] += 1
        for (_, i, _), (sx, sy, n) in sums.items():
            ax.text(sx / n, sy / n, _letter(i), ha="center", va="center", fontsize=8)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.invert_yaxis()
    ax.set_axis_off()
    ax.set_title(f"{d.piece_count} pieces" + (" (optimal)" if d.optimal else ""))
    return ax


def _letter(i: int) -> str:
    return chr(ord("A") + i) if i < 26 else str(i)


def svg(d, scale: float = 20.0) -> str:
    """``d`` as a standalone SVG document."""
    cells = _layout(d)
    xs = [x for _, _, poly, _ in cells for x, _ in poly]
    ys = [y for _, _, poly, _ in cells for _, y in poly]
    w, h = (max(xs) + 1) * scale, (max(ys) + 1) * scale
    pad = scale / 2

    def pt(p: Point) -> str:
        return f"{p[0] * scale + pad:.2f},{p[1] * scale + pad:.2f}"

    parts = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0f}" height="{h:.0f}" '
        f'viewBox="0 0 {w:.0f} {h:.0f}">'
    ]
    for _, i, poly, _ in cells:
        c = colour(i)
        parts.append(
            f'<polygon points="{" ".join(pt(p) for p in poly)}" fill="{c}" stroke="{c}" stroke-width="0.5"/>'
        )
    for a, b in _outline(cells):
        parts.append(
            f'<line x1="{a[0] * scale + pad:.2f}" y1="{a[1] * scale + pad:.2f}" '
            f'x2="{b[0] * scale + pad:.2f}" y2="{b[1] * scale + pad:.2f}" stroke="black" stroke-width="1.5"/>'
        )
    parts.append("</svg>")
    return "\n".join(parts)
