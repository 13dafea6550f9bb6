import json
import subprocess
from pathlib import Path
from typing import Any, Callable, Dict, List, Type

import numpy as np
import pytest

import dissect
from dissect import Figure

from conftest import check_with_verify_py, instance

CASES = [
    ("squares-3-4-split-to-5", "square", 4),
    ("tri-triangle8-to-rect4x8", "tri4", 2),
    ("cube4-cavity-to-7x4x2", "cubic", 4),
]


@pytest.mark.parametrize("name, lattice, pieces", CASES)
def test_solve_shared_instances_checked_by_verify_py(
    name: str, lattice: str, pieces: int, tmp_path: Path
) -> None:
    figures, files = instance(name, lattice)
    d = dissect.solve(figures, seed=1)
    assert d.lattice == lattice
    assert d.piece_count == pieces
    assert len(d.pieces) == len(figures)
    assert d.verify()
    assert dissect.verify(figures, d) == pieces
    check_with_verify_py(d, files, tmp_path)
    assert d.lower_bound is not None and d.lower_bound <= d.piece_count
    assert d.optimal == (d.lower_bound == d.piece_count)
    assert d.history and d.history[-1]["pieces"] == pieces
    assert d.found_by in ("greedy", "search", "repair", "sat")
    sol = json.loads(d.to_json())
    assert sol["format"] == "dissection-solution/1"
    assert [f["name"] for f in sol["figures"]] == [p.name for p in files]
    assert sol["pieces"] == pieces and sol["seed"] == 1


def test_solve_from_arrays_and_thread_count_does_not_matter() -> None:
    a = Figure.from_array(np.ones((3, 4), bool))
    b = Figure.from_array(np.ones((2, 6), bool))
    one = dissect.solve([a, b], seed=5, threads=1)
    two = dissect.solve([a, b], seed=5, threads=2)
    assert one.piece_count == 2
    assert one.pieces == two.pieces
    assert one.names == ["figure-1", "figure-2"]


@pytest.mark.parametrize(
    "args, options",
    [
        ([], {}),
        (["--seed", "2", "--explorations", "40", "--patience", "5", "--no-mirror"],
         {"seed": 2, "explorations": 40, "patience": 5, "mirror": False}),
    ],
)
def test_same_answer_as_the_cli_for_the_same_seed(
    dissect_bin: Path, tmp_path: Path, args: List[str], options: Dict[str, Any]
) -> None:
    figures, files = instance("squares-3-4-split-to-5", "square")
    out = tmp_path / "cli.json"
    r = subprocess.run(
        [str(dissect_bin), "solve", "-q", *args, "-o", str(out), *map(str, files)],
        capture_output=True, text=True,
    )
    assert r.returncode == 0, r.stderr
    cli = json.loads(out.read_text())
    py = json.loads(dissect.solve(figures, **options).to_json())
    assert py["mirror"] == cli["mirror"]
    assert [f["pieces"] for f in py["figures"]] == [f["pieces"] for f in cli["figures"]]
    assert py["pieces"] == cli["pieces"]


def test_verify_rejects_a_bad_solution(tmp_path: Path) -> None:
    figures, _ = instance("squares-3-4-split-to-5", "square")
    d = dissect.solve(figures, seed=1)
    sol = d.to_dict()
    # Move one cell from piece 0 to piece 1 in the first figure.
    sol["figures"][0]["pieces"][1].append(sol["figures"][0]["pieces"][0].pop())
    with pytest.raises(dissect.InvalidSolution) as e:
        dissect.verify(figures, sol)
    assert "not a valid dissection" in str(e.value)
    path = tmp_path / "s.json"
    path.write_text(json.dumps(sol))
    with pytest.raises(dissect.InvalidSolution):
        dissect.verify(figures, path)
    with pytest.raises(dissect.InvalidSolution) as e:
        dissect.verify(figures, "{ not json")
    assert "line 1" in str(e.value)


def test_bound() -> None:
    figures, _ = instance("squares-3-4-split-to-5", "square")
    b = dissect.bound(figures, max_pieces=3, time_limit=60)
    assert b.value == 4 and int(b) == 4
    assert "b.txt" in b.reason and "no piece can hold two" in b.reason
    assert not b.stopped and b.dissection is None


HOLE = Figure.from_text("#####\n#..##\n#..##\n#####\n")
SQUARE_4 = Figure.from_text("####\n####\n####\n####\n")


