//! Tests of the benchmark harness: the manifest, the scaler, timed and
//! verified runs, the tables (golden files) and the binary end to end.

use std::path::Path;
use std::process::Command;
use std::time::Duration;

use dissect_bench::manifest::Manifest;
use dissect_bench::paper::paper_result;
use dissect_bench::report::{
    growth_exponent, median_worst, scale_table, seed_table, suite_table, InstanceResult, ScaleStep,
    Style,
};
use dissect_bench::run::{run_seed, SeedRun};
use dissect_bench::scale::scale;
use dissect_bench::{BenchError, Plan};
use dissect_core::io::{format_figure, parse_figure};
use dissect_core::solver::Options;
use dissect_core::verify::verify_pieces;
use dissect_core::{Figure, LatticeKind};
use dissect_testkit::repo;

fn fig(lattice: LatticeKind, text: &str) -> Figure {
    parse_figure(text, lattice).expect("test figure parses")
}

fn square(text: &str) -> Figure {
    fig(LatticeKind::Square, text)
}

/// Small, quick solver settings.
fn quick() -> Options {
    Options {
        explorations: 24,
        keep: 6,
        iterations: 20,
        threads: 2,
        ..Options::default()
    }
}

// ---------------------------------------------------------------- manifest

#[test]
fn the_manifest_parses_and_every_instance_loads() {
    let m = Manifest::load(&repo::instances()).expect("instances/manifest.json");
    let names: Vec<&str> = m.instances().iter().map(|i| i.name.as_str()).collect();
    for expected in [
        "rect10x7-hole-to-square8",
        "rect15x10-hole-to-square12",
        "squares-3-4-split-to-5",
        "squares-12-5-joined-to-13",
        "squares-6-6-7-split-to-11",
        "sierpinski9-to-square8",
        "three-square12-rect16x12cross-rect16x9",
        "cube4-cavity-to-7x4x2",
        "cubes-3-4-5-to-6",
        "tri-triangle8-to-rect4x8",
        "tri3-triangles-6-8-split-to-10",
        "tri3-hexagon2-to-parallelogram4x3",
        "hex-hexagon6-to-rhombus13x7",
        "disc21-to-square37",
        "torus512-to-slab16x8x4",
    ] {
        assert!(
            names.contains(&expected),
            "{expected} missing from {names:?}"
        );
    }
    for inst in m.instances() {
        let figures = inst.load_figures(m.root()).expect("instance loads");
        assert_eq!(figures.len(), inst.files.len(), "{}", inst.name);
        assert!(figures.iter().all(|f| f.lattice() == inst.lattice()));
        assert!(figures.iter().all(|f| Some(f.len()) == inst.area));
        // Every instance reconstructing a figure of the paper has its result.
        if inst.source.starts_with("paper") {
            assert!(paper_result(&inst.name).is_some(), "{}", inst.name);
        }
    }
    let joined = m.get("cubes-3-4-5-joined-to-6").expect("joined cubes");
    // 5 pieces kept beside it (solution-5.json), optimal (BENCHMARKS.md).
    assert_eq!(joined.reference, Some(5));
    assert_eq!(joined.paper_pieces, Some(6));
}

/// The best dissections kept beside an instance (`solution-N.json`, N its
/// piece count) are accepted by the independent checkers with N pieces,
/// and N is the manifest's reference count, at least its lower bound.
#[test]
fn the_kept_best_dissections_verify_and_meet_the_reference() {
    let m = Manifest::load(&repo::instances()).expect("instances/manifest.json");
    let mut kept = 0;
    for inst in m.instances() {
        let dir = m.root().join(&inst.name);
        for entry in std::fs::read_dir(&dir).unwrap() {
            let name = entry.unwrap().file_name().to_string_lossy().into_owned();
            let Some(n) = name
                .strip_prefix("solution-")
                .and_then(|r| r.strip_suffix(".json"))
            else {
                continue;
            };
            let n: usize = n.parse().expect("solution-N.json");
            let lattice = inst.lattice().to_string();
            assert_eq!(
                repo::assert_checked(&dir, &lattice, &name, &inst.files),
                n,
                "{}/{name}",
                inst.name
            );
            assert_eq!(inst.reference, Some(n), "{}", inst.name);
            assert!(inst.lower_bound.unwrap_or(1) <= n, "{}", inst.name);
            kept += 1;
        }
    }
    // sierpinski9 → 8² in 5 pieces (found by SAT) and the joined cubes in
    // 5 (found by `solve`), both optimal: no 4-piece dissection,
    // BENCHMARKS.md.
    assert!(kept >= 2);
    let s = m.get("sierpinski9-to-square8").unwrap();
    assert_eq!(
        (s.reference, s.lower_bound, s.paper_pieces),
        (Some(5), Some(5), Some(7))
    );
}

