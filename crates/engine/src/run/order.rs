//! The canonical order of a run's figures: the search sees the figures in
//! an order that depends on their shapes only, never on the order the user
//! gave them in, so the piece count a run reaches does not depend on it
//! (the answer is put back in the user's order).
//!
//! The most regular figure comes first (the most self-symmetries; the cube
//! before the castle), ties broken by the figure's normal form (its cells
//! under the symmetry that gives the smallest sorted list of points, moved
//! to the origin), then by the input order (only congruent figures tie).

use std::cmp::Reverse;

use dissect_core::lattice::Point;
use dissect_core::Figure;

use crate::report::Report;

/// What orders a figure: self-symmetries (most first), then normal form.
type Key = (Reverse<usize>, Vec<[i32; 3]>);

/// The order the search sees the figures in: `order[i]` is the input index
/// of the `i`-th figure the search sees.
pub(super) fn canonical_order(figures: &[Figure], mirror: bool) -> Vec<usize> {
    let keys: Vec<Key> = figures.iter().map(|f| key(f, mirror)).collect();
    let mut order: Vec<usize> = (0..figures.len()).collect();
    // Stable: congruent figures keep their input order.
    order.sort_by(|&a, &b| keys[a].cmp(&keys[b]));
    order
}

/// The figure's [`Key`]: every symmetry of the lattice (turns, and flips
/// when `mirror`) applied to its points, each image moved so that its
/// smallest coordinates are 0 and sorted; the smallest image is the normal
/// form, and the symmetries that give it are the self-symmetries.
fn key(figure: &Figure, mirror: bool) -> Key {
    let lattice = figure.lattice().lattice();
    let points: Vec<Point> = figure
        .cells()
        .iter()
        .map(|&c| lattice.to_point(c))
        .collect();
    let mut best: Option<Vec<[i32; 3]>> = None;
    let mut count = 0;
    for sym in lattice.symmetries(mirror) {
        let image = normalised(points.iter().map(|&p| sym.apply(p).coords()));
        match &best {
            Some(b) if image == *b => count += 1,
            Some(b) if image > *b => {}
            _ => {
                best = Some(image);
                count = 1;
            }
        }
    }
    (Reverse(count), best.unwrap_or_default())
}

/// `points` moved so that each coordinate's smallest value is 0, sorted.
fn normalised(points: impl Iterator<Item = [i32; 3]>) -> Vec<[i32; 3]> {
    let mut v: Vec<[i32; 3]> = points.collect();
    let mut lo = [i32::MAX; 3];
    for p in &v {
        for d in 0..3 {
            lo[d] = lo[d].min(p[d]);
        }
    }
    for p in &mut v {
        for d in 0..3 {
            p[d] -= lo[d];
        }
    }
    v.sort_unstable();
    v
}

/// `report` of a run on the figures in `order`, put back in input order:
/// every dissection's figures (and per-figure levels) moved to the place
/// the user gave them.
pub(super) fn restore(mut report: Report, order: &[usize]) -> Report {
    let mut back = vec![0; order.len()];
    for (i, &input) in order.iter().enumerate() {
        back[input] = i;
    }
    report.best = report.best.map(|b| b.reordered(&back));
    for s in &mut report.solutions {
        s.dissection = s.dissection.reordered(&back);
        if let Some(levels) = &mut s.scores.levels {
            *levels = back.iter().map(|&i| levels[i]).collect();
        }
    }
    report
}

#[cfg(test)]
mod tests {
    use super::*;
    use dissect_core::io::parse_figure;
    use dissect_core::LatticeKind;

    fn fig(text: &str) -> Figure {
        parse_figure(text, LatticeKind::Square).expect("a figure")
    }

    #[test]
    fn the_most_regular_figure_comes_first_whatever_the_input_order() {
        let square = fig("###\n###\n###\n");
        let l = fig("#....\n#....\n#####\n#....\n");
        let bar = fig("#########\n");
        let figures = [l.clone(), bar.clone(), square.clone()];
        let order = canonical_order(&figures, true);
        // The square has 8 self-symmetries, the bar 4, the T-like figure 1.
        assert_eq!(order, vec![2, 1, 0]);
        let again = [square, l, bar];
        assert_eq!(canonical_order(&again, true), vec![0, 2, 1]);
    }

    #[test]
    fn a_turned_and_moved_copy_has_the_same_key() {
        let a = fig("##.\n.##\n.#.\n");
        let b = fig("....\n..#.\n.###\n...#\n");
        assert_eq!(key(&a, true), key(&b, true));
        assert_eq!(canonical_order(&[a.clone(), b.clone()], true), vec![0, 1]);
        assert_eq!(canonical_order(&[b, a], true), vec![0, 1]);
    }
}
