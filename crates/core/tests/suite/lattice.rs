//! One generic suite run for every lattice: adjacency, point embedding,
//! symmetries and translations.

use std::collections::HashSet;

use dissect_core::lattice::{Point, Symmetry};
use dissect_core::{Cell, Lattice, LatticeKind};

use super::util::{cells_around, Cubic, Square, Tri4};

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
    }
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
    let mut q = p;
    for d in 0..l.dim() {
        q[d] += m * steps[d];
    }
    q
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
        ["square", "tri4", "cubic"]
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
                    let p = [x, y, z];
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
            for c in cells_around(l.kind(), 1) {
                let moved = l.from_point(translate(l, l.to_point(c), s));
                let moved = moved.unwrap_or_else(|| panic!("{c:?} + {s:?}"));
                assert_eq!(l.block(moved)[0], l.block(c)[0] + s[0]);
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
                    assert_eq!(s.apply([0, 0, 1]), [0, 0, 1]);
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
    assert_eq!(rot90.apply([1, 0, 0]), [0, 1, 0]);
    assert_eq!(rot90.compose(&rot90).apply([1, 2, 3]), [-1, -2, 3]);
    assert_eq!(rot90.determinant(), 1);
    assert_eq!(flip.determinant(), -1);
    assert_eq!(rot90.compose(&flip).determinant(), -1);
    assert_eq!(flip.compose(&flip), Symmetry::IDENTITY);
    assert_eq!(rot90.inverse(), rot90.compose(&rot90).compose(&rot90));
    // compose applies the right-hand side first.
    let p = [2, 5, 7];
    assert_eq!(rot90.compose(&flip).apply(p), rot90.apply(flip.apply(p)));
    assert_ne!(rot90.compose(&flip), flip.compose(&rot90));
    assert_eq!(rot90.apply_wide([1, 2, 3]), [-2, 1, 3]);
    assert_eq!(rot90.matrix(), [[0, -1, 0], [1, 0, 0], [0, 0, 1]]);
}

#[test]
fn only_signed_permutations_are_symmetries() {
    for m in [
        [[0, 0, 0], [0, 1, 0], [0, 0, 1]],
        [[2, 0, 0], [0, 1, 0], [0, 0, 1]],
        [[1, 1, 0], [0, 1, 0], [0, 0, 1]],
        [[1, 0, 0], [1, 0, 0], [0, 0, 1]],
        [[1, 0, 0], [0, 0, 1], [0, 0, 1]],
    ] {
        assert_eq!(Symmetry::new(m), None, "{m:?}");
    }
    assert!(Symmetry::new([[0, 0, -1], [1, 0, 0], [0, -1, 0]]).is_some());
}
