//! The exact mode against a brute-force enumeration of every partition of
//! small figures into connected pieces, on every lattice. Every dissection
//! the SAT search reports is checked by `dissect_core::verify`, and one by
//! the independent checkers (`tools/check_solution.py`, and the external
//! `verify.py` when present).

use std::collections::HashSet;
use std::sync::atomic::{AtomicBool, AtomicUsize};

use dissect_core::figure::components_of;
use dissect_core::io::parse_figure;
use dissect_core::lattice::Point;
use dissect_core::Dissection;
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_exact::{
    cheap_bound, search, ExactOptions, ExactOutcome, Mode, MotionEncoding, Reason,
};

fn figures(lattice: LatticeKind, texts: &[&str]) -> Vec<Figure> {
    texts
        .iter()
        .map(|t| parse_figure(t, lattice).expect("test figure parses"))
        .collect()
}

fn run(figs: &[Figure], mirror: bool, mode: Mode, max_pieces: Option<usize>) -> ExactOutcome {
    run_with(figs, mirror, mode, max_pieces, true)
}

fn run_with(
    figs: &[Figure],
    mirror: bool,
    mode: Mode,
    max_pieces: Option<usize>,
    eager_connectivity: bool,
) -> ExactOutcome {
    run_encoded(
        figs,
        mirror,
        (mode, max_pieces),
        eager_connectivity,
        MotionEncoding::Auto,
    )
}

fn run_encoded(
    figs: &[Figure],
    mirror: bool,
    (mode, max_pieces): (Mode, Option<usize>),
    eager_connectivity: bool,
    motion_encoding: MotionEncoding,
) -> ExactOutcome {
    let options = ExactOptions {
        mirror,
        mode,
        max_pieces,
        eager_connectivity,
        motion_encoding,
        ..ExactOptions::default()
    };
    let stop = AtomicBool::new(false);
    let upper = AtomicUsize::new(usize::MAX);
    search(figs, &options, &stop, &upper, &()).expect("search runs")
}

// ---------------------------------------------------------------------------
// Brute force: every partition of the first figure into connected pieces, in
// order of piece count; a partition works when every other figure can be
// tiled by its pieces (each once, under any allowed motion).

struct Brute {
    lattice: LatticeKind,
    syms: Vec<dissect_core::lattice::Symmetry>,
}

impl Brute {
    fn new(lattice: LatticeKind, mirror: bool) -> Brute {
        let l = lattice.lattice();
        Brute {
            lattice,
            syms: l.symmetries(mirror && l.supports_mirror()),
        }
    }

    fn is_translation(&self, t: Point) -> bool {
        let l = self.lattice.lattice();
        (0..3).all(|k| {
            if k < l.dim() {
                t[k].rem_euclid(l.modulus()) == 0
            } else {
                t[k] == 0
            }
        })
    }

    /// The fewest connected pieces, with one partition of the first figure.
    fn minimum(&self, figs: &[Figure]) -> (usize, Vec<Vec<Cell>>) {
        let cells = figs[0].cells();
        let n = cells.len();
        assert!(n <= 9, "brute force is for small figures");
        for k in 1..=n {
            let mut labels = vec![0usize; n];
            if let Some(p) = self.partitions(figs, &mut labels, 0, 0, k) {
                return (k, p);
            }
        }
        unreachable!("single cells always work")
    }

    /// Restricted growth strings with exactly `k` labels.
    fn partitions(
        &self,
        figs: &[Figure],
        labels: &mut Vec<usize>,
        i: usize,
        used: usize,
        k: usize,
    ) -> Option<Vec<Vec<Cell>>> {
        let n = labels.len();
        if n - i < k - used {
            return None;
        }
        if i == n {
            let cells = figs[0].cells();
            let pieces: Vec<Vec<Cell>> = (0..k)
                .map(|p| {
                    (0..n)
                        .filter(|&c| labels[c] == p)
                        .map(|c| cells[c])
                        .collect()
                })
                .collect();
            let connected = pieces
                .iter()
                .all(|p| components_of(self.lattice, p).len() == 1);
            let works = connected && figs[1..].iter().all(|f| self.tiles(f, &pieces));
            return works.then_some(pieces);
        }
        for l in 0..=used.min(k - 1) {
            labels[i] = l;
            let next = if l == used { used + 1 } else { used };
            if let Some(p) = self.partitions(figs, labels, i + 1, next, k) {
                return Some(p);
            }
        }
        None
    }

