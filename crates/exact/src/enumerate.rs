//! Every dissection with K pieces, counted: `dissect enumerate`.
//!
//! Without a K the minimum is proved on the way, as `solve --exact` proves
//! it, level by level from the cheap bound: the model for exactly K pieces
//! that has no model refutes K (and, with the levels below, every count up
//! to K); the first K with a model is the minimum, and its enumeration
//! goes on to the end.
//!
//! Two dissections are *the same* when they cut the first figure into the
//! same pieces (how the pieces then tile the other figures does not matter:
//! a cut that tiles them in several ways is one dissection). The SAT model of
//! [`crate::placement_encoding`] for exactly K pieces, with the first input
//! figure as its reference shape and full connectivity, is solved again and
//! again; every model is decoded, verified and then forbidden by a blocking
//! clause over the cut of the first figure.
//!
//! The blocking clause is exact because the model's symmetry breaking gives
//! every cut of the first figure exactly one labelling: the cells of the
//! incompatible clique (when it lies in the first figure) are fixed to pieces
//! `0..q`, which must hold them in different pieces anyway, and the other
//! pieces are ordered by their first cell, with every piece non-empty. So
//! `⋁_c ¬cell[label(c)][c]` forbids that cut and nothing else. (The first
//! piece's motion into each *other* figure is taken up to that figure's
//! symmetries; that never removes a cut of the first figure.)
//!
//! Up to symmetry: two cuts are one class when a symmetry of the first
//! figure (rotations, and reflections when pieces may be turned over) maps
//! one onto the other ([`dissect_puzzle::Motions::canonical_cut`]). Such an
//! image of a dissection's cut is a dissection too (the same pieces, placed
//! as before in the other figures; the symmetry is an allowed motion), so
//! each model yields its whole class at once: every distinct image is
//! verified, counted and blocked (by the clause of its own labelling), and
//! the SAT solver is asked once per class, not once per dissection.
//!
//! With [`EnumerateOptions::symmetry_breaking`] (the default) the model
//! also holds lex-leader constraints (`enumerate_symmetry.rs`): only
//! the lex-least cut of each class is a model, and each component of the
//! other figures is filled in one way up to its own symmetries, so the
//! search that proves the list complete covers a fraction of the space.

use std::collections::{HashMap, HashSet};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use dissect_core::{Cell, Figure};

use crate::bound::{cheap, Bound, Reason};
use crate::connectivity_cut::cuts;
use crate::motion::MotionSet;
use crate::placement_encoding::{encode, estimate, Encoding, EncodingSize, MotionEncoding};

/// Enumeration keeps one variable per motion (its symmetry breaking and
/// constraints speak of them).
const DIRECT: (MotionSet, MotionEncoding) = (MotionSet::All, MotionEncoding::Direct);
use crate::reachability_encoding::{add_connectivity, connectivity_size};
use crate::sat_backend::Sat;
use crate::search::{model_inputs_from, ExactEvent, Limit, DEFAULT_MAX_ENCODING_BYTES};
use crate::ExactError;

/// Settings of [`enumerate`].
#[derive(Clone, Debug, PartialEq)]
pub struct EnumerateOptions {
    /// Whether 2D pieces may be turned over (ignored on `cubic`); also
    /// whether the first figure's reflections count as its symmetries.
    pub mirror: bool,
    /// Count the dissections with exactly this many pieces; `None`: the
    /// minimum, proved first.
    pub pieces: Option<usize>,
    /// Stop (with the dissections found so far) at this instant.
    pub deadline: Option<Instant>,
    /// Refuse an encoding estimated above this many bytes
    /// ([`Limit::TooLarge`]).
    pub max_encoding_bytes: u64,
    /// Break the symmetries (see `enumerate_symmetry.rs`): the SAT
    /// solver finds each class once, as the lex-least cut, and assemblies
    /// are taken up to the symmetries of each component of the other
    /// figures. Off, every cut is found by the solver (the counts agree;
    /// the tests compare both with a brute force).
    pub symmetry_breaking: bool,
}

impl Default for EnumerateOptions {
    fn default() -> EnumerateOptions {
        EnumerateOptions {
            mirror: true,
            pieces: None,
            deadline: None,
            max_encoding_bytes: DEFAULT_MAX_ENCODING_BYTES,
            symmetry_breaking: true,
        }
    }
}

