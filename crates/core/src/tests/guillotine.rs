//! Guillotine cuts: figures of a few boxes cut into boxes and bent slabs.

use std::sync::atomic::AtomicBool;

use crate::figure::Figure;
use crate::lattice::{Cell, LatticeKind};
use crate::solver::guillotine::{Boxes, Order, Rung, MAX_BOXES, ORDERS, RUNGS};
use crate::tests::util::{geometry, labelled};
use crate::verify::verify_pieces;

/// Cubes of these sides side by side on one floor, one column apart, and
/// the cube of side `whole`.
fn cubes(sides: &[i32], whole: i32) -> [Figure; 2] {
    let mut a: Vec<Cell> = Vec::new();
    let mut x0 = 0;
    for &s in sides {
        for z in 0..s {
            for y in 0..s {
                for x in 0..s {
                    a.push([x0 + x, y, z]);
                }
            }
        }
        x0 += s + 1;
    }
    let b =
        (0..whole).flat_map(|z| (0..whole).flat_map(move |y| (0..whole).map(move |x| [x, y, z])));
    [
        Figure::new(LatticeKind::Cubic, a).expect("cells"),
        Figure::new(LatticeKind::Cubic, b).expect("cells"),
    ]
}

/// Dissects two figures by the search of `rung` in `order`, checks the
/// answer with the verifier and returns its pieces.
fn solved_in(
    rung: Rung,
    order: Order,
    lattice: LatticeKind,
    mirror: bool,
    figs: &[Figure; 2],
) -> Option<usize> {
    let syms = geometry(lattice, mirror).syms;
    let stop = AtomicBool::new(false);
    let boxes = Boxes::new([figs[0].cells(), figs[1].cells()], &syms)?;
    let pieces = boxes.dissect(rung, order, &stop)?;
    verify_pieces(lattice, mirror, figs, &pieces).expect("a valid dissection");
    Some(pieces[0].len())
}

/// [`solved_in`] the first order.
fn solved_by(rung: Rung, lattice: LatticeKind, mirror: bool, figs: &[Figure; 2]) -> Option<usize> {
    solved_in(rung, ORDERS[0], lattice, mirror, figs)
}

/// [`solved_by`] the wider plain beam.
fn solved(lattice: LatticeKind, mirror: bool, figs: &[Figure; 2]) -> Option<usize> {
    solved_by(RUNGS[1], lattice, mirror, figs)
}

/// 1³ + 6³ + 8³ = 9³: the 8³ whole, the 6³ cut into slabs bent round the
/// shell it leaves: 10 pieces (the lower bound is 8), whichever figure
/// comes first.
#[test]
fn sums_of_cubes_get_bent_slabs() {
    let [a, b] = cubes(&[1, 6, 8], 9);
    assert_eq!(
        solved(LatticeKind::Cubic, false, &[a.clone(), b.clone()]),
        Some(10)
    );
    assert_eq!(solved(LatticeKind::Cubic, false, &[b, a]), Some(10));
}

/// 3³ + 4³ + 5³ = 6³, the cubes apart: the plain beam stops at 10 pieces;
/// the pilot of width 32, each state's 16 best children completed
/// greedily, finds an optimal 8 (the corners of the 6³ need 8).
#[test]
fn the_pilot_sees_past_the_score() {
    let [a, b] = cubes(&[3, 4, 5], 6);
    let figs = [a, b];
    assert_eq!(solved(LatticeKind::Cubic, false, &figs), Some(10));
    let pilot = Rung { width: 32, fan: 16 };
    assert!(RUNGS.contains(&pilot));
    assert_eq!(solved_by(pilot, LatticeKind::Cubic, false, &figs), Some(8));
}

/// Every rung in every order, on a small sum of cubes: a valid
/// dissection (checked by the verifier) of 8 (the corner bound) to 13
/// pieces.
#[test]
fn every_rung_dissects() {
    let figs = cubes(&[3, 4, 5], 6);
    for rung in RUNGS {
        for order in ORDERS {
            let k = solved_in(rung, order, LatticeKind::Cubic, false, &figs).expect("boxes");
            assert!((8..=13).contains(&k), "{rung:?} {order:?}: {k} pieces");
        }
    }
}

/// The order the target's boxes are filled in changes the answer: on
/// 3³ + 4³ + 5³ = 6³ the pilot of width 16 gives 9 pieces filling the
/// lowest corner in `(z, y, x)` order first, an optimal 8 in `(x, y, z)`
/// order; so every rung runs every order.
#[test]
fn the_order_of_the_target_boxes_matters() {
    let figs = cubes(&[3, 4, 5], 6);
    let rung = Rung { width: 16, fan: 16 };
    assert!(RUNGS.contains(&rung));
    assert_eq!(ORDERS[0], Order::Low);
    assert!(ORDERS.contains(&Order::LowX));
    let low = solved_in(rung, Order::Low, LatticeKind::Cubic, false, &figs);
    let low_x = solved_in(rung, Order::LowX, LatticeKind::Cubic, false, &figs);
    assert_eq!((low, low_x), (Some(9), Some(8)));
}

/// The square lattice too: 3² + 4² = 5², the squares apart.
#[test]
fn squares_apart_are_cut_into_rectangles() {
    let (a, _) = labelled(LatticeKind::Square, "AAA.AAAA|AAA.AAAA|AAA.AAAA|....AAAA");
    let (b, _) = labelled(LatticeKind::Square, "AAAAA|AAAAA|AAAAA|AAAAA|AAAAA");
    let k = solved(LatticeKind::Square, true, &[a, b]).expect("two rectangles each");
    assert!((4..=6).contains(&k), "{k} pieces");
}

/// A staircase of `steps` steps (one box each) and a rectangle of
/// `rows` rows of the same area.
fn staircase(steps: usize, rows: usize) -> [Figure; 2] {
    let stairs: Vec<String> = (1..=steps).map(|w| "A".repeat(w)).collect();
    let (a, _) = labelled(LatticeKind::Square, &stairs.join("|"));
    let n = a.len();
    let (b, _) = labelled(
        LatticeKind::Square,
        &vec!["A".repeat(n / rows); rows].join("|"),
    );
    assert_eq!(a.len(), b.len());
    [a, b]
}

/// A figure that needs more than `MAX_BOXES` boxes (a staircase) is not
/// searched; one step fewer is.
#[test]
fn figures_of_many_boxes_are_left_alone() {
    assert_eq!(MAX_BOXES, 12);
    assert_eq!(solved(LatticeKind::Square, true, &staircase(13, 7)), None);
    let k = solved(LatticeKind::Square, true, &staircase(12, 6)).expect("12 boxes");
    assert!((2..=12).contains(&k), "{k} pieces");
}

/// Only the square and cubic lattices are grids of boxes.
#[test]
fn only_square_and_cubic_are_grids() {
    use LatticeKind::*;
    for (kind, grid) in [
        (Square, true),
        (Cubic, true),
        (Tri4, false),
        (Tri3, false),
        (Hex, false),
    ] {
        assert_eq!(kind.lattice().is_grid(), grid, "{kind}");
    }
}