def test_bound_by_another_solver(tmp_path: Path) -> None:
    """``bound(solver=...)``: stand-in solvers everywhere, CaDiCaL when on
    the PATH (CI installs it), its certificate verified by check-proof."""
    liar = tmp_path / "liar.sh"
    liar.write_text("echo 's UNSATISFIABLE'\n")
    with pytest.raises(dissect.DissectError) as e:
        dissect.bound([HOLE, SQUARE_4], solver=f"sh {liar}", certificate=tmp_path / "liar")
    assert "wrote no proof" in str(e.value)
    with pytest.raises(dissect.OptionError):
        dissect.bound([HOLE, SQUARE_4], solver=" ")
    slow = tmp_path / "slow.sh"
    slow.write_text("sleep 30\n")
    b = dissect.bound([HOLE, SQUARE_4], solver=f"sh {slow}", time_limit=1)
    assert b.stopped and b.certificates == []
    try:
        subprocess.run(["cadical", "--version"], capture_output=True, check=True)
    except (OSError, subprocess.CalledProcessError):
        pytest.skip("no cadical on the PATH")
    cert = tmp_path / "cert"
    b = dissect.bound([HOLE, SQUARE_4], solver="cadical --no-binary", certificate=cert)
    assert b.value == 3 and "cadical: no 2-piece dissection" in b.reason
    assert b.certificates == [2] and not b.stopped
    assert b.dissection is not None and b.dissection.piece_count == 3 and b.dissection.verify()
    assert (cert / "k2.cnf").exists() and (cert / "README.txt").exists()
    assert dissect.check_proof(cert).verdict == "verified: 1 certificate (k2)"


def test_bound_writes_certificates_that_check_proof_verifies(tmp_path: Path) -> None:
    """The built-in solver's certificates (``bound(certificate=...)``),
    replayed by ``check_proof``; a proof with its lemmas gone fails; a
    folder without certificates raises ``CertificateError``."""
    cert = tmp_path / "cert"
    b = dissect.bound([HOLE, SQUARE_4], max_pieces=2, certificate=cert)
    assert b.value == 3 and b.certificates == [1, 2]
    assert "k2.cnf, k2.drat: no dissection into at most 2 pieces" in (
        cert / "README.txt"
    ).read_text()
    lines: List[str] = []
    check = dissect.check_proof(cert, progress=lines.append)
    assert check and check.verified
    assert check.verdict == "verified: 2 certificates (k1, k2)"
    assert [c["k"] for c in check.certificates] == [1, 2]
    assert lines == [c["line"] for c in check.certificates]
    assert lines[1].startswith("k2: verified: no dissection into at most 2 pieces")

    (cert / "k2.drat").write_text("0\n")
    check = dissect.check_proof(str(cert))
    assert not check and check.certificates[0]["verified"]
    assert not check.certificates[1]["verified"]
    assert "k2.drat: proof line 1" in check.certificates[1]["failure"]
    assert check.verdict == "failed: 1 of 2 certificates do not verify"

    with pytest.raises(dissect.CertificateError) as e:
        dissect.check_proof(tmp_path)
    assert "no certificate" in str(e.value)
    (tmp_path / "file").write_text("")
    with pytest.raises(dissect.CertificateError) as e:
        dissect.bound([HOLE, SQUARE_4], max_pieces=2, certificate=tmp_path / "file")
    assert "not a folder" in str(e.value)


def test_no_dissection_found_within_max_pieces() -> None:
    figures, _ = instance("squares-3-4-split-to-5", "square")
    with pytest.raises(dissect.NoDissectionFound) as e:
        dissect.solve(figures, max_pieces=2, explorations=20)
    assert "max_pieces=2" in str(e.value)


def test_time_limit_zero_stops_at_once() -> None:
    figures, _ = instance("squares-6-6-7-split-to-11", "square")
    with pytest.raises(dissect.NoDissectionFound) as e:
        dissect.solve(figures, time_limit=0)
    assert "time limit" in str(e.value)


A = Figure.from_text("###\n###\n")
B = Figure.from_text("######\n")
C = Figure.from_text("#####\n")


@pytest.mark.parametrize(
    "call, cls, words",
    [
        (lambda: dissect.solve([A, C]), dissect.ProblemError, ["different areas", "6 cells", "5 cells"]),
        (lambda: dissect.solve([A]), dissect.ProblemError, ["at least two figures, got 1"]),
        (lambda: dissect.solve([A, Figure.from_text("######", lattice="tri4")]), dissect.ProblemError,
         ["different lattices", "square", "tri4"]),
        (lambda: dissect.solve([A, "######"]), dissect.ProblemError,  # type: ignore[list-item]
         ["figure 2 is a str"]),
        (lambda: dissect.solve(A), dissect.ProblemError, ["list"]),  # type: ignore[arg-type]
        (lambda: dissect.solve([A, B], explorashuns=3), dissect.OptionError, ["unknown option", "explorashuns"]),
        (lambda: dissect.solve([A, B], explorations=-1), dissect.OptionError, ["explorations", "-1"]),
        (lambda: dissect.solve([A, B], area_weight=float("nan")), dissect.OptionError, ["area_weight"]),
        (lambda: dissect.solve([A, B], time_limit=-2), dissect.OptionError, ["time_limit", "-2"]),
        (lambda: dissect.solve([A, B], threads=1000), dissect.OptionError, ["threads=1000"]),
        (lambda: dissect.solve([A, B], mirror="yes"), dissect.OptionError,  # type: ignore[arg-type]
         ["mirror", "True or False"]),
    ],
)
def test_errors_are_exceptions_naming_the_problem(
    call: Callable[[], object], cls: Type[Exception], words: List[str]
) -> None:
    with pytest.raises(cls) as e:
        call()
    assert isinstance(e.value, dissect.DissectError)
    for w in words:
        assert w in str(e.value)
