#!/usr/bin/env python3
"""Unit tests of tools/check_solution.py: small solutions on every lattice
that it must accept, and broken ones (a piece moved, a piece disconnected, a
mirror image where mirrors are not allowed, pieces of different shapes,
malformed files) that it must reject.

    python3 -m unittest discover -s tools -p 'test_*.py'

(`cargo test -p dissect-testkit` runs it too.) Standard library only.
"""

import contextlib
import io
import json
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_solution  # noqa: E402


class Checker(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)

    def run_checker(self, lattice, figures, pieces, mirror=None, fmt="dissection-solution/1", raw=None):
        """Writes the figures and a solution, runs the checker; returns (exit code, last line)."""
        paths = []
        for i, text in enumerate(figures):
            p = os.path.join(self.tmp.name, "f%d.txt" % i)
            with open(p, "w") as f:
                f.write(text)
            paths.append(p)
        sol = {"format": fmt, "lattice": lattice}
        if mirror is not None:
            sol["mirror"] = mirror
        sol["figures"] = [{"name": "f%d.txt" % i, "pieces": ps} for i, ps in enumerate(pieces)]
        sol["scores"] = {"variance": 0.0}  # unknown keys are ignored
        s = os.path.join(self.tmp.name, "s.json")
        with open(s, "w") as f:
            f.write(raw if raw is not None else json.dumps(sol))
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            code = check_solution.main(["--lattice", lattice, "--solution", s] + paths)
        return code, out.getvalue().strip().splitlines()[-1]

    def assertValid(self, n, *args, **kw):
        code, last = self.run_checker(*args, **kw)
        self.assertEqual((code, last), (0, "valid: %d pieces" % n))

    def assertInvalid(self, why, *args, **kw):
        code, last = self.run_checker(*args, **kw)
        self.assertEqual(code, 1, last)
        self.assertTrue(last.startswith("invalid: "), last)
        self.assertIn(why, last)

    # ------------------------------------------------------------ square

    SQUARE = ["##\n##\n", "####\n"]
    SQUARE_PIECES = [[[[0, 0], [1, 0]], [[0, 1], [1, 1]]], [[[0, 0], [1, 0]], [[2, 0], [3, 0]]]]

    def test_square_valid(self):
        self.assertValid(2, "square", self.SQUARE, self.SQUARE_PIECES)

    def test_square_piece_moved(self):
        pieces = json.loads(json.dumps(self.SQUARE_PIECES))
        pieces[1][1] = [[1, 0], [2, 0]]
        self.assertInvalid("is in piece 0 and piece 1", "square", self.SQUARE, pieces)

    def test_square_piece_outside_the_figure(self):
        pieces = json.loads(json.dumps(self.SQUARE_PIECES))
        pieces[1][1] = [[3, 0], [4, 0]]
        self.assertInvalid("not in the figure", "square", self.SQUARE, pieces)

    def test_square_piece_disconnected(self):
        pieces = [[[[0, 0], [1, 1]], [[1, 0], [0, 1]]], [[[0, 0], [2, 0]], [[1, 0], [3, 0]]]]
        self.assertInvalid("not connected", "square", self.SQUARE, pieces)

    def test_square_different_shapes(self):
        pieces = [[[[0, 0], [1, 0], [0, 1]], [[1, 1]]], [[[0, 0], [1, 0], [2, 0]], [[3, 0]]]]
        self.assertInvalid("not piece 0 of figure 0 moved", "square", self.SQUARE, pieces)

    L = ["#.\n#.\n##\n", ".#\n.#\n##\n"]
    L_PIECES = [[[[0, 0], [0, 1], [0, 2], [1, 2]]], [[[1, 0], [1, 1], [1, 2], [0, 2]]]]

    def test_square_mirror_only_when_allowed(self):
        self.assertValid(1, "square", self.L, self.L_PIECES, mirror=True)
        self.assertValid(1, "square", self.L, self.L_PIECES)  # mirror defaults to true in 2D
        self.assertInvalid("mirror images not allowed", "square", self.L, self.L_PIECES, mirror=False)

    def test_square_turned_piece_without_mirror(self):
        # The L turned by a quarter: ###/#.. is a rotation, not a mirror image.
        figs = ["#.\n#.\n##\n", "###\n#..\n"]
        pieces = [[[[0, 0], [0, 1], [0, 2], [1, 2]]], [[[0, 0], [1, 0], [2, 0], [0, 1]]]]
        self.assertValid(1, "square", figs, pieces, mirror=False)

    # -------------------------------------------------------------- tri4

    def test_tri4_halves(self):
        # A square cut along its \ diagonal; the halves laid side by side.
        figs = ["#\n", "C6\n"]
        pieces = [[[[0, 0, 2], [0, 0, 3]], [[0, 0, 0], [0, 0, 1]]],
                  [[[0, 0, 2], [0, 0, 3]], [[1, 0, 1], [1, 0, 2]]]]
        self.assertValid(2, "tri4", figs, pieces, mirror=False)

    def test_tri4_triangles_touching_at_the_centre_are_not_connected(self):
        figs = ["#\n", "#\n"]
        pieces = [[[[0, 0, 0], [0, 0, 2]], [[0, 0, 1], [0, 0, 3]]]] * 2
        self.assertInvalid("not connected", "tri4", figs, pieces)

    def test_tri4_piece_moved(self):
        figs = ["#\n", "C6\n"]
        pieces = [[[[0, 0, 2], [0, 0, 3]], [[0, 0, 0], [0, 0, 1]]],
                  [[[0, 0, 2], [0, 0, 3]], [[1, 0, 0], [1, 0, 1]]]]
        self.assertInvalid("not in the figure", "tri4", figs, pieces)

    def test_tri4_bad_triangle_index(self):
        self.assertInvalid("is not a tri4 cell", "tri4", ["#\n", "#\n"],
                           [[[[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 0, 4]]]] * 2)

    # -------------------------------------------------------------- tri3

    def test_tri3_up_and_down_triangles_are_turns_of_each_other(self):
        self.assertValid(1, "tri3", ["#\n", ".#\n"], [[[[0, 0]]], [[[1, 0]]]], mirror=False)

    def test_tri3_translation(self):
        self.assertValid(1, "tri3", ["##\n", "..##\n"], [[[[0, 0], [1, 0]]], [[[2, 0], [3, 0]]]], mirror=False)

    def test_tri3_mirror_only_when_allowed(self):
        # A 1 x 2 parallelogram leaning one way, then the other: mirror images.
        figs = ["####\n", ".####\n"]
        pieces = [[[[0, 0], [1, 0], [2, 0], [3, 0]]], [[[1, 0], [2, 0], [3, 0], [4, 0]]]]
        self.assertValid(1, "tri3", figs, pieces, mirror=True)
        self.assertInvalid("mirror images not allowed", "tri3", figs, pieces, mirror=False)

    def test_tri3_triangles_touching_at_a_corner_are_not_connected(self):
        # Up (0,0) and up (2,0) touch at a single corner.
        figs = ["#.#\n", "#.#\n"]
        pieces = [[[[0, 0], [2, 0]]], [[[0, 0], [2, 0]]]]
        self.assertInvalid("not connected", "tri3", figs, pieces)

    def test_tri3_rows_stack_without_shift(self):
        # Up (0,0) sits on down (0,1): they share the horizontal edge.
        self.assertValid(1, "tri3", ["#\n#\n", "##\n"], [[[[0, 0], [0, 1]]], [[[0, 0], [1, 0]]]])

    # --------------------------------------------------------------- hex

    def test_hex_odd_rows_are_shifted_right(self):
        # (0,0) and (0,1) touch ((0,1) is below-right); (0,0) and (1,1) do not.
        self.assertValid(1, "hex", ["##\n", "#\n#\n"], [[[[0, 0], [1, 0]]], [[[0, 0], [0, 1]]]], mirror=False)
        self.assertInvalid("not connected", "hex", ["##\n", "#\n.#\n"],
                           [[[[0, 0], [1, 0]]], [[[0, 0], [1, 1]]]])

    def test_hex_mirror_only_when_allowed(self):
        figs = ["###\n..#\n", ".###\n#\n"]
        pieces = [[[[0, 0], [1, 0], [2, 0], [2, 1]]], [[[1, 0], [2, 0], [3, 0], [0, 1]]]]
        self.assertValid(1, "hex", figs, pieces, mirror=True)
        self.assertInvalid("mirror images not allowed", "hex", figs, pieces, mirror=False)

    def test_hex_piece_moved(self):
        figs = ["##\n##\n", "####\n"]
        pieces = [[[[0, 0], [1, 0]], [[0, 1], [1, 1]]], [[[0, 0], [1, 0]], [[2, 0], [3, 0]]]]
        self.assertValid(2, "hex", figs, pieces)
        pieces[1][1] = [[3, 0], [4, 0]]
        self.assertInvalid("not in the figure", "hex", figs, pieces)

    # ------------------------------------------------------------- cubic

    CHIRAL = ["##\n.#\n\n..\n.#\n", "..\n.#\n\n##\n.#\n"]
    CHIRAL_PIECES = [[[[0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 1, 1]]],
                     [[[0, 0, 1], [1, 0, 1], [1, 1, 1], [1, 1, 0]]]]

    def test_cubic_never_mirrors(self):
        self.assertInvalid("not piece 0 of figure 0 moved", "cubic", self.CHIRAL, self.CHIRAL_PIECES, mirror=True)
        self.assertInvalid("not piece 0 of figure 0 moved", "cubic", self.CHIRAL, self.CHIRAL_PIECES)

    def test_cubic_rotation(self):
        # The same chiral piece turned a quarter about the x axis.
        figs = [self.CHIRAL[0], "..\n##\n\n.#\n.#\n"]
        pieces = [self.CHIRAL_PIECES[0], [[[0, 1, 0], [1, 1, 0], [1, 1, 1], [1, 0, 1]]]]
        self.assertValid(1, "cubic", figs, pieces, mirror=False)

    def test_cubic_layers_and_disconnection(self):
        figs = ["##\n##\n", "#\n#\n\n#\n#\n"]
        pieces = [[[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 0]]],
                  [[[0, 0, 0], [0, 1, 0]], [[0, 0, 1], [0, 1, 1]]]]
        self.assertValid(2, "cubic", figs, pieces)
        broken = [[[[0, 0, 0], [1, 1, 0]], [[0, 1, 0], [1, 0, 0]]],
                  [[[0, 0, 0], [0, 1, 1]], [[0, 1, 0], [0, 0, 1]]]]
        self.assertInvalid("not connected", "cubic", figs, broken)

    # ------------------------------------------------------------- files

    def test_the_format_key_is_required(self):
        self.assertInvalid("not \"dissection-solution/1\"", "square", self.SQUARE, self.SQUARE_PIECES,
                           fmt="something/2")

    def test_piece_counts_must_agree(self):
        pieces = [self.SQUARE_PIECES[0], [[[0, 0], [1, 0], [2, 0], [3, 0]]]]
        self.assertInvalid("different or no piece counts", "square", self.SQUARE, pieces)

    def test_a_bad_figure_is_an_input_error(self):
        code, last = self.run_checker("square", ["#x\n", "##\n"], [[[[0, 0]]], [[[0, 0]]]])
        self.assertEqual(code, 2)
        self.assertIn("line 1, column 2", last)

    def test_unreadable_json_is_an_input_error(self):
        code, last = self.run_checker("square", self.SQUARE, [], raw="{ not json")
        self.assertEqual(code, 2)
        self.assertIn("cannot read", last)


if __name__ == "__main__":
    unittest.main()
