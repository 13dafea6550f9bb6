//! Lower bounds on the number of pieces, each with the reason that proves it.

use std::fmt;

use dissect_core::{Cell, Figure};

use crate::component_count::{all_congruent, most_components};
use crate::extent_clique::extent_clique;
use crate::incompatible_clique::Incompatibility;
use crate::instance::Instance;
use crate::ExactError;

/// A proved lower bound.
#[derive(Clone, Debug, PartialEq)]
pub struct Bound {
    /// No dissection into fewer than `value` connected pieces exists.
    pub value: usize,
    /// What proves it.
    pub reason: Reason,
}

/// Why a lower bound holds. Figures are numbered from 0 in input order.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Reason {
    /// Every dissection has at least one piece.
    Trivial,
    /// The figures are connected but not congruent.
    NotCongruent,
    /// A figure has this many connected components.
    Components {
        /// The figure.
        figure: usize,
        /// Its number of components.
        components: usize,
    },
    /// These cells of a figure are pairwise incompatible: no connected piece
    /// can hold two of them and still fit into every other figure.
    Incompatible {
        /// The figure.
        figure: usize,
        /// The cells.
        cells: Vec<Cell>,
    },
    /// The SAT solver proved that no dissection into `refuted` pieces exists.
    Sat {
        /// The piece count proved impossible.
        refuted: usize,
        /// Seconds the proof of this count took.
        seconds: f64,
        /// Connectivity cuts added (0: the relaxation with disconnected
        /// pieces was already unsatisfiable).
        cuts: usize,
    },
    /// Another SAT solver answered UNSAT on the formula of "at most
    /// `refuted` connected pieces" (`dimacs_connected`); its proof is its
    /// own, to be checked by `dissect check-proof`.
    External {
        /// The piece count proved impossible.
        refuted: usize,
        /// Seconds the solver took.
        seconds: f64,
        /// The solver (its command).
        solver: String,
    },
}

impl Bound {
    /// The reason in words, naming figures by `names` (input order).
    pub fn describe(&self, names: &[String]) -> String {
        let name = |f: usize| {
            names
                .get(f)
                .cloned()
                .unwrap_or_else(|| format!("figure {f}"))
        };
        match &self.reason {
            Reason::Trivial => "every dissection has a piece".to_string(),
            Reason::NotCongruent => "the figures are not congruent".to_string(),
            Reason::Components { figure, components } => {
                format!("{} has {components} connected components", name(*figure))
            }
            Reason::Incompatible { figure, cells } => format!(
                "{} cells of {} that no piece can hold two of, e.g. {:?} and {:?}",
                cells.len(),
                name(*figure),
                cells[0],
                cells.get(1).unwrap_or(&cells[0])
            ),
            Reason::Sat {
                refuted,
                seconds,
                cuts,
            } => {
                if *cuts == 0 {
                    format!("SAT: no {refuted}-piece dissection, {seconds:.1} s")
                } else {
                    format!(
                        "SAT: no {refuted}-piece dissection, {seconds:.1} s, {cuts} connectivity cuts"
                    )
                }
            }
            Reason::External {
                refuted,
                seconds,
                solver,
            } => format!("{solver}: no {refuted}-piece dissection, {seconds:.1} s"),
        }
    }
}

impl fmt::Display for Bound {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} ({})", self.value, self.describe(&[]))
    }
}

/// The cheap bounds and what the exact search reuses from them.
pub(crate) struct Cheap {
    pub bound: Bound,
    /// The shape (input index) holding the largest incompatible clique.
    pub clique_figure: usize,
    /// Its cells (indices into that figure's sorted cells).
    pub clique: Vec<usize>,
    /// The incompatibility graph of every figure (input order); `None` when
    /// interrupted before they were all built (the bound then holds
    /// without them).
    pub graphs: Option<Vec<Incompatibility>>,
}

