//! The matching `M`: min-cost assignments with a known optimum, whose
//! distances and transforms agree.

use std::collections::BTreeSet;

use crate::lattice::{LatticeKind, Point};

use super::util::{candidate, matching, piece_points, Cubic, Square, Tri4};

/// The optimal matching from the pieces of `a` to those of `b` is
/// `partner` with cost `cost`.
fn check(lattice: LatticeKind, mirror: bool, a: &str, b: &str, partner: &[usize], cost: u64) {
    let (_, problem, cand) = candidate(lattice, mirror, &[a, b]);
    let m = matching(&problem, &cand, 0, 1);
    assert_eq!(
        (&m.partner[..], m.cost),
        (partner, cost),
        "matching {a:?} -> {b:?} on {lattice}"
    );
    assert_eq!(m.dists.iter().map(|d| *d as u64).sum::<u64>(), m.cost);
    // Each transform carries piece i onto its partner with the distance.
    for (i, &j) in m.partner.iter().enumerate() {
        let pa = piece_points(&problem, &cand, 0, i);
        let pb = piece_points(&problem, &cand, 1, j);
        let moved: BTreeSet<Point> = pa.iter().map(|p| m.transforms[i].apply(*p)).collect();
        let overlap = moved.intersection(&pb).count();
        assert_eq!(
            m.dists[i] as usize,
            pa.len() + pb.len() - 2 * overlap,
            "pair {i} -> {j}"
        );
    }
}

#[test]
fn square_matchings() {
    check(Square, true, "AAB", "AAB", &[0, 1], 0);
    check(Square, true, "AABBB", "AAABB", &[1, 0], 0);
    // I3 and a single against L3 and a single: the shapes pair up, cost 2.
    check(Square, true, "AAAB", "AA|AB", &[0, 1], 2);
    check(Square, true, "AAAB", "AB|BB", &[1, 0], 2);
    check(Square, true, "AABCCC", "ABBBCC", &[2, 0, 1], 0);
    // Bars of lengths 4, 2, 1 against 1, 4, 2: D is the length difference.
    check(
        Square,
        true,
        "AAAA.|BB...|C....",
        "A....|BBBB.|CC...",
        &[1, 2, 0],
        0,
    );
    check(
        Square,
        true,
        "AAAA.|BB...|C....",
        "AAA..|BBBBB|C....",
        &[1, 0, 2],
        2,
    );
    // S and a bar against Z and a bar: zero with mirror, D(S, Z) without.
    check(
        Square,
        true,
        ".AA|AA.|...|BBBB",
        "AA.|.AA|...|BBBB",
        &[0, 1],
        0,
    );
    check(
        Square,
        false,
        ".AA|AA.|...|BBBB",
        "AA.|.AA|...|BBBB",
        &[0, 1],
        2,
    );
    // A domino and a straight tromino against an L tromino and a domino.
    check(Square, true, "AAB|..B|..B", "B..|BAA|..A", &[1, 0], 2);
}

#[test]
fn tri4_matchings() {
    check(Tri4, true, "AAAA B...", "B... AAAA", &[0, 1], 0);
    check(Tri4, true, "AAAA B...", "A... BBBB", &[1, 0], 0);
    check(Tri4, true, "AAAA BB..", "AA.. BBB.", &[1, 0], 1);
}

#[test]
fn cubic_matchings() {
    check(Cubic, false, "AAB", "A|B|B", &[1, 0], 0);
    check(Cubic, false, "AA|AA/B.|..", "A./BB|BB", &[1, 0], 0);
    check(Cubic, false, "AAB/CCC", "CCC/A../BB.", &[1, 0, 2], 0);
}
