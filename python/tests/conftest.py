"""Shared helpers: the shared instances, the independent checker
(../shared/tools/verify.py) and the `dissect` binary for CLI comparisons."""

import os
import subprocess
import sys
from pathlib import Path

import pytest

import dissect

REPO = Path(__file__).resolve().parents[2]
SHARED = Path(os.environ.get("DISSECT_SHARED", REPO.parent / "shared"))
INSTANCES = SHARED / "instances"
VERIFY_PY = SHARED / "tools" / "verify.py"


def instance(name, lattice):
    """The figures of a shared instance, named after their files."""
    d = INSTANCES / name
    files = sorted(p for p in d.iterdir() if p.suffix == ".txt")
    return [dissect.read_figure(p, lattice=lattice) for p in files], files


def check_with_verify_py(dissection, files, tmp_path):
    """Runs the external checker on the dissection's JSON; returns its last line."""
    sol = tmp_path / "solution.json"
    dissection.to_json(sol)
    r = subprocess.run(
        [sys.executable, str(VERIFY_PY), "--lattice", dissection.lattice,
         "--solution", str(sol), *map(str, files)],
        capture_output=True, text=True,
    )
    last = (r.stdout.strip().splitlines() or [""])[-1]
    assert r.returncode == 0, f"verify.py rejected the solution: {r.stdout}{r.stderr}"
    assert last == f"valid: {dissection.piece_count} pieces", last
    return last


@pytest.fixture(scope="session")
def dissect_bin():
    """The CLI binary: $DISSECT_BIN, or target/release/dissect of this checkout."""
    target = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    path = Path(os.environ.get("DISSECT_BIN", target / "release" / "dissect"))
    if not path.exists():
        pytest.fail(f"{path} not found: build it with `cargo build --release -p dissect-cli`")
    return path
