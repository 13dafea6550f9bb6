//! The motions of one lattice (its allowed point symmetries and its
//! translations) acting on sets of cells: canonical forms, self-symmetries
//! and the placements of a piece inside a figure.
//!
//! Everything goes through the [`Lattice`] trait (points, symmetries,
//! translation modulus), so it works unchanged on every lattice.

use std::collections::HashSet;

use dissect_core::lattice::{Lattice, Point, Symmetry};
use dissect_core::transform::Transform;
use dissect_core::{Cell, LatticeKind};

/// The allowed motions of a lattice: point symmetries (mirror images only
/// when asked and allowed) followed by lattice translations.
#[derive(Clone, Debug)]
pub struct Motions {
    kind: LatticeKind,
    mirror: bool,
    syms: Vec<Symmetry>,
    dim: usize,
    modulus: i32,
}

impl Motions {
    /// The motions of `lattice`; `mirror` is ignored where the lattice has
    /// no mirror images.
    pub fn new(lattice: LatticeKind, mirror: bool) -> Motions {
        let l = lattice.lattice();
        let mirror = mirror && l.supports_mirror();
        Motions {
            kind: lattice,
            mirror,
            syms: l.symmetries(mirror),
            dim: l.dim(),
            modulus: l.modulus(),
        }
    }

    /// The lattice.
    pub fn lattice(&self) -> LatticeKind {
        self.kind
    }

