"""Shared helpers: the repository's benchmark instances (instances/), the
independent checkers (tools/check_solution.py of this repository, and the
external oracle verify.py when $DISSECT_VERIFY names it: CI's Python step
sets it when the project's shared folder is beside the checkout) and the
`dissect` binary for CLI comparisons."""

import os
import subprocess
import sys
import warnings
from pathlib import Path
from typing import List, Sequence, Tuple

import pytest

import dissect

REPO = Path(__file__).resolve().parents[2]
INSTANCES = REPO / "instances"
CHECK_SOLUTION = REPO / "tools" / "check_solution.py"
_VERIFY = os.environ.get("DISSECT_VERIFY")
VERIFY_PY = Path(_VERIFY) if _VERIFY else None
_skipped: List[bool] = []


def instance(name: str, lattice: str) -> Tuple[List[dissect.Figure], List[Path]]:
    """The figures of an instance of instances/, named after their files."""
    d = INSTANCES / name
    files = sorted(p for p in d.iterdir() if p.suffix == ".txt")
    return [dissect.read_figure(p, lattice=lattice) for p in files], files


def _run_checker(
    script: Path, dissection: dissect.Dissection, sol: Path, files: Sequence[Path]
) -> str:
    r = subprocess.run(
        [sys.executable, str(script), "--lattice", dissection.lattice,
         "--solution", str(sol), *map(str, files)],
        capture_output=True, text=True,
    )
    last = (r.stdout.strip().splitlines() or [""])[-1]
    assert r.returncode == 0, f"{script.name} rejected the solution: {r.stdout}{r.stderr}"
    assert last == f"valid: {dissection.piece_count} pieces", last
    return last


def check_with_verify_py(
    dissection: dissect.Dissection, files: Sequence[Path], tmp_path: Path
) -> str:
    """Checks the dissection's JSON with tools/check_solution.py and, when it
    is present, the external verify.py (otherwise says once that it skipped
    it); returns the last line."""
    sol = tmp_path / "solution.json"
    dissection.to_json(sol)
    last = _run_checker(CHECK_SOLUTION, dissection, sol, files)
    if VERIFY_PY is not None and VERIFY_PY.is_file():
        _run_checker(VERIFY_PY, dissection, sol, files)
    elif not _skipped:
        _skipped.append(True)
        # A warning, so that pytest's summary shows it once.
        why = f"{VERIFY_PY} not found" if VERIFY_PY else "DISSECT_VERIFY is not set"
        warnings.warn(f"{why}: the external oracle's checks are skipped")
    return last


def check_independently(dissection: dissect.Dissection, tmp_path: Path) -> None:
    """`dissect.verify` and the independent checkers, the figures written
    from their text (figures made from text keep their coordinates)."""
    assert dissect.verify(dissection.figures, dissection) == dissection.piece_count
    tmp_path.mkdir(parents=True, exist_ok=True)
    files = []
    for f, name in zip(dissection.figures, dissection.names):
        p = tmp_path / name
        p.write_text(f.to_text())
        files.append(p)
    check_with_verify_py(dissection, files, tmp_path)


@pytest.fixture(scope="session")
def dissect_bin() -> Path:
    """The CLI binary: $DISSECT_BIN, or target/release/dissect of this checkout."""
    target = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    path = Path(os.environ.get("DISSECT_BIN", target / "release" / "dissect"))
    if not path.exists():
        pytest.fail(f"{path} not found: build it with `cargo build --release -p dissect-cli`")
    return path
