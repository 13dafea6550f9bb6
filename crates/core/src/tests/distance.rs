//! The distance `D(a, b)`: exactly zero for congruent pieces (and then its
//! transform carries one piece onto the other), hand-checked values
//! otherwise, and symmetric. `D` is read from the solver's matching of two
//! one-piece figures.

use std::collections::BTreeSet;

use rand::RngExt;

use crate::figure::Figure;
use crate::lattice::{Cell, LatticeKind, Point};
use crate::solver::distance::Geometry;

use super::util::{
    candidate, candidate_of, matching, piece_points, rng, Cubic, Hex, Square, Tri3, Tri4,
};

/// `D` between the single pieces written (with letter `A`) by `a` and `b`.
fn check(lattice: LatticeKind, mirror: bool, a: &str, b: &str, expected: u32) {
    let d = dist(lattice, mirror, a, b);
    assert_eq!(d, expected, "D({a:?}, {b:?}) on {lattice}, mirror {mirror}");
}

/// `D` between two single pieces, checked both ways.
fn dist(lattice: LatticeKind, mirror: bool, a: &str, b: &str) -> u32 {
    let (_, problem, cand) = candidate(lattice, mirror, &[a, b]);
    assert_eq!(cand.k, 1, "one piece per figure: {a:?}, {b:?}");
    let m = matching(&problem, &cand, 0, 1);
    let d = m.dists[0];
    let back = matching(&problem, &cand, 1, 0).dists[0];
    assert_eq!(d, back, "D is symmetric: {a:?}, {b:?} on {lattice}");
    assert_eq!(m.cost, d as u64);
    assert!(problem.geo.syms.contains(&m.transforms[0].symmetry()));
    d
}

/// The transform that comes with `D` carries the first piece onto the
/// second with exactly `D` cells missed.
fn check_transform(lattice: LatticeKind, mirror: bool, a: &str, b: &str) {
    let (_, problem, cand) = candidate(lattice, mirror, &[a, b]);
    let m = matching(&problem, &cand, 0, 1);
    let (d, t) = (m.dists[0], m.transforms[0]);
    let (pa, pb) = (
        piece_points(&problem, &cand, 0, 0),
        piece_points(&problem, &cand, 1, 0),
    );
    let moved: BTreeSet<Point> = pa.iter().map(|p| t.apply(*p)).collect();
    let overlap = moved.intersection(&pb).count();
    assert_eq!(
        d as usize,
        pa.len() + pb.len() - 2 * overlap,
        "the transform {t:?} does not reach D = {d}: {a:?} -> {b:?} on {lattice}"
    );
}

/// `D` by its definition, written independently of the solver: over every
/// symmetry, the nearest lattice translations of the centroid offset.
fn reference_distance(geo: &Geometry, a: &[Point], b: &[Point]) -> u32 {
    let (na, nb) = (a.len() as i64, b.len() as i64);
    let target: BTreeSet<Point> = b.iter().copied().collect();
    let sum = |ps: &[Point]| -> [i64; 3] {
        let mut s = [0i64; 3];
        for p in ps {
            for d in 0..3 {
                s[d] += p[d] as i64;
            }
        }
        s
    };
    let sb = sum(b);
    let m = geo.modulus as i64;
    let mut best = 0;
    for g in &geo.syms {
        let ga: Vec<Point> = a.iter().map(|p| g.apply(*p)).collect();
        let sa = sum(&ga);
        let mut options: Vec<Vec<i32>> = vec![vec![0]; 3];
        for d in 0..geo.dim {
            // The offset sb/nb - sa/na, in units of m, rounded both ways.
            let (num, den) = (sb[d] * na - sa[d] * nb, na * nb * m);
            let lo = num.div_euclid(den);
            options[d] = if num.rem_euclid(den) == 0 {
                vec![(lo * m) as i32]
            } else {
                vec![(lo * m) as i32, ((lo + 1) * m) as i32]
            };
        }
        for &x in &options[0] {
            for &y in &options[1] {
                for &z in &options[2] {
                    let hits = ga
                        .iter()
                        .filter(|p| target.contains(&(*p + Point::new(x, y, z))))
                        .count();
                    best = best.max(hits);
                }
            }
        }
    }
    (na + nb) as u32 - 2 * best as u32
}

/// A random connected piece of up to `max` cells around `start`.
fn random_piece(lattice: LatticeKind, start: Cell, max: usize, rng: &mut impl RngExt) -> Vec<Cell> {
    let l = lattice.lattice();
    let mut cells = vec![start];
    let size = rng.random_range(1..=max);
    while cells.len() < size {
        let from = cells[rng.random_range(0..cells.len())];
        let ns = l.neighbors(from);
        let n = ns[rng.random_range(0..ns.len())];
        if !cells.contains(&n) {
            cells.push(n);
        }
    }
    cells
}

