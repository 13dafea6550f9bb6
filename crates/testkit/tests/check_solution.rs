//! The repository's own solution checker, `tools/check_solution.py`: its
//! unit tests (valid solutions on every lattice accepted; a piece moved, a
//! piece disconnected, a mirror image without mirror, malformed files
//! rejected) run with the workspace's tests, and it rejects a broken copy of
//! a real solution file.

use std::process::Command;

use dissect_testkit::repo;
use serde_json::json;

#[test]
fn the_checkers_unit_tests_pass() {
    let out = Command::new("python3")
        .args([
            "-m",
            "unittest",
            "discover",
            "-s",
            "tools",
            "-p",
            "test_*.py",
        ])
        .current_dir(repo::root())
        .output()
        .expect("python3 runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("OK"), "{stderr}");
}

#[test]
fn the_checker_accepts_a_shipped_solution_and_rejects_it_broken() {
    let root = repo::root();
    let figures = [
        repo::instance_file("cubes-3-4-5-joined-to-6", "a.txt"),
        repo::instance_file("cubes-3-4-5-joined-to-6", "b.txt"),
    ];
    let solution = root.join("docs/solutions/cubes-3-4-5-joined-to-6.json");
    let v = repo::check_solution(&root, "cubic", &solution, &figures);
    assert_eq!(v.pieces(), Some(6), "{v:?}");

    // The same file with one cell of the first piece of figure 1 moved
    // to the other end of the figure: two pieces now overlap.
    let text = std::fs::read_to_string(&solution).expect("solution");
    let mut json: serde_json::Value = serde_json::from_str(&text).expect("json");
    let cell = &mut json["figures"][1]["pieces"][0][0];
    let moved = json!([cell[0].as_i64().unwrap() + 100, cell[1], cell[2]]);
    *cell = moved;
    let dir = tempfile::tempdir().expect("temp dir");
    let broken = dir.path().join("broken.json");
    std::fs::write(&broken, json.to_string()).expect("write");
    let v = repo::check_solution(&root, "cubic", &broken, &figures);
    assert!(!v.ok, "{v:?}");
    assert!(v.stdout.contains("invalid: "), "{v:?}");
}
