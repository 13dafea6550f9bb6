//! Random flood fill: every cell gets a label, seeds keep theirs, and in a
//! connected figure every cluster grown from one seed stays connected.

use crate::lattice::LatticeKind;
use crate::solver::flood_fill::{flood_fill, Fallback};
use crate::solver::piece::{Pieces, UNSET};

use super::util::{candidate, draw_square, rng, Cubic, Square, Tri4};

/// Fills the `?` cells of `labelled` (one seed per label) with many random
/// streams and checks the result.
fn check(lattice: LatticeKind, labelled: &str) {
    let (figures, problem, cand) = candidate(lattice, true, &[labelled]);
    let shape = &problem.shapes[0];
    let start = &cand.labels[0];
    assert_eq!(figures[0].components().len(), 1, "a connected figure");
    let k = cand.k;
    for seed in 0..20 {
        let mut labels = start.clone();
        flood_fill(shape, &mut labels, Fallback::Random(k), &mut rng(seed));
        assert!(
            labels.iter().all(|l| (*l as usize) < k),
            "{labelled:?}: {labels:?}"
        );
        for (c, &l) in start.iter().enumerate() {
            if l != UNSET {
                assert_eq!(labels[c], l, "seed cell {c} of {labelled:?} changed");
            }
        }
        let pieces = Pieces::of(shape, &labels, k);
        let mut scratch = vec![false; shape.len()];
        for i in 0..k {
            assert!(pieces.size(i) > 0, "label {i} of {labelled:?}");
            assert_eq!(
                pieces.components(shape, i, &mut scratch),
                1,
                "cluster {i} of {labelled:?} is split: {labels:?}"
            );
        }
    }
}

#[test]
fn fills_connected_clusters() {
    check(Square, "A????|?????|????B");
    check(Square, "A??|?.?|??B");
    check(Square, "?A?|?.?|?B?|?.?|?C?");
    check(Square, "A???????????????????????????????????B");
    check(Square, "AB|??");
    check(Tri4, "A??? ????|???? ???B");
    check(Tri4, "A??? ???? ????|???? . ????|???? ???? B??C");
    check(Cubic, "A??|???/???|??B");
    check(Cubic, "A?|??/??|?./?.|C?/B?|??");
}

#[test]
fn unreachable_cells_fall_back() {
    // Two components; the right one has no seed.
    let (_, problem, cand) = candidate(Square, true, &["A?.??"]);
    let shape = &problem.shapes[0];
    let previous = [0u16, 0, 1, 1];
    for seed in 0..10 {
        let mut labels = cand.labels[0].clone();
        flood_fill(
            shape,
            &mut labels,
            Fallback::Previous(&previous),
            &mut rng(seed),
        );
        assert_eq!(labels, vec![0, 0, 1, 1]);
        let mut labels = cand.labels[0].clone();
        flood_fill(shape, &mut labels, Fallback::Random(5), &mut rng(seed));
        assert_eq!(&labels[..2], &[0, 0]);
        assert!(labels[2] < 5 && labels[2] == labels[3], "{labels:?}");
    }
    // Nothing labelled at all.
    let (figures, problem, cand) = candidate(Square, true, &["???|???"]);
    let mut labels = cand.labels[0].clone();
    flood_fill(
        &problem.shapes[0],
        &mut labels,
        Fallback::Random(3),
        &mut rng(1),
    );
    assert!(
        labels.iter().all(|l| *l < 3),
        "{}",
        draw_square(&figures[0], &labels)
    );
}

#[test]
fn a_full_labelling_is_left_alone() {
    let (_, problem, cand) = candidate(Square, true, &["AB|CA"]);
    let mut labels = cand.labels[0].clone();
    flood_fill(
        &problem.shapes[0],
        &mut labels,
        Fallback::Random(3),
        &mut rng(3),
    );
    assert_eq!(labels, cand.labels[0]);
}
