"""Design a dissection puzzle end to end: figures from numpy arrays, solve,
check, plot and save.

The puzzle is Pythagoras' theorem in pieces: a 3x3 and a 4x4 square that
together make a 5x5 square. Run it with

    python python/examples/design_puzzle.py --out puzzle

and it writes puzzle/puzzle.json (FORMAT.md; `dissect verify` and
`dissect render` read it) and puzzle/puzzle.png (with matplotlib) or
puzzle/puzzle.svg (without).
"""

import argparse
import os
from typing import List

import numpy as np

import dissect


def figures() -> List[dissect.Figure]:
    """The two figures, drawn as boolean arrays (row y, column x)."""
    two_squares = np.zeros((4, 8), dtype=bool)
    two_squares[1:4, 0:3] = True  # the 3x3 square
    two_squares[0:4, 4:8] = True  # the 4x4 square
    five = np.ones((5, 5), dtype=bool)
    return [
        dissect.Figure.from_array(two_squares, name="squares-3-4.txt"),
        dissect.Figure.from_array(five, name="square-5.txt"),
    ]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="puzzle", help="output folder (default: puzzle)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--time-limit", type=float, default=60.0)
    args = ap.parse_args()

    a, b = figures()
    print(f"{a.name}: {a.area} cells; {b.name}: {b.area} cells")
    print(a.to_text())
    d = dissect.solve(
        [a, b],
        seed=args.seed,
        time_limit=args.time_limit,
        solutions=2,  # the two best different dissections, ranked
        rank="smallest",  # by their smallest piece, largest first
        min_piece=3,  # no piece under 3 cells
        progress=lambda pieces, seconds, by: print(f"  {pieces} pieces at {seconds:.2f} s ({by})"),
    )
    d.verify()  # the independent verifier; raises if anything is wrong
    state = "optimal" if d.optimal else f"lower bound {d.lower_bound}"
    print(f"{d.piece_count} pieces ({state}), areas {d.areas}, {d.seconds or 0:.2f} s")
    for s in d.solutions:
        s.verify()
        print(f"  solution: smallest piece {s.scores['smallest']}, areas {s.areas}")
    for c in d.assemblies(time_limit=10):
        print(f"  {c.figure}: {c.tilings} tilings, {c.up_to_symmetry} up to its symmetries")

    os.makedirs(args.out, exist_ok=True)
    d.to_json(os.path.join(args.out, "puzzle.json"))
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        picture = os.path.join(args.out, "puzzle.svg")
        with open(picture, "w", encoding="utf-8") as f:
            f.write(d.to_svg())
    else:
        picture = os.path.join(args.out, "puzzle.png")
        ax = d.plot()
        ax.figure.savefig(picture, dpi=120, bbox_inches="tight")
        plt.close(ax.figure)
    print(f"wrote {os.path.join(args.out, 'puzzle.json')} and {picture}")


if __name__ == "__main__":
    main()
