//! One time-limit rule for every long command: `solve`, `bound` and
//! `assemblies` give `--time-limit` the same verdict (the engine's
//! `TimeLimit`), and none panics.

use crate::support::Sandbox;

/// Three cells in a row and in an L: two pieces, found and proved at once.
const BAR: &str = "###\n";
const ELL: &str = "##\n#.\n";

/// The first line of stderr naming the time limit (clap's usage lines
/// after it name the command, so only this line is compared).
fn complaint(stderr: &str) -> String {
    stderr
        .lines()
        .find(|l| l.contains("--time-limit must be"))
        .unwrap_or_default()
        .to_string()
}

#[test]
fn every_command_gives_a_time_limit_the_same_verdict() {
    let sb = Sandbox::new();
    let a = sb.write("bar.txt", BAR);
    let b = sb.write("ell.txt", ELL);
    sb.run(&["solve", "-q", "-o", "two.json", &a, &b])
        .expect_code(0);
    // (value, exit code, whether it is refused)
    let cases = [
        ("1e300", 0, false),
        ("inf", 0, false),
        ("nan", 2, true),
        ("-1", 2, true),
        ("0.5", 0, false),
    ];
    for (value, code, refused) in cases {
        let commands: [Vec<&str>; 3] = [
            vec!["solve", "-q", "--time-limit", value, &a, &b],
            vec!["bound", "-q", "--time-limit", value, &a, &b],
            vec![
                "assemblies",
                "-q",
                "--solution",
                "two.json",
                "--time-limit",
                value,
                &a,
            ],
        ];
        let mut complaints = Vec::new();
        for args in &commands {
            let run = sb.run(args);
            assert_eq!(
                run.code,
                Some(code),
                "{args:?}: exit {:?}, stderr:\n{}",
                run.code,
                run.stderr
            );
            assert!(!run.stderr.contains("panicked"), "{args:?}: {}", run.stderr);
            if refused {
                complaints.push(complaint(&run.stderr));
            }
        }
        if refused {
            assert!(!complaints[0].is_empty(), "{value}: no complaint");
            assert!(
                complaints.iter().all(|c| *c == complaints[0]),
                "{value}: different complaints: {complaints:#?}"
            );
        }
    }
}

#[test]
fn thread_counts_have_one_cap() {
    let sb = Sandbox::new();
    let a = sb.write("bar.txt", BAR);
    let b = sb.write("ell.txt", ELL);
    let too_many = (dissect_engine::MAX_THREADS + 1).to_string();
    sb.run(&["solve", "-q", "--threads", &too_many, &a, &b])
        .expect_code(2)
        .stderr_has(&[&format!(
            "--threads must be from 0 to {}",
            dissect_engine::MAX_THREADS
        )]);
    let most = dissect_engine::MAX_THREADS.to_string();
    sb.run(&["solve", "-q", "--threads", &most, &a, &b])
        .expect_code(0);
}