/// Figures of more cells get the incompatible-cell bound of
/// `extent_clique` (extreme cells, difference sets) instead of the full
/// incompatibility graph, whose cost grows with the square of the cells.
pub const FULL_GRAPH_MAX_CELLS: usize = 600;

/// Figures of more cells get no SAT model (only the cheap bounds); up to
/// this size, figures over [`FULL_GRAPH_MAX_CELLS`] get one without
/// incompatibility clauses (their graphs are not built), the clique of
/// extreme cells fixing the first pieces.
pub const SAT_MAX_CELLS: usize = 2_000;

/// Branch-and-bound nodes spent on one figure's clique.
const CLIQUE_NODES: usize = 200_000;

/// The cheap bounds; `interrupted` (the stop flag or a deadline) cuts the
/// incompatibility graphs and the clique search short, keeping what is
/// proved by then.
pub(crate) fn cheap(
    figures: &[Figure],
    mirror: bool,
    interrupted: &dyn Fn() -> bool,
) -> Result<Cheap, ExactError> {
    cheap_with(figures, mirror, interrupted, &|_| {})
}

/// [`cheap`], telling `early` the bound of the components and congruence
/// as soon as it is known (before the incompatibility graphs, which take
/// long on large figures and may be interrupted).
pub(crate) fn cheap_with(
    figures: &[Figure],
    mirror: bool,
    interrupted: &dyn Fn() -> bool,
    early: &dyn Fn(&Bound),
) -> Result<Cheap, ExactError> {
    dissect_core::solver::check_figures(figures)?;
    let inst = Instance::new(figures, mirror, 0);
    let mut bound = Bound {
        value: 1,
        reason: Reason::Trivial,
    };
    let (k, comps) = most_components(&inst);
    if comps > 1 {
        bound = Bound {
            value: comps,
            reason: Reason::Components {
                figure: inst.order[k],
                components: comps,
            },
        };
    } else if !all_congruent(&inst) {
        bound = Bound {
            value: 2,
            reason: Reason::NotCongruent,
        };
    }
    early(&bound);
    let mut clique_figure = 0;
    let mut clique = Vec::new();
    let large = inst.shapes.iter().any(|s| s.len() > FULL_GRAPH_MAX_CELLS);
    let mut graphs = (!large).then(|| Vec::with_capacity(inst.shapes.len()));
    for k in 0..inst.shapes.len() {
        if large {
            // The full graphs would cost too much: extreme cells only.
            let c = extent_clique(&inst, k, CLIQUE_NODES, interrupted).unwrap_or_default();
            if c.len() > clique.len() {
                clique = c;
                clique_figure = inst.order[k];
            }
            continue;
        }
        let Some(g) = Incompatibility::of_shape(&inst, k, interrupted) else {
            graphs = None;
            break;
        };
        let c = g.clique(CLIQUE_NODES, interrupted);
        if c.len() > clique.len() {
            clique = c;
            clique_figure = inst.order[k];
        }
        if let Some(gs) = &mut graphs {
            gs.push(g);
        }
    }
    if large && !interrupted() && inst.shapes.iter().all(|s| s.len() <= SAT_MAX_CELLS) {
        graphs = Some(
            inst.shapes
                .iter()
                .map(|s| Incompatibility::none(s.len()))
                .collect(),
        );
    }
    if clique.len() > bound.value {
        let cells = &inst.shapes[inst
            .order
            .iter()
            .position(|&i| i == clique_figure)
            .expect("shape")]
        .cells;
        bound = Bound {
            value: clique.len(),
            reason: Reason::Incompatible {
                figure: clique_figure,
                cells: clique.iter().map(|&i| cells[i]).collect(),
            },
        };
    }
    Ok(Cheap {
        bound,
        clique_figure,
        clique,
        graphs,
    })
}

/// The best bound that needs no SAT solver: components, congruence and
/// incompatible cells.
pub fn cheap_bound(figures: &[Figure], mirror: bool) -> Result<Bound, ExactError> {
    Ok(cheap(figures, mirror, &|| false)?.bound)
}
