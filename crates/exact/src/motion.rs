//! Motions (a point symmetry, then a lattice translation) that carry a piece
//! of the reference figure into another figure, and the symmetries of a
//! figure, used to break the symmetry of the search.

use rustc_hash::FxHashMap;

use dissect_core::lattice::Point;
use dissect_core::transform::Transform;

use crate::instance::Instance;

/// Which point symmetries a search may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MotionSet {
    /// Translations only.
    Translations,
    /// Rotations (determinant +1), no flips.
    Rotations,
    /// Every allowed symmetry.
    All,
}

impl std::fmt::Display for MotionSet {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            MotionSet::Translations => "translations only",
            MotionSet::Rotations => "rotations without flips",
            MotionSet::All => "all motions",
        })
    }
}

impl MotionSet {
    /// Whether the symmetry with this determinant (and index, 0 = identity) is in the set.
    pub fn admits(self, index: usize, determinant: i32) -> bool {
        match self {
            MotionSet::Translations => index == 0,
            MotionSet::Rotations => determinant == 1,
            MotionSet::All => true,
        }
    }
}

/// A motion of the reference figure, with the index of its symmetry.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Motion {
    pub sym: usize,
    pub transform: Transform,
}

/// Every motion of `set` under which at least one cell of shape 0 lands in
/// shape `to`, sorted by symmetry then shift; `None` when `interrupted`
/// says so (asked every 256 cells).
pub(crate) fn motions_into(
    inst: &Instance,
    to: usize,
    set: MotionSet,
    interrupted: &dyn Fn() -> bool,
) -> Option<Vec<Motion>> {
    let from = &inst.shapes[0];
    let target = &inst.shapes[to];
    let mut out = Vec::new();
    for (gi, g) in inst.syms.iter().enumerate() {
        if !set.admits(gi, g.determinant()) {
            continue;
        }
        let mut shifts: FxHashMap<Point, u32> = FxHashMap::default();
        for (c, p) in from.points.iter().enumerate() {
            if c.is_multiple_of(256) && interrupted() {
                return None;
            }
            let gp = g.apply(*p);
            for q in &target.points {
                let t = q - gp;
                if inst.is_translation(t) {
                    *shifts.entry(t).or_default() += 1;
                }
            }
        }
        let mut list: Vec<Point> = shifts.into_keys().collect();
        list.sort();
        out.extend(list.into_iter().map(|t| Motion {
            sym: gi,
            transform: Transform::new(*g, t),
        }));
    }
    Some(out)
}

/// The indices of the symmetries `g` for which `g(shape) + t = shape` for
/// some translation `t`.
pub(crate) fn self_symmetries(inst: &Instance, shape: usize) -> Vec<usize> {
    let s = &inst.shapes[shape];
    let min = *s.points.iter().min().expect("non-empty");
    let mut out = Vec::new();
    for (gi, g) in inst.syms.iter().enumerate() {
        let img: Vec<Point> = s.points.iter().map(|p| g.apply(*p)).collect();
        let m = *img.iter().min().expect("non-empty");
        let t = min - m;
        if inst.is_translation(t) && img.iter().all(|p| s.index.contains_key(&(p + t))) {
            out.push(gi);
        }
    }
    out
}

/// For each symmetry index, whether it is the representative (smallest
/// index) of its coset `{h ∘ g : h ∈ group}`.
pub(crate) fn coset_representatives(inst: &Instance, group: &[usize]) -> Vec<bool> {
    (0..inst.syms.len())
        .map(|gi| {
            group.iter().all(|&h| {
                let hg = inst.syms[h].compose(&inst.syms[gi]);
                inst.syms.iter().position(|s| *s == hg).unwrap_or(gi) >= gi
            })
        })
        .collect()
}
