//! The solver's form of a figure (`Shape`) and of its pieces (`Pieces`).

use crate::lattice::LatticeKind;
use crate::solver::piece::Pieces;
use crate::solver::shape::Shape;

use super::util::{labelled, Cubic, Square, Tri4};

/// The shape of a figure numbers its cells in figure order, finds each by
/// its point, and lists exactly its in-figure neighbours.
fn check(lattice: LatticeKind, compact: &str) {
    let (figure, _) = labelled(lattice, compact);
    let shape = Shape::of_figure(&figure);
    let l = lattice.lattice();
    assert_eq!(shape.len(), figure.len());
    for (i, &c) in figure.cells().iter().enumerate() {
        let i = i as u32;
        assert_eq!(shape.point(i), l.to_point(c));
        assert_eq!(shape.lookup(l.to_point(c)), Some(i));
        let mut got: Vec<u32> = shape.neighbors(i).to_vec();
        got.sort();
        let mut want: Vec<u32> = l
            .neighbors(c)
            .into_iter()
            .filter_map(|n| figure.cells().iter().position(|d| *d == n))
            .map(|j| j as u32)
            .collect();
        want.sort();
        assert_eq!(got, want, "neighbours of {c:?} in {compact:?}");
        for n in l.neighbors(c) {
            if !figure.contains(n) {
                assert_eq!(shape.lookup(l.to_point(n)), None);
            }
        }
    }
}

#[test]
fn shapes() {
    check(Square, "A");
    check(Square, "AAA|A.A|AAA");
    check(Square, "A.A|.A.");
    check(Tri4, "AAAA A..A|A..A .");
    check(Tri4, "A.A. .A.A");
    check(Cubic, "AA|A./.A|AA");
}

#[test]
fn subsets_renumber_cells() {
    let (figure, _) = labelled(Square, "AAA|A.A|AAA");
    let shape = Shape::of_figure(&figure);
    // Cells are sorted by x, then y: the left column is 0, 1, 2.
    let sub = shape.subset(&[0, 1, 2, 3]);
    assert_eq!(sub.len(), 4);
    assert_eq!(sub.point(3), shape.point(3));
    let sorted = |s: &[u32]| {
        let mut v = s.to_vec();
        v.sort();
        v
    };
    assert_eq!(sorted(sub.neighbors(0)), vec![1, 3]);
    assert_eq!(sorted(sub.neighbors(3)), vec![0]);
    assert_eq!(sorted(sub.neighbors(2)), vec![1]);
    assert_eq!(sub.lookup(shape.point(4)), None);
}

#[test]
fn pieces_know_members_sizes_and_sums() {
    let (figure, labels) = labelled(Square, "AAB|ABB|CCB");
    let shape = Shape::of_figure(&figure);
    let p = Pieces::of(&shape, &labels, 4);
    assert_eq!(p.count(), 4);
    assert_eq!((p.size(0), p.size(1), p.size(2), p.size(3)), (3, 4, 2, 0));
    // A is (0,0), (1,0), (0,1).
    assert_eq!(p.sum(0), [1, 1, 0]);
    assert_eq!(p.sum(3), [0, 0, 0]);
    let members: Vec<_> = p
        .members(0)
        .iter()
        .map(|&c| figure.cells()[c as usize])
        .collect();
    assert_eq!(members, vec![[0, 0, 0], [0, 1, 0], [1, 0, 0]]);
    let mut scratch = vec![false; shape.len()];
    for i in 0..3 {
        assert_eq!(p.components(&shape, i, &mut scratch), 1);
    }
    assert!(scratch.iter().all(|s| !s), "scratch is left clean");
    let q = p.permuted(&[2, 0, 1, 3]);
    assert_eq!((q.size(0), q.sum(0)), (p.size(2), p.sum(2)));
    assert_eq!(q.members(1), p.members(0));

    let (figure, labels) = labelled(Tri4, "ABAB BBBB");
    let shape = Shape::of_figure(&figure);
    let p = Pieces::of(&shape, &labels, 2);
    let mut scratch = vec![false; shape.len()];
    assert_eq!(p.components(&shape, 0, &mut scratch), 2);
    // B's left triangle touches only A and the outside.
    assert_eq!(p.components(&shape, 1, &mut scratch), 2);
}
