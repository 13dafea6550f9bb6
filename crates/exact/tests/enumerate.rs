//! `enumerate` against a brute force written here (no code shared with the
//! enumerator): every partition of the first figure into K connected
//! pieces (figures up to 16 cells), each checked for whether its pieces
//! tile every other figure by backtracking, and the classes up to the first
//! figure's symmetries by canonical forms computed here, on square, tri4
//! and cubic.

use std::collections::HashSet;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use dissect_core::io::parse_figure;
use dissect_core::lattice::{Point, Symmetry};
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_exact::{enumerate, EnumerateOptions, Enumeration};

fn figures(lattice: LatticeKind, texts: &[&str]) -> Vec<Figure> {
    texts
        .iter()
        .map(|t| parse_figure(t, lattice).expect("test figure parses"))
        .collect()
}

struct Brute {
    lattice: LatticeKind,
    syms: Vec<Symmetry>,
}

impl Brute {
    fn new(lattice: LatticeKind, mirror: bool) -> Brute {
        let l = lattice.lattice();
        Brute {
            lattice,
            syms: l.symmetries(mirror && l.supports_mirror()),
        }
    }

    fn point(&self, c: Cell) -> Point {
        self.lattice.lattice().to_point(c)
    }

    fn is_translation(&self, t: Point) -> bool {
        let l = self.lattice.lattice();
        (0..3).all(|k| {
            if k < l.dim() {
                t[k].rem_euclid(l.modulus()) == 0
            } else {
                t[k] == 0
            }
        })
    }

    /// Every partition of the first figure into `k` connected pieces whose
    /// pieces tile every other figure, as bit masks over its cells.
    fn dissections(&self, figs: &[Figure], k: usize) -> Vec<Vec<u32>> {
        let cells = figs[0].cells();
        let n = cells.len();
        assert!(n <= 16, "the brute force is for small figures");
        let l = self.lattice.lattice();
        let adj: Vec<u32> = cells
            .iter()
            .map(|c| {
                l.neighbors(*c)
                    .into_iter()
                    .filter_map(|d| cells.iter().position(|x| *x == d))
                    .fold(0u32, |m, i| m | 1 << i)
            })
            .collect();
        let mut out = Vec::new();
        let mut parts = Vec::new();
        self.partitions(&adj, (1u32 << n) - 1, k, &mut parts, &mut |parts| {
            let pieces: Vec<Vec<Cell>> = parts
                .iter()
                .map(|&m| {
                    (0..n)
                        .filter(|&i| m >> i & 1 == 1)
                        .map(|i| cells[i])
                        .collect()
                })
                .collect();
            if figs[1..].iter().all(|f| self.tiles(f, &pieces)) {
                out.push(parts.to_vec());
            }
        });
        out
    }

    fn connected(adj: &[u32], set: u32) -> bool {
        if set == 0 {
            return false;
        }
        let mut seen = set & set.wrapping_neg();
        loop {
            let mut grow = seen;
            for (i, a) in adj.iter().enumerate() {
                if seen >> i & 1 == 1 {
                    grow |= a & set;
                }
            }
            if grow == seen {
                return seen == set;
            }
            seen = grow;
        }
    }

    /// Parts in order of their lowest cell: each part is a connected subset
    /// of what is left holding its lowest cell.
    fn partitions(
        &self,
        adj: &[u32],
        rest: u32,
        k: usize,
        parts: &mut Vec<u32>,
        emit: &mut dyn FnMut(&[u32]),
    ) {
        if rest == 0 {
            if parts.len() == k {
                emit(parts);
            }
            return;
        }
        if parts.len() == k {
            return;
        }
        if parts.len() + 1 == k {
            if Self::connected(adj, rest) {
                parts.push(rest);
                emit(parts);
                parts.pop();
            }
            return;
        }
        let low = rest & rest.wrapping_neg();
        let others = rest & !low;
        // Every subset of the others, with the lowest cell added.
        let mut sub = others;
        loop {
            let part = sub | low;
            if part != rest && Self::connected(adj, part) {
                parts.push(part);
                self.partitions(adj, rest & !part, k, parts, emit);
                parts.pop();
            }
            if sub == 0 {
                break;
            }
            sub = (sub - 1) & others;
        }
    }

    fn tiles(&self, fig: &Figure, pieces: &[Vec<Cell>]) -> bool {
        let mut free: HashSet<Point> = fig.cells().iter().map(|c| self.point(*c)).collect();
        let shapes: Vec<Vec<Point>> = pieces
            .iter()
            .map(|p| p.iter().map(|c| self.point(*c)).collect())
            .collect();
        let mut used = vec![false; shapes.len()];
        self.place(&mut free, &shapes, &mut used)
    }

