//! Refinement steps: conflicting cells, copy-paste with hole filling and
//! label switching (`pivot_step`), `refine` and `all_connected`.

use std::sync::atomic::AtomicBool;

use crate::lattice::{Cell, LatticeKind};
use crate::solver::refine::{
    all_connected, conflicts, mismatched_cells, pivot_step, refine_with_patience, Motions,
};

use super::util::{candidate, labelled, rng, verified, Cubic, Square, Tri4};

/// The cells of figure `f` named by index.
fn cells(figure: &crate::figure::Figure, idx: &[u32]) -> Vec<Cell> {
    idx.iter().map(|&c| figure.cells()[c as usize]).collect()
}

/// With figure 0 as the pivot, the conflicting cells of each figure (against
/// the pivot only, and against all figures) are `expected[f]`.
fn check_conflicts(lattice: LatticeKind, labelled: &[&str], expected: &[&[Cell]]) {
    let (figures, problem, mut cand) = candidate(lattice, false, labelled);
    let aligned = cand.align(&problem, 0);
    let motions = Motions::of(&aligned, 0, cand.k);
    for (f, want) in expected.iter().enumerate() {
        let got = conflicts(&problem, &cand, &motions, f, true);
        assert_eq!(
            cells(&figures[f], &got),
            want.to_vec(),
            "figure {f} of {labelled:?}"
        );
        // Comparing with the pivot alone finds a subset.
        let pivot_only = conflicts(&problem, &cand, &motions, f, false);
        assert!(
            pivot_only.iter().all(|c| got.contains(c)),
            "figure {f} of {labelled:?}"
        );
    }
    let mut again = cand.clone();
    let marked = mismatched_cells(&problem, &mut again);
    for (f, want) in expected.iter().enumerate() {
        assert_eq!(
            cells(&figures[f], &marked[f]),
            want.to_vec(),
            "mismatched, figure {f}"
        );
    }
}

#[test]
fn conflicting_cells() {
    check_conflicts(Square, &["AB|AB", "AABB"], &[&[], &[]]);
    check_conflicts(Square, &["AB|AB", "BBAA"], &[&[], &[]]);
    // L4 + domino against P5 + single: the P's extra cell conflicts.
    // L5 + a 6-cell piece against L6 + J5: (4, 0) changed sides, so it
    // conflicts in the other figure and its image conflicts in the pivot
    // (and in a copy of the pivot as a third figure).
    let (pivot, moved) = ("AAAAB|ABBBB|....B", "AAAAA|ABBBB|....B");
    check_conflicts(Square, &[pivot, moved], &[&[[4, 0, 0]], &[[4, 0, 0]]]);
    check_conflicts(
        Square,
        &[pivot, moved, pivot],
        &[&[[4, 0, 0]], &[[4, 0, 0]], &[[4, 0, 0]]],
    );
    check_conflicts(
        Tri4,
        &["AABB A..A|B..B .", ".AA. ..AA|BB.. B..B"],
        &[&[], &[]],
    );
    check_conflicts(Cubic, &["AA|AA/BB|BB", "AABB|AABB"], &[&[], &[]]);
}

/// One `pivot_step` with pivot 0 turns the second figure's labels into
/// `after`, whatever the random stream: the copy-paste of the pivot's pieces.
fn check_paste(lattice: LatticeKind, pivot: &str, other: &str, after: &str) {
    let (figures, problem, cand) = candidate(lattice, false, &[pivot, other]);
    let (_, want) = labelled(lattice, after);
    for seed in 0..8 {
        let mut c = cand.clone();
        let conflicts = pivot_step(&problem, &mut c, 0, &mut rng(seed));
        assert_eq!(conflicts, 0, "{pivot:?} -> {other:?}");
        assert_eq!(c.labels[0], cand.labels[0], "the pivot is not changed");
        assert_eq!(c.labels[1], want, "{pivot:?} pasted into {other:?}");
        assert!(verified(lattice, false, &figures, &c));
    }
}

#[test]
fn copy_paste_takes_the_pivots_pieces() {
    check_paste(Square, "AAB", "ABB", "BAA");
    check_paste(Square, "AAB", "BAA", "BAA");
    // The figure turned by 90 degrees, its labels swapped.
    check_paste(Square, "AAA|ABB", "BB|AB|AB", "AA|BA|BA");
    // Turned by 180 degrees, labels renamed.
    check_paste(Square, "AAA|ABB|CCB", "ABB|AAC|CCC", "BCC|BBA|AAA");
    // A square and a half square, turned by 180 degrees, labels swapped.
    check_paste(Tri4, "AAAA B..B", ".AA. BBBB", ".BB. AAAA");
    // A flat figure stood up into the x-z plane.
    check_paste(Cubic, "AAA|ABB", "BBB/BAA", "AAA/ABB");
}

