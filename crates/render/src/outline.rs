//! Outlines: the boundary of a set of lattice cells as closed polygons, one
//! per connected boundary curve (the outer boundary and each hole), found by
//! cancelling shared edges and tracing the rest.
//!
//! Coordinates are *half units*: the point `(x, y)` of the plane is stored as
//! `[2x, 2y]`, so the centre of a `tri4` square is an integer point too.
//! The plane is in image orientation (y grows downward).

use std::collections::HashMap;

use dissect_core::{Cell, LatticeKind};

/// A point in half units (`[2x, 2y]`).
pub type HalfPoint = [i64; 2];

/// One closed boundary curve.
///
/// # Validity
/// At least 3 points, no two consecutive points equal and no three
/// consecutive points collinear (edges are merged). Edges are horizontal,
/// vertical or at 45°. The material is always on the same side
/// ([`Loop::is_hole`] tells which way round the curve goes). A curve may
/// touch itself at a vertex where two corners of the material meet; it is
/// then traced so that each corner is turned round on its own.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Loop {
    points: Vec<HalfPoint>,
}

impl Loop {
    /// The corners in half units.
    pub fn points(&self) -> &[HalfPoint] {
        &self.points
    }

    /// The corners in lattice units.
    pub fn points_f64(&self) -> Vec<[f64; 2]> {
        self.points
            .iter()
            .map(|p| [p[0] as f64 / 2.0, p[1] as f64 / 2.0])
            .collect()
    }

    /// Twice the signed area in half units squared (shoelace, image
    /// orientation): positive for an outer boundary, negative for a hole.
    pub fn doubled_area(&self) -> i64 {
        let n = self.points.len();
        (0..n)
            .map(|i| {
                let a = self.points[i];
                let b = self.points[(i + 1) % n];
                a[0] * b[1] - b[0] * a[1]
            })
            .sum()
    }

    /// Whether this curve bounds a hole (it runs the other way round).
    pub fn is_hole(&self) -> bool {
        self.doubled_area() < 0
    }
}

/// The outline of a set of cells: its boundary curves.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Outline {
    loops: Vec<Loop>,
}

impl Outline {
    /// The outline of `cells` (any 2D lattice; `cubic` cells are read as
    /// squares `(x, y)` and their `z` ignored).
    pub fn of_cells(lattice: LatticeKind, cells: &[Cell]) -> Outline {
        let mut edges: HashMap<(HalfPoint, HalfPoint), i32> = HashMap::new();
        for &c in cells {
            let poly = cell_polygon(lattice, c);
            for i in 0..poly.len() {
                let a = poly[i];
                let b = poly[(i + 1) % poly.len()];
                if let Some(n) = edges.get_mut(&(b, a)) {
                    *n -= 1;
                    if *n == 0 {
                        edges.remove(&(b, a));
                    }
                } else {
                    *edges.entry((a, b)).or_insert(0) += 1;
                }
            }
        }
        let mut out_edges: HashMap<HalfPoint, Vec<HalfPoint>> = HashMap::new();
        let mut sorted: Vec<(HalfPoint, HalfPoint)> = edges.keys().copied().collect();
        sorted.sort();
        for &(a, b) in &sorted {
            out_edges.entry(a).or_default().push(b);
        }
        let mut loops = Vec::new();
        for &(a0, b0) in &sorted {
            // Take this edge if it is still unused.
            let Some(list) = out_edges.get_mut(&a0) else {
                continue;
            };
            let Some(pos) = list.iter().position(|b| *b == b0) else {
                continue;
            };
            list.swap_remove(pos);
            let mut pts = vec![a0];
            let (mut prev, mut cur) = (a0, b0);
            loop {
                let d_in = dir_index(prev, cur);
                let list = out_edges
                    .get_mut(&cur)
                    .expect("boundary edges form closed curves");
                let best = list
                    .iter()
                    .enumerate()
                    .max_by_key(|(_, b)| turn(d_in, dir_index(cur, **b)));
                // Back at the start: close unless the curve hugs another
                // corner of the material here first.
                if cur == a0
                    && !matches!(best, Some((_, b))
                        if turn(d_in, dir_index(cur, *b)) >= turn(d_in, dir_index(cur, b0)))
                {
                    break;
                }
                let (k, _) = best.expect("boundary edges form closed curves");
                let next = list.swap_remove(k);
                pts.push(cur);
                prev = cur;
                cur = next;
            }
            loops.push(Loop {
                points: merge_collinear(pts),
            });
        }
        loops.sort_by_key(|l| std::cmp::Reverse(l.doubled_area()));
        Outline { loops }
    }

    /// The boundary curves, outer boundaries first (largest first).
    pub fn loops(&self) -> &[Loop] {
        &self.loops
    }