    fn place(&self, free: &mut HashSet<Point>, shapes: &[Vec<Point>], used: &mut [bool]) -> bool {
        let Some(&first) = free.iter().min() else {
            return true;
        };
        for s in 0..shapes.len() {
            if used[s] {
                continue;
            }
            for g in &self.syms {
                let img: Vec<Point> = shapes[s].iter().map(|p| g.apply(*p)).collect();
                for anchor in &img {
                    let t = first - *anchor;
                    if !self.is_translation(t) {
                        continue;
                    }
                    let moved: Vec<Point> = img.iter().map(|p| *p + t).collect();
                    if moved.iter().all(|p| free.contains(p)) {
                        for p in &moved {
                            free.remove(p);
                        }
                        used[s] = true;
                        if self.place(free, shapes, used) {
                            return true;
                        }
                        used[s] = false;
                        free.extend(moved.iter().copied());
                    }
                }
            }
        }
        false
    }

    /// The classes of cuts up to the first figure's symmetries.
    fn classes(&self, fig: &Figure, cuts: &[Vec<Vec<Cell>>]) -> usize {
        let mut pts: Vec<Point> = fig.cells().iter().map(|c| self.point(*c)).collect();
        pts.sort();
        let mut motions = Vec::new();
        for g in &self.syms {
            let mut img: Vec<Point> = pts.iter().map(|p| g.apply(*p)).collect();
            img.sort();
            let t = pts[0] - img[0];
            if self.is_translation(t) && img.iter().map(|p| *p + t).eq(pts.iter().copied()) {
                motions.push((*g, t));
            }
        }
        let forms: HashSet<Vec<Vec<Point>>> = cuts
            .iter()
            .map(|cut| {
                motions
                    .iter()
                    .map(|(g, t)| {
                        let mut f: Vec<Vec<Point>> = cut
                            .iter()
                            .map(|p| {
                                let mut q: Vec<Point> =
                                    p.iter().map(|c| g.apply(self.point(*c)) + *t).collect();
                                q.sort();
                                q
                            })
                            .collect();
                        f.sort();
                        f
                    })
                    .min()
                    .expect("the identity")
            })
            .collect();
        forms.len()
    }
}

fn run(figs: &[Figure], mirror: bool, pieces: Option<usize>) -> Enumeration {
    run_with(figs, mirror, pieces, true)
}

fn run_with(figs: &[Figure], mirror: bool, pieces: Option<usize>, breaking: bool) -> Enumeration {
    let stop = AtomicBool::new(false);
    enumerate(
        figs,
        &EnumerateOptions {
            mirror,
            pieces,
            symmetry_breaking: breaking,
            ..EnumerateOptions::default()
        },
        &stop,
        &(),
    )
    .expect("the enumeration runs")
}

/// The count and the classes for `k` pieces agree with the brute force,
/// every dissection is valid and no cut of the first figure comes twice,
/// with the symmetry breaking and without it; returns the count.
fn check(lattice: LatticeKind, mirror: bool, texts: &[&str], k: usize) -> usize {
    let n = check_with(lattice, mirror, texts, k, true);
    assert_eq!(check_with(lattice, mirror, texts, k, false), n);
    n
}

fn check_with(
    lattice: LatticeKind,
    mirror: bool,
    texts: &[&str],
    k: usize,
    breaking: bool,
) -> usize {
    let figs = figures(lattice, texts);
    let brute = Brute::new(lattice, mirror);
    let expected = brute.dissections(&figs, k);
    let got = run_with(&figs, mirror, Some(k), breaking);
    assert!(got.complete, "{texts:?} k={k}");
    assert_eq!(got.pieces, k);
    assert_eq!(
        got.dissections.len(),
        expected.len(),
        "dissections of {texts:?} into {k} pieces"
    );
    let mut cuts = HashSet::new();
    for d in &got.dissections {
        let n = dissect_core::verify::verify_pieces(lattice, mirror, &figs, d).expect("valid");
        assert_eq!(n, k);
        let mut cut: Vec<Vec<Cell>> = d[0].clone();
        for p in &mut cut {
            p.sort();
        }
        cut.sort();
        assert!(cuts.insert(cut), "a cut of the first figure came twice");
    }
    let cells = figs[0].cells();
    let expected_cuts: Vec<Vec<Vec<Cell>>> = expected
        .iter()
        .map(|parts| {
            parts
                .iter()
                .map(|&m| {
                    (0..cells.len())
                        .filter(|&i| m >> i & 1 == 1)
                        .map(|i| cells[i])
                        .collect()
                })
                .collect()
        })
        .collect();
    for cut in &expected_cuts {
        let mut c = cut.clone();
        c.sort();
        assert!(cuts.contains(&c), "the brute force's cut {c:?} is missing");
    }
    assert_eq!(
        got.classes,
        brute.classes(&figs[0], &expected_cuts),
        "classes of {texts:?} into {k} pieces"
    );
    assert_eq!(got.class_of.len(), got.dissections.len());
    expected.len()
}

