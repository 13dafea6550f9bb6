//! "All solutions": every minimum dissection of the studio's figures
//! ([`dissect_engine::enumerate`], as `dissect enumerate` counts them), run
//! as a solve job (`"enumerate": true` in `POST /api/solve`), with its
//! count so far in the job's snapshot and the classes in its result.
//!
//! Only small figures are enumerated ([`MAX_CELLS`]); the result lists the
//! first [`MAX_LISTED`] classes (each its first dissection, verified by the
//! engine) and counts all of them.

use dissect_engine::{EnumerationReport, Scores};
use serde::Serialize;
use serde_json::{json, Map, Value};

/// The most cells of a figure this server enumerates.
pub const MAX_CELLS: usize = 144;

/// The most classes a result lists (all are counted).
pub const MAX_LISTED: usize = 200;

/// The count so far of a running enumeration, as the snapshot shows it.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Progress {
    /// The piece count being enumerated (the minimum once proved).
    pub pieces: usize,
    /// Whether that count is the proved minimum.
    pub minimum: bool,
    /// Dissections found so far.
    pub dissections: usize,
    /// Their classes up to the first figure's symmetries.
    pub classes: usize,
}

/// What the result says of the whole enumeration: `{"pieces", "minimum",
/// "dissections", "classes", "complete", "listed", "limit"}`.
fn summary(report: &EnumerationReport) -> Value {
    json!({
        "pieces": report.pieces,
        "minimum": report.minimum,
        "dissections": report.dissections.len(),
        "classes": report.classes.len(),
        "complete": report.complete,
        "listed": report.classes.len().min(MAX_LISTED),
        "limit": report.limit.as_ref().map(|l| format!("{l:?}")),
    })
}

/// The result of a finished enumeration:
///
/// ```json
/// {"found": true, "stopped": false, "pieces": 3, "lower_bound": 3, "optimal": true,
///  "seconds": 1.2, "enumeration": {"pieces": 3, "minimum": true, "dissections": 16,
///  "classes": 2, "complete": true, "listed": 2, "limit": null},
///  "solution": {..}, "solution_text": "..",
///  "solutions": [{"position": 1, "class_size": 8, "pieces": 3, "areas": [..],
///                 "area_variance": 0.0, "scores": {..}, "assemblies": [], "unique": false,
///                 "solution": {..}, "solution_text": ".."}, ..]}
/// ```
///
/// `stopped` is true when the list is not known to be complete (the time
/// limit, Stop, or a size limit); `solution` is the first class's file.
pub fn result_json(report: &EnumerationReport) -> Value {
    let seconds = (report.seconds * 1000.0).round() / 1000.0;
    let enumeration = summary(report);
    let solutions: Vec<Value> = report
        .classes
        .iter()
        .take(MAX_LISTED)
        .enumerate()
        .map(|(i, class)| class_json(report, i, &class.dissection, class.size, &class.scores))
        .collect();
    let mut v = json!({
        "found": !solutions.is_empty(),
        "stopped": !report.complete,
        "pieces": report.pieces,
        "lower_bound": report.lower_bound.value,
        "optimal": report.minimum && !solutions.is_empty(),
        "seconds": seconds,
        "enumeration": enumeration,
    });
    if let Some(first) = solutions.first() {
        v["solution"] = first["solution"].clone();
        v["solution_text"] = first["solution_text"].clone();
        v["areas"] = first["areas"].clone();
        v["area_variance"] = first["area_variance"].clone();
    } else {
        // What the studio shows for a run that found nothing.
        v["last_pieces"] = json!(report.pieces);
        v["best_mismatch"] = Value::Null;
    }
    v["solutions"] = Value::Array(solutions);
    v
}

/// One listed class: its first dissection's file (with an `enumeration`
/// key: the class, its size, the totals) and scores.
fn class_json(
    report: &EnumerationReport,
    i: usize,
    d: &dissect_engine::Verified,
    size: usize,
    scores: &Scores,
) -> Value {
    let mut extra = Map::new();
    extra.insert("pieces".into(), json!(d.piece_count()));
    extra.insert("areas".into(), json!(d.areas()));
    extra.insert("optimal".into(), json!(report.minimum));
    extra.insert(
        "enumeration".into(),
        json!({
            "class": i + 1,
            "classes": report.classes.len(),
            "dissections_in_class": size,
            "dissections": report.dissections.len(),
            "complete": report.complete,
            "minimum": report.minimum,
        }),
    );
    extra.insert(
        "scores".into(),
        serde_json::to_value(scores).unwrap_or_default(),
    );
    let text = d.dissection().to_file(extra).to_json();
    let file: Value = serde_json::from_str(&text).unwrap_or(Value::Null);
    json!({
        "position": i + 1,
        "class_size": size,
        "pieces": d.piece_count(),
        "areas": d.areas(),
        "area_variance": d.variance(),
        "scores": scores,
        "assemblies": [],
        "unique": false,
        "solution": file,
        "solution_text": text,
    })
}