#[test]
fn the_projects_own_instances_load() {
    // A voxelized torus mesh (instances/make_torus.py) to a cuboid.
    let m = Manifest::load(&repo::instances()).expect("instances/manifest.json");
    let torus = m.get("torus512-to-slab16x8x4").expect("torus instance");
    let figures = torus.load_figures(m.root()).expect("torus loads");
    assert_eq!(torus.lattice(), LatticeKind::Cubic);
    assert!(figures.iter().all(|f| f.len() == 512));
    // One closed ring: connected, and the slab is a full 16x8x4 box.
    assert_eq!(figures[0].stats().components, 1);
    assert_eq!(figures[1].stats().max, [15, 7, 3]);
}

#[test]
fn manifest_json_error_names_file_line_and_column() {
    let path = Path::new("some/dir/manifest.json");
    let text = "[\n {\"name\": \"a\",\n  \"lattice\": square}\n]";
    let err = Manifest::parse(text, path).expect_err("bad JSON");
    let msg = err.to_string();
    assert!(
        matches!(err, BenchError::ManifestJson { line: 3, .. }),
        "{err:?}"
    );
    assert!(
        msg.starts_with("some/dir/manifest.json: line 3, column "),
        "{msg}"
    );
}

#[test]
fn manifest_entry_errors_name_the_instance() {
    let path = Path::new("m.json");
    let cases = [
        (
            r#"[{"name": "x", "lattice": "octagon", "files": ["a.txt"]}]"#,
            r#"m.json: instance "x" unknown lattice "octagon""#,
        ),
        (
            r#"[{"name": "y", "lattice": "square", "files": []}]"#,
            r#"m.json: instance "y" lists no figure files"#,
        ),
        (
            r#"[{"name": "z", "lattice": "square"}]"#,
            "m.json: line 1, column",
        ),
    ];
    for (text, want) in cases {
        let msg = Manifest::parse(text, path).expect_err(text).to_string();
        assert!(msg.starts_with(want), "{msg:?} should start with {want:?}");
    }
    let m = Manifest::parse(
        r#"[{"name": "a", "lattice": "square", "files": ["a.txt"]}]"#,
        path,
    )
    .expect("valid");
    let msg = m.get("b").expect_err("unknown").to_string();
    assert_eq!(msg, r#"m.json: no instance "b"; known: a"#);
}

#[test]
fn figure_errors_name_the_file_line_and_column() {
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::create_dir(dir.path().join("i")).expect("mkdir");
    std::fs::write(dir.path().join("i/a.txt"), "##\n#x\n").expect("write");
    std::fs::write(dir.path().join("i/b.txt"), "###\n").expect("write");
    std::fs::write(
        dir.path().join("manifest.json"),
        r#"[{"name": "i", "lattice": "square", "files": ["a.txt", "b.txt"], "area": 3}]"#,
    )
    .expect("write");
    let m = Manifest::load(dir.path()).expect("manifest");
    let msg = m.instances()[0]
        .load_figures(m.root())
        .expect_err("bad figure")
        .to_string();
    assert!(
        msg.contains("i/a.txt: line 2, column 2: unexpected character 'x'"),
        "{msg}"
    );

    std::fs::write(dir.path().join("i/a.txt"), "##\n").expect("write");
    let msg = m.instances()[0]
        .load_figures(m.root())
        .expect_err("wrong area")
        .to_string();
    assert!(
        msg.ends_with("i/a.txt: 2 cells, the manifest says 3"),
        "{msg}"
    );

    let msg = Manifest::load(&dir.path().join("nowhere"))
        .expect_err("missing")
        .to_string();
    assert!(msg.contains("nowhere/manifest.json: cannot read"), "{msg}");
}

// ------------------------------------------------------------------ scaler

#[test]
fn scaling_multiplies_cells_and_keeps_the_topology() {
    let cases = [
        (LatticeKind::Square, "###\n#.#\n###\n", 2),
        (LatticeKind::Square, "#.#\n##.\n", 2),
        (LatticeKind::Tri4, "C6\n3F\n", 2),
        (LatticeKind::Tri4, "1.4\n", 2),
        (LatticeKind::Cubic, "###\n#.#\n###\n\n###\n###\n###\n", 3),
    ];
    for (lattice, text, dim) in cases {
        let f = fig(lattice, text);
        let s1 = f.stats();
        for k in 1..=4u32 {
            let g = scale(&f, k).expect("scales");
            let s = g.stats();
            assert_eq!(g.len(), f.len() * (k as usize).pow(dim), "{text} k={k}");
            assert_eq!(s.components, s1.components, "{text} k={k}");
            assert_eq!(s.holes, s1.holes, "{text} k={k}");
            let ki = k as i32;
            for a in 0..dim as usize {
                assert_eq!(s.min[a], s1.min[a] * ki);
                assert_eq!(s.max[a], s1.max[a] * ki + ki - 1);
            }
        }
        assert_eq!(scale(&f, 1).expect("k = 1"), f);
    }
}

#[test]
fn scaling_draws_the_expected_figures() {
    let cases = [
        (
            LatticeKind::Square,
            "##\n#.\n",
            2,
            "####\n####\n##..\n##..\n",
        ),
        // Half squares below and above the `\` diagonal.
        (LatticeKind::Tri4, "C\n", 2, "C.\nFC\n"),
        (LatticeKind::Tri4, "3\n", 2, "3F\n.3\n"),
        // The top triangle alone; half squares of the `/` diagonal.
        (LatticeKind::Tri4, "1\n", 2, "39\n"),
        (LatticeKind::Tri4, "6\n", 3, "..6\n.6F\n6FF\n"),
        (
            LatticeKind::Cubic,
            "#\n\n#\n",
            2,
            "##\n##\n\n##\n##\n\n##\n##\n\n##\n##\n",
        ),
    ];
    for (lattice, text, k, want) in cases {
        let got = scale(&fig(lattice, text), k).expect("scales");
        assert_eq!(
            got,
            fig(lattice, want),
            "{lattice} {text:?} ×{k}:\n{}",
            format_figure(&got)
        );
    }
    assert!(matches!(
        scale(&square("#\n"), 0),
        Err(BenchError::ScaleFactor)
    ));
}

#[test]
fn a_scaled_dissection_keeps_its_piece_count() {
    // The 2×2 square and the 1×4 bar: 2 pieces at every scale.
    let a = square("##\n##\n");
    let b = square("####\n");
    let plan = Plan {
        seeds: vec![1, 2],
        options: quick(),
        time_limit_2d: Some(Duration::from_secs(60)),
        time_limit_3d: None,
        mode: Default::default(),
    };
    let mut seen = 0;
    let steps = plan
        .run_scaling(&[a.clone(), b.clone()], &[1, 2, 3], |_, _| seen += 1)
        .expect("runs");
    assert_eq!(seen, 6);
    assert_eq!(
        steps.iter().map(|s| s.cells).collect::<Vec<_>>(),
        [4, 16, 36]
    );
    for s in &steps {
        let figures = [scale(&a, s.k).expect("a"), scale(&b, s.k).expect("b")];
        for r in &s.runs {
            assert_eq!(r.error, None);
            assert_eq!(r.pieces, Some(2), "k = {}", s.k);
            let found = r.found.as_ref().expect("found");
            assert_eq!(
                verify_pieces(LatticeKind::Square, true, &figures, &found.pieces),
                Ok(2)
            );
            assert!(r.first_valid.expect("first valid") <= r.total);
        }
    }
}

// -------------------------------------------------------------------- runs

#[test]
fn a_run_is_verified_and_reproducible() {
    let a = square("###\n#..\n");
    let b = square("##\n##\n");
    let options = Options { seed: 7, ..quick() };
    let r1 = run_seed(&[a.clone(), b.clone()], &options, None);
    let r2 = run_seed(&[a.clone(), b.clone()], &options, None);
    assert_eq!(r1.error, None);
    assert_eq!(r1.pieces, Some(2));
    assert_eq!(r1.seed, 7);
    assert!(!r1.stopped);
    let found = r1.found.as_ref().expect("found");
    assert_eq!(
        verify_pieces(LatticeKind::Square, true, &[a, b], &found.pieces),
        Ok(2)
    );
    assert_eq!(r1.found, r2.found, "same seed, same dissection");
}

#[test]
fn the_time_limit_stops_a_run() {
    let m = Manifest::load(&repo::instances()).expect("instances/manifest.json");
    let inst = m.get("sierpinski9-to-square8").expect("instance");
    let figures = inst.load_figures(m.root()).expect("loads");
    let r = run_seed(&figures, &quick(), Some(Duration::from_millis(30)));
    assert!(r.stopped, "{r:?}");
    assert!(r.total < Duration::from_secs(10), "{r:?}");
    assert_eq!(r.error, None);
    if let Some(found) = &r.found {
        assert_eq!(
            verify_pieces(LatticeKind::Square, true, &figures, &found.pieces),
            Ok(found.piece_count())
        );
    }
}

#[test]
fn the_solver_refusing_figures_is_an_error_row() {
    let r = run_seed(&[square("##\n"), square("###\n")], &quick(), None);
    let e = r.error.expect("unequal areas");
    assert!(e.contains("different areas"), "{e}");
    assert_eq!(r.pieces, None);
}

// ------------------------------------------------------------------ report

#[test]
fn median_and_worst_count_a_missing_result_as_worst() {
    assert_eq!(median_worst::<u32>(&[]), None);
    assert_eq!(median_worst(&[Some(3)]), Some((Some(3), Some(3))));
    assert_eq!(
        median_worst(&[Some(3), None, Some(2)]),
        Some((Some(3), None))
    );
    assert_eq!(
        median_worst(&[Some(5), Some(2), Some(9)]),
        Some((Some(5), Some(9)))
    );
    // Even counts take the upper middle value.
    assert_eq!(median_worst(&[Some(1), Some(4)]), Some((Some(4), Some(4))));
    let s = Duration::from_secs;
    assert_eq!(growth_exponent(100, s(1), 400, s(4)), Some(1.0));
    assert_eq!(growth_exponent(100, s(2), 400, s(32)), Some(2.0));
    assert_eq!(growth_exponent(100, s(2), 100, s(3)), None);
}

fn seed_run(seed: u64, pieces: Option<usize>, first: Option<u64>, total: u64) -> SeedRun {
    SeedRun {
        seed,
        pieces,
        first_valid: first.map(Duration::from_millis),
        time_to_best: first.map(|f| Duration::from_millis(f * 2)),
        total: Duration::from_millis(total),
        cpu: Some(Duration::from_millis(total * 3 / 2)),
        variance: pieces.map(|p| p as f64 * 1.5),
        stopped: pieces.is_none(),
        lower_bound: Some(2),
        optimal: pieces == Some(2),
        explorations: 400 * seed as usize,
        last_level: (
            pieces.unwrap_or(6),
            Some(if pieces.is_some() { 0 } else { 8 }),
        ),
        error: None,
        found: None,
        peak_rss: Some((20 + 3 * seed) << 20),
        recording: None,
    }
}

fn sample_results() -> Vec<InstanceResult> {
    let mut broken = seed_run(2, None, None, 1_500);
    broken.error = Some("BUG: verification failed".to_string());
    vec![
        InstanceResult {
            name: "rect10x7-hole-to-square8".to_string(),
            lattice: LatticeKind::Square,
            cells: 64,
            figures: 2,
            reference: Some(2),
            paper: paper_result("rect10x7-hole-to-square8"),
            time_limit: Some(Duration::from_secs(300)),
            target: Some(10.0),
            runs: vec![
                seed_run(1, Some(2), Some(40), 40),
                seed_run(2, Some(2), Some(25), 31),
                seed_run(3, Some(3), Some(1_250), 12_500),
            ],
        },
        InstanceResult {
            name: "three-square12-rect16x12cross-rect16x9".to_string(),
            lattice: LatticeKind::Square,
            cells: 144,
            figures: 3,
            reference: Some(6),
            paper: paper_result("three-square12-rect16x12cross-rect16x9"),
            time_limit: Some(Duration::from_secs(300)),
            target: Some(60.0),
            runs: vec![seed_run(1, None, None, 300_000), broken],
        },
        InstanceResult {
            name: "cubes-3-4-5-joined-to-6".to_string(),
            lattice: LatticeKind::Cubic,
            cells: 216,
            figures: 2,
            reference: None,
            paper: paper_result("cubes-3-4-5-joined-to-6"),
            time_limit: Some(Duration::from_secs(600)),
            target: None,
            runs: vec![seed_run(1, Some(7), Some(123_456), 123_456)],
        },
    ]
}

fn sample_steps() -> Vec<ScaleStep> {
    vec![
        ScaleStep {
            k: 1,
            cells: 144,
            runs: vec![seed_run(1, Some(3), Some(500), 500)],
        },
        ScaleStep {
            k: 2,
            cells: 576,
            runs: vec![seed_run(1, Some(3), Some(2_000), 2_000)],
        },
        ScaleStep {
            k: 4,
            cells: 2304,
            runs: vec![seed_run(1, None, None, 60_000)],
        },
    ]
}

#[test]
fn the_target_needs_the_reference_count_and_the_time_at_the_median() {
    let mut r = sample_results();
    assert_eq!(r[0].target_verdict(), "< 10 s: met");
    assert_eq!(r[1].target_verdict(), "< 60 s: missed");
    assert_eq!(r[2].target_verdict(), "-");
    // Too slow at the median.
    r[0].runs[1].first_valid = Some(Duration::from_secs(11));
    assert_eq!(
        r[0].target_verdict(),
        "< 10 s: met",
        "one slow seed of three"
    );
    r[0].runs[0].first_valid = Some(Duration::from_secs(11));
    assert_eq!(r[0].target_verdict(), "< 10 s: missed");
    // Fast, but one piece too many at the median.
    let mut r = sample_results();
    r[0].runs[0].pieces = Some(3);
    assert_eq!(r[0].target_verdict(), "< 10 s: missed");
}

/// Compares `got` with `tests/golden/<name>`; `BLESS=1` rewrites it.
fn golden(name: &str, got: &str) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(name);
    if std::env::var_os("BLESS").is_some() {
        std::fs::create_dir_all(path.parent().expect("dir")).expect("mkdir");
        std::fs::write(&path, got).expect("write golden");
        return;
    }
    let want = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (run with BLESS=1 to create it)", path.display()));
    assert_eq!(
        got,
        want,
        "{} differs (BLESS=1 rewrites it)",
        path.display()
    );
}