    fn tiles(&self, fig: &Figure, pieces: &[Vec<Cell>]) -> bool {
        let l = self.lattice.lattice();
        let target: Vec<Point> = fig.cells().iter().map(|c| l.to_point(*c)).collect();
        let shapes: Vec<Vec<Point>> = pieces
            .iter()
            .map(|p| p.iter().map(|c| l.to_point(*c)).collect())
            .collect();
        let mut free: HashSet<Point> = target.iter().copied().collect();
        let mut used = vec![false; shapes.len()];
        self.place(&mut free, &shapes, &mut used)
    }

    fn place(&self, free: &mut HashSet<Point>, shapes: &[Vec<Point>], used: &mut [bool]) -> bool {
        let Some(&first) = free.iter().min() else {
            return true;
        };
        for s in 0..shapes.len() {
            if used[s] {
                continue;
            }
            for g in &self.syms {
                let img: Vec<Point> = shapes[s].iter().map(|p| g.apply(*p)).collect();
                for anchor in &img {
                    let t = first - anchor;
                    if !self.is_translation(t) {
                        continue;
                    }
                    let moved: Vec<Point> = img.iter().map(|p| p + t).collect();
                    if moved.iter().all(|p| free.contains(p)) {
                        for p in &moved {
                            free.remove(p);
                        }
                        used[s] = true;
                        if self.place(free, shapes, used) {
                            return true;
                        }
                        used[s] = false;
                        for p in &moved {
                            free.insert(*p);
                        }
                    }
                }
            }
        }
        false
    }
}

/// The exact answer agrees with brute force; the lower bound proved by SAT
/// below it is exactly the brute-force minimum; the cheap bound is below it.
fn check(lattice: LatticeKind, mirror: bool, texts: &[&str]) -> usize {
    check_with(lattice, mirror, texts, true)
}

fn check_with(lattice: LatticeKind, mirror: bool, texts: &[&str], eager: bool) -> usize {
    check_encoded(lattice, mirror, texts, eager, MotionEncoding::Auto)
}

fn check_encoded(
    lattice: LatticeKind,
    mirror: bool,
    texts: &[&str],
    eager: bool,
    style: MotionEncoding,
) -> usize {
    let figs = figures(lattice, texts);
    let (brute, partition) = Brute::new(lattice, mirror).minimum(&figs);
    assert!(
        components_of(lattice, &partition[0]).len() == 1,
        "brute force returns connected pieces"
    );

    let cheap = cheap_bound(&figs, mirror).expect("valid figures");
    assert!(
        cheap.value <= brute,
        "cheap bound {cheap} exceeds the minimum {brute}"
    );

    let exact = run_encoded(&figs, mirror, (Mode::Minimum, None), eager, style);
    let found = exact
        .found
        .clone()
        .expect("the exact search finds a dissection");
    let count = dissect_core::verify::verify_pieces(lattice, mirror, &figs, &found)
        .expect("the SAT dissection is valid");
    assert_eq!(count, brute, "SAT minimum vs brute force for {texts:?}");
    assert!(exact.optimal(), "a minimum found by SAT is proved optimal");
    assert_eq!(exact.lower_bound.value, brute);

    if brute > 1 {
        let bound = run_encoded(
            &figs,
            mirror,
            (Mode::LowerBound, Some(brute - 1)),
            eager,
            style,
        );
        assert_eq!(
            bound.lower_bound.value, brute,
            "the bound proved below the minimum is the minimum for {texts:?}"
        );
        assert!(bound.found.is_none());
    }
    brute
}