/// Progress of [`enumerate`].
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum EnumerateEvent {
    /// On the way to the minimum: a piece count with no dissection
    /// ([`ExactEvent::Refuted`], the bound rose).
    Search(ExactEvent),
    /// The minimum piece count is proved (its first dissection was found,
    /// every count below is refuted): every dissection with it is counted.
    Minimum {
        /// K.
        pieces: usize,
        /// Seconds since the start.
        seconds: f64,
    },
    /// The model for exactly `pieces` pieces was built.
    Encoded {
        /// K.
        pieces: usize,
        /// Its size.
        size: EncodingSize,
    },
    /// A new verified dissection.
    Found {
        /// Dissections so far.
        count: usize,
        /// Classes up to the first figure's symmetries so far.
        classes: usize,
        /// Seconds since the start.
        seconds: f64,
    },
}

/// Receives [`EnumerateEvent`]s.
pub trait EnumerateObserver: Sync {
    /// Called for every event.
    fn on_event(&self, event: &EnumerateEvent);
}

impl EnumerateObserver for () {
    fn on_event(&self, _event: &EnumerateEvent) {}
}

/// What [`enumerate`] found.
#[derive(Clone, Debug, PartialEq)]
pub struct Enumeration {
    /// K: the piece count counted (the minimum when none was asked; the
    /// lower bound proved so far when stopped before the minimum was found).
    pub pieces: usize,
    /// Whether K is the proved minimum.
    pub minimum: bool,
    /// The lower bound proved.
    pub lower_bound: Bound,
    /// Every dissection found (`pieces[f][i]`, input order), each verified
    /// by `dissect_core::verify`, in the order found.
    pub dissections: Vec<Vec<Vec<Vec<Cell>>>>,
    /// The class of each dissection up to the first figure's symmetries,
    /// classes numbered from 0 in the order of their first dissection.
    pub class_of: Vec<usize>,
    /// The number of classes.
    pub classes: usize,
    /// Whether the list is complete (no dissection with K pieces is
    /// missing): false when stopped, past the deadline or over a limit.
    pub complete: bool,
    /// The limit that ended it, if one did.
    pub limit: Option<Limit>,
    /// SAT conflicts spent on the enumeration itself.
    pub conflicts: u64,
}

/// Counts every dissection of `figures` with K pieces (K from
/// [`EnumerateOptions::pieces`], else the minimum: the enumeration runs for
/// K = the cheap bound, the bound + 1, ... and the first K with a
/// dissection is the minimum, every count below refuted by an
/// unsatisfiable model), and their classes up to the first figure's
/// symmetries. Raising `stop` or passing the deadline ends it with
/// what was found (`complete` false).
pub fn enumerate(
    figures: &[Figure],
    options: &EnumerateOptions,
    stop: &AtomicBool,
    observer: &dyn EnumerateObserver,
) -> Result<Enumeration, ExactError> {
    let start = Instant::now();
    dissect_core::solver::check_figures(figures)?;
    let cheap_bound = crate::cheap_bound(figures, options.mirror)?;
    let mut k = options.pieces.unwrap_or(cheap_bound.value);
    let mut out = Enumeration {
        pieces: k,
        minimum: false,
        lower_bound: cheap_bound,
        dissections: Vec::new(),
        class_of: Vec::new(),
        classes: 0,
        complete: false,
        limit: None,
        conflicts: 0,
    };
    let cells = figures[0].len();
    loop {
        let level = Instant::now();
        let mut run = Run {
            figures,
            options,
            stop,
            observer,
            start,
            canonical: HashMap::new(),
            out: &mut out,
        };
        run.at(k)?;
        let none = out.complete && out.dissections.is_empty();
        if options.pieces.is_some() || !none || k >= cells {
            break;
        }
        // No dissection with exactly k pieces, nor (by the levels below
        // and the cheap bound) with fewer: the bound rises.
        out.lower_bound = Bound {
            value: k + 1,
            reason: Reason::Sat {
                refuted: k,
                seconds: level.elapsed().as_secs_f64(),
                cuts: 0,
            },
        };
        observer.on_event(&EnumerateEvent::Search(ExactEvent::Refuted(
            out.lower_bound.clone(),
        )));
        k += 1;
        out.pieces = k;
        out.complete = false;
    }
    Ok(out)
}

