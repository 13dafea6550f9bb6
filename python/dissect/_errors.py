"""The exceptions of `dissect`. Each message names the problem."""


class DissectError(Exception):
    """Base class of every error `dissect` raises on purpose."""


class FigureError(DissectError, ValueError):
    """A figure text, cell list or array that is not a valid figure
    (the message names the line and column, or the bad cell)."""


class ProblemError(DissectError, ValueError):
    """Figures that cannot be dissected together: fewer than two, different
    lattices, or different areas (the message gives every figure's area)."""


class OptionError(DissectError, ValueError):
    """An unknown option or a bad option value (the message names it)."""


class InvalidSolution(DissectError, ValueError):
    """A solution that is not a valid dissection of its figures (the message
    lists every violation)."""


class NoDissectionFound(DissectError):
    """The search ended (time limit, max_pieces) without a dissection; the
    message says why and how close the best candidate came."""


class CertificateError(DissectError, ValueError):
    """A certificate folder or file that ``check_proof`` cannot read: no
    ``kK.cnf`` in it, a formula without its proof, a file that is not text
    or not DIMACS/DRAT (the message names the file and line). A proof that
    reads but does not refute its formula is not an error: ``check_proof``
    reports it as failed."""
