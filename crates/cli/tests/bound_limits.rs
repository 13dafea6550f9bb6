//! `dissect bound` within memory and time: a SAT encoding too large for
//! memory is refused with a clear message, and `--time-limit` is honoured
//! on figures whose bounds alone would take minutes.

use std::path::Path;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

fn dissect(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dissect"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("dissect runs")
}

fn rect(w: usize, h: usize) -> String {
    format!("{}\n", "#".repeat(w)).repeat(h)
}

#[test]
fn dimacs_of_a_million_pieces_is_refused_at_once() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("a.txt"), rect(85, 3)).unwrap();
    std::fs::write(dir.path().join("b.txt"), rect(15, 17)).unwrap();
    let start = Instant::now();
    let out = dissect(
        dir.path(),
        &[
            "bound",
            "--max-pieces",
            "1000000",
            "--dimacs",
            "k.cnf",
            "a.txt",
            "b.txt",
        ],
    );
    assert!(start.elapsed() < Duration::from_secs(2));
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("SAT encoding for 1000000 pieces would need about")
            && err.contains("over the cap of 512 MiB"),
        "{err}"
    );
    assert!(!dir.path().join("k.cnf").exists());
}

#[test]
fn bound_stops_at_its_time_limit_on_big_figures() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("a.txt"), rect(100, 90)).unwrap();
    std::fs::write(dir.path().join("b.txt"), rect(60, 150)).unwrap();
    let start = Instant::now();
    let out = dissect(
        dir.path(),
        &["bound", "--time-limit", "1", "-q", "a.txt", "b.txt"],
    );
    let took = start.elapsed();
    assert!(took < Duration::from_millis(2500), "took {took:?}");
    assert!(out.status.success());
    // Over the exact search's size only the cheap bounds run: they end
    // within the limit (or are stopped by it), never building a SAT model.
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("stopped") || text.contains("no SAT search: a figure has 9000 cells"),
        "{text}"
    );
    assert!(text.contains("lower bound: 2"), "{text}");
}
