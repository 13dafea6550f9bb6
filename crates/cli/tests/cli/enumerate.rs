//! `dissect enumerate`: the last line, exit codes, one verified file per
//! class, `--unique`, `--rank`, the time limit and bad input. The counts
//! are those the exact crate's brute-force tests check
//! (`crates/exact/tests/enumerate.rs`).

use crate::support::{json, Sandbox};

const LAST_2X3: &str =
    "7 dissections with 3 pieces (3 up to the first figure's symmetries), complete";

#[test]
fn every_class_is_written_and_verified() {
    let sb = Sandbox::new();
    let a = sb.write("rect.txt", "###\n###\n");
    let b = sb.write("bar.txt", "######\n");
    let run = sb.run(&["enumerate", "--pieces", "3", "-o", "out", &a, &b]);
    run.expect_code(0);
    assert_eq!(run.stdout.lines().last(), Some(LAST_2X3), "{}", run.stdout);
    for i in 1..=3 {
        let s = format!("out/{i}.json");
        assert_eq!(
            crate::support::assert_valid(&sb, "square", &s, &[&a, &b]),
            3
        );
        let v = json(&sb.read(&s));
        assert_eq!(v["enumeration"]["classes"], 3);
        assert_eq!(v["enumeration"]["complete"], true);
    }
    assert!(!sb.path("out/4.json").exists());
    // Cubic: a 2x2x2 cube into a 4x2 slab, two pieces (3 cuts, 1 class).
    let c = sb.write("cube.txt", "##\n##\n\n##\n##\n");
    let d = sb.write("slab.txt", "####\n####\n");
    let run = sb.run(&["enumerate", "--lattice", "cubic", "-o", "cubic", &c, &d]);
    run.expect_code(0).stdout_has(&[
        "3 dissections with 2 pieces (1 up to the first figure's symmetries), complete",
    ]);
    crate::support::assert_valid(&sb, "cubic", "cubic/1.json", &[&c, &d]);
}

#[test]
fn without_pieces_the_proved_minimum_is_counted() {
    let sb = Sandbox::new();
    let a = sb.write("sq4.txt", "####\n####\n####\n####\n");
    let b = sb.write("r28.txt", "########\n########\n");
    let run = sb.run(&["enumerate", &a, &b]);
    run.expect_code(0).stderr_has(&["minimum: 2 pieces"]);
    assert_eq!(
        run.stdout.lines().last(),
        Some("2 dissections with 2 pieces (1 up to the first figure's symmetries), complete")
    );
}

#[test]
fn unique_keeps_single_assemblies_and_rank_orders_the_classes() {
    let sb = Sandbox::new();
    let a = sb.write("sq4.txt", "####\n####\n####\n####\n");
    let b = sb.write("r28.txt", "########\n########\n");
    let run = sb.run(&["enumerate", "--pieces", "3", "--unique", "--quiet", &a, &b]);
    run.expect_code(0);
    assert_eq!(
        run.stdout.trim(),
        "36 dissections with 3 pieces (6 up to the first figure's symmetries), complete"
    );
    let run = sb.run(&[
        "enumerate",
        "--pieces",
        "3",
        "--rank",
        "smallest",
        "-o",
        "r",
        &a,
        &b,
    ]);
    run.expect_code(0)
        .stdout_has(&["178 dissections with 3 pieces (27 up to"])
        .stderr_has(&["r/1.json: "]);
    let smallest = |i: usize| {
        json(&sb.read(&format!("r/{i}.json")))["scores"]["smallest"]
            .as_u64()
            .expect("a score")
    };
    assert!((1..27).all(|i| smallest(i) >= smallest(i + 1)));
    // Without mirror images: more classes (4 rotations of the square only).
    let run = sb.run(&["enumerate", "--pieces", "3", "--no-mirror", "-q", &a, &b]);
    run.expect_code(0)
        .stdout_has(&["138 dissections with 3 pieces (35 up to"]);
}

#[test]
fn stopped_or_none_exits_1() {
    let sb = Sandbox::new();
    let a = sb.write("rect.txt", "###\n###\n");
    let b = sb.write("bar.txt", "######\n");
    let run = sb.run(&["enumerate", "--time-limit", "0", &a, &b]);
    run.expect_code(1);
    let last = run.stdout.lines().last().unwrap_or_default().to_string();
    assert!(last.starts_with("at least 0 dissections with "), "{last}");
    assert!(
        last.ends_with(" (0 up to the first figure's symmetries), stopped"),
        "{last}"
    );
    let run = sb.run(&["enumerate", "--pieces", "1", &a, &b]);
    run.expect_code(1).stdout_has(&[
        "0 dissections with 1 pieces (0 up to the first figure's symmetries), complete",
    ]);
}

#[test]
fn bad_input_exits_2() {
    let sb = Sandbox::new();
    let a = sb.write("rect.txt", "###\n###\n");
    let b = sb.write("bar.txt", "######\n");
    let c = sb.write("small.txt", "#####\n");
    sb.write("file", "x");
    for (args, says) in [
        (vec!["--pieces", "0"], "--pieces"),
        (vec!["--time-limit", "-1"], "--time-limit"),
        (vec!["--rank", "beauty"], "unknown ranking"),
        (vec!["-o", "file"], "not a folder"),
        (vec!["-o", "no/such"], "cannot create the folder"),
    ] {
        let mut all = vec!["enumerate"];
        all.extend(args);
        all.extend([a.as_str(), b.as_str()]);
        sb.run(&all).expect_code(2).stderr_has(&[says]);
    }
    sb.run(&["enumerate", &a, &c]).expect_code(2);
}
