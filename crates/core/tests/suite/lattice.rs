//! One generic suite run for every lattice: adjacency, point embedding,
//! symmetries and translations.

use std::collections::HashSet;

use dissect_core::lattice::{Point, Symmetry};
use dissect_core::{Cell, Lattice, LatticeKind};

use super::util::{cells_around, Cubic, Hex, Square, Tri3, Tri4};

/// What each lattice must be.
struct Expect {
    dim: usize,
    degree: usize,
    cells_per_block: usize,
    group: usize,
    group_no_mirror: usize,
    mirror: bool,
}

fn expect(kind: LatticeKind) -> Expect {
    match kind {
        Square => Expect {
            dim: 2,
            degree: 4,
            cells_per_block: 1,
            group: 8,
            group_no_mirror: 4,
            mirror: true,
        },
        Tri4 => Expect {
            dim: 2,
            degree: 3,
            cells_per_block: 4,
            group: 8,
            group_no_mirror: 4,
            mirror: true,
        },
        Cubic => Expect {
            dim: 3,
            degree: 6,
            cells_per_block: 1,
            group: 24,
            group_no_mirror: 24,
            mirror: false,
        },
        Tri3 => Expect {
            dim: 2,
            degree: 3,
            cells_per_block: 1,
            group: 12,
            group_no_mirror: 6,
            mirror: true,
        },
        Hex => Expect {
            dim: 2,
            degree: 6,
            cells_per_block: 1,
            group: 12,
            group_no_mirror: 6,
            mirror: true,
        },
    }
}

/// The corners of a 2D cell in the plane (y down), written from
/// `docs/FORMAT.md` alone, independently of the lattice code: a square
/// `(x, y)`; a `tri4` triangle (two square corners and the centre); a `tri3`
/// triangle (`h = √3/2`, apex `((x+1)/2, y·h)` when up, lower vertex
/// `((x+1)/2, (y+1)·h)` when down); a `hex` hexagon around its centre
/// `(x + (y mod 2)/2, y·h)` at circumradius `1/√3`.
fn corners(kind: LatticeKind, [x, y, t]: Cell) -> Vec<[f64; 2]> {
    let (xf, yf) = (x as f64, y as f64);
    let h = 3f64.sqrt() / 2.0;
    match kind {
        Square => vec![
            [xf, yf],
            [xf + 1.0, yf],
            [xf + 1.0, yf + 1.0],
            [xf, yf + 1.0],
        ],
        Tri4 => {
            let sq = [
                [xf, yf],
                [xf + 1.0, yf],
                [xf + 1.0, yf + 1.0],
                [xf, yf + 1.0],
            ];
            let t = t as usize;
            vec![sq[t], sq[(t + 1) % 4], [xf + 0.5, yf + 0.5]]
        }
        Tri3 => {
            let mid = (xf + 1.0) / 2.0;
            if (x + y).rem_euclid(2) == 0 {
                vec![
                    [mid, yf * h],
                    [mid + 0.5, (yf + 1.0) * h],
                    [mid - 0.5, (yf + 1.0) * h],
                ]
            } else {
                vec![
                    [mid - 0.5, yf * h],
                    [mid + 0.5, yf * h],
                    [mid, (yf + 1.0) * h],
                ]
            }
        }
        Hex => {
            let c = [xf + y.rem_euclid(2) as f64 / 2.0, yf * h];
            let r = 1.0 / 3f64.sqrt();
            (0..6)
                .map(|k| {
                    let a = std::f64::consts::PI / 6.0 + k as f64 * std::f64::consts::PI / 3.0;
                    [c[0] + r * a.cos(), c[1] + r * a.sin()]
                })
                .collect()
        }
        Cubic => unreachable!("2D lattices only"),
    }
}

/// Whether two cells share an edge, from their corners: two common corners.
fn share_an_edge(kind: LatticeKind, a: Cell, b: Cell) -> bool {
    let (ca, cb) = (corners(kind, a), corners(kind, b));
    let common = ca
        .iter()
        .filter(|p| {
            cb.iter()
                .any(|q| (p[0] - q[0]).abs() < 1e-9 && (p[1] - q[1]).abs() < 1e-9)
        })
        .count();
    common >= 2
}

