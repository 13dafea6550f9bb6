#!/usr/bin/env python3
"""Checks a solution file of dissect against its figure files.

usage: check_solution.py --lattice square|tri4|cubic|tri3|hex --solution S.json FIGURE...

Written from docs/FORMAT.md alone, sharing no code with the Rust verifier
(`dissect verify`): it reads the figures and the `dissection-solution/1`
file and checks that in every figure the pieces partition the figure's cells
exactly, that every piece is connected, and that piece i is the same shape in
every figure, up to a motion of the lattice (a translation combined with a
rotation, or a reflection when the solution allows `mirror`).

The geometry is its own: every cell is drawn as its polygon (a cube in 3D)
with exact integer corners, a piece is the set of its cells' polygons, two
cells touch when they share a whole edge (a face in 3D), and two pieces are
congruent when one of the lattice's point symmetries followed by the
translation that brings the smallest corners together makes the two sets of
polygons equal.

Exit 0 with a last line `valid: N pieces`; exit 1 with the problems and a
last line `invalid: <reason>`; exit 2 when an input cannot be read.
Python standard library only.
"""

import argparse
import itertools
import json
import sys

LATTICES = ("square", "tri4", "cubic", "tri3", "hex")
MAX_COORDINATE = 1 << 24


class InputError(Exception):
    """A figure or solution file that cannot be read."""


# ------------------------------------------------------------------ figures

def figure_lines(text):
    """The lines of a figure text: \\n or \\r\\n ends, trailing spaces and
    trailing blank lines dropped."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    lines = [ln[:-1] if ln.endswith("\r") else ln for ln in lines]
    lines = [ln.rstrip(" ") for ln in lines]
    while lines and lines[-1] == "":
        lines.pop()
    return lines


def read_figure(path, lattice):
    """The set of cells (tuples) of the figure file `path`."""
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as e:
        raise InputError("%s: cannot read: %s" % (path, e))
    cells = set()

    def bad(line, column, ch):
        return InputError("%s: line %d, column %d: unexpected character %r" % (path, line, column, ch))

    if lattice == "cubic":
        layer, row, blank_before = 0, 0, False
        for n, line in enumerate(figure_lines(text), start=1):
            if line == "":
                if n == 1 or blank_before:
                    raise InputError("%s: line %d: a blank line must separate two z layers" % (path, n))
                blank_before, layer, row = True, layer + 1, 0
                continue
            blank_before = False
            for col, ch in enumerate(line):
                if ch == "#":
                    cells.add((col, row, layer))
                elif ch != ".":
                    raise bad(n, col + 1, ch)
            row += 1
    else:
        for row, line in enumerate(figure_lines(text)):
            for col, ch in enumerate(line):
                if lattice == "tri4":
                    if ch == "#":
                        bits = 15
                    elif ch == ".":
                        bits = 0
                    elif ch in "0123456789abcdefABCDEF":
                        bits = int(ch, 16)
                    else:
                        raise bad(row + 1, col + 1, ch)
                    cells.update((col, row, t) for t in range(4) if bits & (1 << t))
                elif ch == "#":
                    cells.add((col, row))
                elif ch != ".":
                    raise bad(row + 1, col + 1, ch)
    if not cells:
        raise InputError("%s: the figure has no cell" % path)
    return cells


# ----------------------------------------------------------------- geometry
#
# Exact integer drawings of the cells (y grows downward, as in the files):
#   square  corners of the unit square, as they are;
#   tri4    coordinates doubled, so that a square's centre is an integer;
#   cubic   corners of the unit cube, as they are;
#   tri3    X = 2 * (horizontal position) + 1, Y = row lines: the triangles
#           have side 2 in X and height 1 in Y (the true height is
#           sqrt(3)/2 of the side, which the rotations below account for);
#   hex     X = 2 * (horizontal position of the centre), Y = 3 * row: a
#           pointy-top hexagon with centres 2 apart in X.
# Each drawing is a polygon: its corners in order around it.

def cell_polygon(cell, lattice):
    if lattice == "square":
        x, y = cell
        return ((x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1))
    if lattice == "tri4":
        x, y, t = cell
        corners = ((2 * x, 2 * y), (2 * x + 2, 2 * y), (2 * x + 2, 2 * y + 2), (2 * x, 2 * y + 2))
        # Triangle t lies on the square's edge t (top, right, bottom, left).
        return (corners[t], corners[(t + 1) % 4], (2 * x + 1, 2 * y + 1))
    if lattice == "tri3":
        x, y = cell
        X = x + 1
        if (x + y) % 2 == 0:  # points up: apex on the row's top line
            return ((X + 1, y), (X + 2, y + 1), (X, y + 1))
        return ((X, y), (X + 2, y), (X + 1, y + 1))  # points down
    if lattice == "hex":
        x, y = cell
        cx, cy = 2 * x + (y % 2), 3 * y
        return ((cx, cy - 2), (cx + 1, cy - 1), (cx + 1, cy + 1),
                (cx, cy + 2), (cx - 1, cy + 1), (cx - 1, cy - 1))
    raise ValueError(lattice)


def cube_faces(cell):
    x, y, z = cell
    faces = []
    for axis in range(3):
        for side in (0, 1):
            face = []
            for a, b in ((0, 0), (0, 1), (1, 0), (1, 1)):
                p = [x, y, z]
                p[axis] += side
                others = [i for i in range(3) if i != axis]
                p[others[0]] += a
                p[others[1]] += b
                face.append(tuple(p))
            faces.append(frozenset(face))
    return faces


def cell_shape(cell, lattice):
    """A cell's drawing as a frozenset of its corners."""
    if lattice == "cubic":
        return frozenset(itertools.chain.from_iterable(cube_faces(cell)))
    return frozenset(cell_polygon(cell, lattice))