#[test]
fn square_figures_match_brute_force() {
    let s = LatticeKind::Square;
    assert_eq!(check(s, true, &["###\n#..", "##\n##"]), 2);
    assert_eq!(check(s, true, &["####", "##\n##"]), 2);
    assert_eq!(check(s, true, &["#.#\n###", "#####"]), 3);
    assert_eq!(check(s, true, &["###\n###", "######"]), 2);
    assert_eq!(check(s, true, &["##..\n.##.\n..##", "###\n###"]), 2);
    assert_eq!(check(s, true, &["###\n#.#\n###", "####\n####"]), 2);
    assert_eq!(check(s, true, &["####\n####", "##\n##\n##\n##"]), 1);
}

#[test]
fn lazy_connectivity_cuts_match_brute_force() {
    let s = LatticeKind::Square;
    assert_eq!(check_with(s, true, &["#.#\n###", "#####"], false), 3);
    assert_eq!(
        check_with(s, true, &["###\n#.#\n###", "####\n####"], false),
        2
    );
    assert_eq!(
        check_with(s, true, &["##..\n.##.\n..##", "###\n###"], false),
        2
    );
    check_with(LatticeKind::Tri4, true, &["FF", "6C\n39"], false);
    check_with(
        LatticeKind::Cubic,
        false,
        &["###\n#..\n\n##.\n...", "###\n###"],
        false,
    );
}

/// The shift chain (a symmetry and one shift per axis, moved through level
/// variables) proves and finds exactly what brute force says, on square,
/// tri4 (translations of modulus 2) and cubic figures, with two and three
/// figures, mirror images on and off, eager and lazy connectivity.
#[test]
fn shift_encoding_matches_brute_force() {
    let shifts = MotionEncoding::Shifts;
    let s = LatticeKind::Square;
    let square: [(&[&str], usize); 6] = [
        (&["###\n#..", "##\n##"], 2),
        (&["#.#\n###", "#####"], 3),
        (&["###\n###", "######"], 2),
        (&["##..\n.##.\n..##", "###\n###"], 2),
        (&["###\n#.#\n###", "####\n####"], 2),
        (&["####", "##\n##", "#..\n###"], 2),
    ];
    for (texts, want) in square {
        for eager in [true, false] {
            assert_eq!(
                check_encoded(s, true, texts, eager, shifts),
                want,
                "{texts:?}"
            );
        }
    }
    assert_eq!(
        check_encoded(s, true, &["##.\n.##", ".##\n##."], true, shifts),
        1
    );
    assert_eq!(
        check_encoded(s, false, &["##.\n.##", ".##\n##."], true, shifts),
        2
    );
    let t = LatticeKind::Tri4;
    check_encoded(t, true, &["FF", "6C\n39"], true, shifts);
    check_encoded(t, false, &["F", "3C"], true, shifts);
    let c = LatticeKind::Cubic;
    let two = ["##\n##\n\n##\n##", "####\n####"];
    assert_eq!(check_encoded(c, false, &two, true, shifts), 2);
    check_encoded(
        c,
        false,
        &["###\n#..\n\n##.\n...", "###\n###"],
        false,
        shifts,
    );
}

#[test]
fn components_force_pieces() {
    let s = LatticeKind::Square;
    assert_eq!(check(s, true, &["#.#.#", "###"]), 3);
    let figs = figures(s, &["#.#.#", "###"]);
    let b = cheap_bound(&figs, true).unwrap();
    assert_eq!(b.value, 3);
    assert!(matches!(
        b.reason,
        Reason::Components { .. } | Reason::Incompatible { .. }
    ));
}

#[test]
fn mirror_matters() {
    let s = LatticeKind::Square;
    // S and Z tetrominoes: one piece when it may be turned over.
    assert_eq!(check(s, true, &["##.\n.##", ".##\n##."]), 1);
    assert_eq!(check(s, false, &["##.\n.##", ".##\n##."]), 2);
}

#[test]
fn tri4_figures_match_brute_force() {
    let t = LatticeKind::Tri4;
    // A 2x1 rectangle and a diamond of 8 triangles.
    check(t, true, &["FF", "6C\n39"]);
    // A unit square and a parallelogram of two half squares.
    check(t, true, &["F", "3C"]);
    check(t, false, &["F", "3C"]);
}