/// The centre of mass of a 2D cell's corners.
fn centre(kind: LatticeKind, cell: Cell) -> [f64; 2] {
    let c = corners(kind, cell);
    let n = c.len() as f64;
    [
        c.iter().map(|p| p[0]).sum::<f64>() / n,
        c.iter().map(|p| p[1]).sum::<f64>() / n,
    ]
}

/// Runs `test` for every lattice, naming the lattice when it fails.
fn for_every_lattice(test: impl Fn(LatticeKind, &dyn Lattice, &Expect)) {
    for kind in LatticeKind::ALL {
        let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            test(kind, kind.lattice(), &expect(kind))
        }));
        if let Err(e) = result {
            eprintln!("failed on the {kind} lattice");
            std::panic::resume_unwind(e);
        }
    }
}

fn translate(l: &dyn Lattice, p: Point, steps: [i32; 3]) -> Point {
    let m = l.modulus();
    let mut q = p.coords();
    for d in 0..l.dim() {
        q[d] += m * steps[d];
    }
    Point::from(q)
}

#[test]
fn identity_of_each_lattice() {
    for_every_lattice(|kind, l, e| {
        assert_eq!(l.kind(), kind);
        assert_eq!(l.dim(), e.dim);
        assert_eq!(l.supports_mirror(), e.mirror);
        assert_eq!(kind.name().parse::<LatticeKind>(), Ok(kind));
        assert_eq!(kind.to_string(), kind.name());
    });
    assert_eq!(
        LatticeKind::ALL.map(|k| k.name()),
        ["square", "tri4", "cubic", "tri3", "hex"]
    );
    let err = "hexagonal".parse::<LatticeKind>().unwrap_err();
    assert!(err.to_string().contains("\"hexagonal\""), "{err}");
    assert!("Square".parse::<LatticeKind>().is_err());
}

#[test]
fn is_cell_and_blocks() {
    for_every_lattice(|kind, l, e| {
        let cells = l.cells_in_box([-1, 0, 2], [1, 1, 3]);
        let blocks = 3 * 2 * if e.dim == 3 { 2 } else { 1 };
        assert_eq!(cells.len(), blocks * e.cells_per_block);
        let distinct: HashSet<Cell> = cells.iter().copied().collect();
        assert_eq!(distinct.len(), cells.len());
        for c in cells {
            assert!(l.is_cell(c), "{c:?}");
            let b = l.block(c);
            assert!((-1..=1).contains(&b[0]) && (0..=1).contains(&b[1]), "{c:?}");
            if e.dim == 3 {
                assert!((2..=3).contains(&b[2]), "{c:?}");
            } else {
                assert_eq!(b[2], 0);
            }
        }
        match kind {
            Square => {
                assert!(!l.is_cell([0, 0, 1]));
                assert!(!l.is_cell([0, 0, -1]));
            }
            Tri4 => {
                assert!(!l.is_cell([0, 0, 4]));
                assert!(!l.is_cell([0, 0, -1]));
                assert_eq!(l.block([3, -2, 2]), [3, -2, 0]);
            }
            Cubic => assert!(l.is_cell([5, -7, 9])),
            Tri3 | Hex => {
                assert!(!l.is_cell([0, 0, 1]));
                assert_eq!(l.block([3, -2, 0]), [3, -2, 0]);
            }
        }
    });
}

#[test]
fn neighbours_are_symmetric_and_of_the_right_degree() {
    for_every_lattice(|_, l, e| {
        for c in cells_around(l.kind(), 2) {
            let ns = l.neighbors(c);
            assert_eq!(ns.len(), e.degree, "degree of {c:?}");
            let distinct: HashSet<Cell> = ns.iter().copied().collect();
            assert_eq!(distinct.len(), e.degree, "distinct neighbours of {c:?}");
            assert!(!distinct.contains(&c), "{c:?} is its own neighbour");
            for n in ns {
                assert!(l.is_cell(n), "neighbour {n:?} of {c:?}");
                assert!(l.neighbors(n).contains(&c), "{n:?} -> {c:?} missing");
            }
        }
    });
}

/// On every 2D lattice the neighbours are exactly the cells that share an
/// edge in the plane (the geometry of `FORMAT.md`, computed here on its own).
#[test]
fn neighbours_match_the_geometry() {
    for_every_lattice(|kind, l, e| {
        if e.dim == 3 {
            return;
        }
        let all = cells_around(kind, 3);
        for c in cells_around(kind, 2) {
            let mut want: Vec<Cell> = all
                .iter()
                .copied()
                .filter(|&d| d != c && share_an_edge(kind, c, d))
                .collect();
            let mut got = l.neighbors(c);
            want.sort();
            got.sort();
            assert_eq!(got, want, "neighbours of {c:?}");
        }
    });
}

