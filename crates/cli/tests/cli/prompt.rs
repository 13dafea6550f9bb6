//! Every long command ends within one second of its time limit (the test
//! allows two seconds from the start of the process for `--time-limit 1`),
//! on figures large enough that the phase is still running when the limit
//! comes, and Ctrl-C ends a large solve within a second with a valid file.

use std::time::Duration;

use crate::support::{assert_valid, Sandbox};

/// Two seconds from the start of the process: the limit of one second and
/// one second to stop.
const PROMPT: Duration = Duration::from_secs(2);

/// A 48×48 square and a 64×36 rectangle: 2,304 cells.
fn large(sb: &Sandbox) -> [String; 2] {
    [
        sb.write("square48.txt", &format!("{}\n", "#".repeat(48)).repeat(48)),
        // Not 64x36: its 2-piece staircase meets the bound 2 at once, and
        // the run would end proved optimal before any stop.
        sb.write(
            "rect128x18.txt",
            &format!("{}\n", "#".repeat(128)).repeat(18),
        ),
    ]
}

fn sierpinski(sb: &Sandbox) -> [String; 2] {
    [
        sb.copy_instance("sierpinski9-to-square8", "a.txt", "a.txt"),
        sb.copy_instance("sierpinski9-to-square8", "b.txt", "b.txt"),
    ]
}

#[track_caller]
fn prompt(run: &crate::support::Run, what: &str) {
    assert!(
        run.elapsed < PROMPT,
        "{what} with --time-limit 1 took {:?}\n{}",
        run.elapsed,
        run.stderr
    );
}

#[test]
fn solve_on_2304_cells_ends_within_a_second_of_its_limit() {
    let sb = Sandbox::new();
    let [a, b] = large(&sb);
    let run = sb.run(&["solve", "-q", "--time-limit", "1", "-o", "out.json", &a, &b]);
    prompt(&run, "solve on 2,304 cells");
    run.expect_code(0);
    assert!(assert_valid(&sb, "square", "out.json", &[&a, &b]) >= 2);
}

#[test]
fn bound_on_sierpinski9_ends_within_a_second_of_its_limit() {
    let sb = Sandbox::new();
    let [a, b] = sierpinski(&sb);
    let run = sb.run(&["bound", "-q", "--time-limit", "1", &a, &b]);
    prompt(&run, "bound on sierpinski9");
    run.expect_code(0).stdout_has(&["lower bound: "]);
}

#[test]
fn exact_solve_on_sierpinski9_ends_within_a_second_of_its_limit() {
    let sb = Sandbox::new();
    let [a, b] = sierpinski(&sb);
    let run = sb.run(&[
        "solve",
        "-q",
        "--exact",
        "--time-limit",
        "1",
        "-o",
        "out.json",
        &a,
        &b,
    ]);
    prompt(&run, "solve --exact on sierpinski9");
    // The SAT search alone finds no dissection in a second.
    assert!(matches!(run.code, Some(0 | 1)), "{}", run.stderr);
    if run.code == Some(0) {
        assert_valid(&sb, "square", "out.json", &[&a, &b]);
    }
}

#[test]
fn assemblies_of_a_disc_answer_end_within_a_second_of_their_limit() {
    // A 17-piece answer of disc21-to-square37: building each board alone
    // took seconds before the counter looked at its limits while building.
    let sb = Sandbox::new();
    let a = sb.copy_instance("disc21-to-square37", "a.txt", "a.txt");
    let b = sb.copy_instance("disc21-to-square37", "b.txt", "b.txt");
    let fixture = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/disc21-to-square37.solution.json");
    let text = std::fs::read_to_string(fixture).expect("the fixture");
    sb.write("disc.json", &text);
    assert_eq!(assert_valid(&sb, "square", "disc.json", &[&a, &b]), 17);
    let run = sb.run(&[
        "assemblies",
        "--solution",
        "disc.json",
        "--time-limit",
        "1",
        &a,
        &b,
    ]);
    prompt(&run, "assemblies of a 17-piece disc answer");
    run.expect_code(0)
        .stdout_has(&["a.txt: at least ", "b.txt: at least "])
        .stderr_has(&["lower bounds"]);
}

#[test]
fn ctrl_c_ends_a_large_solve_within_a_second_with_a_valid_file() {
    let sb = Sandbox::new();
    let [a, b] = large(&sb);
    let running = sb.spawn_until_first_line(&["solve", "-o", "out.json", &a, &b]);
    // The constructive answer comes at once (under a second); the search
    // goes on for long.
    std::thread::sleep(Duration::from_millis(3000));
    running.signal("INT");
    let run = running.wait(Duration::from_secs(1));
    run.expect_code(0)
        .stdout_has(&["interrupted; best found so far"]);
    assert!(assert_valid(&sb, "square", "out.json", &[&a, &b]) >= 2);
}
