//! `assemblies::count` against brute-force enumeration on small figures of
//! every lattice.

use std::collections::{BTreeSet, HashSet};

use dissect_core::lattice::Point;
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_puzzle::assemblies::{count, CountLimits, PieceSet};
use dissect_puzzle::Motions;

/// A small deterministic random stream (xorshift).
struct Rng(u64);
impl Rng {
    fn next(&mut self, n: usize) -> usize {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % n as u64) as usize
    }
}

/// A small box of cells of the lattice (about 8 to 12 cells).
fn small_box(lattice: LatticeKind) -> Vec<Cell> {
    let l = lattice.lattice();
    let per_block = l.cells_in_box([0, 0, 0], [0, 0, 0]).len();
    let hi = if per_block > 1 {
        [1, 0, 0]
    } else if l.dim() == 3 {
        [1, 1, 2]
    } else {
        [3, 2, 0]
    };
    l.cells_in_box([0, 0, 0], hi)
}

/// Cuts `cells` into `k` connected pieces grown from random seeds.
fn random_pieces(lattice: LatticeKind, cells: &[Cell], k: usize, rng: &mut Rng) -> Vec<Vec<Cell>> {
    let l = lattice.lattice();
    let set: HashSet<Cell> = cells.iter().copied().collect();
    loop {
        let mut owner: std::collections::HashMap<Cell, usize> = Default::default();
        let mut pieces: Vec<Vec<Cell>> = Vec::new();
        for i in 0..k {
            let c = cells[rng.next(cells.len())];
            if owner.insert(c, i).is_some() {
                break;
            }
            pieces.push(vec![c]);
        }
        if pieces.len() < k {
            continue;
        }
        let mut stuck = 0;
        while owner.len() < cells.len() && stuck < 1000 {
            let i = rng.next(k);
            let frontier: Vec<Cell> = pieces[i]
                .iter()
                .flat_map(|c| l.neighbors(*c))
                .filter(|n| set.contains(n) && !owner.contains_key(n))
                .collect();
            if frontier.is_empty() {
                stuck += 1;
                continue;
            }
            let n = frontier[rng.next(frontier.len())];
            owner.insert(n, i);
            pieces[i].push(n);
        }
        if owner.len() == cells.len() {
            return pieces;
        }
    }
}

