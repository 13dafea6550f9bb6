//! `solve` exits 0 with a valid solution written, 1 when it finds none, 2 on
//! usage errors and bad input.

use crate::support::{assert_valid, json, Sandbox};

/// Three cells in a row and in an L: two pieces are needed.
const BAR: &str = "###\n";
const ELL: &str = "##\n#.\n";

#[test]
fn solve_writes_a_valid_solution_and_exits_0() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("squares-3-4-split-to-5", "a.txt", "a.txt");
    let b = sb.copy_instance("squares-3-4-split-to-5", "b.txt", "b.txt");
    let run = sb.run(&["solve", "--seed", "1", "-o", "out.json", &a, &b]);
    run.expect_code(0);
    let n = assert_valid(&sb, "square", "out.json", &[&a, &b]);
    // Four pieces is optimal (the manifest's lower bound).
    assert!(n >= 4, "{n} pieces beat the lower bound of 4?");
    run.stdout_has(&[
        &format!("\n{n} pieces\n"),
        "piece areas: A=",
        "area variance: ",
        "time: ",
    ]);
    let sol = json(&sb.read("out.json"));
    assert_eq!(sol["format"], "dissection-solution/1");
    assert_eq!(sol["lattice"], "square");
    assert_eq!(sol["mirror"], true);
    assert_eq!(sol["figures"][0]["name"], "a.txt");
    assert_eq!(sol["figures"][1]["name"], "b.txt");
}

#[test]
fn congruent_figures_are_one_piece() {
    let sb = Sandbox::new();
    let a = sb.write("a.txt", "##.\n.##\n");
    let b = sb.write("b.txt", ".#\n##\n#.\n");
    let run = sb.run(&["solve", "-o", "out.json", &a, &b]);
    run.expect_code(0).stdout_has(&["\n1 piece\n"]);
    assert_eq!(assert_valid(&sb, "square", "out.json", &[&a, &b]), 1);
}

#[test]
fn no_mirror_needs_more_pieces_for_mirror_images() {
    // An S and a Z tetromino: one piece with flips, two without.
    let sb = Sandbox::new();
    let s = sb.write("s.txt", ".##\n##.\n");
    let z = sb.write("z.txt", "##.\n.##\n");
    sb.run(&["solve", "-q", "-o", "flip.json", &s, &z])
        .expect_code(0);
    assert_eq!(assert_valid(&sb, "square", "flip.json", &[&s, &z]), 1);
    sb.run(&["solve", "-q", "--no-mirror", "-o", "rot.json", &s, &z])
        .expect_code(0);
    assert_eq!(json(&sb.read("rot.json"))["mirror"], false);
    assert!(assert_valid(&sb, "square", "rot.json", &[&s, &z]) >= 2);
}

#[test]
fn max_pieces_too_low_exits_1_with_the_best_score() {
    let sb = Sandbox::new();
    let a = sb.write("bar.txt", BAR);
    let b = sb.write("ell.txt", ELL);
    let run = sb.run(&["solve", "--max-pieces", "1", "-o", "out.json", &a, &b]);
    run.expect_code(1).stderr_has(&[
        "no dissection found",
        "--max-pieces 1 was reached",
        "matching score E_M = ",
    ]);
    assert!(
        !sb.path("out.json").exists(),
        "nothing is written without a dissection"
    );
}

#[test]
fn time_limit_0_exits_1_with_the_best_score() {
    let sb = Sandbox::new();
    let a = sb.write("bar.txt", BAR);
    let b = sb.write("ell.txt", ELL);
    let run = sb.run(&["solve", "--time-limit", "0", &a, &b]);
    run.expect_code(1).stderr_has(&[
        "no dissection found",
        "time limit of 0 s was reached",
        "matching score E_M = ",
    ]);
}

#[test]
fn usage_errors_exit_2() {
    let sb = Sandbox::new();
    let a = sb.write("bar.txt", BAR);
    let b = sb.write("ell.txt", ELL);
    let cases: &[(&[&str], &str)] = &[
        (&["solve", "bar.txt"], "2 values required"),
        (&["solve"], "required"),
        (
            &["solve", "--frobnicate", "bar.txt", "ell.txt"],
            "--frobnicate",
        ),
        (
            &["solve", "--lattice", "octagon", "bar.txt", "ell.txt"],
            "unknown lattice \"octagon\"",
        ),
        (
            &["solve", "--time-limit", "soon", "bar.txt", "ell.txt"],
            "--time-limit",
        ),
        (
            &["solve", "--time-limit=-1", "bar.txt", "ell.txt"],
            "--time-limit must be",
        ),
        (
            &["solve", "--time-limit", "NaN", "bar.txt", "ell.txt"],
            "--time-limit must be",
        ),
        (
            &["solve", "--area-weight=-0.5", "bar.txt", "ell.txt"],
            "--area-weight must be",
        ),
        (&["solve", "--seed", "-3", "bar.txt", "ell.txt"], "-3"),
        (
            &["solve", "--threads", "many", "bar.txt", "ell.txt"],
            "--threads",
        ),
        (&["verify", "bar.txt", "ell.txt"], "--solution"),
        (&["info"], "required"),
        (
            &["info", "--lattice", "hexagonal", "bar.txt"],
            "unknown lattice",
        ),
        (&["frobnicate"], "frobnicate"),
    ];
    for (args, says) in cases {
        let run = sb.run(args);
        assert_eq!(run.code, Some(2), "{args:?} should exit 2:\n{}", run.stderr);
        assert!(
            run.stderr.contains(says),
            "{args:?}: stderr lacks {says:?}:\n{}",
            run.stderr
        );
    }
    // The figures were fine all along.
    sb.run(&["solve", "-q", &a, &b]).expect_code(0);
}

#[test]
fn far_away_time_limits_are_no_limit() {
    let sb = Sandbox::new();
    let a = sb.write("bar.txt", BAR);
    let b = sb.write("ell.txt", ELL);
    for limit in ["inf", "1e300", "1e15", "3600"] {
        let out = format!("out-{limit}.json");
        sb.run(&["solve", "-q", "--time-limit", limit, "-o", &out, &a, &b])
            .expect_code(0);
        assert_eq!(assert_valid(&sb, "square", &out, &[&a, &b]), 2);
    }
}
