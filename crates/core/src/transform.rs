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
        shift: Point::ORIGIN,
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
        self.sym.apply(p) + self.shift
    }

    /// The inverse motion: `q ↦ sym⁻¹ · (q − shift)`.
    pub fn inverse(&self) -> Transform {
        let inv = self.sym.inverse();
        Transform {
            sym: inv,
            shift: -inv.apply(self.shift),
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
