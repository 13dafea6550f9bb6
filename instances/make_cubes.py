#!/usr/bin/env python3
"""Writes a sum-of-cubes instance: cubes of the given sides side by side
(one empty column between them, all on one floor and against one wall)
as a.txt, and the cube of the sum's side as b.txt, in the cubic lattice's
layer format (one block of rows per layer, blank lines between layers):

    python3 make_cubes.py OUTDIR 1 6 8 9     # 1^3 + 6^3 + 8^3 = 9^3
"""
import argparse
import os
import sys


def layers(width, depth, height, filled):
    out = []
    for z in range(height):
        rows = []
        for y in range(depth):
            rows.append("".join("#" if filled(x, y, z) else "." for x in range(width)))
        out.append("\n".join(rows))
    return "\n\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description="Write cubes apart on one floor (a.txt) and the last cube (b.txt).")
    parser.add_argument("outdir")
    parser.add_argument("sides", type=int, nargs="+", help="the cubes' sides, the whole cube last")
    args = parser.parse_args()
    outdir, sides = args.outdir, args.sides
    parts, whole = sides[:-1], sides[-1]
    if sum(s ** 3 for s in parts) != whole ** 3:
        sys.exit("the cubes' volumes do not add up to the last cube's")
    starts, x = [], 0
    for s in parts:
        starts.append(x)
        x += s + 1
    width, top = x - 1, max(parts)

    def apart(x, y, z):
        return any(x0 <= x < x0 + s and y < s and z < s for x0, s in zip(starts, parts))

    os.makedirs(outdir, exist_ok=True)
    with open(os.path.join(outdir, "a.txt"), "w") as f:
        f.write(layers(width, top, top, apart))
    with open(os.path.join(outdir, "b.txt"), "w") as f:
        f.write(layers(whole, whole, whole, lambda x, y, z: True))


if __name__ == "__main__":
    main()
