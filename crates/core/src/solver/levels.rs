//! Explorations (paper section 3.2): level 1 grows two random clusters per
//! figure; level ℓ adds one piece to a candidate of the previous level, by
//! splitting the worst-matched piece (75%) or by a new piece made of
//! mismatched cells (25%), and refines all pieces together.

use std::collections::VecDeque;
use std::sync::atomic::AtomicBool;

use rand::RngExt;

use crate::solver::candidate::{Aligned, Candidate, Problem, Score};
use crate::solver::flood_fill::{flood_fill, Fallback};
use crate::solver::piece::UNSET;
use crate::solver::refine::{mismatched_cells, refine_with_patience};
use crate::solver::Options;

/// `λ` at a level: `area_weight · 0.8^(ℓ−1)`.
pub(crate) fn lambda(options: &Options, level: usize) -> f64 {
    options.area_weight * 0.8f64.powi(level as i32 - 1)
}

/// One level-1 exploration: two random flood-fill clusters in every figure,
/// refined and scored.
pub(crate) fn level_one<R: rand::Rng>(
    problem: &Problem,
    options: &Options,
    rng: &mut R,
    stop: &AtomicBool,
) -> (Candidate, Score) {
    let mut labels = Vec::with_capacity(problem.shapes.len());
    for shape in &problem.shapes {
        let n = shape.len();
        let mut l = vec![UNSET; n];
        if n >= 2 {
            let a = rng.random_range(0..n);
            let mut b = rng.random_range(0..n - 1);
            if b >= a {
                b += 1;
            }
            l[a] = 0;
            l[b] = 1;
        } else {
            l[0] = 0;
        }
        flood_fill(shape, &mut l, Fallback::Random(2), rng);
        labels.push(l);
    }
    let cand = Candidate { labels, k: 2 };
    refine_and_score(problem, cand, 1, options, rng, stop)
}

/// One level-ℓ exploration: `parent` (with ℓ pieces) gets one more piece,
/// then all pieces are refined together and scored at `level`.
pub(crate) fn grow<R: rand::Rng>(
    problem: &Problem,
    parent: &Candidate,
    level: usize,
    options: &Options,
    rng: &mut R,
    stop: &AtomicBool,
) -> (Candidate, Score) {
    let mut cand = parent.clone();
    let split = rng.random_bool(0.75) && {
        let pivot = rng.random_range(0..problem.shapes.len());
        split_worst(problem, &mut cand, pivot, options, rng, stop)
    };
    if !split {
        piece_from_mismatches(problem, &mut cand, rng);
    }
    refine_and_score(problem, cand, level, options, rng, stop)
}

/// Refines a candidate (with the options' patience) and scores it at `level`.
fn refine_and_score<R: rand::Rng>(
    problem: &Problem,
    mut cand: Candidate,
    level: usize,
    options: &Options,
    rng: &mut R,
    stop: &AtomicBool,
) -> (Candidate, Score) {
    refine_with_patience(
        problem,
        &mut cand,
        options.iterations,
        options.patience,
        rng,
        stop,
    );
    let score = cand.evaluate(problem, lambda(options, level), options.split_penalty);
    (cand, score)
}

/// Splits the piece with the worst total distance to its matches (seen from
/// a random pivot), with all its matched pieces, into two by running level 1
/// on those pieces as if they were the input figures. Returns false when no
/// piece can be split (a piece of one cell somewhere).
pub(crate) fn split_worst<R: rand::Rng>(
    problem: &Problem,
    cand: &mut Candidate,
    pivot: usize,
    options: &Options,
    rng: &mut R,
    stop: &AtomicBool,
) -> bool {
    let aligned = cand.align(problem, pivot);
    let worst = worst_piece(&aligned);
    let Some(a) = worst else { return false };
    let members: Vec<Vec<u32>> = aligned
        .pieces
        .iter()
        .map(|p| p.members(a).to_vec())
        .collect();
    let sub = Problem::new(
        problem
            .shapes
            .iter()
            .zip(&members)
            .map(|(s, m)| s.subset(m))
            .collect(),
        problem.geo.clone(),
    );
    // The best try that really splits: both labels survive in every figure
    // (refinement can empty a small piece everywhere).
    let mut best: Option<(Candidate, Score)> = None;
    for t in 0..options.split_tries.max(1) {
        // A stop ends the tries (a million of them outlast any time limit).
        if t > 0 && stop.load(std::sync::atomic::Ordering::Relaxed) {
            break;
        }
        let (c, s) = level_one(&sub, options, rng, stop);
        let splits = c.labels.iter().all(|l| l.contains(&0) && l.contains(&1));
        if splits && best.as_ref().is_none_or(|(_, b)| s.value < b.value) {
            best = Some((c, s));
        }
    }
    let Some((split, _)) = best else { return false };
    let new_label = cand.k as u16;
    for (f, m) in members.iter().enumerate() {
        for (i, &c) in m.iter().enumerate() {
            if split.labels[f][i] == 1 {
                cand.labels[f][c as usize] = new_label;
            }
        }
    }
    cand.k += 1;
    true
}

