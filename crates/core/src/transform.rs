//! Rigid motions of the lattice: a point symmetry followed by a translation.

use crate::lattice::{Point, Symmetry};

/// `p ↦ sym · p + shift`.
///
/// # Validity
/// `shift` is a lattice translation (a multiple of the lattice modulus in the
/// moved coordinates) when the transform comes from the solver.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Transform {
    sym: Symmetry,
    shift: Point,
}

impl Transform {
    /// The identity.
    pub const IDENTITY: Transform = Transform {
        sym: Symmetry::IDENTITY,
        shift: [0, 0, 0],
    };

    /// `p ↦ sym · p + shift`.
    pub fn new(sym: Symmetry, shift: Point) -> Transform {
        Transform { sym, shift }
    }

    /// The point symmetry.
    pub fn symmetry(&self) -> Symmetry {
        self.sym
    }

    /// The translation applied after the symmetry.
    pub fn shift(&self) -> Point {
        self.shift
    }

    /// Applies the transform.
    #[inline]
    pub fn apply(&self, p: Point) -> Point {
        let q = self.sym.apply(p);
        [
            q[0] + self.shift[0],
            q[1] + self.shift[1],
            q[2] + self.shift[2],
        ]
    }

    /// The inverse motion: `q ↦ sym⁻¹ · (q − shift)`.
    pub fn inverse(&self) -> Transform {
        let inv = self.sym.inverse();
        let s = inv.apply(self.shift);
        Transform {
            sym: inv,
            shift: [-s[0], -s[1], -s[2]],
        }
    }

    /// `self ∘ other` (apply `other` first).
    pub fn compose(&self, other: &Transform) -> Transform {
        Transform {
            sym: self.sym.compose(&other.sym),
            shift: self.apply(other.shift),
        }
    }
}
