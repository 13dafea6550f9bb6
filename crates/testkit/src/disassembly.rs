//! An independent replay of disassembly plans (the `dissection-disassembly/1`
//! format's moves) on unit cubes, written from the format's definition and
//! sharing no code with the search in `dissect-puzzle`; and lettered voxel
//! figures for the tests.

use std::collections::{HashMap, HashSet};

/// A unit cube `[x, y, z]`.
pub type Voxel = [i32; 3];

/// One move of a plan, as the format writes it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlanMove {
    /// The pieces moved together.
    pub pieces: Vec<usize>,
    /// The translation, along one axis.
    pub by: [i32; 3],
    /// Whether the group goes away to infinity along `by`.
    pub removed: bool,
}

/// The pieces of a lettered voxel figure: one block of rows per `z` layer
/// (blocks separated by a blank line), one character per cube along `x`,
/// rows along `y`; piece `i` is letter `A + i`, `.` is empty.
pub fn voxel_pieces(layers: &str) -> Vec<Vec<Voxel>> {
    let mut pieces: Vec<Vec<Voxel>> = Vec::new();
    let text = layers.trim_matches('\n');
    for (z, block) in text.split("\n\n").enumerate() {
        for (y, row) in block.lines().map(str::trim).enumerate() {
            for (x, ch) in row.chars().enumerate() {
                if ch.is_ascii_uppercase() {
                    let i = (ch as u8 - b'A') as usize;
                    if pieces.len() <= i {
                        pieces.resize(i + 1, Vec::new());
                    }
                    pieces[i].push([x as i32, y as i32, z as i32]);
                }
            }
        }
    }
    pieces
}

/// Replays `moves` on `pieces` (their cubes where the figure has them):
/// every move's pieces lie in one part and are not all of it, `by` runs
/// along one axis, every unit step keeps the group off the part's other
/// pieces, a removal's whole sweep (until the group is past the rest along
/// its axis) is free and makes the group a part of its own, and at the end
/// every part holds one piece. Returns the level (the 1-based index of the
/// first removal; 0 without moves) or what is wrong.
pub fn replay(pieces: &[Vec<Voxel>], moves: &[PlanMove]) -> Result<usize, String> {
    let mut cubes: Vec<Vec<Voxel>> = pieces.to_vec();
    let mut part: Vec<usize> = vec![0; pieces.len()];
    let mut parts = 1;
    let mut level = 0;
    for (t, m) in moves.iter().enumerate() {
        let at = |e: String| format!("move {}: {e}", t + 1);
        let group: HashSet<usize> = m.pieces.iter().copied().collect();
        if group.is_empty() || group.len() != m.pieces.len() {
            return Err(at("no pieces or a piece twice".into()));
        }
        if m.pieces.iter().any(|&i| i >= pieces.len()) {
            return Err(at("no such piece".into()));
        }
        let p = part[m.pieces[0]];
        if m.pieces.iter().any(|&i| part[i] != p) {
            return Err(at("its pieces lie in different parts".into()));
        }
        let others: Vec<usize> = (0..pieces.len())
            .filter(|i| part[*i] == p && !group.contains(i))
            .collect();
        if others.is_empty() {
            return Err(at("it moves a whole part".into()));
        }
        let axes: Vec<usize> = (0..3).filter(|&a| m.by[a] != 0).collect();
        if axes.len() != 1 {
            return Err(at(format!("{:?} is not along one axis", m.by)));
        }
        let axis = axes[0];
        let sign = m.by[axis].signum();
        let blocked: HashSet<Voxel> = others.iter().flat_map(|&i| cubes[i].clone()).collect();
        let rest_lo = blocked.iter().map(|v| v[axis]).min().unwrap_or(0);
        let rest_hi = blocked.iter().map(|v| v[axis]).max().unwrap_or(0);
        let mut steps = m.by[axis].abs();
        if m.removed {
            // Go on until every cube of the group is past the rest.
            loop {
                let past = m.pieces.iter().flat_map(|&i| &cubes[i]).all(|v| {
                    let w = v[axis] + sign * steps;
                    if sign > 0 {
                        w > rest_hi
                    } else {
                        w < rest_lo
                    }
                });
                if past {
                    break;
                }
                steps += 1;
            }
        }
        for k in 1..=steps {
            for &i in &m.pieces {
                for v in &cubes[i] {
                    let mut w = *v;
                    w[axis] += sign * k;
                    if blocked.contains(&w) {
                        return Err(at(format!("piece {i} meets another piece at {w:?}")));
                    }
                }
            }
        }
        for &i in &m.pieces {
            for v in cubes[i].iter_mut() {
                v[axis] += m.by[axis];
            }
        }
        if m.removed {
            for &i in &m.pieces {
                part[i] = parts;
            }
            parts += 1;
            if level == 0 {
                level = t + 1;
            }
        }
    }
    let mut sizes: HashMap<usize, usize> = HashMap::new();
    for p in &part {
        *sizes.entry(*p).or_default() += 1;
    }
    if pieces.len() > 1 && sizes.values().any(|&n| n > 1) {
        return Err("at the end some part still holds several pieces".into());
    }
    Ok(level)
}
