//! The default `solve`: a dissection at once, improvements on stderr, the
//! lower bound and `optimal` in the JSON, a stop at any moment keeps a
//! verified dissection, and without a time limit the same seed gives the
//! same answer on any thread count.

use std::time::Duration;

use crate::support::{assert_valid, json, Sandbox};

#[test]
fn the_readme_example_is_optimal_with_bound_and_history() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("squares-3-4-split-to-5", "a.txt", "a.txt");
    let b = sb.copy_instance("squares-3-4-split-to-5", "b.txt", "b.txt");
    let run = sb.run(&["solve", "--color", "never", "-o", "out.json", &a, &b]);
    run.expect_code(0);
    assert!(run.elapsed < Duration::from_secs(20), "{:?}", run.elapsed);
    assert_eq!(assert_valid(&sb, "square", "out.json", &[&a, &b]), 4);
    let last = run.stdout.lines().last().unwrap_or_default();
    assert!(last.starts_with("4 pieces — optimal ("), "{last}");
    let sol = json(&sb.read("out.json"));
    assert_eq!(sol["lower_bound"], 4);
    assert_eq!(sol["optimal"], true);
    let history = sol["history"].as_array().expect("history");
    assert!(!history.is_empty());
    assert_eq!(history.last().unwrap()["pieces"], 4);
    assert!(history[0]["seconds"].as_f64().is_some());
    // Each improvement is a line on stderr.
    assert!(
        run.stderr.lines().any(|l| l.starts_with("4 pieces at ")),
        "{}",
        run.stderr
    );
}

/// A rasterized disc to a square (1,369 cells): the constructive
/// dissection leaves pieces of one cell along the rim; the sectors (one
/// large common piece, the rim dissected exactly sector by sector) give
/// fewer pieces within a second or so, none of fewer than three cells.
#[test]
fn a_disc_to_a_square_has_no_sliver() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("disc21-to-square37", "a.txt", "a.txt");
    let b = sb.copy_instance("disc21-to-square37", "b.txt", "b.txt");
    let run = sb.run(&[
        "solve",
        "--seed",
        "1",
        "--time-limit",
        "12",
        "-o",
        "out.json",
        &a,
        &b,
    ]);
    run.expect_code(0);
    let n = assert_valid(&sb, "square", "out.json", &[&a, &b]);
    let sol = json(&sb.read("out.json"));
    let history = sol["history"].as_array().expect("history");
    let first = history[0]["pieces"].as_u64().expect("pieces") as usize;
    assert!(
        history.iter().any(|h| h["by"] == "sectors"),
        "{}",
        run.stderr
    );
    assert!(n < first && n <= 17, "{n} pieces after {first}");
    let areas: Vec<u64> = sol["areas"]
        .as_array()
        .expect("areas")
        .iter()
        .map(|a| a.as_u64().expect("area"))
        .collect();
    assert!(areas.iter().all(|&a| a >= 3), "{areas:?}");
}

#[test]
fn improvements_never_raise_the_piece_count() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("sierpinski9-to-square8", "a.txt", "a.txt");
    let b = sb.copy_instance("sierpinski9-to-square8", "b.txt", "b.txt");
    let run = sb.run(&[
        "solve",
        "--no-prove",
        "--explorations",
        "24",
        "-o",
        "out.json",
        &a,
        &b,
    ]);
    run.expect_code(0);
    let n = assert_valid(&sb, "square", "out.json", &[&a, &b]);
    let sol = json(&sb.read("out.json"));
    let counts: Vec<u64> = sol["history"]
        .as_array()
        .expect("history")
        .iter()
        .map(|h| h["pieces"].as_u64().expect("pieces"))
        .collect();
    assert!(counts.windows(2).all(|w| w[1] < w[0]), "{counts:?}");
    assert_eq!(counts.last().copied(), Some(n as u64));
    let printed: Vec<u64> = run
        .stderr
        .lines()
        .filter_map(|l| l.split_once(" pieces at ").map(|(n, _)| n.parse().unwrap()))
        .collect();
    assert_eq!(printed, counts, "{}", run.stderr);
}

#[test]
fn without_a_time_limit_the_same_seed_gives_the_same_answer_on_1_and_2_threads() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("sierpinski9-to-square8", "a.txt", "a.txt");
    let b = sb.copy_instance("sierpinski9-to-square8", "b.txt", "b.txt");
    for (seed, prove) in [("4", "--no-prove"), ("5", "--prove")] {
        let mut answers = Vec::new();
        for threads in ["1", "2"] {
            let out = format!("s{seed}-t{threads}.json");
            sb.run(&[
                "solve",
                "-q",
                prove,
                "--explorations",
                "24",
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
            answers.push(json(&sb.read(&out))["figures"].clone());
        }
        assert_eq!(answers[0], answers[1], "seed {seed} {prove}");
    }
}

#[test]
fn a_stop_at_any_moment_writes_a_verified_dissection_or_exits_1() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("cubes-3-4-5-to-6", "a.txt", "a.txt");
    let b = sb.copy_instance("cubes-3-4-5-to-6", "b.txt", "b.txt");
    for (i, delay) in [0u64, 50, 300, 1000].into_iter().enumerate() {
        let out = format!("out{i}.json");
        let running =
            sb.spawn_until_first_line(&["solve", "--lattice", "cubic", "-o", &out, &a, &b]);
        std::thread::sleep(Duration::from_millis(delay));
        running.signal("INT");
        let run = running.wait(Duration::from_secs(10));
        match run.code {
            Some(0) => {
                assert_valid(&sb, "cubic", &out, &[&a, &b]);
            }
            Some(1) => {
                run.stderr_has(&["no dissection found"]);
                assert!(!sb.path(&out).exists());
            }
            c => panic!("stopped after {delay} ms: exit {c:?}\n{}", run.stderr),
        }
    }
}

#[test]
fn paper_and_exact_stay_reachable() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("squares-3-4-split-to-5", "a.txt", "a.txt");
    let b = sb.copy_instance("squares-3-4-split-to-5", "b.txt", "b.txt");
    let paper = sb.run(&["solve", "--paper", "--no-prove", "-o", "p.json", &a, &b]);
    paper.expect_code(0);
    assert_valid(&sb, "square", "p.json", &[&a, &b]);
    let sol = json(&sb.read("p.json"));
    assert_eq!(sol["found_by"], "search");
    assert!(sol["level"].as_u64().is_some());
    // No level line after the first valid level: the paper's schedule stops.
    let levels = paper
        .stderr
        .lines()
        .filter(|l| l.starts_with("level "))
        .count();
    assert_eq!(
        levels as u64,
        sol["level"].as_u64().unwrap() + 1,
        "{}",
        paper.stderr
    );
    let exact = sb.run(&["solve", "--exact", "-q", "-o", "e.json", &a, &b]);
    exact.expect_code(0);
    assert_eq!(json(&sb.read("e.json"))["found_by"], "sat");
}