#[test]
fn cubic_figures_match_brute_force() {
    let c = LatticeKind::Cubic;
    assert_eq!(check(c, false, &["##\n##\n\n##\n##", "####\n####"]), 2);
    check(c, false, &["##\n#.\n\n#.\n..", "####"]);
    check(c, false, &["###\n#..\n\n##.\n...", "###\n###"]);
}

#[test]
fn three_figures_match_brute_force() {
    let s = LatticeKind::Square;
    check(s, true, &["####", "##\n##", "#..\n###"]);
    check(s, true, &["###\n#..", "##\n##", ".#.\n###"]);
}

#[test]
fn corners_of_a_square_force_four_pieces() {
    // 3² + 4² = 5²: the corners of the 5x5 square fit in neither small one,
    // so they need 4 pieces, and SAT finds 4.
    let figs = figures(
        LatticeKind::Square,
        &[
            "####..###\n####..###\n####..###\n####.....",
            "#####\n#####\n#####\n#####\n#####",
        ],
    );
    let b = cheap_bound(&figs, true).unwrap();
    assert_eq!(b.value, 4);
    let Reason::Incompatible { figure, cells } = &b.reason else {
        panic!("expected the corner argument, got {b}");
    };
    assert_eq!(*figure, 1);
    let mut corners = cells.clone();
    corners.sort();
    assert_eq!(corners, vec![[0, 0, 0], [0, 4, 0], [4, 0, 0], [4, 4, 0]]);
    let exact = run(&figs, true, Mode::Minimum, None);
    let found = exact.found.clone().expect("4 pieces exist");
    assert_eq!(
        dissect_core::verify::verify_pieces(LatticeKind::Square, true, &figs, &found),
        Ok(4)
    );
    assert!(exact.optimal());
}

#[test]
fn sat_refutes_two_pieces_for_a_rectangle_with_a_hole() {
    let figs = figures(
        LatticeKind::Square,
        &[
            "###############\n###############\n###############\n####...########\n####...########\n\
             ###############\n###############\n###############\n###############\n###############",
            &"############\n".repeat(12),
        ],
    );
    let out = run(&figs, true, Mode::LowerBound, Some(2));
    assert_eq!(out.lower_bound.value, 3);
    assert!(matches!(
        out.lower_bound.reason,
        Reason::Sat { refuted: 2, .. }
    ));
}

#[test]
fn unequal_areas_are_an_error() {
    let figs = figures(LatticeKind::Square, &["###", "##"]);
    let options = ExactOptions::default();
    let r = search(
        &figs,
        &options,
        &AtomicBool::new(false),
        &AtomicUsize::new(usize::MAX),
        &(),
    );
    assert!(r.unwrap_err().to_string().contains("different areas"));
}

#[test]
fn a_raised_stop_flag_ends_the_search_with_what_is_proved() {
    let figs = figures(LatticeKind::Square, &["###\n#..", "##\n##"]);
    let r = search(
        &figs,
        &ExactOptions::default(),
        &AtomicBool::new(true),
        &AtomicUsize::new(usize::MAX),
        &(),
    )
    .unwrap();
    assert!(r.stopped);
    assert!(r.found.is_none());
    assert_eq!(r.lower_bound.value, 2);
}

#[test]
fn the_independent_checkers_accept_a_sat_dissection() {
    let texts = ["###\n#.#\n###", "####\n####"];
    let figs = figures(LatticeKind::Square, &texts);
    let exact = run(&figs, true, Mode::Minimum, None);
    let pieces = exact.found.expect("found");
    let dir = tempfile::tempdir().unwrap();
    let mut paths = Vec::new();
    for (i, t) in texts.iter().enumerate() {
        let p = dir.path().join(format!("f{i}.txt"));
        std::fs::write(&p, t).unwrap();
        paths.push(p);
    }
    let d = Dissection::new(
        LatticeKind::Square,
        true,
        vec!["f0.txt".into(), "f1.txt".into()],
        pieces,
    )
    .unwrap();
    let sol = dir.path().join("s.json");
    std::fs::write(&sol, d.to_file(Default::default()).to_json()).unwrap();
    assert_eq!(
        dissect_testkit::repo::assert_checked(dir.path(), "square", &sol, &paths),
        2
    );
}

