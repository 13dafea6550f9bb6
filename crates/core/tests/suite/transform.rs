//! Rigid motions: composition and inverse laws, for every lattice's
//! symmetries combined with lattice translations.

use dissect_core::lattice::Point;
use dissect_core::transform::Transform;
use dissect_core::LatticeKind;

use super::util::cells_around;

/// Some motions of `lattice`: each symmetry with a few lattice translations.
fn motions(lattice: LatticeKind) -> Vec<Transform> {
    let l = lattice.lattice();
    let m = l.modulus();
    let shifts: Vec<Point> = [[0, 0, 0], [1, 0, 0], [-2, 3, 1], [0, -1, -2]]
        .into_iter()
        .map(|s: [i32; 3]| {
            let mut p = [0; 3];
            for d in 0..l.dim() {
                p[d] = m * s[d];
            }
            Point::from(p)
        })
        .collect();
    let mut out = Vec::new();
    for g in l.symmetries(true) {
        for s in &shifts {
            out.push(Transform::new(g, *s));
        }
    }
    out
}

#[test]
fn compose_and_inverse_laws() {
    for lattice in LatticeKind::ALL {
        let l = lattice.lattice();
        let ms = motions(lattice);
        let points: Vec<Point> = cells_around(lattice, 1)
            .iter()
            .map(|c| l.to_point(*c))
            .collect();
        // A thinned set of triples keeps this fast.
        for (i, a) in ms.iter().enumerate() {
            assert_eq!(a.compose(&a.inverse()), Transform::IDENTITY, "{a:?}");
            assert_eq!(a.inverse().compose(a), Transform::IDENTITY, "{a:?}");
            assert_eq!(a.inverse().inverse(), *a);
            assert_eq!(a.compose(&Transform::IDENTITY), *a);
            assert_eq!(Transform::IDENTITY.compose(a), *a);
            for (j, b) in ms.iter().enumerate().filter(|(j, _)| (i + j) % 3 == 0) {
                let ab = a.compose(b);
                assert_eq!(ab.inverse(), b.inverse().compose(&a.inverse()));
                let c = &ms[(i * 7 + j * 3) % ms.len()];
                assert_eq!(ab.compose(c), a.compose(&b.compose(c)), "associativity");
                for &p in &points {
                    assert_eq!(ab.apply(p), a.apply(b.apply(p)));
                    let q = a.apply(p);
                    assert_eq!(a.inverse().apply(q), p);
                    // Motions map lattice points to lattice points.
                    assert!(
                        l.from_point(q).is_some(),
                        "{a:?} maps {p:?} off the lattice"
                    );
                }
            }
        }
    }
}

#[test]
fn apply_is_symmetry_then_shift() {
    let l = LatticeKind::Square.lattice();
    let rot = l.symmetries(false)[1];
    let t = Transform::new(rot, Point::new(5, -1, 0));
    assert_eq!(t.symmetry(), rot);
    assert_eq!(t.shift(), Point::new(5, -1, 0));
    let p = Point::new(2, 3, 0);
    let r = rot.apply(p);
    assert_eq!(t.apply(p), Point::new(r[0] + 5, r[1] - 1, 0));
    assert_eq!(Transform::IDENTITY.apply(p), p);
    // The inverse undoes the shift first, then the symmetry.
    assert_eq!(t.inverse().apply(t.apply(p)), p);
    assert_eq!(
        t.inverse().shift(),
        rot.inverse().apply(Point::new(-5, 1, 0))
    );
}