/// Independent brute force: every labelled choice of a placement per
/// piece, then the distinct tilings as sets of (shape, cells) and the
/// distinct tilings up to the figure's own motions.
fn brute_force(
    lattice: LatticeKind,
    mirror: bool,
    pieces: &[Vec<Cell>],
    figure: &[Cell],
) -> (usize, usize) {
    let l = lattice.lattice();
    let syms = l.symmetries(mirror && l.supports_mirror());
    let (dim, modulus) = (l.dim(), l.modulus());
    let is_t = |t: Point| {
        (0..3).all(|k| {
            if k < dim {
                t[k] % modulus == 0
            } else {
                t[k] == 0
            }
        })
    };
    let fig: BTreeSet<Cell> = figure.iter().copied().collect();
    let fig_pts: Vec<Point> = figure.iter().map(|c| l.to_point(*c)).collect();
    // Every motion image of a cell set that lies inside the figure.
    let images = |cells: &[Cell], inside: &BTreeSet<Cell>| -> BTreeSet<BTreeSet<Cell>> {
        let pts: Vec<Point> = cells.iter().map(|c| l.to_point(*c)).collect();
        let mut out = BTreeSet::new();
        for g in &syms {
            let img: Vec<Point> = pts.iter().map(|p| g.apply(*p)).collect();
            for q in &fig_pts {
                for p in &img {
                    let t = q - p;
                    if !is_t(t) {
                        continue;
                    }
                    let moved: Option<BTreeSet<Cell>> = img
                        .iter()
                        .map(|p| l.from_point(p + t).filter(|c| inside.contains(c)))
                        .collect();
                    if let Some(m) = moved {
                        out.insert(m);
                    }
                }
            }
        }
        out
    };
    // A shape id per piece: pieces are congruent when one is among the
    // other's images (placed anywhere: use the union box of both).
    let mut shape = vec![usize::MAX; pieces.len()];
    for i in 0..pieces.len() {
        if shape[i] != usize::MAX {
            continue;
        }
        shape[i] = i;
        for j in i + 1..pieces.len() {
            let target: BTreeSet<Cell> = pieces[j].iter().copied().collect();
            let pts_j: Vec<Point> = pieces[j].iter().map(|c| l.to_point(*c)).collect();
            let pi: Vec<Point> = pieces[i].iter().map(|c| l.to_point(*c)).collect();
            let congruent = pieces[i].len() == pieces[j].len()
                && syms.iter().any(|g| {
                    let img: Vec<Point> = pi.iter().map(|p| g.apply(*p)).collect();
                    pts_j.iter().any(|q| {
                        let t = q - img[0];
                        is_t(t)
                            && img
                                .iter()
                                .all(|p| l.from_point(p + t).is_some_and(|c| target.contains(&c)))
                    })
                });
            if congruent && shape[j] == usize::MAX {
                shape[j] = i;
            }
        }
    }
    let places: Vec<Vec<BTreeSet<Cell>>> = pieces
        .iter()
        .map(|p| images(p, &fig).into_iter().collect())
        .collect();
    let mut tilings: HashSet<BTreeSet<(usize, BTreeSet<Cell>)>> = HashSet::new();
    fn rec(
        i: usize,
        places: &[Vec<BTreeSet<Cell>>],
        shape: &[usize],
        used: &mut BTreeSet<Cell>,
        chosen: &mut Vec<(usize, BTreeSet<Cell>)>,
        out: &mut HashSet<BTreeSet<(usize, BTreeSet<Cell>)>>,
    ) {
        if i == places.len() {
            out.insert(chosen.iter().cloned().collect());
            return;
        }
        for p in &places[i] {
            if p.iter().any(|c| used.contains(c)) {
                continue;
            }
            used.extend(p.iter().copied());
            chosen.push((shape[i], p.clone()));
            rec(i + 1, places, shape, used, chosen, out);
            chosen.pop();
            for c in p {
                used.remove(c);
            }
        }
    }
    rec(
        0,
        &places,
        &shape,
        &mut BTreeSet::new(),
        &mut Vec::new(),
        &mut tilings,
    );
    // The figure's own motions, as cell maps.
    let figure_motions: Vec<Vec<(Cell, Cell)>> = syms
        .iter()
        .filter_map(|g| {
            let img: Vec<Point> = fig_pts.iter().map(|p| g.apply(*p)).collect();
            let (mi, mf) = (img.iter().min()?, fig_pts.iter().min()?);
            let t = mf - mi;
            let map: Option<Vec<(Cell, Cell)>> = figure
                .iter()
                .zip(&img)
                .map(|(c, p)| {
                    let d = l.from_point(p + t)?;
                    fig.contains(&d).then_some((*c, d))
                })
                .collect();
            map.filter(|_| is_t(t))
        })
        .collect();
    let orbits: HashSet<BTreeSet<(usize, BTreeSet<Cell>)>> = tilings
        .iter()
        .map(|t| {
            figure_motions
                .iter()
                .map(|m| {
                    let map: std::collections::HashMap<Cell, Cell> = m.iter().copied().collect();
                    t.iter()
                        .map(|(s, cells)| (*s, cells.iter().map(|c| map[c]).collect()))
                        .collect::<BTreeSet<_>>()
                })
                .min()
                .expect("the identity")
        })
        .collect();
    (tilings.len(), orbits.len())
}

fn check(lattice: LatticeKind, mirror: bool, pieces: &[Vec<Cell>], figure: &[Cell]) -> (u64, u64) {
    let f = Figure::new(lattice, figure.iter().copied()).unwrap();
    let set = PieceSet::new(Motions::new(lattice, mirror), pieces).unwrap();
    let c = count(&set, &f, CountLimits::default()).unwrap();
    assert!(c.complete);
    let (n, m) = brute_force(lattice, mirror, pieces, figure);
    assert_eq!(
        (c.tilings, c.up_to_symmetry),
        (n as u64, m as u64),
        "{lattice} mirror {mirror}: pieces {pieces:?} in {figure:?}"
    );
    (c.tilings, c.up_to_symmetry)
}