/// The piece with the largest total distance to its matches in the other
/// figures (labels aligned to the pivot), among the pieces with at least two
/// cells in every figure; ties go to the lowest label.
pub(crate) fn worst_piece(aligned: &Aligned) -> Option<usize> {
    let k = aligned.pieces.first().map_or(0, |p| p.count());
    (0..k)
        .filter(|&a| aligned.pieces.iter().all(|p| p.size(a) >= 2))
        .max_by_key(|&a| {
            let d: u64 = aligned
                .matchings
                .iter()
                .flatten()
                .map(|m| m.dists[a] as u64)
                .sum();
            (d, std::cmp::Reverse(a))
        })
}

/// A new piece grown, in every figure, from a random mismatched cell by
/// flood fill through mismatched cells.
pub(crate) fn piece_from_mismatches<R: rand::Rng>(
    problem: &Problem,
    cand: &mut Candidate,
    rng: &mut R,
) {
    let marked = mismatched_cells(problem, cand);
    let new_label = cand.k as u16;
    for (f, cells) in marked.iter().enumerate() {
        let shape = &problem.shapes[f];
        if cells.is_empty() {
            let c = rng.random_range(0..shape.len());
            cand.labels[f][c] = new_label;
            continue;
        }
        let mut is_marked = vec![false; shape.len()];
        for &c in cells {
            is_marked[c as usize] = true;
        }
        let seed = cells[rng.random_range(0..cells.len())];
        let mut queue = VecDeque::from([seed]);
        is_marked[seed as usize] = false;
        while let Some(c) = queue.pop_front() {
            cand.labels[f][c as usize] = new_label;
            for &n in shape.neighbors(c) {
                if is_marked[n as usize] {
                    is_marked[n as usize] = false;
                    queue.push_back(n);
                }
            }
        }
    }
    cand.k += 1;
}

/// One descent exploration: `parent` (a dissection, or any candidate) with
/// one piece fewer, by merging a piece (the smallest one half of the time,
/// else a random one) into a neighbouring piece in every figure, then
/// refined and scored at `level` (pieces − 1). A piece that touches no
/// other piece in some figure (a whole component there, such as the 1³ of
/// 1³+6³+8³) is never merged: the merged piece would be split in that
/// figure, and those were the near misses the descent kept returning.
/// When every piece is such a piece, any may be merged.
pub(crate) fn merge<R: rand::Rng>(
    problem: &Problem,
    parent: &Candidate,
    level: usize,
    options: &Options,
    rng: &mut R,
    stop: &AtomicBool,
) -> (Candidate, Score) {
    let mut cand = parent.clone();
    let k = cand.k;
    if k < 2 {
        return refine_and_score(problem, cand, level, options, rng, stop);
    }
    let f = rng.random_range(0..problem.shapes.len());
    let shape = &problem.shapes[f];
    let labels = &cand.labels[f];
    let mut sizes = vec![0usize; k];
    for &l in labels {
        sizes[l as usize] += 1;
    }
    // The pieces that may be merged: all of them when every one is
    // isolated (with none isolated, the draws are those of `0..k`).
    let alone = isolated(problem, &cand);
    let mut free: Vec<usize> = (0..k).filter(|&i| !alone[i]).collect();
    if free.is_empty() {
        free = (0..k).collect();
    }
    let b = if rng.random_bool(0.5) {
        let least = free
            .iter()
            .map(|&i| sizes[i])
            .filter(|&s| s > 0)
            .min()
            .unwrap_or(0);
        let smallest: Vec<usize> = free.into_iter().filter(|&i| sizes[i] == least).collect();
        smallest[rng.random_range(0..smallest.len())]
    } else {
        free[rng.random_range(0..free.len())]
    };
    // A neighbour of piece b, chosen in proportion to the shared boundary
    // (none that touches nothing in some figure, while b may be merged).
    let mut touching: Vec<u16> = Vec::new();
    for c in 0..shape.len() as u32 {
        if labels[c as usize] as usize != b {
            continue;
        }
        for &n in shape.neighbors(c) {
            let l = labels[n as usize];
            if l as usize != b && (alone[b] || !alone[l as usize]) {
                touching.push(l);
            }
        }
    }
    let a = if touching.is_empty() {
        let mut a = rng.random_range(0..k - 1);
        if a >= b {
            a += 1;
        }
        a as u16
    } else {
        touching[rng.random_range(0..touching.len())]
    };
    let last = (k - 1) as u16;
    for l in cand.labels.iter_mut().flatten() {
        if *l as usize == b {
            *l = a;
        }
        if *l == last {
            *l = b as u16;
        }
    }
    cand.k = k - 1;
    refine_and_score(problem, cand, level, options, rng, stop)
}

/// `isolated[i]`: whether piece `i` of `cand` touches no other piece in
/// some figure (each of its parts there is a whole component).
pub(crate) fn isolated(problem: &Problem, cand: &Candidate) -> Vec<bool> {
    let mut touches = vec![vec![false; cand.k]; problem.shapes.len()];
    for (f, (shape, labels)) in problem.shapes.iter().zip(&cand.labels).enumerate() {
        for c in 0..shape.len() as u32 {
            let l = labels[c as usize];
            if touches[f][l as usize] {
                continue;
            }
            if shape.neighbors(c).iter().any(|&n| labels[n as usize] != l) {
                touches[f][l as usize] = true;
            }
        }
    }
    (0..cand.k).map(|i| touches.iter().any(|t| !t[i])).collect()
}