/// With three figures, `pivot_step` with pivot `pivot` gives every figure
/// the labels `after` (the pivot's own included): the pivot's pieces are
/// pasted into every other figure and carry their labels there.
fn check_paste_all(lattice: LatticeKind, figures: &[&str], pivot: usize, after: &[&str]) {
    let (figs, problem, cand) = candidate(lattice, false, figures);
    for seed in 0..8 {
        let mut c = cand.clone();
        let conflicts = pivot_step(&problem, &mut c, pivot, &mut rng(seed));
        assert_eq!(conflicts, 0, "{figures:?} with pivot {pivot}");
        for (f, want) in after.iter().enumerate() {
            let (_, want) = labelled(lattice, want);
            assert_eq!(
                c.labels[f], want,
                "figure {f} of {figures:?}, pivot {pivot}"
            );
        }
        assert!(verified(lattice, false, &figs, &c));
    }
}

#[test]
fn copy_paste_from_any_pivot() {
    // L4 + domino: as given, turned by 90 degrees, turned by 180 degrees;
    // labels renamed in the other figures.
    let figures = ["BB|AB|AB", "AAB|BBB", "AAA|ABB"];
    check_paste_all(Square, &figures, 2, &["AA|BA|BA", "BBA|AAA", "AAA|ABB"]);
    check_paste_all(Square, &figures, 0, &["BB|AB|AB", "AAB|BBB", "BBB|BAA"]);
    check_paste_all(
        Cubic,
        &["AAA|ABB", "BBB/BAA", "A|A|A/A|B|B"],
        0,
        &["AAA|ABB", "AAA/ABB", "A|A|A/A|B|B"],
    );
}

/// Aligning to a pivot renames the other figures' labels to the pivot's
/// (matched pieces share a label) and leaves the pivot alone.
fn check_align(lattice: LatticeKind, figures: &[&str], pivot: usize, after: &[&str], cost: &[u64]) {
    let (_, problem, cand) = candidate(lattice, true, figures);
    let mut c = cand.clone();
    let aligned = c.align(&problem, pivot);
    for (f, want) in after.iter().enumerate() {
        let (_, want) = labelled(lattice, want);
        assert_eq!(
            c.labels[f], want,
            "figure {f} of {figures:?}, pivot {pivot}"
        );
        match &aligned.matchings[f] {
            None => assert_eq!(f, pivot),
            Some(m) => assert_eq!(m.cost, cost[f], "cost to figure {f}"),
        }
    }
}

#[test]
fn alignment_to_a_pivot() {
    let figures = ["AAB", "ABB", "B|A|A"];
    check_align(Square, &figures, 0, &["AAB", "BAA", "B|A|A"], &[0, 0, 0]);
    check_align(Square, &figures, 1, &["BBA", "ABB", "A|B|B"], &[0, 0, 0]);
    check_align(Square, &figures, 2, &["AAB", "BAA", "B|A|A"], &[0, 0, 0]);
    // Costs are the matched distances: I3 + single against L3 + single.
    check_align(
        Square,
        &["AAAB", "BB|BA", "BAAA"],
        0,
        &["AAAB", "AA|AB", "BAAA"],
        &[0, 2, 0],
    );
}

/// `pivot_step` on imperfect candidates: the pivot keeps its labels (with
/// two figures), every cell keeps a valid label, and a step that reports no
/// conflict leaves matching pieces.
fn check_step(lattice: LatticeKind, labelled: &[&str]) {
    let (figures, problem, cand) = candidate(lattice, true, labelled);
    for pivot in 0..labelled.len() {
        for seed in 0..8 {
            let mut c = cand.clone();
            let n = pivot_step(&problem, &mut c, pivot, &mut rng(seed));
            assert_eq!(c.k, cand.k);
            for labels in &c.labels {
                assert!(labels.iter().all(|l| (*l as usize) < c.k), "{labels:?}");
            }
            if labelled.len() == 2 {
                assert_eq!(c.labels[pivot], cand.labels[pivot], "pivot {pivot}");
            }
            if n == 0 && all_connected(&problem, &c) {
                assert!(verified(lattice, true, &figures, &c), "{:?}", c.labels);
            }
        }
    }
}

#[test]
fn pivot_steps_keep_labellings_sound() {
    check_step(Square, &["AAA|ABB", "AAA|AAB"]);
    check_step(Square, &["AAB|ABB|CCC", "ABC|ABC|BBC"]);
    check_step(Square, &["AAA|ABB", "AAA|AAB", "AB|AB|AB"]);
    check_step(Tri4, &["AABB A..A|B..B .", ".AB. ..AA|BB.. B..B"]);
    check_step(Cubic, &["AA|AA/BB|BB", "ABBB|AABB", "AA|BA|BB|BB"]);
}

