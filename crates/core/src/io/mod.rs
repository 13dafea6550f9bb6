//! Reading and writing the two contract formats of `shared/FORMAT.md` from
//! and to strings (never files: the core does no I/O).

mod figure_text;
mod solution_json;

pub use figure_text::{format_figure, parse_figure, ParseError, ParseErrorKind};
pub use solution_json::{
    parse_solution, SolutionError, SolutionFigure, SolutionFile, SOLUTION_FORMAT,
};
