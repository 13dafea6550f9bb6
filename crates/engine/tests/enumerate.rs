//! `dissect_engine::enumerate`: every dissection `Verified`, classes with
//! their sizes, `unique`, `rank`, the time limit and the stop flag.

use std::sync::atomic::AtomicBool;

use dissect_core::io::parse_figure;
use dissect_core::{Figure, LatticeKind};
use dissect_engine::{enumerate, EnumerateConfig, Rank, TimeLimit};

fn figures(texts: &[&str]) -> Vec<Figure> {
    texts
        .iter()
        .map(|t| parse_figure(t, LatticeKind::Square).expect("figure"))
        .collect()
}

fn names() -> Vec<String> {
    vec!["a".into(), "b".into()]
}

#[test]
fn every_dissection_is_verified_and_the_classes_add_up() {
    let figs = figures(&["####\n####\n####\n####", "########\n########"]);
    let config = EnumerateConfig {
        mirror: true,
        pieces: Some(3),
        ..EnumerateConfig::default()
    };
    let stop = AtomicBool::new(false);
    let r = enumerate(&figs, &names(), &config, &stop, &()).expect("runs");
    assert!(r.complete && !r.minimum);
    assert_eq!((r.dissections.len(), r.classes.len()), (178, 27));
    assert_eq!(r.classes.iter().map(|c| c.size).sum::<usize>(), 178);
    for d in &r.dissections {
        assert_eq!(d.piece_count(), 3);
        dissect_core::verify::verify(d.dissection(), &figs).expect("valid");
    }
    // --unique: the classes whose pieces tile both figures one way.
    let unique = enumerate(
        &figs,
        &names(),
        &EnumerateConfig {
            unique: true,
            rank: Some(Rank::Smallest),
            ..config.clone()
        },
        &stop,
        &(),
    )
    .expect("runs");
    assert_eq!(unique.before_unique, Some((178, 27)));
    assert_eq!((unique.dissections.len(), unique.classes.len()), (36, 6));
    let smallest: Vec<usize> = unique.classes.iter().map(|c| c.scores.smallest).collect();
    assert!(smallest.windows(2).all(|w| w[0] >= w[1]), "{smallest:?}");
    assert!(unique
        .classes
        .iter()
        .all(|c| c.scores.assemblies == Some(2)));
}

#[test]
fn the_minimum_is_proved_and_limits_are_honoured() {
    let figs = figures(&["###\n###", "######"]);
    let stop = AtomicBool::new(false);
    let config = EnumerateConfig {
        mirror: true,
        ..EnumerateConfig::default()
    };
    let r = enumerate(&figs, &names(), &config, &stop, &()).expect("runs");
    assert!(r.complete && r.minimum);
    assert_eq!((r.pieces, r.dissections.len(), r.classes.len()), (2, 1, 1));
    let past = EnumerateConfig {
        time_limit: TimeLimit::new(0.0).expect("a limit"),
        ..config.clone()
    };
    assert!(
        !enumerate(&figs, &names(), &past, &stop, &())
            .expect("runs")
            .complete
    );
    let raised = AtomicBool::new(true);
    assert!(
        !enumerate(&figs, &names(), &config, &raised, &())
            .expect("runs")
            .complete
    );
    let bad = EnumerateConfig {
        time_limit: Some(-1.0),
        ..config
    };
    assert!(matches!(
        enumerate(&figs, &names(), &bad, &stop, &()),
        Err(EnumerateError::Options(_))
    ));
}