#[test]
fn tables_match_their_golden_files() {
    let results = sample_results();
    let steps = sample_steps();
    for (style, ext) in [(Style::Text, "txt"), (Style::Markdown, "md")] {
        golden(&format!("suite.{ext}"), &suite_table(&results, style));
        golden(&format!("seeds.{ext}"), &seed_table(&results, style));
        golden(&format!("scaling.{ext}"), &scale_table(&steps, style));
    }
}

// -------------------------------------------------------------- end to end

#[test]
fn the_binary_runs_a_manifest_and_its_solutions_pass_the_checkers() {
    let dir = tempfile::tempdir().expect("temp dir");
    let root = dir.path().join("instances");
    std::fs::create_dir_all(root.join("l-to-bar")).expect("mkdir");
    std::fs::write(root.join("l-to-bar/a.txt"), "###\n#..\n").expect("write");
    std::fs::write(root.join("l-to-bar/b.txt"), "##\n##\n").expect("write");
    std::fs::write(
        root.join("manifest.json"),
        r#"[{"name": "l-to-bar", "lattice": "square", "reference": 2,
             "files": ["a.txt", "b.txt"], "area": 4}]"#,
    )
    .expect("write");
    let save = dir.path().join("out");
    let out = Command::new(env!("CARGO_BIN_EXE_dissect-bench"))
        .arg(&root)
        .args(["--seeds", "1,2", "--time-limit", "60", "--threads", "2"])
        .args(["--explorations", "24", "--keep", "6", "--iterations", "20"])
        .args(["--markdown", "--per-seed", "--save"])
        .arg(&save)
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stdout}\n{stderr}");
    assert!(
        stdout.contains("| l-to-bar | square | 4 | 2 | - | - | 2 / 2 / 2 | "),
        "{stdout}"
    );
    assert!(stdout.contains("| 2/2 |"), "{stdout}");
    assert!(stderr.contains("l-to-bar seed 2: 2 pieces"), "{stderr}");
    for seed in [1, 2] {
        let solution = save.join(format!("l-to-bar-seed{seed}.json"));
        let figures = [root.join("l-to-bar/a.txt"), root.join("l-to-bar/b.txt")];
        let n = repo::assert_checked(dir.path(), "square", &solution, &figures);
        assert_eq!(n, 2);
    }
}

