//! Disassembly of a dissection's figures: whether each can be taken apart
//! by straight moves, under the run's time limit and stop flag (the search
//! is [`dissect_puzzle::disassembly`]).

use std::sync::atomic::AtomicBool;

use dissect_core::Dissection;
use dissect_puzzle::disassembly::{disassemble as search, Disassembly, DisassemblyError, Limits};

use crate::limits::TimeLimit;
use crate::verified::Verified;

/// Takes apart every figure of `dissection` in turn (its pieces where that
/// figure has them), all within `time_limit` and until
/// `stop` is raised; a figure not decided by then is
/// [`Disassembly::Undecided`]. `each` hears every figure's outcome as soon
/// as it is known (figure index, outcome). On a flat lattice every piece
/// lifts off (level 1).
pub fn disassemble(
    dissection: &Dissection,
    time_limit: TimeLimit,
    stop: Option<&AtomicBool>,
    mut each: impl FnMut(usize, &Disassembly),
) -> Result<Vec<Disassembly>, DisassemblyError> {
    let deadline = time_limit.deadline();
    let lattice = dissection.lattice().lattice();
    let mut out = Vec::with_capacity(dissection.pieces().len());
    for (f, pieces) in dissection.pieces().iter().enumerate() {
        let limits = Limits {
            stop,
            deadline,
            ..Limits::default()
        };
        let outcome = search(lattice, pieces, limits)?;
        each(f, &outcome);
        out.push(outcome);
    }
    Ok(out)
}

impl Verified {
    /// [`disassemble`] of this dissection: one outcome per figure.
    pub fn disassemble(
        &self,
        time_limit: TimeLimit,
        stop: Option<&AtomicBool>,
    ) -> Result<Vec<Disassembly>, DisassemblyError> {
        disassemble(self.dissection(), time_limit, stop, |_, _| {})
    }
}