def cell_facets(cell, lattice):
    """The edges (faces in 3D) of a cell: two cells touch when they share one."""
    if lattice == "cubic":
        return cube_faces(cell)
    poly = cell_polygon(cell, lattice)
    return [frozenset((poly[i], poly[(i + 1) % len(poly)])) for i in range(len(poly))]


def linear_maps(lattice, mirror):
    """The point symmetries as functions on drawing coordinates."""
    if lattice == "cubic":
        maps = []
        for perm in itertools.permutations(range(3)):
            for signs in itertools.product((1, -1), repeat=3):
                # The sign of the permutation times the signs: +1 for rotations.
                inversions = sum(1 for i in range(3) for j in range(i + 1, 3) if perm[i] > perm[j])
                if (-1) ** inversions * signs[0] * signs[1] * signs[2] == 1:
                    maps.append(lambda p, perm=perm, signs=signs:
                                tuple(signs[i] * p[perm[i]] for i in range(3)))
        return maps
    if lattice in ("square", "tri4"):
        turn = lambda p: (-p[1], p[0])  # a quarter turn
        flip = lambda p: (-p[0], p[1])
    elif lattice == "tri3":
        # A sixth of a turn. With the real point (X/2, Y*s) (s = sqrt(3)/2)
        # it maps to (X/4 - 3Y/4, X/2 + Y/2) in the same units: integers,
        # because X + Y is even at every corner of the drawing.
        turn = lambda p: ((p[0] - 3 * p[1]) // 2, (p[0] + p[1]) // 2)
        flip = lambda p: (-p[0], p[1])
    elif lattice == "hex":
        # The real point is (X/2, Y*s/3); a sixth of a turn maps it to
        # ((X - Y)/2, (3X + Y)/2) in the same units (X + Y is even).
        turn = lambda p: ((p[0] - p[1]) // 2, (3 * p[0] + p[1]) // 2)
        flip = lambda p: (-p[0], p[1])
    else:
        raise ValueError(lattice)
    steps = 4 if lattice in ("square", "tri4") else 6
    maps = []
    for k in range(steps):
        def rotate(p, k=k):
            for _ in range(k):
                p = turn(p)
            return p
        maps.append(rotate)
        if mirror:
            maps.append(lambda p, rotate=rotate: rotate(flip(p)))
    return maps


def placed(shapes):
    """A set of cell drawings moved so that its smallest corner is at 0."""
    low = min(min(s) for s in shapes)
    return frozenset(frozenset(tuple(a - b for a, b in zip(p, low)) for p in s) for s in shapes)


def shape_forms(cells, lattice, mirror):
    """Every placed form of a piece under the lattice's point symmetries."""
    shapes = [cell_shape(c, lattice) for c in cells]
    return {placed([frozenset(f(p) for p in s) for s in shapes])
            for f in linear_maps(lattice, mirror)}


def is_connected(cells, lattice):
    by_facet = {}
    for c in cells:
        for f in cell_facets(c, lattice):
            by_facet.setdefault(f, []).append(c)
    start = next(iter(cells))
    seen, todo = {start}, [start]
    while todo:
        c = todo.pop()
        for f in cell_facets(c, lattice):
            for d in by_facet[f]:
                if d not in seen:
                    seen.add(d)
                    todo.append(d)
    return len(seen) == len(cells)


# ----------------------------------------------------------------- solution

def read_cell(value, lattice):
    """A solution's cell as a tuple, or None when it is not a cell of the lattice."""
    arity = 3 if lattice in ("tri4", "cubic") else 2
    if not isinstance(value, list) or len(value) != arity:
        return None
    if any(type(v) is not int or abs(v) > MAX_COORDINATE for v in value):
        return None
    if lattice == "tri4" and value[2] not in (0, 1, 2, 3):
        return None
    return tuple(value)


def check(solution, figures, lattice):
    """The problems of a parsed solution (a list of strings) and its piece count."""
    if not isinstance(solution, dict):
        return ["the solution is not a JSON object"], 0
    if solution.get("format") != "dissection-solution/1":
        return ["\"format\" is %r, not \"dissection-solution/1\"" % (solution.get("format"),)], 0
    if solution.get("lattice") != lattice:
        return ["the solution's lattice is %r, not %r" % (solution.get("lattice"), lattice)], 0
    mirror = solution.get("mirror", lattice != "cubic")
    if not isinstance(mirror, bool):
        return ["\"mirror\" is %r, not true or false" % (mirror,)], 0
    mirror = mirror and lattice != "cubic"  # a solid is never turned inside out
    entries = solution.get("figures")
    if not isinstance(entries, list) or len(entries) != len(figures):
        return ["the solution lists %s figures, %d figure files were given" % (
            len(entries) if isinstance(entries, list) else "no", len(figures))], 0

    pieces = []
    for k, entry in enumerate(entries):
        raw = entry.get("pieces") if isinstance(entry, dict) else None
        if not isinstance(raw, list):
            return ["figure %d has no \"pieces\" list" % k], 0
        fig_pieces = []
        for i, piece in enumerate(raw):
            if not isinstance(piece, list) or not piece:
                return ["figure %d piece %d is not a non-empty list of cells" % (k, i)], 0
            cells = []
            for value in piece:
                cell = read_cell(value, lattice)
                if cell is None:
                    return ["figure %d piece %d: %s is not a %s cell" % (
                        k, i, json.dumps(value), lattice)], 0
                cells.append(cell)
            fig_pieces.append(cells)
        pieces.append(fig_pieces)
    counts = {len(p) for p in pieces}
    if len(counts) != 1 or 0 in counts:
        return ["the figures list different or no piece counts: %s" % [len(p) for p in pieces]], 0
    n = counts.pop()

    problems = []
    for k, (fig_pieces, figure) in enumerate(zip(pieces, figures)):
        owner = {}
        for i, cells in enumerate(fig_pieces):
            for c in cells:
                if c in owner:
                    problems.append("figure %d: cell %s is in piece %d and piece %d" % (k, list(c), owner[c], i))
                else:
                    owner[c] = i
                if c not in figure:
                    problems.append("figure %d piece %d: cell %s is not in the figure" % (k, i, list(c)))
            if not is_connected(set(cells), lattice):
                problems.append("figure %d piece %d is not connected" % (k, i))
        uncovered = figure - set(owner)
        if uncovered:
            problems.append("figure %d: %d cell(s) in no piece, e.g. %s" % (
                k, len(uncovered), list(min(uncovered))))

    for i in range(n):
        first = set(pieces[0][i])
        forms = None
        for k in range(1, len(pieces)):
            other = set(pieces[k][i])
            if len(other) != len(first):
                problems.append("piece %d has %d cells in figure 0 and %d in figure %d" % (
                    i, len(first), len(other), k))
                continue
            if forms is None:
                forms = shape_forms(first, lattice, mirror)
            if placed([cell_shape(c, lattice) for c in other]) not in forms:
                problems.append("piece %d of figure %d is not piece %d of figure 0 moved%s" % (
                    i, k, i, "" if mirror or lattice == "cubic" else " (mirror images not allowed)"))
    return problems, n


def main(argv=None):
    ap = argparse.ArgumentParser(description="Check a dissection solution file against its figures.")
    ap.add_argument("--lattice", required=True, choices=LATTICES)
    ap.add_argument("--solution", required=True)
    ap.add_argument("figures", nargs="+")
    args = ap.parse_args(argv)
    try:
        figures = [read_figure(p, args.lattice) for p in args.figures]
        try:
            with open(args.solution, encoding="utf-8") as f:
                solution = json.load(f)
        except (OSError, UnicodeDecodeError, ValueError) as e:
            raise InputError("%s: cannot read: %s" % (args.solution, e))
    except InputError as e:
        print("error: %s" % e)
        return 2
    if len({len(f) for f in figures}) != 1:
        print("invalid: the figures have different areas: %s" % ", ".join(
            "%s: %d" % (p, len(f)) for p, f in zip(args.figures, figures)))
        return 1
    problems, n = check(solution, figures, args.lattice)
    if problems:
        for p in problems[:20]:
            print(p)
        if len(problems) > 20:
            print("... and %d more" % (len(problems) - 20))
        print("invalid: %s" % problems[0])
        return 1
    print("valid: %d pieces" % n)
    return 0


if __name__ == "__main__":
    sys.exit(main())
