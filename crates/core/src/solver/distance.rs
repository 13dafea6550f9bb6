//! The distance `D(a, b)` between two pieces by centroid alignment
//! (paper section 3.1): over every allowed symmetry `g`, put the centroid of
//! `g(a)` on the centroid of `b` (trying the nearest lattice translations
//! when the offset is not a lattice translation) and count the cells of `a`
//! that miss `b` plus those of `b` that miss `a`.

use crate::lattice::Point;
use crate::lattice::Symmetry;
use crate::solver::piece::Pieces;
use crate::solver::shape::Layout;
use crate::transform::Transform;

/// The symmetries and translation lattice the solver may use.
#[derive(Clone, Debug)]
pub(crate) struct Geometry {
    pub(crate) syms: Vec<Symmetry>,
    /// Coordinates moved by translations (2 or 3).
    pub(crate) dim: usize,
    /// Translations are multiples of this.
    pub(crate) modulus: i32,
}

/// One side of a distance computation: a labelled shape's pieces, its cells'
/// addresses under every symmetry (see [`Shape::moved`](crate::solver::shape::Shape::moved); read on the side
/// moved from) and its labels by address (see [`Layout::label_grid`]; read on
/// the side moved onto, may be empty on the other).
#[derive(Clone, Copy)]
pub(crate) struct Side<'a> {
    pub(crate) pieces: &'a Pieces,
    pub(crate) moved: &'a [i64],
    pub(crate) grid: &'a [u16],
    pub(crate) origin: i64,
    pub(crate) layout: &'a Layout,
}

fn floor_div(a: i64, b: i64) -> i64 {
    a.div_euclid(b)
}

/// `D(a, b)` and the transform of `a` onto `b` that reaches it.
pub(crate) fn distance(
    geo: &Geometry,
    from: Side<'_>,
    a: usize,
    to: Side<'_>,
    b: usize,
) -> (u32, Transform) {
    let na = from.pieces.size(a) as i64;
    let nb = to.pieces.size(b) as i64;
    if na == 0 || nb == 0 {
        return ((na + nb) as u32, Transform::IDENTITY);
    }
    let best_possible = na.min(nb) as u32;
    let sa = from.pieces.sum(a);
    let sb = to.pieces.sum(b);
    let m = geo.modulus as i64;
    let cells = from.pieces.members(a);
    let n = from.moved.len() / geo.syms.len();
    let target = b as u16 + 1;
    let mut best_overlap = 0u32;
    let mut best = Transform::IDENTITY;
    let mut found = false;
    for (s, sym) in geo.syms.iter().enumerate() {
        let moved = &from.moved[s * n..(s + 1) * n];
        let gs = sym.apply_wide(sa);
        // Translation candidates per moved coordinate: the exact centroid
        // offset is (sb/nb - g(sa)/na); in units of m it is num/den.
        let mut choices = [[0i64; 2]; 3];
        let mut n_choices = [1usize; 3];
        for d in 0..geo.dim {
            let num = sb[d] * na - gs[d] * nb;
            let den = na * nb * m;
            let lo = floor_div(num, den);
            choices[d][0] = lo * m;
            if num.rem_euclid(den) != 0 {
                choices[d][1] = (lo + 1) * m;
                n_choices[d] = 2;
            }
        }
        for ix in 0..n_choices[0] {
            for iy in 0..n_choices[1] {
                for iz in 0..n_choices[2] {
                    let shift = Point::new(
                        choices[0][ix] as i32,
                        choices[1][iy] as i32,
                        choices[2][iz] as i32,
                    );
                    // Count hits in chunks, giving up once even all the
                    // remaining cells could not beat the best overlap.
                    let base = to.layout.linear(shift) - to.origin;
                    let mut overlap = 0u32;
                    let mut left = cells.len() as u32;
                    for chunk in cells.chunks(16) {
                        if found && overlap + left <= best_overlap {
                            break;
                        }
                        for &c in chunk {
                            let at = (base + moved[c as usize]) as usize;
                            overlap += (to.grid.get(at).copied().unwrap_or(0) == target) as u32;
                        }
                        left -= chunk.len() as u32;
                    }
                    if !found || overlap > best_overlap {
                        found = true;
                        best_overlap = overlap;
                        best = Transform::new(*sym, shift);
                        if overlap == best_possible {
                            return (distance_from_overlap(na, nb, overlap), best);
                        }
                    }
                }
            }
        }
    }
    (distance_from_overlap(na, nb, best_overlap), best)
}

fn distance_from_overlap(na: i64, nb: i64, overlap: u32) -> u32 {
    (na + nb - 2 * overlap as i64) as u32
}