/// Counts the connectivity events of a search.
#[derive(Default)]
struct SplitModels(std::sync::Mutex<usize>);

impl dissect_exact::ExactObserver for SplitModels {
    fn on_event(&self, event: &dissect_exact::ExactEvent) {
        if matches!(
            event,
            dissect_exact::ExactEvent::Cuts { .. }
                | dissect_exact::ExactEvent::ConnectivityEncoded { .. }
        ) {
            *self.0.lock().unwrap() += 1;
        }
    }
}

#[test]
fn split_models_are_repaired_both_ways() {
    // The relaxation has 2-piece models with split pieces; connectivity
    // (eager encoding or lazy cuts) refutes them, and 3 pieces exist.
    let figs = figures(
        LatticeKind::Square,
        &[
            "######\n#.##.#\n######\n#.##.#",
            "#####\n#####\n#####\n#####",
        ],
    );
    for eager in [true, false] {
        let options = ExactOptions {
            mode: Mode::LowerBound,
            max_pieces: Some(2),
            eager_connectivity: eager,
            ..ExactOptions::default()
        };
        let seen = SplitModels::default();
        let out = search(
            &figs,
            &options,
            &AtomicBool::new(false),
            &AtomicUsize::new(usize::MAX),
            &seen,
        )
        .unwrap();
        assert_eq!(out.lower_bound.value, 3, "eager: {eager}");
        assert!(*seen.0.lock().unwrap() > 0, "a split model was met");
        let exact = run_with(&figs, true, Mode::Minimum, None, eager);
        let found = exact.found.clone().expect("3 pieces exist");
        assert_eq!(
            dissect_core::verify::verify_pieces(LatticeKind::Square, true, &figs, &found),
            Ok(3)
        );
        assert!(exact.optimal());
    }
}

/// The corner bound holds at every size: sums of cubes over the full
/// graph's 600 cells (729 and 8,000 voxels) get the 8 corners of the large
/// cube, with the cells they name pairwise too far apart for any piece that
/// fits in a smaller cube, and a figure's 3 components still count.
#[test]
fn the_corner_bound_holds_for_large_sums_of_cubes() {
    // Each instance with the side of its largest small cube.
    for (name, small) in [("cubes-1-6-8-to-9", 8), ("cubes-7-14-17-to-20", 17)] {
        let figs: Vec<Figure> = ["a.txt", "b.txt"]
            .iter()
            .map(|f| {
                let text = std::fs::read_to_string(dissect_testkit::repo::instance_file(name, f))
                    .expect("instance");
                parse_figure(&text, LatticeKind::Cubic).expect("figure")
            })
            .collect();
        let bound = cheap_bound(&figs, true).expect("valid figures");
        assert_eq!(bound.value, 8, "{name}: {bound}");
        let Reason::Incompatible { figure: 1, cells } = &bound.reason else {
            panic!("{name}: {bound}");
        };
        // Two cells of one small cube differ by less than its side on
        // every axis.
        let largest = small - 1;
        for (i, a) in cells.iter().enumerate() {
            for b in &cells[i + 1..] {
                let spread = (0..3).map(|d| (a[d] - b[d]).abs()).max().unwrap();
                assert!(spread > largest, "{name}: {a:?} and {b:?} fit one piece");
            }
        }
    }
}

