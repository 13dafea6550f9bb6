"""dissect.enumerate: every dissection with K pieces, as `dissect enumerate`
counts them (the counts are those the exact crate's brute-force tests
check, crates/exact/tests/enumerate.rs)."""

from pathlib import Path
from typing import List

import pytest

import dissect
from dissect import Figure

from conftest import check_with_verify_py


def test_counts_classes_and_verified_class_files(tmp_path: Path) -> None:
    a = Figure.from_text("###\n###\n", name="rect.txt")
    b = Figure.from_text("######\n", name="bar.txt")
    e = dissect.enumerate([a, b], pieces=3)
    assert e.complete and not e.stopped
    assert (e.count, len(e.classes), e.pieces) == (7, 3, 3)
    assert sum(e.class_sizes) == 7
    assert e.summary() == (
        "7 dissections with 3 pieces (3 up to the first figure's symmetries), complete"
    )
    files: List[Path] = []
    for f, text in (("rect.txt", "###\n###\n"), ("bar.txt", "######\n")):
        (tmp_path / f).write_text(text)
        files.append(tmp_path / f)
    for d in e.classes:
        assert d.piece_count == 3
        assert dissect.verify([a, b], d) == 3
        assert "valid" in check_with_verify_py(d, files, tmp_path)
    cuts = {tuple(sorted(tuple(sorted(p)) for p in d[0])) for d in e.dissections}
    assert len(cuts) == 7


def test_minimum_unique_rank_and_stop() -> None:
    a = Figure.from_text("####\n" * 4)
    b = Figure.from_text("########\n" * 2)
    m = dissect.enumerate([a, b])
    assert m.minimum and m.complete and (m.pieces, m.count, len(m.classes)) == (2, 2, 1)
    u = dissect.enumerate([a, b], pieces=3, unique=True)
    assert (u.count, len(u.classes)) == (36, 6)
    r = dissect.enumerate([a, b], pieces=3, rank="smallest")
    smallest = [min(d.areas) for d in r.classes]
    assert smallest == sorted(smallest, reverse=True)
    s = dissect.enumerate([a, b], time_limit=0)
    assert not s.complete and s.stopped


def test_bad_options_raise() -> None:
    a = Figure.from_text("###\n###\n")
    b = Figure.from_text("######\n")
    with pytest.raises(dissect.OptionError):
        dissect.enumerate([a, b], rank="beauty")
    with pytest.raises(dissect.OptionError):
        dissect.enumerate([a, b], time_limit=-1)
    with pytest.raises(dissect.OptionError):
        dissect.enumerate([a, b], pieces=0)
    with pytest.raises(dissect.ProblemError):
        dissect.enumerate([a, Figure.from_text("#####\n")])
