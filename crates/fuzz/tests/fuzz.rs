//! A short fuzz run of every target inside `cargo test` (the long runs are
//! `cargo run -p dissect-fuzz --release -- --seconds S`, see RELIABILITY.md).

use dissect_fuzz::{Target, TARGETS};

#[test]
fn every_parser_survives_a_short_fuzz_run() {
    for name in TARGETS {
        let mut t = Target::new(name).unwrap();
        let inputs = if *name == "picture" || *name == "mesh" || *name == "puzzle" {
            150
        } else {
            600
        };
        let tally = t.fuzz(17, inputs, None);
        assert_eq!(tally.inputs, inputs);
        assert!(
            tally.accepted > 0,
            "{name}: no input was accepted: the seeds are broken"
        );
        assert!(
            tally.failures.is_empty(),
            "{name}: {} panics, first {:?} on {:?}",
            tally.failures.len(),
            tally.failures[0].1,
            String::from_utf8_lossy(&tally.failures[0].0)
        );
    }
}

#[test]
fn mutations_are_reproducible_and_bounded() {
    let mut a = dissect_fuzz::Rng::new(5);
    let mut b = dissect_fuzz::Rng::new(5);
    let mut x = b"###\n".to_vec();
    let mut y = x.clone();
    for _ in 0..200 {
        dissect_fuzz::mutate(&mut a, &mut x, &[], 100);
        dissect_fuzz::mutate(&mut b, &mut y, &[], 100);
        assert!(x.len() <= 100);
    }
    assert_eq!(x, y);
}
