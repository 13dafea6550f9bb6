//! The matching `M` between the pieces of two figures: a min-cost perfect
//! assignment under `D` (Kuhn-Munkres, from the `pathfinding` crate).

use pathfinding::kuhn_munkres::kuhn_munkres_min;
use pathfinding::matrix::Matrix;

use crate::solver::distance::{distance, Geometry, Side};
use crate::transform::Transform;

/// A matching from the pieces of figure A to those of figure B.
#[derive(Clone, Debug)]
pub(crate) struct PairMatching {
    /// `E_M`: the sum of the matched distances.
    pub(crate) cost: u64,
    /// `partner[a]` is the piece of B matched to piece `a` of A.
    pub(crate) partner: Vec<usize>,
    /// `transforms[a]` carries piece `a` of A onto its partner.
    pub(crate) transforms: Vec<Transform>,
    /// `dists[a]` is `D(a, partner[a])`.
    pub(crate) dists: Vec<u32>,
}

/// The min-cost matching between the pieces of `a` and `b` (same count).
pub(crate) fn match_pieces(geo: &Geometry, a: Side<'_>, b: Side<'_>) -> PairMatching {
    let k = a.pieces.count();
    debug_assert_eq!(k, b.pieces.count());
    let mut table = Vec::with_capacity(k * k);
    for i in 0..k {
        for j in 0..k {
            table.push(distance(geo, a, i, b, j));
        }
    }
    let partner: Vec<usize> = if k == 1 {
        vec![0]
    } else {
        let weights = Matrix::from_vec(k, k, table.iter().map(|(d, _)| *d as i64).collect())
            .expect("k*k weights");
        kuhn_munkres_min(&weights).1
    };
    let mut cost = 0u64;
    let mut transforms = Vec::with_capacity(k);
    let mut dists = Vec::with_capacity(k);
    for (i, &j) in partner.iter().enumerate() {
        let (d, t) = table[i * k + j];
        cost += d as u64;
        dists.push(d);
        transforms.push(t);
    }
    PairMatching {
        cost,
        partner,
        transforms,
        dists,
    }
}
