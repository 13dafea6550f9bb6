//! `--time-limit` and Ctrl-C stop the search promptly and keep its result.

use std::time::Duration;

use crate::support::{assert_valid, json, Sandbox};

/// A big instance no run finds a dissection of within a second (8 pieces
/// are needed).
fn big(sb: &Sandbox) -> [String; 2] {
    [
        sb.copy_instance("cubes-3-4-5-to-6", "a.txt", "a.txt"),
        sb.copy_instance("cubes-3-4-5-to-6", "b.txt", "b.txt"),
    ]
}

#[test]
fn time_limit_ends_a_big_search_within_seconds() {
    let sb = Sandbox::new();
    let [a, b] = big(&sb);
    let run = sb.run(&[
        "solve",
        "--paper",
        "--no-prove",
        "--lattice",
        "cubic",
        "--time-limit",
        "1",
        "-o",
        "out.json",
        &a,
        &b,
    ]);
    // Within one second of the limit, process start included.
    assert!(
        run.elapsed < Duration::from_secs(2),
        "--time-limit 1 took {:?}",
        run.elapsed
    );
    run.expect_code(1).stderr_has(&[
        "no dissection found: the time limit of 1 s was reached",
        "matching score E_M = ",
    ]);
    assert!(!sb.path("out.json").exists());
}

#[test]
fn time_limit_keeps_a_dissection_found_before_it() {
    // --full-level goes on after the first dissection; the limit stops it
    // and the dissection found is written.
    let sb = Sandbox::new();
    let a = sb.write("bar.txt", "###\n");
    let b = sb.write("ell.txt", "##\n#.\n");
    let run = sb.run(&[
        "solve",
        "--paper",
        "--no-prove",
        "--full-level",
        "--explorations",
        "1000000",
        "--time-limit",
        "0.5",
        "-o",
        "out.json",
        &a,
        &b,
    ]);
    assert!(
        run.elapsed < Duration::from_millis(1500),
        "took {:?}",
        run.elapsed
    );
    run.expect_code(0)
        .stdout_has(&["time limit reached; best found so far"]);
    assert_eq!(assert_valid(&sb, "square", "out.json", &[&a, &b]), 2);
    assert_eq!(json(&sb.read("out.json"))["stopped_early"], true);
}

#[test]
fn ctrl_c_before_a_dissection_exits_1_with_the_best_score() {
    let sb = Sandbox::new();
    let [a, b] = big(&sb);
    let running = sb.spawn_until_first_line(&[
        "solve",
        "--paper",
        "--no-prove",
        "--lattice",
        "cubic",
        "-o",
        "out.json",
        &a,
        &b,
    ]);
    assert!(running.first.starts_with("level 0 "), "{}", running.first);
    std::thread::sleep(Duration::from_millis(300));
    running.signal("INT");
    let run = running.wait(Duration::from_secs(1));
    run.expect_code(1).stderr_has(&[
        "no dissection found: interrupted (Ctrl-C)",
        "matching score E_M = ",
    ]);
    assert!(!sb.path("out.json").exists());
}

#[test]
fn ctrl_c_after_a_dissection_writes_it_and_exits_0() {
    let sb = Sandbox::new();
    let a = sb.write("bar.txt", "###\n");
    let b = sb.write("ell.txt", "##\n#.\n");
    let running = sb.spawn_until_first_line(&[
        "solve",
        "--paper",
        "--no-prove",
        "--full-level",
        "--explorations",
        "1000000",
        "-o",
        "out.json",
        &a,
        &b,
    ]);
    // Level 1 finds a dissection in its first batch, then goes on.
    std::thread::sleep(Duration::from_millis(500));
    running.signal("INT");
    let run = running.wait(Duration::from_secs(1));
    run.expect_code(0)
        .stdout_has(&["2 pieces", "interrupted; best found so far"]);
    assert_eq!(assert_valid(&sb, "square", "out.json", &[&a, &b]), 2);
}

#[test]
fn sigterm_stops_like_ctrl_c() {
    let sb = Sandbox::new();
    let [a, b] = big(&sb);
    let running = sb.spawn_until_first_line(&[
        "solve",
        "--paper",
        "--no-prove",
        "--lattice",
        "cubic",
        &a,
        &b,
    ]);
    std::thread::sleep(Duration::from_millis(200));
    running.signal("TERM");
    let run = running.wait(Duration::from_secs(1));
    run.expect_code(1).stderr_has(&["no dissection found"]);
}
