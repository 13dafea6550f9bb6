//! Crate-internal unit tests of the solver's building blocks: distance,
//! matching, flood fill, refinement and levels. Figures are ASCII strings
//! (see [`util`]).

mod anytime;
mod coarse;
mod distance;
mod flood_fill;
mod guillotine;
mod levels;
mod matching;
mod multi_figure;
mod refine;
mod regroup;
mod sectors;
mod shape;
mod util;
