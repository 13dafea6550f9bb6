//! The sector dissection of large figures: one large common piece, and
//! what is left cut into sectors of equal area in every figure.

use std::sync::atomic::AtomicBool;

use crate::figure::Figure;
use crate::lattice::{Cell, LatticeKind, Point};
use crate::solver::candidate::Problem;
use crate::solver::greedy::{greedy, Choice, GreedyStyle};
use crate::solver::sectors::{dissect, plans, Plan};
use crate::solver::shape::Shape;
use crate::solver::Repair;
use crate::tests::util::{candidate, cells_by_label, geometry};

/// A `side`×`side` square (in a frame with a margin of 3) whose four
/// corners are cut by staircases of rows 6, 5, ..., 1 (21 cells each) and
/// whose four sides carry caps of rows 9, 7, 5 (21 cells each): the same
/// area as the square, like a rasterized disc.
fn capped_square(side: i32) -> String {
    let (m, n) = (3, side + 6);
    let corner = |x: i32, y: i32| {
        // Distance from the nearest corner of the square, along each axis.
        let dx = (x - m).min(m + side - 1 - x);
        let dy = (y - m).min(m + side - 1 - y);
        dx >= 0 && dy >= 0 && dx + dy < 6
    };
    let cap = |along: i32, out: i32| {
        // `out` cells beyond a side (1..=3), `along` from the side's start.
        let width = [9, 7, 5][(out - 1) as usize];
        let start = side / 2 - width / 2;
        (start..start + width).contains(&along)
    };
    let mut rows = Vec::new();
    for y in 0..n {
        let row: String = (0..n)
            .map(|x| {
                let inside = (m..m + side).contains(&x) && (m..m + side).contains(&y);
                let on = if inside {
                    !corner(x, y)
                } else if (m..m + side).contains(&x) && y < m {
                    cap(x - m, m - y)
                } else if (m..m + side).contains(&x) && y >= m + side {
                    cap(x - m, y - m - side + 1)
                } else if (m..m + side).contains(&y) && x < m {
                    cap(y - m, m - x)
                } else if (m..m + side).contains(&y) && x >= m + side {
                    cap(y - m, x - m - side + 1)
                } else {
                    false
                };
                if on {
                    'A'
                } else {
                    '.'
                }
            })
            .collect();
        rows.push(row);
    }
    rows.join("|")
}

fn square(side: i32) -> String {
    vec!["A".repeat(side as usize); side as usize].join("|")
}

/// Every plan parts each figure into the large piece and sectors of equal
/// area in every figure; the large piece is connected and congruent.
#[test]
fn plans_part_the_figures_into_a_large_piece_and_balanced_sectors() {
    let a = capped_square(30);
    let b = square(30);
    let (figs, problem, _) = candidate(LatticeKind::Square, true, &[&a, &b]);
    assert_eq!(
        figs[0].len(),
        figs[1].len(),
        "the test figures have equal areas"
    );
    for pivot in 0..2 {
        let plans = plans(&problem, pivot);
        assert!(!plans.is_empty(), "pivot {pivot}: a plan");
        assert!(
            plans[0].sectors.len() >= 2,
            "pivot {pivot}: several sectors"
        );
        for plan in &plans {
            check_plan(&figs, plan);
        }
    }
}

fn check_plan(figs: &[Figure], plan: &Plan) {
    for (f, fig) in figs.iter().enumerate() {
        let mut seen = vec![0u32; fig.len()];
        for &c in &plan.big[f] {
            seen[c as usize] += 1;
        }
        for sector in &plan.sectors {
            assert_eq!(sector[f].len(), sector[0].len(), "balanced sector");
            assert!(!sector[f].is_empty());
            for &c in &sector[f] {
                seen[c as usize] += 1;
            }
        }
        assert!(seen.iter().all(|&n| n == 1), "figure {f} parted exactly");
    }
    // The large piece alone: one piece of the figures it covers.
    let big: Vec<Figure> = figs
        .iter()
        .zip(&plan.big)
        .map(|(fig, cells)| {
            Figure::new(
                fig.lattice(),
                cells.iter().map(|&c| fig.cells()[c as usize]),
            )
            .unwrap()
        })
        .collect();
    let whole: Vec<Vec<Vec<Cell>>> = big.iter().map(|f| vec![f.cells().to_vec()]).collect();
    assert_eq!(
        crate::verify::verify_pieces(LatticeKind::Square, true, &big, &whole),
        Ok(1),
        "the large piece is connected and congruent"
    );
}

/// Dissects each sector by the constructive dissection (a stand-in for the
/// exact search, which the core cannot call).
struct Constructive;

impl Repair for Constructive {
    fn repair(&self, _: &[Vec<Vec<Cell>>], _: &AtomicBool) -> Option<Vec<Vec<Vec<Cell>>>> {
        None
    }

    fn dissect(
        &self,
        figures: &[Vec<Cell>],
        _: usize,
        _: &AtomicBool,
    ) -> Option<Vec<Vec<Vec<Cell>>>> {
        let figs: Vec<Figure> = figures
            .iter()
            .map(|c| Figure::new(LatticeKind::Square, c.iter().copied()).unwrap())
            .collect();
        let problem = Problem::new(
            figs.iter().map(Shape::of_figure).collect(),
            geometry(LatticeKind::Square, true),
        );
        let cand = greedy(
            &problem,
            GreedyStyle {
                pivot: 0,
                divisor: 1,
                choice: Choice::Overlap,
                start: Point::ORIGIN,
            },
        );
        Some(cells_by_label(&figs, &cand))
    }
}

/// The large piece and the sectors' dissections together are a dissection
/// of the figures, for every plan; a stop ends it with none.
#[test]
fn the_sectors_dissections_with_the_large_piece_dissect_the_figures() {
    let a = capped_square(24);
    let b = square(24);
    let (figs, problem, _) = candidate(LatticeKind::Square, true, &[&b, &a]);
    let plans = plans(&problem, 0);
    assert!(!plans.is_empty());
    for plan in &plans {
        let pieces = dissect(
            &figs,
            plan,
            usize::MAX,
            &Constructive,
            &AtomicBool::new(false),
        )
        .expect("pieces");
        assert!(
            crate::verify::verify_pieces(LatticeKind::Square, true, &figs, &pieces).is_ok(),
            "{pieces:?}"
        );
    }
    assert_eq!(
        dissect(
            &figs,
            &plans[0],
            usize::MAX,
            &Constructive,
            &AtomicBool::new(true)
        ),
        None
    );
    // The large piece and one piece per sector at least: a cap below that
    // (or below what the sectors' dissections need) gives none.
    let least = plans[0].sectors.len() + 1;
    let stop = AtomicBool::new(false);
    assert_eq!(
        dissect(&figs, &plans[0], least - 1, &Constructive, &stop),
        None
    );
}

/// Figures with nothing large in common (less than half) get no plan.
#[test]
fn figures_with_little_in_common_get_no_plan() {
    let (_, problem, _) = candidate(LatticeKind::Square, true, &["AAAAAAAAA", "AAA|AAA|AAA"]);
    assert!(plans(&problem, 0).is_empty());
    assert!(plans(&problem, 1).is_empty());
}