#[test]
fn tri3_and_hex_adjacency_follows_the_format() {
    let sorted = |mut v: Vec<Cell>| {
        v.sort();
        v
    };
    let t = Tri3.lattice();
    // Up when x + y is even: across the base, the triangle below.
    assert_eq!(
        sorted(t.neighbors([0, 0, 0])),
        sorted(vec![[-1, 0, 0], [1, 0, 0], [0, 1, 0]])
    );
    assert_eq!(
        sorted(t.neighbors([1, 0, 0])),
        sorted(vec![[0, 0, 0], [2, 0, 0], [1, -1, 0]])
    );
    let h = Hex.lattice();
    // Even rows: columns x - 1 and x above and below; odd rows: x and x + 1.
    assert_eq!(
        sorted(h.neighbors([2, 2, 0])),
        sorted(vec![
            [1, 2, 0],
            [3, 2, 0],
            [1, 1, 0],
            [2, 1, 0],
            [1, 3, 0],
            [2, 3, 0]
        ])
    );
    assert_eq!(
        sorted(h.neighbors([2, 1, 0])),
        sorted(vec![
            [1, 1, 0],
            [3, 1, 0],
            [2, 0, 0],
            [3, 0, 0],
            [2, 2, 0],
            [3, 2, 0]
        ])
    );
}

#[test]
fn tri4_adjacency_follows_the_format() {
    let l = Tri4.lattice();
    let sorted = |mut v: Vec<Cell>| {
        v.sort();
        v
    };
    // Inside a square t touches t±1; across squares top touches the bottom
    // of the square above, right the left of the square to the right.
    assert_eq!(
        sorted(l.neighbors([0, 0, 0])),
        sorted(vec![[0, 0, 1], [0, 0, 3], [0, -1, 2]])
    );
    assert_eq!(
        sorted(l.neighbors([0, 0, 1])),
        sorted(vec![[0, 0, 0], [0, 0, 2], [1, 0, 3]])
    );
    assert_eq!(
        sorted(l.neighbors([0, 0, 2])),
        sorted(vec![[0, 0, 1], [0, 0, 3], [0, 1, 0]])
    );
    assert_eq!(
        sorted(l.neighbors([0, 0, 3])),
        sorted(vec![[0, 0, 2], [0, 0, 0], [-1, 0, 1]])
    );
}

#[test]
fn points_and_cells_are_inverse() {
    for_every_lattice(|_, l, _| {
        let cells = cells_around(l.kind(), 2);
        let mut points = HashSet::new();
        for &c in &cells {
            let p = l.to_point(c);
            assert_eq!(l.from_point(p), Some(c), "{c:?} -> {p:?}");
            assert!(points.insert(p), "two cells share {p:?}");
        }
        // Every point that names a cell names the cell that maps to it.
        let r = 2 * l.modulus() + 1;
        for x in -r..=r {
            for y in -r..=r {
                for z in -2..=2 {
                    let p = Point::new(x, y, z);
                    if let Some(c) = l.from_point(p) {
                        assert!(l.is_cell(c), "{p:?} -> {c:?}");
                        assert_eq!(l.to_point(c), p);
                    }
                }
            }
        }
    });
}

