//! Puzzle runs through the engine: several different solutions with the
//! fewest pieces, ranked; the designer's constraints honoured by every
//! answer (each verified and checked), steering the search, and refused
//! with a typed error when they cannot hold.

use std::collections::HashSet;
use std::sync::atomic::AtomicBool;

use dissect_core::io::parse_figure;
use dissect_core::verify::verify_pieces;
use dissect_core::{Figure, LatticeKind};
use dissect_engine::{
    run, Constraints, EngineError, KeepRegions, OptionsError, Rank, Report, RunConfig, RunOptions,
    Strategy, TimeLimit,
};
use dissect_puzzle::scores::canonical;
use dissect_puzzle::Motions;

fn square(text: &str) -> Figure {
    parse_figure(text, LatticeKind::Square).expect("test figure")
}

fn config() -> RunConfig {
    RunConfig {
        explorations: 24,
        keep: 6,
        iterations: 20,
        threads: 2,
        ..RunConfig::default()
    }
}

fn solve(figures: &[Figure], config: RunConfig) -> Result<Report, EngineError> {
    let names: Vec<String> = (0..figures.len()).map(|i| format!("f{i}")).collect();
    let options = RunOptions::new(config).expect("valid options");
    run(figures, &names, &options, &AtomicBool::new(false), &())
}

/// Every solution verified; returns the first figure's piece areas of each.
fn checked(report: &Report, figures: &[Figure], constraints: &Constraints) -> Vec<Vec<usize>> {
    let motions = Motions::new(LatticeKind::Square, true);
    report
        .solutions
        .iter()
        .map(|s| {
            let pieces = s.dissection.pieces();
            assert_eq!(
                verify_pieces(LatticeKind::Square, true, figures, pieces),
                Ok(s.dissection.piece_count())
            );
            assert_eq!(constraints.check(&motions, pieces), vec![]);
            let mut a: Vec<usize> = pieces[0].iter().map(Vec::len).collect();
            a.sort();
            a
        })
        .collect()
}

#[test]
fn several_solutions_are_different_have_the_fewest_pieces_and_are_ranked() {
    // A 3×3 and a 4×4 square into a 5×5 square: 4 pieces at least.
    let figures = [
        square("###.....\n###.....\n###.####\n....####\n....####\n....####\n"),
        square("#####\n#####\n#####\n#####\n#####\n"),
    ];
    for rank in [Rank::Variance, Rank::Smallest] {
        let report = solve(
            &figures,
            RunConfig {
                solutions: 3,
                rank,
                time_limit: TimeLimit::new(30.0).unwrap(),
                ..config()
            },
        )
        .unwrap();
        assert_eq!(report.solutions.len(), 3, "{rank}");
        checked(&report, &figures, &Constraints::none());
        let motions = Motions::new(LatticeKind::Square, true);
        let forms: HashSet<_> = report
            .solutions
            .iter()
            .map(|s| canonical(&motions, &s.dissection.pieces()[0]))
            .collect();
        assert_eq!(forms.len(), 3, "different up to the motions");
        assert!(report.solutions.iter().all(|s| s.scores.pieces == 4));
        assert!(report
            .solutions
            .windows(2)
            .all(|w| rank.compare(&w[0].scores, &w[1].scores).is_le()));
        assert_eq!(report.best.as_ref(), Some(&report.solutions[0].dissection));
        let json: serde_json::Value =
            serde_json::from_str(&report.solution_json_at(2).unwrap()).unwrap();
        assert_eq!(json["rank"]["by"], rank.name());
        assert_eq!(json["rank"]["position"], 3);
        assert_eq!(json["pieces"], 4);
    }
}

#[test]
fn each_constraint_changes_the_answer_and_is_honoured() {
    // A 2×3 rectangle and a 1×6 bar: two 3-cell bars without constraints.
    let rect = square("###\n###\n");
    let bar = square("######\n");
    let figures = [rect.clone(), bar];
    let free = solve(&figures, config()).unwrap();
    assert_eq!(free.best.unwrap().piece_count(), 2);

    // The left column kept whole: three vertical dominoes.
    let keep = KeepRegions::parse("a..\na..\n", 0, std::slice::from_ref(&rect)).unwrap();
    let c = Constraints::none().with_keep(keep);
    let r = solve(
        &figures,
        RunConfig {
            constraints: c.clone(),
            ..config()
        },
    )
    .unwrap();
    assert_eq!(checked(&r, &figures, &c), vec![vec![2, 2, 2]]);

    // At most 2 cells a piece: 3 pieces; at least 4: none (6 = 4 + 2).
    let c = Constraints::none().with_sizes(None, Some(2));
    let r = solve(
        &figures,
        RunConfig {
            constraints: c.clone(),
            ..config()
        },
    )
    .unwrap();
    assert_eq!(checked(&r, &figures, &c), vec![vec![2, 2, 2]]);

    // The checkerboard: an L moved one column over changes colours, so it
    // takes 2 pieces instead of 1.
    let l = square("#.\n#.\n##\n");
    let m = square(".#.\n.#.\n.##\n");
    let figures = [l, m];
    assert_eq!(
        solve(&figures, config())
            .unwrap()
            .best
            .unwrap()
            .piece_count(),
        1
    );
    let c = Constraints::none().with_checkerboard(true);
    let r = solve(
        &figures,
        RunConfig {
            constraints: c.clone(),
            ..config()
        },
    )
    .unwrap();
    assert_eq!(checked(&r, &figures, &c).len(), 1);
    assert_eq!(r.best.unwrap().piece_count(), 2);
}