    /// The bounding box `[min, max]` in half units.
    pub fn bounds(&self) -> Option<[HalfPoint; 2]> {
        let mut it = self.loops.iter().flat_map(|l| l.points.iter());
        let first = *it.next()?;
        Some(it.fold([first, first], |[lo, hi], p| {
            [
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            ]
        }))
    }
}

/// The polygon of one cell in half units, in the orientation that gives a
/// positive shoelace area.
pub fn cell_polygon(lattice: LatticeKind, [x, y, t]: Cell) -> Vec<HalfPoint> {
    let (x, y) = (2 * x as i64, 2 * y as i64);
    let (tl, tr, br, bl, c) = (
        [x, y],
        [x + 2, y],
        [x + 2, y + 2],
        [x, y + 2],
        [x + 1, y + 1],
    );
    match (lattice, t) {
        (LatticeKind::Tri4, 0) => vec![tl, tr, c],
        (LatticeKind::Tri4, 1) => vec![tr, br, c],
        (LatticeKind::Tri4, 2) => vec![br, bl, c],
        (LatticeKind::Tri4, _) => vec![bl, tl, c],
        _ => vec![tl, tr, br, bl],
    }
}

/// The direction of `a -> b` as a multiple of 45° (0 = +x, 2 = +y).
fn dir_index(a: HalfPoint, b: HalfPoint) -> i32 {
    let d = [(b[0] - a[0]).signum(), (b[1] - a[1]).signum()];
    match d {
        [1, 0] => 0,
        [1, 1] => 1,
        [0, 1] => 2,
        [-1, 1] => 3,
        [-1, 0] => 4,
        [-1, -1] => 5,
        [0, -1] => 6,
        _ => 7,
    }
}

/// The turn from direction `a` to `b` in steps of 45°, in `-3..=4`; positive
/// turns toward the material (which lies on the `+90°` side of every edge).
fn turn(a: i32, b: i32) -> i32 {
    let t = (b - a).rem_euclid(8);
    if t > 4 {
        t - 8
    } else {
        t
    }
}

/// Drops the points where the curve goes straight on.
fn merge_collinear(pts: Vec<HalfPoint>) -> Vec<HalfPoint> {
    let n = pts.len();
    let keep: Vec<HalfPoint> = (0..n)
        .filter(|&i| {
            let a = pts[(i + n - 1) % n];
            let b = pts[i];
            let c = pts[(i + 1) % n];
            dir_index(a, b) != dir_index(b, c)
        })
        .map(|i| pts[i])
        .collect();
    keep
}

#[cfg(test)]
mod tests {
    use super::*;
    use dissect_core::io::parse_figure;

    fn outline(text: &str, lattice: LatticeKind) -> Outline {
        let f = parse_figure(text, lattice).unwrap();
        Outline::of_cells(lattice, f.cells())
    }

    #[test]
    fn rectangle_is_one_quadrilateral() {
        let o = outline("###\n###\n", LatticeKind::Square);
        assert_eq!(o.loops().len(), 1);
        assert_eq!(o.loops()[0].points(), &[[0, 0], [6, 0], [6, 4], [0, 4]]);
        assert_eq!(o.loops()[0].doubled_area(), 2 * 24);
    }

    #[test]
    fn ring_has_an_outer_curve_and_a_hole() {
        let o = outline("###\n#.#\n###\n", LatticeKind::Square);
        assert_eq!(o.loops().len(), 2);
        assert!(!o.loops()[0].is_hole());
        assert!(o.loops()[1].is_hole());
        assert_eq!(o.loops()[1].points().len(), 4);
    }

    #[test]
    fn pinched_hole_joins_the_outer_curve() {
        // The hole at (1,1) touches the outside at the corner (1,1).
        let o = outline(".##\n#.#\n###\n", LatticeKind::Square);
        assert_eq!(o.loops().len(), 1);
        // 7 cells; the curve visits the pinch point twice.
        assert_eq!(o.loops()[0].doubled_area(), 2 * 7 * 4);
        let pinch = o.loops()[0]
            .points()
            .iter()
            .filter(|p| **p == [2, 2])
            .count();
        assert_eq!(pinch, 2);
    }

    #[test]
    fn tri4_half_square_is_a_triangle() {
        // C = bottom + left: the half square below the \ diagonal.
        let o = outline("C\n", LatticeKind::Tri4);
        assert_eq!(o.loops().len(), 1);
        assert_eq!(o.loops()[0].points().len(), 3);
        assert_eq!(o.loops()[0].doubled_area(), 2 * 2);
    }

    #[test]
    fn tri4_staircase_of_half_squares_is_smooth() {
        // A right triangle of legs 2 made of two half squares and one square.
        let o = outline(".6\n6#\n", LatticeKind::Tri4);
        assert_eq!(o.loops().len(), 1);
        assert_eq!(o.loops()[0].points().len(), 3);
    }
}