    fn geometry(&self) -> &'static dyn Lattice {
        self.kind.lattice()
    }

    /// Whether mirror images are allowed.
    pub fn mirror(&self) -> bool {
        self.mirror
    }

    /// The allowed point symmetries (the identity first).
    pub fn symmetries(&self) -> &[Symmetry] {
        &self.syms
    }

    /// Whether `t` is a translation of the lattice.
    pub fn is_translation(&self, t: Point) -> bool {
        (0..3).all(|k| {
            if k < self.dim {
                t[k].rem_euclid(self.modulus) == 0
            } else {
                t[k] == 0
            }
        })
    }

    /// The points of cells.
    pub fn points(&self, cells: &[Cell]) -> Vec<Point> {
        let l = self.geometry();
        cells.iter().map(|c| l.to_point(*c)).collect()
    }

    /// The cell at a point, if the point is one.
    pub fn cell(&self, p: Point) -> Option<Cell> {
        self.geometry().from_point(p)
    }

    /// Sorts points and translates them so that the smallest one lies in the
    /// translation cell at the origin: two sets get the same result exactly
    /// when one is a lattice translate of the other.
    pub fn normalize(&self, mut pts: Vec<Point>) -> Vec<Point> {
        pts.sort_unstable();
        let Some(&min) = pts.first() else {
            return pts;
        };
        let mut t = [0; 3];
        for k in 0..self.dim {
            t[k] = -min[k].div_euclid(self.modulus) * self.modulus;
        }
        let t = Point::from(t);
        for p in &mut pts {
            *p = *p + t;
        }
        pts
    }

    /// The canonical form of a set of cells under every allowed motion: the
    /// smallest normalized image. Two sets are congruent exactly when their
    /// canonical forms are equal.
    pub fn canonical(&self, cells: &[Cell]) -> Vec<Point> {
        let pts = self.points(cells);
        self.syms
            .iter()
            .map(|g| self.normalize(pts.iter().map(|p| g.apply(*p)).collect()))
            .min()
            .unwrap_or_default()
    }

    /// The number of allowed motions that map a set of cells onto itself
    /// (1 for an asymmetric piece; the identity counts).
    pub fn self_symmetries(&self, cells: &[Cell]) -> usize {
        let pts = self.points(cells);
        let base = self.normalize(pts.clone());
        self.syms
            .iter()
            .filter(|g| self.normalize(pts.iter().map(|p| g.apply(*p)).collect()) == base)
            .count()
    }

    /// The motion (among those `allowed` admits) carrying `from` onto `to`
    /// as sets, if any.
    pub fn motion_between(
        &self,
        from: &[Cell],
        to: &[Cell],
        allowed: impl Fn(&Transform) -> bool,
    ) -> Option<Transform> {
        if from.len() != to.len() || from.is_empty() {
            return None;
        }
        let a = self.points(from);
        let mut b = self.points(to);
        b.sort_unstable();
        let bmin = b[0];
        for g in &self.syms {
            let mut img: Vec<Point> = a.iter().map(|p| g.apply(*p)).collect();
            img.sort_unstable();
            let m = img[0];
            let t = bmin - m;
            if !self.is_translation(t) {
                continue;
            }
            let same = img.iter().zip(&b).all(|(p, q)| *p + t == *q);
            let motion = Transform::new(*g, t);
            if same && allowed(&motion) {
                return Some(motion);
            }
        }
        None
    }

    /// Every distinct placement (as a sorted cell set) of `piece` inside
    /// `region` under the allowed motions.
    pub fn placements(&self, piece: &[Cell], region: &HashSet<Cell>) -> Vec<Vec<Cell>> {
        self.placements_until(piece, region, &|| false)
            .unwrap_or_default()
    }

    /// [`Motions::placements`], asking `interrupted` before each of the
    /// lattice's orientations (`None` when it says so).
    pub fn placements_until(
        &self,
        piece: &[Cell],
        region: &HashSet<Cell>,
        interrupted: &dyn Fn() -> bool,
    ) -> Option<Vec<Vec<Cell>>> {
        let Some(&first) = piece.first() else {
            return Some(Vec::new());
        };
        let l = self.geometry();
        let pts = self.points(piece);
        let anchor_cell = l.to_point(first);
        let region_pts: Vec<Point> = region.iter().map(|c| l.to_point(*c)).collect();
        let mut seen: HashSet<Vec<Cell>> = HashSet::new();
        let mut out = Vec::new();
        for g in &self.syms {
            if interrupted() {
                return None;
            }
            let img: Vec<Point> = pts.iter().map(|p| g.apply(*p)).collect();
            let a = g.apply(anchor_cell);
            for q in &region_pts {
                let t = *q - a;
                if !self.is_translation(t) {
                    continue;
                }
                let mut cells = Vec::with_capacity(img.len());
                let fits = img.iter().all(|p| match l.from_point(*p + t) {
                    Some(c) if region.contains(&c) => {
                        cells.push(c);
                        true
                    }
                    _ => false,
                });
                if fits {
                    cells.sort_unstable();
                    if seen.insert(cells.clone()) {
                        out.push(cells);
                    }
                }
            }
        }
        Some(out)
    }

    /// The allowed motions that map `region` onto itself (its symmetries
    /// within the lattice's allowed ones; the identity first).
    pub fn symmetries_of(&self, region: &[Cell]) -> Vec<Transform> {
        let mut out = Vec::new();
        let sorted: Vec<Cell> = region.to_vec();
        for g in &self.syms {
            if let Some(m) = self.motion_between(region, &sorted, |m| m.symmetry() == *g) {
                out.push(m);
            }
        }
        out
    }

    /// The canonical form of a cut of a region into pieces (each a list of
    /// cells) under `symmetries`, motions that map the region onto itself
    /// ([`Motions::symmetries_of`]): the smallest image, each piece sorted
    /// and the pieces sorted. Two cuts of the region are the same up to its
    /// symmetries exactly when their canonical forms are equal; the
    /// identity among `symmetries` makes the cut itself a candidate.
    pub fn canonical_cut(&self, symmetries: &[Transform], pieces: &[Vec<Cell>]) -> Vec<Vec<Cell>> {
        let image = |m: Option<&Transform>| {
            let mut out: Vec<Vec<Cell>> = pieces
                .iter()
                .map(|p| {
                    let mut cells: Vec<Cell> = p
                        .iter()
                        .map(|&c| m.map_or(Some(c), |m| self.move_cell(m, c)).unwrap_or(c))
                        .collect();
                    cells.sort_unstable();
                    cells
                })
                .collect();
            out.sort_unstable();
            out
        };
        symmetries
            .iter()
            .map(|m| image(Some(m)))
            .min()
            .unwrap_or_else(|| image(None))
    }

    /// Applies a motion to a cell (`None` when the image is not a cell).
    pub fn move_cell(&self, motion: &Transform, cell: Cell) -> Option<Cell> {
        let l = self.geometry();
        l.from_point(motion.apply(l.to_point(cell)))
    }
}
