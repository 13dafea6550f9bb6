//! The command line's one stop flag: Ctrl-C (SIGINT) and SIGTERM raise it,
//! and every long command (solve, bound, assemblies) hands it to the
//! engine, which ends the operation within a second with the best result
//! so far. A second Ctrl-C exits at once (status 130).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Once;

/// Raised by the first Ctrl-C (or SIGTERM).
static STOP: AtomicBool = AtomicBool::new(false);

/// Installs the handler (once) and returns the flag it raises.
pub fn flag() -> &'static AtomicBool {
    static INSTALL: Once = Once::new();
    INSTALL.call_once(|| {
        // Without a handler (no signal support), Ctrl-C ends the process
        // as it always does; the commands still work.
        let _ = ctrlc::set_handler(|| {
            if STOP.swap(true, Ordering::SeqCst) {
                std::process::exit(130);
            }
        });
    });
    &STOP
}