#[test]
fn square_counts_match_brute_force() {
    let s = LatticeKind::Square;
    assert!(check(s, true, &["###\n###", "######"], 2) > 0);
    assert!(check(s, true, &["###\n###", "######"], 3) > 1);
    for k in 1..=3 {
        check(s, true, &["####\n####", "##\n##\n##\n##"], k);
    }
    check(s, true, &["###\n#.#\n###", "####\n####"], 2);
    check(s, true, &["###\n#.#\n###", "####\n####"], 3);
    assert!(
        check(
            s,
            true,
            &["####\n####\n####\n####", "########\n########"],
            2
        ) > 1
    );
    assert!(
        check(
            s,
            true,
            &["####\n####\n####\n####", "########\n########"],
            3
        ) > 10
    );
}

#[test]
fn square_counts_without_mirror_and_with_three_figures() {
    let s = LatticeKind::Square;
    check(s, false, &["##.\n.##", ".##\n##."], 2);
    check(s, true, &["##.\n.##", ".##\n##."], 1);
    check(
        s,
        false,
        &["####\n####\n####\n####", "########\n########"],
        3,
    );
    check(s, true, &["####", "##\n##", "#..\n###"], 2);
    check(s, true, &["####", "##\n##", "#..\n###"], 3);
}

#[test]
fn tri4_counts_match_brute_force() {
    let t = LatticeKind::Tri4;
    check(t, true, &["FF", "6C\n39"], 2);
    check(t, true, &["FF", "6C\n39"], 3);
    assert!(check(t, true, &["FF\nFF", "FFFF"], 2) > 0);
    check(t, true, &["FF\nFF", "FFFF"], 3);
    check(t, false, &["FF\nFF", "FFFF"], 3);
}

#[test]
fn cubic_counts_match_brute_force() {
    let c = LatticeKind::Cubic;
    assert!(check(c, false, &["##\n##\n\n##\n##", "####\n####"], 2) > 0);
    check(c, false, &["##\n##\n\n##\n##", "####\n####"], 3);
    check(c, false, &["###\n#..\n\n##.\n...", "###\n###"], 2);
    check(c, false, &["###\n#..\n\n##.\n...", "###\n###"], 3);
}

/// Targets of several symmetric components (as Loyd's three squares):
/// the symmetry breaking inside each component loses no cut.
#[test]
fn targets_of_several_symmetric_components_match_brute_force() {
    let s = LatticeKind::Square;
    let two = ["####\n####", "##.##\n##.##"];
    check(s, true, &two, 2);
    check(s, false, &two, 3);
    let halves = ["####\n####\n####", "###.###\n###.###"];
    assert!(check(s, true, &halves, 2) > 0);
    check(s, false, &halves, 3);
    let three = ["####\n####\n####", "##.##.##\n##.##.##"];
    // Three pieces cannot make them (4x3 holds no three 2x2 squares).
    assert_eq!(check(s, false, &three, 3), 0);
    assert!(check(s, false, &three, 4) > 0);
    check(s, true, &three, 4);
    let tri = LatticeKind::Tri4;
    check(tri, true, &["FF\nFF", "F.F\nF.F"], 2);
}

#[test]
fn without_a_count_the_minimum_is_proved_then_enumerated() {
    let s = LatticeKind::Square;
    for texts in [
        &["###\n#.#\n###", "####\n####"][..],
        &["#.#\n###", "#####"][..],
        &["####", "##\n##", "#..\n###"][..],
    ] {
        let figs = figures(s, texts);
        let brute = Brute::new(s, true);
        let (k, expected) = (1..)
            .map(|k| (k, brute.dissections(&figs, k)))
            .find(|(_, d)| !d.is_empty())
            .expect("single cells always work");
        let got = run(&figs, true, None);
        assert!(got.complete && got.minimum, "{texts:?}");
        assert_eq!(got.pieces, k, "{texts:?}");
        assert_eq!(got.lower_bound.value, k);
        assert_eq!(got.dissections.len(), expected.len(), "{texts:?}");
    }
}

#[test]
fn too_many_pieces_or_too_few_count_nothing_and_are_complete() {
    let s = LatticeKind::Square;
    let figs = figures(s, &["###\n###", "######"]);
    let one = run(&figs, true, Some(1));
    assert!(one.complete && one.dissections.is_empty());
    let seven = run(&figs, true, Some(7));
    assert!(seven.complete && seven.dissections.is_empty());
    let six = run(&figs, true, Some(6));
    assert_eq!((six.dissections.len(), six.classes), (1, 1));
}

#[test]
fn a_raised_stop_or_a_past_deadline_ends_it_incomplete() {
    let s = LatticeKind::Square;
    let figs = figures(s, &["####\n####\n####\n####", "########\n########"]);
    let stop = AtomicBool::new(true);
    let got = enumerate(&figs, &EnumerateOptions::default(), &stop, &()).expect("runs");
    assert!(!got.complete);
    let start = Instant::now();
    let got = enumerate(
        &figs,
        &EnumerateOptions {
            pieces: Some(3),
            deadline: Some(Instant::now()),
            ..EnumerateOptions::default()
        },
        &AtomicBool::new(false),
        &(),
    )
    .expect("runs");
    assert!(!got.complete);
    assert!(start.elapsed() < Duration::from_secs(5));
}
