#!/usr/bin/env python3
"""Writes the closed, outward-facing ASCII STL meshes of the project's
voxelized-mesh instances (then `dissect voxelize --cells N`):

    python3 make_meshes.py pawn /tmp/pawn.stl   # a chess pawn (a surface of revolution)
    python3 make_meshes.py blob /tmp/blob.stl   # a lumpy star-shaped body r(u, v)
"""
import argparse
import math

NU, NV = 64, 48


def pawn_profile(t):
    """(radius, height) along the pawn's outline, t in [0, 1] from the bottom
    centre to the top."""
    pts = [(0.0, 0.0), (1.6, 0.0), (1.6, 0.35), (1.25, 0.55), (1.1, 0.8), (0.75, 1.1),
           (0.55, 1.9), (0.5, 2.5), (0.9, 2.7), (0.9, 2.85), (0.45, 3.0), (0.7, 3.3),
           (0.78, 3.6), (0.7, 3.9), (0.45, 4.15), (0.0, 4.25)]
    seg = t * (len(pts) - 1)
    i = min(int(seg), len(pts) - 2)
    f = seg - i
    (r0, z0), (r1, z1) = pts[i], pts[i + 1]
    return r0 + (r1 - r0) * f, z0 + (z1 - z0) * f


def pawn(i, j):
    u = 2 * math.pi * (i % NU) / NU
    r, z = pawn_profile(j / NV)
    return (r * math.cos(u), r * math.sin(u), z)


def blob(i, j):
    u = 2 * math.pi * (i % NU) / NU
    v = math.pi * j / NV
    r = 1.0 + 0.28 * math.sin(3 * u) * math.sin(v) ** 2 + 0.22 * math.cos(2 * v) + 0.12 * math.cos(5 * u + v)
    return (1.4 * r * math.sin(v) * math.cos(u), r * math.sin(v) * math.sin(u), 1.1 * r * math.cos(v))


def normal(a, b, c):
    ux, uy, uz = (b[k] - a[k] for k in range(3))
    vx, vy, vz = (c[k] - a[k] for k in range(3))
    n = (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx)
    length = math.sqrt(sum(x * x for x in n)) or 1.0
    return tuple(x / length for x in n)


def main():
    parser = argparse.ArgumentParser(description="Write a mesh of the instances as ASCII STL.")
    parser.add_argument("kind", choices=["pawn", "blob"])
    parser.add_argument("out", help="the STL file to write")
    args = parser.parse_args()
    kind, out = args.kind, args.out
    point = {"pawn": pawn, "blob": blob}[kind]
    # pawn: j runs bottom to top, so (i, j) -> (i+1, j) -> (i+1, j+1) faces
    # outward; blob: j runs top to bottom, the opposite turn.
    flip = kind == "blob"
    lines = ["solid " + kind]
    for i in range(NU):
        for j in range(NV):
            p00, p10 = point(i, j), point(i + 1, j)
            p01, p11 = point(i, j + 1), point(i + 1, j + 1)
            for tri in ((p00, p10, p11), (p00, p11, p01)):
                if flip:
                    tri = (tri[0], tri[2], tri[1])
                a, b, c = tri
                if a == b or b == c or a == c:
                    continue  # degenerate at a pole
                lines.append("  facet normal %.6f %.6f %.6f" % normal(*tri))
                lines.append("    outer loop")
                for p in tri:
                    lines.append("      vertex %.6f %.6f %.6f" % p)
                lines.append("    endloop")
                lines.append("  endfacet")
    lines.append("endsolid " + kind)
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
