"""Shared helpers: the shared instances, the independent checkers of
solution files (../shared/tools/verify.py, and tools/check_solution.py of
this repository when present) and the `dissect` binary for CLI comparisons."""

import os
import subprocess
import sys
from pathlib import Path
from typing import List, Sequence, Tuple

import pytest

import dissect

REPO = Path(__file__).resolve().parents[2]
SHARED = Path(os.environ.get("DISSECT_SHARED", REPO.parent / "shared"))
INSTANCES = SHARED / "instances"
VERIFY_PY = SHARED / "tools" / "verify.py"
CHECK_SOLUTION_PY = REPO / "tools" / "check_solution.py"


def instance(name: str, lattice: str) -> Tuple[List[dissect.Figure], List[Path]]:
    """The figures of a shared instance, named after their files."""
    d = INSTANCES / name
    files = sorted(p for p in d.iterdir() if p.suffix == ".txt")
    return [dissect.read_figure(p, lattice=lattice) for p in files], files


def checkers() -> List[Path]:
    """The independent checkers of solution files that this checkout has."""
    found = [p for p in (VERIFY_PY, CHECK_SOLUTION_PY) if p.exists()]
    assert found, f"no independent checker: neither {VERIFY_PY} nor {CHECK_SOLUTION_PY}"
    return found


def check_with_verify_py(
    dissection: dissect.Dissection, files: Sequence[Path], tmp_path: Path
) -> str:
    """Runs every independent checker on the dissection's JSON and its
    figure files; returns the last line of the last one."""
    sol = tmp_path / "solution.json"
    dissection.to_json(sol)
    last = ""
    for checker in checkers():
        r = subprocess.run(
            [sys.executable, str(checker), "--lattice", dissection.lattice,
             "--solution", str(sol), *map(str, files)],
            capture_output=True, text=True,
        )
        last = (r.stdout.strip().splitlines() or [""])[-1]
        assert r.returncode == 0, f"{checker.name} rejected the solution: {r.stdout}{r.stderr}"
        assert last == f"valid: {dissection.piece_count} pieces", last
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