/// With three figures the pivot changes only by label switching: a changed
/// cell lay on a piece boundary and took the old label of a neighbour.
fn check_switching(lattice: LatticeKind, labelled: &[&str]) {
    assert_eq!(labelled.len(), 3);
    let (_, problem, cand) = candidate(lattice, true, labelled);
    let shape = &problem.shapes[0];
    let old = &cand.labels[0];
    let mut changed = 0;
    for seed in 0..16 {
        let mut c = cand.clone();
        pivot_step(&problem, &mut c, 0, &mut rng(seed));
        for (cell, (&before, &after)) in old.iter().zip(&c.labels[0]).enumerate() {
            if before == after {
                continue;
            }
            changed += 1;
            let nbrs: Vec<u16> = shape
                .neighbors(cell as u32)
                .iter()
                .map(|&n| old[n as usize])
                .collect();
            assert!(
                nbrs.iter().any(|&l| l != before),
                "cell {cell} was not on a boundary"
            );
            assert!(
                nbrs.contains(&after),
                "cell {cell} took a label no neighbour had"
            );
        }
    }
    assert!(
        changed > 0,
        "label switching changed nothing in {labelled:?}"
    );
}

#[test]
fn label_switching_changes_only_boundary_cells() {
    check_switching(Square, &["AAA|ABB", "AAA|AAB", "AB|AB|AB"]);
    check_switching(
        Square,
        &["AAAB|ACCB|ACCB", "AAAA|BCCB|BCCB", "AAAAAA|BBCCBB"],
    );
    check_switching(Cubic, &["AA|AB/BB|BB", "ABBB|AABB", "AA|BA|BB|BB"]);
}

/// `refine_with_patience` (the paper's loop: patience 0) leaves a valid dissection valid (up to renaming the labels).
fn check_stays_valid(lattice: LatticeKind, mirror: bool, labelled: &[&str]) {
    let (figures, problem, cand) = candidate(lattice, mirror, labelled);
    assert!(verified(lattice, mirror, &figures, &cand), "start is valid");
    assert!(all_connected(&problem, &cand));
    for seed in 0..4 {
        let mut c = cand.clone();
        refine_with_patience(
            &problem,
            &mut c,
            10,
            0,
            &mut rng(seed),
            &AtomicBool::new(false),
        );
        assert!(
            verified(lattice, mirror, &figures, &c),
            "{labelled:?}: {:?}",
            c.labels
        );
        let mut scored = c.clone();
        let score = scored.evaluate(&problem, 0.5, 1000.0);
        assert!(
            score.valid && score.mismatch == 0 && score.split == 0,
            "{score:?}"
        );
    }
}

#[test]
fn refine_keeps_valid_candidates_valid() {
    check_stays_valid(Square, true, &["AB|AB", "AABB"]);
    check_stays_valid(Square, false, &["AAB|ACB|CCB", "AABBB|.ACC.|..C.."]);
    check_stays_valid(Square, true, &["AB|AB", "AABB", "A|A|B|B"]);
    check_stays_valid(Tri4, true, &["AABB A..A|B..B .", ".AA. ..AA|BB.. B..B"]);
    check_stays_valid(Cubic, false, &["AA|AA/BB|BB", "AABB|AABB", "AA|AA|BB|BB"]);
}

#[test]
fn refine_repairs_a_small_mismatch() {
    // L4 + domino against P5 + single: some stream repairs it.
    let (figures, problem, cand) = candidate(Square, false, &["AAA|ABB", "AAA|AAB"]);
    let repaired = (0..10)
        .filter(|&seed| {
            let mut c = cand.clone();
            refine_with_patience(
                &problem,
                &mut c,
                10,
                0,
                &mut rng(seed),
                &AtomicBool::new(false),
            );
            verified(Square, false, &figures, &c)
        })
        .count();
    assert!(repaired > 0, "refine never repaired the candidate");
}

#[test]
fn refine_stops_when_asked() {
    let (_, problem, cand) = candidate(Square, false, &["AAA|ABB", "AAA|AAB"]);
    let mut c = cand.clone();
    refine_with_patience(
        &problem,
        &mut c,
        100,
        0,
        &mut rng(1),
        &AtomicBool::new(true),
    );
    assert_eq!(c, cand);
}

#[test]
fn connectedness() {
    let connected = |lattice, labelled: &[&str]| {
        let (_, problem, cand) = candidate(lattice, true, labelled);
        all_connected(&problem, &cand)
    };
    assert!(connected(Square, &["AB", "AB"]));
    assert!(!connected(Square, &["ABA", "AAB"]));
    assert!(!connected(Square, &["AAB", "ABA"]));
    // A label missing from a figure is an empty piece, not a split one.
    assert!(connected(Square, &["AAB", "AAA"]));
    assert!(!connected(Tri4, &["ABAB", "AABB"]));
    assert!(connected(Tri4, &["AABB", "ABBA"]));
    assert!(!connected(Cubic, &["A./.A", "AA"]));
}
