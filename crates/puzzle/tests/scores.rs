//! Scores, ranking and the canonical form of dissections.

use dissect_core::{Cell, LatticeKind};
use dissect_puzzle::scores::{self, canonical, distinct, Rank, Scores};
use dissect_puzzle::Motions;

fn sq(cells: &[(i32, i32)]) -> Vec<Cell> {
    cells.iter().map(|&(x, y)| [x, y, 0]).collect()
}

#[test]
fn each_score_on_small_pieces() {
    let m = Motions::new(LatticeKind::Square, true);
    let domino = sq(&[(0, 0), (1, 0)]);
    let l = sq(&[(0, 0), (0, 1), (1, 1)]);
    let l2 = sq(&[(5, 5), (6, 5), (6, 6)]); // the same L, turned
    let block = sq(&[(0, 0), (1, 0), (0, 1), (1, 1)]);
    let pieces = vec![domino.clone(), l.clone(), l2.clone(), block.clone()];
    assert_eq!(scores::smallest(&pieces), 2);
    // Areas 2, 3, 3, 4: mean 3, variance (1 + 0 + 0 + 1) / 4.
    assert_eq!(scores::variance(&pieces), 0.5);
    assert_eq!(scores::shapes(&m, &pieces), 3);
    // Self-symmetries beyond the identity: domino 3, L 1 (its diagonal), block 7.
    assert_eq!(scores::symmetry(&m, &pieces), 3 + 1 + 1 + 7);
    // Without mirror images: domino 1 (half turn), L 0, block 3.
    let rot = Motions::new(LatticeKind::Square, false);
    assert_eq!(scores::symmetry(&rot, &pieces), 1 + 3);
    // An S tetromino and its mirror image: one shape with mirror, two without.
    let s = sq(&[(0, 0), (1, 0), (1, 1), (2, 1)]);
    let z = sq(&[(0, 1), (1, 1), (1, 0), (2, 0)]);
    assert_eq!(scores::shapes(&m, &[s.clone(), z.clone()]), 1);
    assert_eq!(scores::shapes(&rot, &[s, z]), 2);
}

#[test]
fn symmetry_on_tri4_and_cubic() {
    // A whole tri4 square (4 triangles) has all 8 symmetries; one triangle
    // has its mirror axis only.
    let m = Motions::new(LatticeKind::Tri4, true);
    let square: Vec<Cell> = (0..4).map(|t| [0, 0, t]).collect();
    assert_eq!(scores::symmetry(&m, &[square]), 7);
    assert_eq!(scores::symmetry(&m, &[vec![[0, 0, 1]]]), 1);
    // A 1x1x2 bar of cubes: 8 of the 24 rotations keep it.
    let c = Motions::new(LatticeKind::Cubic, false);
    assert_eq!(scores::symmetry(&c, &[vec![[0, 0, 0], [0, 0, 1]]]), 7);
}

#[test]
fn the_same_pieces_relabelled_and_turned_are_the_same_dissection() {
    let m = Motions::new(LatticeKind::Square, true);
    let a = vec![sq(&[(0, 0), (1, 0)]), sq(&[(0, 1), (1, 1), (2, 1), (2, 0)])];
    // Relabelled, moved, the L turned over.
    let b = vec![sq(&[(7, 7), (7, 8), (7, 9), (8, 9)]), sq(&[(3, 3), (3, 4)])];
    // Another cut: a straight tromino and an L tromino.
    let c = vec![sq(&[(0, 0), (1, 0), (2, 0)]), sq(&[(0, 1), (1, 1), (1, 2)])];
    assert_eq!(canonical(&m, &a), canonical(&m, &b));
    assert_ne!(canonical(&m, &a), canonical(&m, &c));
    assert_eq!(distinct(&m, &[&a, &b, &c, &a]), vec![0, 2]);
}

