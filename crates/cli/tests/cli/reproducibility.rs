//! The same `--seed` gives the same pieces whatever `--threads` is.

use crate::support::{assert_valid, json, Sandbox};

#[test]
fn same_seed_same_pieces_on_1_and_2_threads() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("squares-3-4-split-to-5", "a.txt", "a.txt");
    let b = sb.copy_instance("squares-3-4-split-to-5", "b.txt", "b.txt");
    for seed in ["7", "12345"] {
        let mut figures = Vec::new();
        for threads in ["1", "2"] {
            let out = format!("seed{seed}-threads{threads}.json");
            sb.run(&[
                "solve",
                "-q",
                "--seed",
                seed,
                "--threads",
                threads,
                "-o",
                &out,
                &a,
                &b,
            ])
            .expect_code(0);
            assert_valid(&sb, "square", &out, &[&a, &b]);
            let sol = json(&sb.read(&out));
            assert_eq!(sol["seed"].as_u64(), seed.parse().ok());
            figures.push(sol["figures"].clone());
        }
        assert_eq!(
            figures[0], figures[1],
            "--seed {seed}: --threads 1 and --threads 2 differ"
        );
    }
}