#[test]
fn translations_map_cells_to_cells_and_keep_adjacency() {
    for_every_lattice(|_, l, e| {
        let steps: &[[i32; 3]] = &[[1, 0, 0], [0, 1, 0], [0, 0, 1], [-2, 3, -1]];
        for &s in steps {
            if e.dim == 2 && s[2] != 0 {
                continue;
            }
            // The same step moves every cell the same way in the plane.
            let mut shift: Option<[f64; 2]> = None;
            for c in cells_around(l.kind(), 1) {
                let moved = l.from_point(translate(l, l.to_point(c), s));
                let moved = moved.unwrap_or_else(|| panic!("{c:?} + {s:?}"));
                if e.dim == 2 {
                    let (a, b) = (centre(l.kind(), c), centre(l.kind(), moved));
                    let d = [b[0] - a[0], b[1] - a[1]];
                    let first = *shift.get_or_insert(d);
                    assert!(
                        (d[0] - first[0]).abs() < 1e-9 && (d[1] - first[1]).abs() < 1e-9,
                        "{c:?} + {s:?} moves by {d:?}, others by {first:?}"
                    );
                    // A translation keeps the cell's shape and orientation.
                    let (ca, cb) = (corners(l.kind(), c), corners(l.kind(), moved));
                    for (p, q) in ca.iter().zip(&cb) {
                        assert!((q[0] - p[0] - d[0]).abs() < 1e-9, "{c:?} -> {moved:?}");
                        assert!((q[1] - p[1] - d[1]).abs() < 1e-9, "{c:?} -> {moved:?}");
                    }
                } else {
                    assert_eq!(l.block(moved), [c[0] + s[0], c[1] + s[1], c[2] + s[2]]);
                }
                for n in l.neighbors(c) {
                    let mn = l.from_point(translate(l, l.to_point(n), s)).unwrap();
                    assert!(l.neighbors(moved).contains(&mn));
                }
            }
        }
    });
}

#[test]
fn symmetries_map_the_lattice_onto_itself() {
    for_every_lattice(|_, l, _| {
        for mirror in [true, false] {
            for g in l.symmetries(mirror) {
                for c in cells_around(l.kind(), 2) {
                    let p = g.apply(l.to_point(c));
                    let gc = l
                        .from_point(p)
                        .unwrap_or_else(|| panic!("{g:?} maps {c:?} off the lattice"));
                    for n in l.neighbors(c) {
                        let gn = l.from_point(g.apply(l.to_point(n))).unwrap();
                        assert!(
                            l.neighbors(gc).contains(&gn),
                            "{g:?} breaks the adjacency {c:?} ~ {n:?}"
                        );
                    }
                }
            }
        }
    });
}

/// In the plane every symmetry is a rigid motion: it keeps the distance
/// between any two cell centres.
#[test]
fn symmetries_are_rigid_motions_of_the_plane() {
    for_every_lattice(|kind, l, e| {
        if e.dim == 3 {
            return;
        }
        let cells = cells_around(kind, 2);
        let dist =
            |a: [f64; 2], b: [f64; 2]| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
        for g in l.symmetries(true) {
            let image = |c: Cell| {
                l.from_point(g.apply(l.to_point(c)))
                    .expect("onto the lattice")
            };
            for &a in cells.iter().step_by(3) {
                for &b in cells.iter().step_by(5) {
                    let before = dist(centre(kind, a), centre(kind, b));
                    let after = dist(centre(kind, image(a)), centre(kind, image(b)));
                    assert!((before - after).abs() < 1e-9, "{g:?} on {a:?}, {b:?}");
                }
            }
        }
    });
}

/// `tri3`: translations keep up triangles up (the point residues differ),
/// while the turns by odd multiples of 60° swap up and down.
#[test]
fn tri3_translations_keep_triangles_pointing_the_same_way() {
    let l = Tri3.lattice();
    let up = |c: Cell| (c[0] + c[1]).rem_euclid(2) == 0;
    for c in cells_around(Tri3, 2) {
        let p = l.to_point(c);
        for t in [[1, 0, 0], [0, 1, 0], [2, 1, 0], [1, 2, 0]] {
            // Only multiples of the modulus are translations.
            assert_eq!(
                l.from_point(p + Point::new(t[0], t[1], 0)),
                None,
                "{c:?} + {t:?}"
            );
            let moved = l.from_point(p + Point::new(3 * t[0], 3 * t[1], 0)).unwrap();
            assert_eq!(up(moved), up(c));
        }
        for (k, g) in l.symmetries(false).iter().enumerate() {
            let image = l.from_point(g.apply(p)).unwrap();
            assert_eq!(up(image) == up(c), k % 2 == 0, "turn {k} of {c:?}");
        }
    }
}