#[test]
fn zero_for_congruent_square_pieces() {
    for mirror in [true, false] {
        check(Square, mirror, "A", "..|.A", 0);
        check(Square, mirror, "AA", "A|A", 0);
        check(Square, mirror, "..|.AA", "AA", 0);
        check(Square, mirror, ".AA|AA.", "A.|AA|.A", 0);
        check(Square, mirror, "AA|AA|A.", ".A|AA|AA", 0);
        check(Square, mirror, "AAA|A.A", "AA|A.|AA", 0);
        check(Square, mirror, "AAAA|A...", "A.|A.|A.|AA", 0);
    }
    // Mirror images: S and Z, L and J, P and its flip.
    check(Square, true, ".AA|AA.", "AA.|.AA", 0);
    check(Square, true, ".A|.A|AA", "A.|A.|AA", 0);
    check(Square, true, "AA|AA|A.", "AA|AA|.A", 0);
}

#[test]
fn zero_for_congruent_tri4_pieces() {
    for mirror in [true, false] {
        // Any triangle is any other, turned.
        check(Tri4, mirror, "A...", ".A..", 0);
        check(Tri4, mirror, "A...", "...A", 0);
        check(Tri4, mirror, "..A.", ". .|. A...", 0);
        // The big triangle, apex down and apex up.
        check(Tri4, mirror, "AA.. A..A", ".AA. ..AA", 0);
        // A square with a half square, turned by 180 degrees.
        check(Tri4, mirror, "AAAA A..A", ".AA. AAAA", 0);
    }
    check(Tri4, true, "AAAA A..A", "AA.. AAAA", 0);
}

#[test]
fn zero_for_congruent_cubic_pieces() {
    for mirror in [true, false] {
        check(Cubic, mirror, "A", "../.A", 0);
        check(Cubic, mirror, "AA", "A/A", 0);
        check(Cubic, mirror, "AA|A.", "A./AA", 0);
        // A chiral tetracube and one of its rotations.
        check(Cubic, mirror, "AA|.A/..|.A", "A.|A./..|AA", 0);
    }
}

#[test]
fn mirror_images_without_mirror() {
    assert_eq!(dist(Square, false, ".AA|AA.", "AA.|.AA"), 2);
    assert!(dist(Square, false, ".A|.A|AA", "A.|A.|AA") > 0);
    assert!(dist(Square, false, "AA|AA|A.", "AA|AA|.A") > 0);
    assert!(dist(Tri4, false, "AAAA A..A", "AA.. AAAA") > 0);
    // In 3D a chiral piece is never its mirror image, whatever `mirror` says.
    for mirror in [true, false] {
        assert!(dist(Cubic, mirror, "AA|.A/..|.A", "AA|A./..|A.") > 0);
    }
}

#[test]
fn hand_checked_values() {
    // |a| + |b| - 2 * (best overlap after centroid alignment).
    check(Square, true, "A", "AA", 1);
    check(Square, true, "AAA", "AA|A.", 2);
    check(Square, true, "AA|AA", "AAAA", 4);
    check(Square, true, "A", "AAAA|AAAA", 7);
    check(Square, false, "AAA|.A.", "AAAA", 2);
    check(Tri4, true, "A...", "AA..", 1);
    check(Tri4, true, "AAAA", "AA..", 2);
    check(Tri4, true, "AAAA", "A...", 3);
    check(Cubic, false, "AA|AA/AA|AA", "AA|AA", 4);
    check(Cubic, false, "AAA", "A/A/A", 0);
    check(Cubic, false, "AA", "A", 1);
}

/// `tri3` and `hex`: pieces turned by 60° (an up triangle then becomes a
/// down one), mirrored, or moved by an odd number of rows are congruent; a
/// lone up triangle is never a down triangle moved.
#[test]
fn zero_for_congruent_tri3_and_hex_pieces() {
    for mirror in [true, false] {
        // One triangle, up or down, anywhere.
        check(Tri3, mirror, "A", ".A", 0);
        check(Tri3, mirror, "A", ".|A", 0);
        // A rhombus of two triangles in its three orientations.
        check(Tri3, mirror, "AA", ".AA", 0);
        check(Tri3, mirror, "AA", "A|A", 0);
        check(Tri3, mirror, "A|A", ".AA", 0);
        // The hexagon of six triangles, a row lower (x + y stays even).
        check(Tri3, mirror, "AAA|AAA", ".|.AAA|.AAA", 0);
        // An hourglass of two trapezoids, turned by 60°.
        check(Tri3, mirror, ".AAA|.AAA", "..A|AAAA|.A", 0);
        // A trapezoid of three, upside down.
        check(Tri3, mirror, "AAA", ".AAA", 0);
        // Hexagons: a bar of three in its three directions, across odd rows.
        check(Hex, mirror, "AAA", "A|A|.A", 0);
        check(Hex, mirror, "AAA", ".|A|.A|.A", 0);
        check(Hex, mirror, "AA|A", ".A|AA", 0);
        check(Hex, mirror, "AA|.A", ".|AA|A", 0);
    }
    // A chiral pentiamond and a chiral tetrahex meet their mirror images
    // only with mirror.
    check(Tri3, true, "AAAA|A", "AA|AA|.A", 0);
    assert!(dist(Tri3, false, "AAAA|A", "AA|AA|.A") > 0);
    check(Hex, true, "AAA|A", "AAA|.A", 0);
    assert!(dist(Hex, false, "AAA|A", "AAA|.A") > 0);
    // Different pieces are at a positive distance.
    check(Tri3, true, "AA", "A", 1);
    check(Hex, true, "AAA", "AA|A", 2);
}

