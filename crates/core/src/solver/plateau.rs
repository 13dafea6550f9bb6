//! The plateau ([`Anytime::plateau`]): other dissections with the best
//! piece count, found by descending from one piece above the incumbent
//! ([`plateau_descents`]) and by a random walk over dissections with the
//! best count ([`plateau_walk`]).
//!
//! [`Anytime::plateau`]: crate::solver::Anytime::plateau

use crate::solver::candidate::{Candidate, Problem, Score};
use crate::solver::incumbent::Incumbent;
use crate::solver::search::{From, Search};
use crate::solver::{stream, Repair, SolveError, Via, DESCENT};

/// Steps of the plateau walk per round ([`Anytime::plateau`](crate::solver::Anytime::plateau)).
const WALK_STEPS: usize = 3;
/// Repaired moves per step of the plateau walk.
const WALK_REPAIRS: usize = 4;

/// Hands a ball of radius 1 or 2 around a random cell of the first figure
/// that touches another piece to that piece; whether it found one.
fn shift_ball<R: rand::Rng>(problem: &Problem, cand: &mut Candidate, rng: &mut R) -> bool {
    use rand::RngExt;
    let shape = &problem.shapes[0];
    let labels = &mut cand.labels[0];
    for _ in 0..32 {
        let start = rng.random_range(0..shape.len()) as u32;
        let own = labels[start as usize];
        let others: Vec<u16> = shape
            .neighbors(start)
            .iter()
            .map(|&n| labels[n as usize])
            .filter(|&l| l != own)
            .collect();
        if others.is_empty() {
            continue;
        }
        let to = others[rng.random_range(0..others.len())];
        let radius = rng.random_range(1..=2);
        let mut ball = vec![start];
        let mut seen = vec![false; shape.len()];
        seen[start as usize] = true;
        let mut frontier = vec![start];
        for _ in 0..radius {
            let mut next = Vec::new();
            for &c in &frontier {
                for &n in shape.neighbors(c) {
                    if !seen[n as usize] {
                        seen[n as usize] = true;
                        next.push(n);
                    }
                }
            }
            ball.extend(&next);
            frontier = next;
        }
        for c in ball {
            labels[c as usize] = to;
        }
        return true;
    }
    false
}

/// Valid dissections one piece above the best that the plateau descends
/// from, per round.
const PLATEAU_DESCENTS: usize = 4;

/// The level one piece above the incumbent from `parents` (a ladder's
/// last kept candidates), then the descent from a few of its valid
/// results, their near misses repaired; every result is seen by the judge.
/// Returns whether it found fewer pieces than the incumbent.
pub(crate) fn plateau_descents(
    search: &Search<'_>,
    inc: &mut Incumbent,
    round: usize,
    parents: &[(Candidate, Score)],
    repairer: Option<&dyn Repair>,
    tries: usize,
) -> Result<bool, SolveError> {
    let Some(k) = inc.pieces() else {
        return Ok(false);
    };
    if parents.is_empty() || k < 2 {
        return Ok(false);
    }
    let up = search.level(round, k, From::Below(parents))?;
    inc.outcome.explorations += up.results.len();
    let mut seen: Vec<Vec<u16>> = Vec::new();
    let mut improved = false;
    for (cand, _) in up.results.iter().filter(|(_, s)| s.valid) {
        if seen.len() >= PLATEAU_DESCENTS || search.stopped() {
            break;
        }
        let key = partition(cand);
        if seen.contains(&key) {
            continue;
        }
        seen.push(key);
        let level = cand.k.saturating_sub(2);
        if level == 0 {
            break;
        }
        let down = search.level(round, level, From::Above(cand, 0))?;
        inc.outcome.explorations += down.results.len();
        if let Some((c, s, via)) = search.settle(&down, level + 1, repairer, tries) {
            improved |= inc.improve(search, c, s, level, round, via);
        }
    }
    Ok(improved)
}

/// How a candidate cuts the first figure: its labels there, renumbered in
/// order of first appearance.
fn partition(c: &Candidate) -> Vec<u16> {
    let mut map = vec![u16::MAX; c.k];
    let mut next = 0u16;
    c.labels[0]
        .iter()
        .map(|&l| {
            let m = &mut map[l as usize];
            if *m == u16::MAX {
                *m = next;
                next += 1;
            }
            *m
        })
        .collect()
}

/// One plateau walk from the incumbent (see [`Anytime::plateau`](crate::solver::Anytime::plateau)): each
/// step goes one piece up (the level search from the current dissection
/// alone) and one piece down again (the descent from a valid result of
/// the step up), and moves to a valid result of the step down: a random
/// walk over dissections with the best count, each seen by the judge.
/// Returns whether it found fewer pieces than the incumbent.
pub(crate) fn plateau_walk(
    search: &Search<'_>,
    inc: &mut Incumbent,
    round: usize,
    repairer: Option<&dyn Repair>,
) -> Result<bool, SolveError> {
    let Some(mut current) = inc.best.clone() else {
        return Ok(false);
    };
    let mut improved = false;
    let mut visited = vec![partition(&current.0)];
    for step in 0..WALK_STEPS {
        if search.stopped() {
            break;
        }
        // Streams of their own: a walk step is no round of the ladder.
        let streams = ((round + 1) << 16) | (step + 1);
        let k = current.0.k;
        // Large-neighbourhood moves: a small ball of the first figure
        // handed to a neighbouring piece, then repaired exactly.
        if let Some(r) = repairer {
            for t in 0..WALK_REPAIRS {
                if search.stopped() {
                    break;
                }
                let mut rng = stream(search.options.seed, streams, DESCENT - 1, t);
                let mut moved = current.0.clone();
                if !shift_ball(&search.problem, &mut moved, &mut rng) {
                    continue;
                }
                let cells = moved.cells_by_label(search.figures);
                let Some(fixed) = r.repair(&cells, search.stop) else {
                    continue;
                };
                let Some(next) = search.candidate_of(&fixed) else {
                    continue;
                };
                if next.0.k < current.0.k {
                    improved |= inc.improve(
                        search,
                        next.0.clone(),
                        next.1,
                        next.0.k - 1,
                        round,
                        Via::Repair,
                    );
                }
                let key = partition(&next.0);
                if next.0.k <= current.0.k && !visited.contains(&key) {
                    visited.push(key);
                    current = next;
                }
            }
        }
        let up = search.level(streams, k, From::Below(std::slice::from_ref(&current)))?;
        inc.outcome.explorations += up.results.len();
        let ups: Vec<&(Candidate, Score)> = up.results.iter().filter(|(_, s)| s.valid).collect();
        let Some(&upper) = ups.get(step % ups.len().max(1)) else {
            break;
        };
        let level = upper.0.k.saturating_sub(2);
        if level == 0 {
            break;
        }
        let down = search.level(streams, level, From::Above(&upper.0, 0))?;
        inc.outcome.explorations += down.results.len();
        // The first valid result that cuts the first figure unlike any
        // dissection the walk stood on.
        let Some(next) = down
            .results
            .iter()
            .filter(|(_, s)| s.valid)
            .find(|(c, _)| !visited.contains(&partition(c)))
        else {
            continue;
        };
        visited.push(partition(&next.0));
        if next.0.k < k {
            improved |= inc.improve(search, next.0.clone(), next.1, level, round, Via::Search);
        }
        current = next.clone();
    }
    Ok(improved)
}