#[test]
fn each_rank_picks_its_own_best() {
    let s = |pieces, variance, smallest, shapes, symmetry, assemblies| Scores {
        pieces,
        variance,
        smallest,
        shapes,
        symmetry,
        objective: variance,
        assemblies,
        levels: None,
    };
    let items = vec![
        (s(5, 0.2, 2, 4, 0, Some(9)), "even"),
        (s(5, 3.0, 4, 5, 1, Some(5)), "big smallest"),
        (s(5, 4.0, 1, 2, 2, Some(7)), "few shapes"),
        (s(5, 5.0, 1, 4, 9, Some(8)), "symmetric"),
        (s(5, 6.0, 1, 5, 0, Some(1)), "unique"),
        (s(4, 9.0, 1, 4, 0, None), "fewer pieces"),
    ];
    let best = |rank: Rank| {
        let mut v = items.clone();
        rank.sort(&mut v);
        v.iter().map(|x| x.1).collect::<Vec<_>>()
    };
    // Fewer pieces always come first.
    assert_eq!(
        best(Rank::Variance)[..3],
        ["fewer pieces", "even", "big smallest"]
    );
    assert_eq!(best(Rank::Smallest)[1], "big smallest");
    assert_eq!(best(Rank::Shapes)[1], "few shapes");
    assert_eq!(best(Rank::Symmetry)[1], "symmetric");
    assert_eq!(best(Rank::Unique)[1..3], ["unique", "big smallest"]);
    // Ties fall back to the variance.
    let mut tie = vec![
        (s(3, 2.0, 1, 1, 0, None), "b"),
        (s(3, 1.0, 1, 1, 0, None), "a"),
    ];
    Rank::Shapes.sort(&mut tie);
    assert_eq!(tie[0].1, "a");
    assert_eq!("symmetry".parse::<Rank>(), Ok(Rank::Symmetry));
    assert!("fancy"
        .parse::<Rank>()
        .unwrap_err()
        .to_string()
        .contains("expected variance"));
}

#[test]
fn a_collection_keeps_distinct_dissections_with_the_fewest_pieces() {
    use dissect_puzzle::{Added, Collection, Constraints};
    let m = Motions::new(LatticeKind::Square, true);
    // A 1x4 bar and a 2x2 square.
    let two = vec![
        vec![sq(&[(0, 0), (1, 0)]), sq(&[(2, 0), (3, 0)])],
        vec![sq(&[(0, 0), (1, 0)]), sq(&[(0, 1), (1, 1)])],
    ];
    let two_swapped = vec![
        vec![sq(&[(2, 0), (3, 0)]), sq(&[(0, 0), (1, 0)])],
        vec![sq(&[(0, 0), (0, 1)]), sq(&[(1, 0), (1, 1)])],
    ];
    let three = vec![
        vec![sq(&[(0, 0)]), sq(&[(1, 0)]), sq(&[(2, 0), (3, 0)])],
        vec![sq(&[(0, 0)]), sq(&[(1, 0)]), sq(&[(0, 1), (1, 1)])],
    ];
    let mut c = Collection::new(m.clone(), Constraints::none());
    assert_eq!(c.add(three.clone()), Added::Fewer);
    assert_eq!(c.add(two.clone()), Added::Fewer);
    assert_eq!(c.add(two_swapped), Added::Duplicate);
    assert_eq!(c.add(three.clone()), Added::MorePieces);
    assert_eq!(c.len(), 1);
    // With a smallest piece of 2 cells the 3-piece cut is refused.
    let mut c = Collection::new(m, Constraints::none().with_sizes(Some(2), None));
    assert!(matches!(c.add(three), Added::Broken(v) if v.len() == 2));
    assert!(c.is_empty());
}

#[test]
fn symmetry_weight_turns_the_variance_ranking() {
    let m = Motions::new(LatticeKind::Square, true);
    // Areas 2 and 2 (variance 0), an L tromino and a domino... both cut 4+4.
    // a: two S tetrominoes (variance 0, each with one half-turn symmetry).
    let a = vec![
        sq(&[(0, 0), (1, 0), (1, 1), (2, 1)]),
        sq(&[(0, 2), (1, 2), (1, 3), (2, 3)]),
    ];
    // b: an I tromino and a 5-cell plus (variance 1, very symmetric).
    let b = vec![
        sq(&[(0, 0), (1, 0), (2, 0)]),
        sq(&[(1, 1), (0, 2), (1, 2), (2, 2), (1, 3)]),
    ];
    let plain = [Scores::of(&m, &a), Scores::of(&m, &b)];
    assert!(Rank::Variance.compare(&plain[0], &plain[1]).is_lt());
    let w = [Scores::weighted(&m, &a, 1.0), Scores::weighted(&m, &b, 1.0)];
    assert_eq!(w[0].variance, plain[0].variance);
    assert_eq!(w[0].objective, w[0].variance - w[0].symmetry as f64);
    assert!(w[1].symmetry > w[0].symmetry);
    assert!(Rank::Variance.compare(&w[0], &w[1]).is_gt());
}