#[test]
fn the_heuristic_alone_honours_the_constraints() {
    // No exact side: the level search's own answers are judged.
    let rect = square("####\n####\n");
    let bar = square("########\n");
    let figures = [rect.clone(), bar];
    let keep = KeepRegions::parse("a...\na...\n", 0, std::slice::from_ref(&rect)).unwrap();
    let c = Constraints::none()
        .with_keep(keep)
        .with_sizes(Some(2), None);
    let r = solve(
        &figures,
        RunConfig {
            constraints: c.clone(),
            prove: false,
            ..config()
        },
    )
    .unwrap();
    let areas = checked(&r, &figures, &c);
    assert_eq!(areas.len(), 1);
    assert!(areas[0].iter().all(|&a| a >= 2), "{areas:?}");
}

#[test]
fn impossible_constraints_are_typed_errors() {
    let bad = RunOptions::new(RunConfig {
        constraints: Constraints::none().with_sizes(Some(4), Some(3)),
        ..config()
    })
    .unwrap_err();
    match bad {
        OptionsError::Constraints(e) => assert!(e.is_impossible()),
        e => panic!("{e}"),
    }
    assert!(RunOptions::new(RunConfig {
        solutions: 0,
        ..config()
    })
    .unwrap_err()
    .to_string()
    .contains("--solutions must be from 1 to"));
    // Checkerboard colours that differ between the figures.
    let figures = [square("#.#\n.#.\n"), square("###\n")];
    match solve(
        &figures,
        RunConfig {
            constraints: Constraints::none().with_checkerboard(true),
            ..config()
        },
    ) {
        Err(EngineError::Constraints(e)) => {
            assert!(e.is_impossible());
            assert!(e.to_string().contains("black cells"), "{e}");
        }
        r => panic!("{r:?}"),
    }
    // Exact alone under the constraints: a minimum under them.
    let figures = [square("###\n###\n"), square("######\n")];
    let c = Constraints::none().with_sizes(None, Some(2));
    let r = solve(
        &figures,
        RunConfig {
            strategy: Strategy::Exact,
            constraints: c.clone(),
            ..config()
        },
    )
    .unwrap();
    assert_eq!(checked(&r, &figures, &c), vec![vec![2, 2, 2]]);
    assert!(r.optimal);
}

#[test]
fn a_verified_answer_counts_its_assemblies_and_check_refuses_early() {
    // 2×3 into 1×6: two 3-cell bars, one way into each figure.
    let figures = [square("###\n###\n"), square("######\n")];
    let r = solve(&figures, config()).unwrap();
    let best = r.best.unwrap();
    let counts = best
        .assemblies(&figures, std::time::Duration::from_secs(5), None)
        .unwrap();
    assert_eq!(counts.len(), 2);
    for c in &counts {
        assert!(c.complete && c.unique(), "{c:?}");
        assert_eq!((c.tilings, c.up_to_symmetry), (1, 1));
    }
    // An L of three cells and one cell tile the 2×2 square in 4 ways, one
    // up to the square's symmetries.
    let sq = square("##\n##\n");
    let l = dissect_engine::Verified::new(
        LatticeKind::Square,
        true,
        vec!["a".into(), "b".into()],
        &[sq.clone(), sq.clone()],
        vec![
            vec![vec![[0, 0, 0], [0, 1, 0], [1, 1, 0]], vec![[1, 0, 0]]],
            vec![vec![[0, 0, 0], [0, 1, 0], [1, 1, 0]], vec![[1, 0, 0]]],
        ],
    )
    .unwrap();
    let c = &l
        .assemblies(
            std::slice::from_ref(&sq),
            std::time::Duration::from_secs(5),
            None,
        )
        .unwrap()[0];
    assert_eq!((c.tilings, c.up_to_symmetry, c.complete), (4, 1, true));
    // `check` refuses what `run` would refuse, before any search.
    let options = RunOptions::new(RunConfig {
        constraints: Constraints::none().with_checkerboard(true),
        ..config()
    })
    .unwrap();
    match dissect_engine::check(&[square("#.#\n.#.\n"), square("###\n")], &options) {
        Err(EngineError::Constraints(e)) => assert!(e.is_impossible(), "{e}"),
        r => panic!("{r:?}"),
    }
    assert!(dissect_engine::check(&figures, &options).is_ok());
}
