#!/usr/bin/env python3
"""Writes a closed, outward-facing ASCII STL mesh of a torus (ring radius 3,
tube radius 1.25, axis z; 48 x 24 quads, two triangles each), the model of
the instance torus512-to-slab16x8x4:

    python3 make_torus.py /tmp/torus.stl
    dissect voxelize --cells 512 -o torus512-to-slab16x8x4/a.txt /tmp/torus.stl
"""
import argparse
import math

R, r, NU, NV = 3.0, 1.25, 48, 24


def point(i, j):
    u = 2 * math.pi * (i % NU) / NU
    v = 2 * math.pi * (j % NV) / NV
    ring = R + r * math.cos(v)
    return (ring * math.cos(u), ring * math.sin(u), r * math.sin(v))


def normal(a, b, c):
    ux, uy, uz = (b[k] - a[k] for k in range(3))
    vx, vy, vz = (c[k] - a[k] for k in range(3))
    n = (uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx)
    length = math.sqrt(sum(x * x for x in n)) or 1.0
    return tuple(x / length for x in n)


def main():
    parser = argparse.ArgumentParser(description="Write the torus mesh as ASCII STL.")
    parser.add_argument("out", nargs="?", default="torus.stl", help="the STL file to write")
    out = parser.parse_args().out
    lines = ["solid torus"]
    for i in range(NU):
        for j in range(NV):
            p00, p10 = point(i, j), point(i + 1, j)
            p01, p11 = point(i, j + 1), point(i + 1, j + 1)
            for tri in ((p00, p10, p11), (p00, p11, p01)):
                lines.append("  facet normal %.6f %.6f %.6f" % normal(*tri))
                lines.append("    outer loop")
                for p in tri:
                    lines.append("      vertex %.6f %.6f %.6f" % p)
                lines.append("    endloop")
                lines.append("  endfacet")
    lines.append("endsolid torus")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