/// The lower bound proved below the brute-force minimum, with the given
/// symmetry breaking and cube threads.
fn bound_with(
    lattice: LatticeKind,
    mirror: bool,
    texts: &[&str],
    (source_symmetries, cube_threads): (bool, usize),
) -> (usize, usize) {
    let figs = figures(lattice, texts);
    let (brute, _) = Brute::new(lattice, mirror).minimum(&figs);
    let run = |mode, max_pieces| {
        let options = ExactOptions {
            mirror,
            mode,
            max_pieces,
            source_symmetries,
            cube_threads,
            ..ExactOptions::default()
        };
        search(
            &figs,
            &options,
            &AtomicBool::new(false),
            &AtomicUsize::new(usize::MAX),
            &(),
        )
        .expect("search runs")
    };
    let found = run(Mode::Minimum, None);
    let pieces = found.found.expect("a dissection");
    let count = dissect_core::verify::verify_pieces(lattice, mirror, &figs, &pieces)
        .expect("the SAT dissection is valid");
    assert_eq!(count, brute, "{texts:?}: SAT minimum vs brute force");
    if brute > 1 {
        let bound = run(Mode::LowerBound, Some(brute - 1));
        assert!(bound.found.is_none());
        return (brute, bound.lower_bound.value);
    }
    (brute, 1)
}

/// Figures with symmetries of their own (the reference figure's
/// symmetries that fix its anchors are broken on top of the second
/// figure's): UNSAT with the breaking exactly when without it, and both
/// as brute force says.
#[test]
fn source_symmetry_breaking_matches_brute_force() {
    let s = LatticeKind::Square;
    let cases: [&[&str]; 6] = [
        &["###\n#.#\n###", "####\n####"],
        &[".#.\n###\n.#.", "#####"],
        &["###\n###\n###", "#########"],
        &["##\n##", "####"],
        &["#.#\n###", "#####"],
        &["##.\n###\n.##", "###\n###\n#.."],
    ];
    for texts in cases {
        for mirror in [true, false] {
            let on = bound_with(s, mirror, texts, (true, 1));
            let off = bound_with(s, mirror, texts, (false, 1));
            assert_eq!(on, off, "{texts:?} mirror {mirror}");
            assert_eq!(on.0, on.1, "{texts:?}: the bound is the minimum");
        }
    }
    let c = LatticeKind::Cubic;
    let cube = ["##\n##\n\n##\n##", "####\n####"];
    assert_eq!(bound_with(c, false, &cube, (true, 1)), (2, 2));
}

/// Cube-and-conquer on two threads: the same minimum and bound as one
/// solver and brute force.
#[test]
fn cube_and_conquer_matches_brute_force() {
    let s = LatticeKind::Square;
    let cases: [&[&str]; 5] = [
        &["###\n#..", "##\n##"],
        &["#.#\n###", "#####"],
        &["###\n#.#\n###", "####\n####"],
        &["##..\n.##.\n..##", "###\n###"],
        &["####", "##\n##", "#..\n###"],
    ];
    for texts in cases {
        let (brute, bound) = bound_with(s, true, texts, (true, 2));
        assert_eq!(brute, bound, "{texts:?}");
    }
    let c = LatticeKind::Cubic;
    let two = ["##\n##\n\n##\n##", "####\n####"];
    assert_eq!(bound_with(c, false, &two, (true, 2)), (2, 2));
}

/// A model of a DIMACS CNF (its true literals, every variable listed with
/// its sign), or `None` when it is unsatisfiable (batsat, the search's own
/// backend, on the text alone, as another solver would see it).
fn model(dimacs: &str) -> Option<Vec<i32>> {
    use batsat::{lbool, Lit, SolverInterface};
    let mut solver = batsat::BasicSolver::default();
    let vars: usize = dimacs.split_whitespace().nth(2).unwrap().parse().unwrap();
    for v in 0..vars {
        solver.var_of_int(v as u32);
    }
    for line in dimacs.lines().filter(|l| !l.starts_with(['p', 'c'])) {
        let mut clause: Vec<Lit> = line
            .split_whitespace()
            .map(|t| t.parse::<i32>().unwrap())
            .take_while(|&l| l != 0)
            .map(|l| Lit::new(solver.var_of_int(l.unsigned_abs() - 1), l > 0))
            .collect();
        solver.add_clause_reuse(&mut clause);
    }
    (solver.solve_limited(&[]) == lbool::TRUE).then(|| {
        (1..=vars as i32)
            .map(|v| {
                let var = solver.var_of_int(v as u32 - 1);
                if solver.value_var(var) == lbool::TRUE {
                    v
                } else {
                    -v
                }
            })
            .collect()
    })
}