#[test]
fn symmetry_groups() {
    for_every_lattice(|_, l, e| {
        for (mirror, size) in [(true, e.group), (false, e.group_no_mirror)] {
            let syms = l.symmetries(mirror);
            assert_eq!(syms.len(), size, "group size with mirror={mirror}");
            assert_eq!(syms[0], Symmetry::IDENTITY, "identity first");
            let set: HashSet<Symmetry> = syms.iter().copied().collect();
            assert_eq!(set.len(), size, "distinct symmetries");
            for a in &syms {
                assert!(set.contains(&a.inverse()), "inverse of {a:?}");
                assert_eq!(a.compose(&a.inverse()), Symmetry::IDENTITY);
                assert_eq!(a.inverse().compose(a), Symmetry::IDENTITY);
                for b in &syms {
                    assert!(set.contains(&a.compose(b)), "{a:?} ∘ {b:?}");
                }
            }
            let reflections = syms.iter().filter(|s| s.determinant() == -1).count();
            let rotations = syms.iter().filter(|s| s.determinant() == 1).count();
            assert_eq!(reflections + rotations, size);
            let want_reflections = if mirror && e.mirror { size / 2 } else { 0 };
            assert_eq!(
                reflections, want_reflections,
                "reflections, mirror={mirror}"
            );
            if e.dim == 2 {
                // Planar symmetries leave the third coordinate alone.
                for s in &syms {
                    assert_eq!(s.apply(Point::new(0, 0, 1)), Point::new(0, 0, 1));
                }
            }
        }
        if !e.mirror {
            assert_eq!(l.symmetries(true), l.symmetries(false), "mirror is ignored");
        }
    });
}

#[test]
fn symmetry_algebra() {
    let rot90 = Symmetry::new([[0, -1, 0], [1, 0, 0], [0, 0, 1]]).unwrap();
    let flip = Symmetry::new([[-1, 0, 0], [0, 1, 0], [0, 0, 1]]).unwrap();
    assert_eq!(rot90.apply(Point::new(1, 0, 0)), Point::new(0, 1, 0));
    assert_eq!(
        rot90.compose(&rot90).apply(Point::new(1, 2, 3)),
        Point::new(-1, -2, 3)
    );
    assert_eq!(rot90.determinant(), 1);
    assert_eq!(flip.determinant(), -1);
    assert_eq!(rot90.compose(&flip).determinant(), -1);
    assert_eq!(flip.compose(&flip), Symmetry::IDENTITY);
    assert_eq!(rot90.inverse(), rot90.compose(&rot90).compose(&rot90));
    // compose applies the right-hand side first.
    let p = Point::new(2, 5, 7);
    assert_eq!(rot90.compose(&flip).apply(p), rot90.apply(flip.apply(p)));
    assert_ne!(rot90.compose(&flip), flip.compose(&rot90));
    assert_eq!(rot90.apply_wide([1, 2, 3]), [-2, 1, 3]);
    assert_eq!(rot90.matrix(), [[0, -1, 0], [1, 0, 0], [0, 0, 1]]);
}

#[test]
fn only_unimodular_matrices_of_finite_order_are_symmetries() {
    for m in [
        [[0, 0, 0], [0, 1, 0], [0, 0, 1]],
        [[2, 0, 0], [0, 1, 0], [0, 0, 1]],
        // A shear: determinant 1 but no finite order.
        [[1, 1, 0], [0, 1, 0], [0, 0, 1]],
        [[2, 1, 0], [1, 1, 0], [0, 0, 1]],
        [[1, 0, 0], [1, 0, 0], [0, 0, 1]],
        [[1, 0, 0], [0, 0, 1], [0, 0, 1]],
        [[9, 0, 0], [0, 1, 0], [0, 0, 1]],
    ] {
        assert_eq!(Symmetry::new(m), None, "{m:?}");
    }
    assert!(Symmetry::new([[0, 0, -1], [1, 0, 0], [0, -1, 0]]).is_some());
    // The 60° turn of the skew basis of tri3 and hex: order 6.
    let turn = Symmetry::new([[0, -1, 0], [1, 1, 0], [0, 0, 1]]).expect("60° turn");
    let mut p = turn;
    for _ in 1..6 {
        assert_ne!(p, Symmetry::IDENTITY);
        p = p.compose(&turn);
    }
    assert_eq!(p, Symmetry::IDENTITY);
    assert_eq!(
        turn.inverse(),
        turn.compose(&turn)
            .compose(&turn)
            .compose(&turn)
            .compose(&turn)
    );
    assert_eq!(turn.inverse().matrix(), [[1, 1, 0], [-1, 0, 0], [0, 0, 1]]);
    assert_eq!(turn.spread(), 2);
}
