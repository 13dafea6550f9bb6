//! End-to-end tests of the `dissect` binary: exit codes, error messages,
//! stopping (time limit, Ctrl-C), reproducibility, output and display.
//!
//! One test binary; every test runs the built binary in its own temporary
//! folder (see `support`), and every solution it writes is checked by
//! `dissect verify`, and in several tests by the repository's own
//! `tools/check_solution.py` and the external `verify.py` (when present) too.

#[path = "cli/support.rs"]
mod support;

#[path = "cli/anytime.rs"]
mod anytime;
#[path = "cli/assemblies.rs"]
mod assemblies;
#[path = "cli/bad_input.rs"]
mod bad_input;
#[path = "cli/disassemble.rs"]
mod disassemble;
#[path = "cli/display.rs"]
mod display;
#[path = "cli/enumerate.rs"]
mod enumerate;
#[path = "cli/exit_codes.rs"]
mod exit_codes;
#[path = "cli/hostile.rs"]
mod hostile;
#[path = "cli/info.rs"]
mod info;
#[path = "cli/limits.rs"]
mod limits;
#[path = "cli/output.rs"]
mod output;
#[path = "cli/reproducibility.rs"]
mod reproducibility;
#[path = "cli/solutions.rs"]
mod solutions;
#[path = "cli/stopping.rs"]
mod stopping;
#[path = "cli/verify.rs"]
mod verify;
