//! The simplest bounds: every connected component of a figure needs its own
//! piece, and figures that are not congruent need at least two.

use dissect_core::lattice::Point;

use crate::instance::Instance;

/// The shape with the most connected components, and how many it has.
pub(crate) fn most_components(inst: &Instance) -> (usize, usize) {
    inst.shapes
        .iter()
        .enumerate()
        .map(|(k, s)| (k, s.components))
        .max_by_key(|&(k, c)| (c, std::cmp::Reverse(k)))
        .expect("at least one shape")
}

/// Whether every shape is congruent to shape 0 (a 1-piece dissection).
pub(crate) fn all_congruent(inst: &Instance) -> bool {
    let canonical = |pts: &[Point]| -> Vec<Point> {
        let mut v = pts.to_vec();
        v.sort();
        let r = inst.residue(v[0]);
        let t = v[0] - r;
        v.iter().map(|p| p - t).collect()
    };
    let base = &inst.shapes[0].points;
    let forms: Vec<Vec<Point>> = inst
        .syms
        .iter()
        .map(|g| canonical(&base.iter().map(|p| g.apply(*p)).collect::<Vec<_>>()))
        .collect();
    inst.shapes[1..]
        .iter()
        .all(|s| forms.contains(&canonical(&s.points)))
}