/// One enumeration at a fixed K.
struct Run<'a> {
    figures: &'a [Figure],
    options: &'a EnumerateOptions,
    stop: &'a AtomicBool,
    observer: &'a dyn EnumerateObserver,
    start: Instant,
    /// Class by canonical cut.
    canonical: HashMap<Vec<Vec<Cell>>, usize>,
    out: &'a mut Enumeration,
}

impl Run<'_> {
    fn interrupted(&self) -> bool {
        self.stop.load(Ordering::Relaxed)
            || self.options.deadline.is_some_and(|d| Instant::now() >= d)
    }

    /// Fills `self.out` with every dissection into exactly `k` pieces.
    fn at(&mut self, k: usize) -> Result<(), ExactError> {
        let mirror = self.options.mirror;
        let cells = self.figures[0].len();
        if k == 0 || k > cells {
            self.out.complete = true;
            return Ok(());
        }
        let interrupted = || self.interrupted();
        let mut cheap = cheap(self.figures, mirror, &interrupted)?;
        if cheap.bound.value > k {
            // Proved: no dissection with so few pieces.
            self.out.complete = true;
            return Ok(());
        }
        let Some((inst, clique, incompat)) =
            model_inputs_from(self.figures, mirror, &mut cheap, true)
        else {
            return Ok(());
        };
        let size = estimate(&inst, k, DIRECT, &clique, &incompat, &|| false);
        let bytes = size.bytes(false);
        if bytes > self.options.max_encoding_bytes {
            self.out.limit = Some(Limit::TooLarge { pieces: k, bytes });
            return Ok(());
        }
        let shape0 = &inst.shapes[0];
        let (cv, cc) = connectivity_size(shape0.len(), k, shape0.adj.iter().map(Vec::len).sum());
        let connectivity_bytes = EncodingSize {
            vars: cv.min(usize::MAX as u64) as usize,
            clauses: cc.min(usize::MAX as u64) as usize,
            motions: 0,
        }
        .bytes(false);
        let eager = bytes.saturating_add(connectivity_bytes) <= self.options.max_encoding_bytes;
        let mut sat = Sat::new(self.stop, None);
        let Some(enc) = encode(&inst, &mut sat, k, DIRECT, &clique, &incompat, &interrupted) else {
            return Ok(());
        };
        // Exactly k pieces: the last one is not empty (the order by first
        // cell then makes every piece non-empty; fixed pieces hold a cell).
        sat.add(&enc.cell[0][k - 1]);
        if eager && !add_connectivity(&mut sat, shape0, &enc.cell[0], &enc.anchors, &interrupted) {
            return Ok(());
        }
        let motions = dissect_puzzle::Motions::new(inst.lattice, inst.mirror);
        let cut_of = Cuts {
            symmetries: motions.symmetries_of(self.figures[0].cells()),
            motions,
            index: shape0
                .cells
                .iter()
                .enumerate()
                .map(|(i, c)| (*c, i))
                .collect(),
        };
        if self.options.symmetry_breaking {
            crate::enumerate_symmetry::break_symmetries(
                &mut sat,
                &inst,
                &enc,
                &cut_of.motions,
                &cut_of.symmetries,
            );
        }
        self.observer.on_event(&EnumerateEvent::Encoded {
            pieces: k,
            size: EncodingSize {
                vars: sat.vars(),
                clauses: sat.clauses(),
                motions: enc.motions(),
            },
        });
        loop {
            let answer = sat.solve(self.options.deadline);
            self.out.conflicts = sat.conflicts();
            match answer {
                None => return Ok(()),
                Some(false) => {
                    self.out.complete = true;
                    return Ok(());
                }
                Some(true) => {}
            }
            let pieces = enc.decode(&sat);
            debug_assert_eq!(pieces[0].len(), k, "every piece is non-empty");
            let split = cuts(&inst.shapes, &pieces, 4);
            if !split.is_empty() {
                if self.interrupted() {
                    return Ok(());
                }
                for cut in &split {
                    for piece in &enc.cell[cut.shape] {
                        let mut clause = vec![-piece[cut.a], -piece[cut.b]];
                        clause.extend(cut.separator.iter().map(|&e| piece[e]));
                        sat.add(&clause);
                    }
                }
                continue;
            }
            let found = crate::search::to_cells(&inst, &pieces);
            self.record(
                &mut sat,
                &enc,
                &cut_of,
                &clique[..clique.len().min(k)],
                &found,
            )?;
        }
    }

    /// Records a dissection found by the model and every image of its cut
    /// under the first figure's symmetries (each one a dissection too: the
    /// same pieces, placed as before in the other figures), each verified
    /// and forbidden by the blocking clause of its one labelling.
    fn record(
        &mut self,
        sat: &mut Sat<'_>,
        enc: &Encoding,
        cut_of: &Cuts,
        fixed: &[usize],
        found: &[Vec<Vec<Cell>>],
    ) -> Result<(), ExactError> {
        if self.out.dissections.is_empty() && self.options.pieces.is_none() {
            // Every count below is refuted: this one is the minimum.
            self.out.minimum = true;
            self.out.lower_bound = Bound {
                value: enc.k,
                reason: self.out.lower_bound.reason.clone(),
            };
            self.observer.on_event(&EnumerateEvent::Minimum {
                pieces: enc.k,
                seconds: self.start.elapsed().as_secs_f64(),
            });
        }
        let mut seen = HashSet::new();
        for t in &cut_of.symmetries {
            let image: Option<Vec<Vec<Cell>>> = found[0]
                .iter()
                .map(|p| p.iter().map(|&c| cut_of.motions.move_cell(t, c)).collect())
                .collect();
            let Some(mut image) = image else {
                continue;
            };
            for p in &mut image {
                p.sort_unstable();
            }
            let mut key = image.clone();
            key.sort_unstable();
            if !seen.insert(key) {
                continue;
            }
            let Some(labels) = cut_of.labelling(&image, fixed) else {
                continue;
            };
            let block: Vec<i32> = labels.iter().map(|&(i, c)| -enc.cell[0][i][c]).collect();
            sat.add(&block);
            let mut dissection = found.to_vec();
            dissection[0] = image;
            dissect_core::verify::verify_pieces(
                self.figures[0].lattice(),
                cut_of.motions.mirror(),
                self.figures,
                &dissection,
            )
            .map_err(|v| ExactError::InvalidModel(v[0].to_string()))?;
            let canonical = cut_of
                .motions
                .canonical_cut(&cut_of.symmetries, &dissection[0]);
            let fresh = self.canonical.len();
            let class = *self.canonical.entry(canonical).or_insert(fresh);
            self.out.classes = self.canonical.len();
            self.out.class_of.push(class);
            self.out.dissections.push(dissection);
            self.observer.on_event(&EnumerateEvent::Found {
                count: self.out.dissections.len(),
                classes: self.out.classes,
                seconds: self.start.elapsed().as_secs_f64(),
            });
        }
        Ok(())
    }
}