fn satisfiable(dimacs: &str) -> bool {
    model(dimacs).is_some()
}

#[test]
fn the_connected_dimacs_settles_what_the_relaxation_cannot() {
    // The figures of split_models_are_repaired_both_ways: the relaxation
    // for 2 pieces has models with split pieces; with the connectivity
    // encoding it has none, and 3 connected pieces exist.
    let figs = figures(
        LatticeKind::Square,
        &[
            "######\n#.##.#\n######\n#.##.#",
            "#####\n#####\n#####\n#####",
        ],
    );
    let relaxed = dissect_exact::dimacs(&figs, true, 2).unwrap();
    assert!(
        satisfiable(&relaxed.text),
        "the relaxation has a split model"
    );
    let max = dissect_exact::DEFAULT_MAX_ENCODING_BYTES;
    let two = dissect_exact::dimacs_connected(&figs, true, 2, max).unwrap();
    assert!(two.clauses > relaxed.clauses && two.vars > relaxed.vars);
    assert!(two
        .text
        .starts_with(&format!("p cnf {} {}\n", two.vars, two.clauses)));
    assert!(!satisfiable(&two.text), "no 2 connected pieces");
    let three = dissect_exact::dimacs_connected(&figs, true, 3, max).unwrap();
    assert!(satisfiable(&three.text), "3 connected pieces exist");
    // Refused past the cap, the connectivity encoding counted: a cap the
    // relaxation fits under and the connected formula does not.
    let fits = |cap: u64| dissect_exact::dimacs_within(&figs, true, 2, cap).is_ok();
    let (mut low, mut cap) = (1u64, 1u64 << 32);
    while low < cap {
        let mid = (low + cap) / 2;
        if fits(mid) {
            cap = mid;
        } else {
            low = mid + 1;
        }
    }
    assert!(fits(cap) && !fits(cap - 1));
    assert!(matches!(
        dissect_exact::dimacs_connected(&figs, true, 2, cap),
        Err(dissect_exact::ExactError::TooLarge { .. })
    ));
}

#[test]
fn a_model_from_another_solver_decodes_into_a_verified_dissection() {
    // The figures of split_models_are_repaired_both_ways: 3 connected
    // pieces, and the relaxation for 2 has split models.
    let figs = figures(
        LatticeKind::Square,
        &[
            "######\n#.##.#\n######\n#.##.#",
            "#####\n#####\n#####\n#####",
        ],
    );
    let max = dissect_exact::DEFAULT_MAX_ENCODING_BYTES;
    let three = dissect_exact::dimacs_connected(&figs, true, 3, max).unwrap();
    let m = model(&three.text).expect("3 connected pieces exist");
    let pieces = dissect_exact::decode_model(&figs, true, 3, &m).expect("a dissection");
    assert_eq!(
        dissect_core::verify::verify_pieces(LatticeKind::Square, true, &figs, &pieces),
        Ok(pieces[0].len())
    );
    assert!(pieces[0].len() <= 3);
    // Only the true literals count: the same model without its negatives.
    let positives: Vec<i32> = m.iter().copied().filter(|&l| l > 0).collect();
    assert_eq!(
        dissect_exact::decode_model(&figs, true, 3, &positives),
        Ok(pieces)
    );
    // A split model of the relaxation is no dissection, nor is nothing.
    let relaxed = dissect_exact::dimacs(&figs, true, 2).unwrap();
    let split = model(&relaxed.text).expect("a split model");
    assert!(matches!(
        dissect_exact::decode_model(&figs, true, 2, &split),
        Err(dissect_exact::ExactError::Model(_))
    ));
    assert!(matches!(
        dissect_exact::decode_model(&figs, true, 3, &[]),
        Err(dissect_exact::ExactError::Model(_))
    ));
}