/// `D` between the pieces made of cells `a` and `b` (each its own figure)
/// is the one of the definition.
fn check_definition(lattice: LatticeKind, mirror: bool, a: &[Cell], b: &[Cell]) {
    let parts: Vec<(Figure, Vec<u16>)> = [a, b]
        .iter()
        .map(|cells| {
            let f = Figure::new(lattice, cells.iter().copied()).unwrap();
            let n = f.len();
            (f, vec![0; n])
        })
        .collect();
    let (_, problem, cand) = candidate_of(lattice, mirror, parts);
    let pts =
        |f: usize| -> Vec<Point> { piece_points(&problem, &cand, f, 0).into_iter().collect() };
    let want = reference_distance(&problem.geo, &pts(0), &pts(1));
    let got = matching(&problem, &cand, 0, 1).dists[0];
    assert_eq!(got, want, "D({a:?}, {b:?}) on {lattice}, mirror {mirror}");
}

/// Ignored: fails since c0834ef, for the reason given at
/// [`transforms_reach_the_distance`]: when every figure is one cell wide in
/// x, `Layout::new` pads x by 0, so a point moved by ±1 in x aliases the
/// point ±1 in y and counts as a hit. E.g. square `.|.|.|A|A` against
/// `A|.|.|A` gives D = 2; the definition (and 89ef82a) gives 4.
#[test]
fn distance_follows_its_definition_on_thin_figures() {
    check_definition(
        Square,
        true,
        &[[0, 3, 0], [0, 4, 0]],
        &[[0, 0, 0], [0, 3, 0]],
    );
    check_definition(
        Square,
        false,
        &[[0, 0, 0], [0, 5, 0]],
        &[[0, 0, 0], [0, 3, 0]],
    );
    check_definition(
        Square,
        true,
        &[[0, 1, 0], [0, 4, 0], [0, 5, 0]],
        &[[0, 0, 0], [0, 1, 0]],
    );
}

#[test]
fn distance_follows_its_definition_on_random_pieces() {
    let mut r = rng(2024);
    for lattice in LatticeKind::ALL {
        for mirror in [true, false] {
            for _ in 0..150 {
                let offset = [r.random_range(-9..9), r.random_range(-9..9), 0];
                let start = match lattice {
                    Tri4 => [offset[0], offset[1], r.random_range(0..4)],
                    Cubic => [offset[0], offset[1], r.random_range(-3..3)],
                    Square | Tri3 | Hex => offset,
                };
                let a = random_piece(lattice, [0, 0, 0], 7, &mut r);
                let b = random_piece(lattice, start, 7, &mut r);
                check_definition(lattice, mirror, &a, &b);
            }
        }
    }
}

/// Ignored: fails since c0834ef ("Faster distance: ... padded linear label
/// grid"). `Layout::new` gives a dimension in which every shape has zero
/// extent no padding (`pad = 0` when `ext == 0`), so translated addresses
/// alias other points; the distance then returns after a false full overlap
/// with a transform that does not carry the piece onto its partner, e.g.
/// tri4 `.A..` -> `A...` gives rot180 + (6, 6), which maps the right
/// triangle onto the left one, and cubic `AA` -> `A/A` a transform that
/// misses both cubes. Copy-paste applies these transforms. Passes at 89ef82a.
#[test]
fn transforms_reach_the_distance() {
    let cases: &[(LatticeKind, &str, &str)] = &[
        (Square, "AA", "A|A"),
        (Square, ".AA|AA.", "A.|AA|.A"),
        (Square, "AAA|.A.", "AAAA"),
        (Square, "A", "AAAA|AAAA"),
        (Tri4, "A...", ".A.."),
        (Tri4, "A...", "...A"),
        (Tri4, "AA.. A..A", ".AA. ..AA"),
        (Tri4, "AAAA", "AA.."),
        (Cubic, "AA", "A/A"),
        (Cubic, "AAA", "A/A/A"),
        (Cubic, "AA|.A/..|.A", "A.|A./..|AA"),
        (Cubic, "AA|AA/AA|AA", "AA|AA"),
        (Tri3, "AA", "A|A"),
        (Tri3, "AAA|AAA", ".|.AAA|.AAA"),
        (Tri3, ".AAA|.AAA", "..A|AAAA|.A"),
        (Tri3, "AAAA|A", "AA|AA|.A"),
        (Tri3, "AAAA", "A"),
        (Hex, "AAA", "A|A|.A"),
        (Hex, "AAA|A", "AAA|.A"),
        (Hex, "A", "AAA|AAA"),
    ];
    for &(lattice, a, b) in cases {
        for mirror in [true, false] {
            check_transform(lattice, mirror, a, b);
            check_transform(lattice, mirror, b, a);
        }
    }
}
