//! Coarse to fine: halving figures (equal areas, the best block phase),
//! lifting a coarse dissection, and `from_coarse` end to end.

use std::sync::atomic::AtomicBool;

use crate::figure::Figure;
use crate::lattice::Cell;
use crate::solver::candidate::Problem;
use crate::solver::coarse::{downsample, from_coarse, MIN_CELLS};
use crate::solver::shape::Shape;
use crate::solver::{Found, Options};

use super::util::{geometry, labelled, rng, verified, Cubic, Square, Tri4};

/// `figure` with every cell made a `k`-block (k×k, or k×k×k on cubic),
/// moved by `offset` cells.
fn enlarged(figure: &Figure, k: i32, offset: Cell) -> Figure {
    let dims = figure.lattice().lattice().dim();
    let mut cells = Vec::new();
    for c in figure.cells() {
        for dz in 0..if dims == 3 { k } else { 1 } {
            for dy in 0..k {
                for dx in 0..k {
                    cells.push([
                        c[0] * k + dx + offset[0],
                        c[1] * k + dy + offset[1],
                        c[2] * k + dz + offset[2],
                    ]);
                }
            }
        }
    }
    Figure::new(figure.lattice(), cells).expect("enlarged figure")
}

#[test]
fn halving_an_enlarged_figure_gives_it_back_whatever_its_block_phase() {
    let (small, _) = labelled(Square, "AAA.|A.AA|AAAA");
    for offset in [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [-3, 5, 0]] {
        let big = enlarged(&small, 2, offset);
        let coarse = downsample(&[big.clone(), big], 2).expect("square coarsens");
        for fig in &coarse.figures {
            assert_eq!(fig.len(), small.len(), "offset {offset:?}");
            // The same shape, up to a translation.
            let shift = |f: &Figure| {
                let c0 = f.cells()[0];
                f.cells()
                    .iter()
                    .map(|c| [c[0] - c0[0], c[1] - c0[1], c[2] - c0[2]])
                    .collect::<Vec<_>>()
            };
            assert_eq!(shift(fig), shift(&small), "offset {offset:?}");
        }
    }
    let (cube, _) = labelled(Cubic, "AA|A./A.|..");
    let coarse = downsample(&[enlarged(&cube, 2, [1, 0, 1])], 2).expect("cubic coarsens");
    assert_eq!(coarse.figures[0].len(), cube.len());
}

#[test]
fn coarse_figures_have_equal_areas_and_the_fullest_blocks() {
    // 10 cells: a 2×5 bar and a plus-like blob; 10 / 4 → 3 coarse cells each.
    let (bar, _) = labelled(Square, "AAAAA|AAAAA");
    let (blob, _) = labelled(Square, ".AA.|AAAA|.AA.|..AA");
    let coarse = downsample(&[bar, blob], 2).expect("square coarsens");
    let areas: Vec<usize> = coarse.figures.iter().map(Figure::len).collect();
    assert_eq!(areas, vec![3, 3]);
}

#[test]
fn lattices_without_coarsening_and_tiny_figures_are_left_alone() {
    let (tri, _) = labelled(Tri4, "AAAA AAAA|AAAA AAAA");
    assert!(downsample(&[tri.clone(), tri], 2).is_none());
    let (one, _) = labelled(Square, "AA");
    assert!(downsample(&[one.clone(), one], 2).is_none());
    assert!(Square.lattice().coarse_cell([0, 0, 0], 2, 4).is_none());
    assert!(Square.lattice().coarse_cell([0, 0, 0], 0, 0).is_none());
}

/// A 2×12 bar and a 4×6 rectangle (two pieces: the bar's halves, one on
/// the other), and the same enlarged `k` times, moved off the block grid.
fn two_piece_instance(k: i32) -> (Vec<Figure>, Vec<Figure>) {
    let (bar, _) = labelled(Square, "AAAAAAAAAAAA|AAAAAAAAAAAA");
    let (block, _) = labelled(Square, "AAAAAA|AAAAAA|AAAAAA|AAAAAA");
    let small = vec![bar, block];
    let big = small
        .iter()
        .enumerate()
        .map(|(i, f)| enlarged(f, k, [i as i32 * 3, 1, 0]))
        .collect();
    (small, big)
}

#[test]
fn a_coarse_dissection_lifts_to_a_valid_fine_one() {
    let (_, big) = two_piece_instance(5);
    assert!(big[0].len() >= MIN_CELLS);
    let problem = Problem::new(
        big.iter().map(Shape::of_figure).collect(),
        geometry(Square, true),
    );
    let stop = AtomicBool::new(false);
    let options = Options {
        threads: 1,
        ..Options::default()
    };
    let mut coarse_calls = Vec::new();
    let (cand, score) = from_coarse(&big, &problem, &options, 7, &stop, |figs| {
        coarse_calls.push(figs[0].len());
        let out = crate::solver::solve(figs, &options, &stop, &()).expect("solves");
        out.found
    })
    .expect("a coarse dissection");
    assert_eq!(coarse_calls, vec![big[0].len().div_ceil(4)]);
    assert!(score.valid, "{score:?}");
    assert_eq!(cand.k, 2);
    assert!(verified(Square, true, &big, &cand));
}

#[test]
fn lifting_keeps_the_coarse_pieces_and_fills_left_out_cells() {
    // The coarse dissection: the bar's two halves. Every fine cell of a
    // full block takes its block's piece; the lift is valid at once.
    let (small, big) = two_piece_instance(2);
    let coarse = downsample(&big, 2).expect("coarsens");
    assert_eq!(coarse.figures[0].len(), small[0].len());
    let pieces: Vec<Vec<Vec<Cell>>> = coarse
        .figures
        .iter()
        .map(|f| {
            let (x0, x1): (Vec<Cell>, Vec<Cell>) = if f.stats().max[0] - f.stats().min[0] > 6 {
                let mid = f.stats().min[0] + 6;
                f.cells().iter().partition(|c| c[0] < mid)
            } else {
                let mid = f.stats().min[1] + 2;
                f.cells().iter().partition(|c| c[1] < mid)
            };
            vec![x0, x1]
        })
        .collect();
    let found = Found {
        pieces,
        level: 1,
        variance: 0.0,
    };
    let problem = Problem::new(
        big.iter().map(Shape::of_figure).collect(),
        geometry(Square, true),
    );
    let cand = coarse.lift(&problem, &found, &mut rng(1));
    assert!(verified(Square, true, &big, &cand));
}