#[test]
fn the_binary_reports_bad_input_with_exit_code_2() {
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::write(dir.path().join("manifest.json"), "[{]").expect("write");
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_dissect-bench"))
            .arg(dir.path())
            .args(args)
            .output()
            .expect("runs")
    };
    let out = run(&[]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("manifest.json: line 1, column 3:"),
        "{stderr}"
    );
    let out = run(&["--time-limit=-1"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--time-limit must be"));
}

#[test]
fn cpu_time_is_read_from_a_proc_stat_line() {
    // Fields 14 and 15 (utime, stime) are 250 and 50 ticks; the command
    // name holds a space and a parenthesis.
    let line = "4242 (my (bench) x) R 1 2 3 4 5 6 7 8 9 10 250 50 0 0 20 0 3 0 99";
    assert_eq!(
        dissect_bench::cpu::parse_stat_cpu(line),
        Some(Duration::from_secs(3))
    );
    assert_eq!(dissect_bench::cpu::parse_stat_cpu("1 (x) R 1 2"), None);
    if cfg!(target_os = "linux") {
        // Busy work advances the process's CPU time (within 10 s of wall
        // time even on a crowded machine).
        let before = dissect_bench::cpu::process_cpu_time().expect("/proc/self/stat");
        let start = std::time::Instant::now();
        let mut x = 0u64;
        let mut now = before;
        while now <= before && start.elapsed() < Duration::from_secs(10) {
            for _ in 0..100_000 {
                x = std::hint::black_box(x.wrapping_mul(6364136223846793005).wrapping_add(1));
            }
            now = dissect_bench::cpu::process_cpu_time().expect("/proc/self/stat");
        }
        assert!(now > before, "{before:?} -> {now:?}");
    }
}

// ---------------------------------------------------------------- schedule

#[test]
fn replays_count_the_waiting_at_batch_barriers() {
    use dissect_bench::schedule::{replay, replay_levels};
    // 4 explorations: one slow (3 s) and three of 1 s.
    let d = [3.0, 1.0, 1.0, 1.0];
    // One thread: no waiting whatever the barriers.
    let one = replay(&d, 2, 1);
    assert_eq!((one.makespan, one.work, one.waiting()), (6.0, 6.0, 0.0));
    // Two threads, batches of 2: {3, 1} then {1, 1}: 3 + 1 = 4 s, of 8
    // thread-seconds 6 are work.
    let batched = replay(&d, 2, 2);
    assert_eq!(batched.makespan, 4.0);
    assert!((batched.waiting() - 0.25).abs() < 1e-12);
    // Without barriers the second thread runs the three short ones while
    // the first runs the long one: 3 s, no waiting.
    let free = replay(&d, 0, 2);
    assert_eq!(free.makespan, 3.0);
    assert_eq!(free.waiting(), 0.0);
    // More threads than work: the slowest exploration bounds the makespan.
    assert_eq!(replay(&d, 0, 16).makespan, 3.0);
    assert_eq!(replay(&[], 16, 4).waiting(), 0.0);
    // Levels add up.
    let both = replay_levels(&[d.to_vec(), vec![2.0, 2.0]], 2, 2);
    assert_eq!((both.makespan, both.work), (6.0, 10.0));
}

#[test]
fn the_solvers_window_lets_threads_run_ahead_without_barriers() {
    use dissect_bench::schedule::{replay, replay_levels_window, replay_window};
    let d = [3.0, 1.0, 1.0, 1.0];
    // A window of 2 on 2 threads: exploration 2 may start only once 0 has
    // ended (at 3), though a thread is free at 1; 3 waits for 0 and 1:
    // both run from 3 to 4 s (without the window: 3 s).
    assert_eq!(replay_window(&d, 2, 2).makespan, 4.0);
    // A window as wide as the level is no barrier at all.
    assert_eq!(replay_window(&d, 4, 2).makespan, replay(&d, 0, 2).makespan);
    // A window of 1 is one exploration at a time.
    assert_eq!(replay_window(&d, 1, 16).makespan, 6.0);
    // Never slower than batches of the window's size.
    let long: Vec<f64> = (0..64).map(|i| 1.0 + (i * 7 % 5) as f64).collect();
    for t in [2, 4, 8, 16] {
        assert!(replay_window(&long, 8, t).makespan <= replay(&long, 8, t).makespan + 1e-9);
    }
    let both = replay_levels_window(&[d.to_vec(), vec![2.0, 2.0]], 4, 2);
    assert_eq!((both.makespan, both.work), (5.0, 10.0));
}

// -------------------------------------------------------------- peak RSS

#[test]
fn peak_rss_is_read_from_proc_status_and_can_be_reset() {
    let status = "Name:\tx\nVmPeak:\t  9000 kB\nVmHWM:\t   2048 kB\nVmRSS:\t 1024 kB\n";
    assert_eq!(dissect_bench::cpu::parse_status_hwm(status), Some(2 << 20));
    assert_eq!(dissect_bench::cpu::parse_status_hwm("VmHWM: 12 MB\n"), None);
    assert_eq!(dissect_bench::cpu::parse_status_hwm("VmRSS: 12 kB\n"), None);
    if cfg!(target_os = "linux") {
        // 64 MiB touched and freed: the peak covers it until a reset.
        let block = vec![1u8; 64 << 20];
        let touched = std::hint::black_box(&block).iter().step_by(4096).count();
        assert_eq!(touched, 16384);
        let with_block = dissect_bench::cpu::peak_rss().expect("VmHWM");
        assert!(with_block >= 64 << 20, "{with_block}");
        drop(block);
        assert!(dissect_bench::cpu::reset_peak_rss());
        let after = dissect_bench::cpu::peak_rss().expect("VmHWM");
        assert!(after + (32 << 20) < with_block, "{after} vs {with_block}");
        // A run reports its own peak.
        let a = square("###\n#..\n");
        let b = square("##\n##\n");
        let r = run_seed(&[a, b], &quick(), None);
        assert!(
            r.peak_rss.is_some_and(|p| p > 0 && p < with_block),
            "{:?}",
            r.peak_rss
        );
    }
}

// ------------------------------------------------------ recorded schedules

#[test]
fn the_threads_cpu_time_counts_its_own_work_only() {
    let Some(start) = dissect_bench::cpu::thread_cpu_time() else {
        return; // not on Linux: recordings fall back to wall time
    };
    // Another thread's work does not count.
    std::thread::spawn(|| {
        let t = std::time::Instant::now();
        while t.elapsed() < Duration::from_millis(50) {
            std::hint::black_box(0u64);
        }
    })
    .join()
    .expect("joins");
    let mid = dissect_bench::cpu::thread_cpu_time().expect("again");
    assert!(mid - start < Duration::from_millis(25), "{:?}", mid - start);
    // Its own does, to well under a millisecond.
    let mut x = 0u64;
    while dissect_bench::cpu::thread_cpu_time().expect("again") - mid < Duration::from_millis(30) {
        x = std::hint::black_box(x + 1);
    }
    let end = dissect_bench::cpu::thread_cpu_time().expect("again");
    assert!(end - mid >= Duration::from_millis(30) && end - mid < Duration::from_millis(31));
}

#[test]
fn the_replay_table_matches_its_golden_files() {
    use dissect_bench::report::replay_table;
    use dissect_bench::schedule::{Clock, RecordedLevel, Recording};
    // Level 1: one slow exploration per batch of 4; level 2: even work.
    let rec = Recording {
        clock: Clock::ThreadCpu,
        levels: vec![
            RecordedLevel {
                level: 1,
                seconds: vec![4.0, 1.0, 1.0, 1.0, 4.0, 1.0, 1.0, 1.0],
            },
            RecordedLevel {
                level: 2,
                seconds: vec![1.0; 8],
            },
        ],
    };
    assert_eq!((rec.explorations(), rec.work()), (16, 22.0));
    // The solver's window: whole batches, 4 explorations per thread, at
    // most 8 batches.
    use dissect_bench::schedule::window;
    assert_eq!(
        [
            window(16, 1),
            window(16, 4),
            window(16, 8),
            window(16, 16),
            window(16, 64)
        ],
        [16, 16, 32, 64, 128]
    );
    assert_eq!((window(4, 2), window(4, 16)), (8, 32));
    // 2 threads with barriers: level 1 is 4 + 4 s, level 2 is 2 + 2 s.
    // Without: level 1 is 6 s ({4, 1, 1} | {1, 1, 4} ... by list order:
    // 4 | 1 1 1 4 -> 4 vs 7, then 1 1 1 -> 7 vs 7), level 2 is 4 s.
    for (style, ext) in [(Style::Text, "txt"), (Style::Markdown, "md")] {
        golden(
            &format!("replay.{ext}"),
            &replay_table(&rec, 4, &[1, 2, 4, 16], style),
        );
    }
}

#[test]
fn a_recorded_run_times_every_exploration_it_counts() {
    use dissect_bench::run::{run_mode, Mode};
    use dissect_bench::schedule::replay_levels;
    let m = Manifest::load(&repo::instances()).expect("instances/manifest.json");
    let inst = m.get("rect10x7-hole-to-square8").expect("instance");
    let figures = inst.load_figures(m.root()).expect("loads");
    let options = Options {
        threads: 1,
        seed: 3,
        ..quick()
    };
    let mode = Mode {
        strategy: dissect_engine::Strategy::Paper,
        prove: false,
        record: true,
    };
    let r = run_mode(&figures, &options, mode, None);
    assert_eq!(r.error, None);
    let rec = r.recording.as_ref().expect("recorded");
    assert!(rec.explorations() > 0);
    // The run counts level 0 (are the figures congruent?) as one.
    assert_eq!(rec.explorations() + 1, r.explorations, "{rec:?}");
    // The paper's schedule: levels one after the other, from 1 pieces up.
    let levels: Vec<usize> = rec.levels.iter().map(|l| l.level).collect();
    assert_eq!(levels, (1..=levels.len()).collect::<Vec<_>>());
    assert!(rec
        .levels
        .iter()
        .flat_map(|l| &l.seconds)
        .all(|s| *s >= 0.0));
    // Exploration work is part of the run's time.
    let work = rec.work();
    assert!(work > 0.0);
    let bound = match rec.clock {
        dissect_bench::schedule::Clock::ThreadCpu => r.cpu.expect("cpu").as_secs_f64() + 0.05,
        dissect_bench::schedule::Clock::Wall => r.total.as_secs_f64(),
    };
    assert!(work <= bound, "{work} > {bound}");
    // One simulated thread runs it all back to back.
    let one = replay_levels(&rec.durations(), 16, 1);
    assert!((one.makespan - work).abs() < 1e-9);
    // Not recording leaves no recording.
    let plain = run_mode(
        &figures,
        &options,
        Mode {
            record: false,
            ..mode
        },
        None,
    );
    assert_eq!(plain.recording, None);
    assert_eq!(plain.found, r.found, "recording does not change the answer");
}

#[test]
fn the_binary_replays_recorded_runs() {
    let dir = tempfile::tempdir().expect("temp dir");
    let root = dir.path().join("instances");
    std::fs::create_dir_all(root.join("l-to-bar")).expect("mkdir");
    std::fs::write(root.join("l-to-bar/a.txt"), "###\n#..\n").expect("write");
    std::fs::write(root.join("l-to-bar/b.txt"), "##\n##\n").expect("write");
    std::fs::write(
        root.join("manifest.json"),
        r#"[{"name": "l-to-bar", "lattice": "square", "reference": 2,
             "files": ["a.txt", "b.txt"], "area": 4}]"#,
    )
    .expect("write");
    let run = |extra: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_dissect-bench"))
            .arg(&root)
            .args([
                "--seeds",
                "1",
                "--time-limit",
                "60",
                "--paper",
                "--no-prove",
            ])
            .args(["--explorations", "24", "--keep", "6", "--iterations", "20"])
            .args(extra)
            .output()
            .expect("runs")
    };
    let out = run(&["--replay"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    assert!(stdout.contains("threads 1;"), "{stdout}");
    assert!(
        stdout.contains("Schedule replay: l-to-bar seed 1 (levels 1, explorations 16, "),
        "{stdout}"
    );
    let rows: Vec<&str> = stdout
        .lines()
        .skip_while(|l| !l.starts_with("Schedule replay"))
        .skip(4)
        .take_while(|l| !l.is_empty())
        .collect();
    let firsts: Vec<&str> = rows
        .iter()
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert_eq!(firsts, ["1", "2", "4", "8", "16"], "{stdout}");
    // One thread: speed-up 1, no waiting.
    let one: Vec<&str> = rows[0].split_whitespace().collect();
    assert_eq!(
        (one[2], one[3], one[6], one[7]),
        ("1.00", "0.0", "1.00", "0.0"),
        "{stdout}"
    );
    // Recording needs one solver thread.
    let out = run(&["--replay", "--threads", "2"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("one solver thread"));
}

#[test]
fn the_binary_reads_the_repositorys_instances_by_default() {
    let out = Command::new(env!("CARGO_BIN_EXE_dissect-bench"))
        .current_dir(repo::root())
        .args(["--only", "rect10x7-hole-to-square8", "--seeds", "1"])
        .args(["--time-limit", "60", "--threads", "1"])
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stdout}\n{stderr}");
    assert!(stdout.contains("rect10x7-hole-to-square8"), "{stdout}");
}