/// The first figure's cells, motions and symmetries: what turns a cut into
/// its images and their labellings.
struct Cuts {
    motions: dissect_puzzle::Motions,
    /// The symmetries of the first figure (the identity first).
    symmetries: Vec<dissect_core::transform::Transform>,
    /// Each cell's index in the model's first shape.
    index: HashMap<Cell, usize>,
}

impl Cuts {
    /// The one labelling the symmetry breaking allows for a cut: the piece
    /// holding `fixed[j]` is piece `j`, the others follow in the order of
    /// their first cell; `(label, cell index)` for every cell. `None` for a
    /// cut that puts two fixed cells in one piece (never a dissection).
    fn labelling(&self, cut: &[Vec<Cell>], fixed: &[usize]) -> Option<Vec<(usize, usize)>> {
        let cells: Vec<Vec<usize>> = cut
            .iter()
            .map(|p| p.iter().map(|c| self.index[c]).collect())
            .collect();
        let mut label = vec![usize::MAX; cells.len()];
        for (j, f) in fixed.iter().enumerate() {
            let piece = cells.iter().position(|p| p.contains(f))?;
            if label[piece] != usize::MAX {
                return None;
            }
            label[piece] = j;
        }
        let mut rest: Vec<usize> = (0..cells.len())
            .filter(|&i| label[i] == usize::MAX)
            .collect();
        rest.sort_by_key(|&i| cells[i].iter().min().copied());
        for (n, i) in rest.into_iter().enumerate() {
            label[i] = fixed.len() + n;
        }
        Some(
            cells
                .iter()
                .enumerate()
                .flat_map(|(i, p)| {
                    let l = label[i];
                    p.iter().map(move |&c| (l, c))
                })
                .collect(),
        )
    }
}