#[test]
fn counts_agree_with_brute_force_on_every_lattice() {
    for lattice in LatticeKind::ALL {
        let cells = small_box(lattice);
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15 ^ lattice as u64);
        let mut total = 0;
        for round in 0..8 {
            let k = 2 + round % 3;
            let pieces = random_pieces(lattice, &cells, k, &mut rng);
            for mirror in [true, false] {
                total += check(lattice, mirror, &pieces, &cells).0;
            }
        }
        assert!(total > 16, "{lattice}: the cases tile in more than one way");
    }
}

#[test]
fn dominoes_tile_a_2x4_rectangle_five_ways() {
    let lattice = LatticeKind::Square;
    let rect: Vec<Cell> = (0..4)
        .flat_map(|x| (0..2).map(move |y| [x, y, 0]))
        .collect();
    let dominoes: Vec<Vec<Cell>> = (0..4).map(|x| vec![[x, 0, 0], [x, 1, 0]]).collect();
    // Tilings: ||||, =||, |=|, ||=, ==; up to the rectangle's 4 symmetries:
    // ||||, ==, =|| (with ||=), |=|.
    assert_eq!(check(lattice, true, &dominoes, &rect), (5, 4));
}

#[test]
fn identical_pieces_are_interchangeable() {
    // Two L trominoes in a 2x3 rectangle: 2 tilings, not 4 labelled ones.
    let lattice = LatticeKind::Square;
    let rect: Vec<Cell> = (0..3)
        .flat_map(|x| (0..2).map(move |y| [x, y, 0]))
        .collect();
    let ls = vec![
        vec![[0, 0, 0], [0, 1, 0], [1, 1, 0]],
        vec![[1, 0, 0], [2, 0, 0], [2, 1, 0]],
    ];
    assert_eq!(check(lattice, true, &ls, &rect), (2, 1));
}

#[test]
fn a_different_area_is_an_error() {
    let lattice = LatticeKind::Square;
    let f = Figure::new(lattice, [[0, 0, 0], [1, 0, 0], [2, 0, 0]]).unwrap();
    let set = PieceSet::new(Motions::new(lattice, true), &[vec![[0, 0, 0], [1, 0, 0]]]).unwrap();
    let e = count(&set, &f, CountLimits::default()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "the pieces have 2 cells in all, the figure has 3"
    );
}

#[test]
fn the_deadline_cuts_a_long_count_short() {
    // 1x1 squares... monominoes of an 8x8 square: one tiling but 64! labelled
    // orders would be slow; dominoes of 8x8 have 12,988,816 tilings.
    let lattice = LatticeKind::Square;
    let sq: Vec<Cell> = (0..8)
        .flat_map(|x| (0..8).map(move |y| [x, y, 0]))
        .collect();
    let dominoes: Vec<Vec<Cell>> = (0..32)
        .map(|i| vec![[i % 8, 2 * (i / 8), 0], [i % 8, 2 * (i / 8) + 1, 0]])
        .collect();
    let f = Figure::new(lattice, sq).unwrap();
    let set = PieceSet::new(Motions::new(lattice, true), &dominoes).unwrap();
    let mut calls = 0;
    let mut progress = |_p: dissect_puzzle::dlx::Progress| calls += 1;
    let c = count(
        &set,
        &f,
        CountLimits {
            // Progress comes every 250 ms: a deadline well past that, so a
            // loaded machine still sees a report before it.
            deadline: Some(std::time::Instant::now() + std::time::Duration::from_millis(1500)),
            progress: Some(&mut progress),
            ..CountLimits::default()
        },
    )
    .unwrap();
    assert!(!c.complete);
    assert!(c.tilings > 0 && c.tilings < 12_988_816);
    assert!(c.elapsed.as_secs_f64() < 5.0);
    assert!(calls > 0, "progress was reported");
}
