//! The HTTP routes: the page, the JSON API and the solve event stream.
//!
//! | route | what |
//! |---|---|
//! | `GET /` and `GET /<asset>` | the page |
//! | `GET /api/info` | version, lattices, limits, export formats |
//! | `GET /api/lattices` | how the page draws each lattice's cells (tiles, neighbours) |
//! | `GET /api/examples` | the shipped examples with their figure texts |
//! | `POST /api/figures` | read figures (cells or text): cells, text, counts |
//! | `POST /api/solve` | start a solve: `202 {"id": ..}` (with `"enumerate": true`: every minimum dissection, counted) |
//! | `GET /api/solve/{id}` | its progress and, once done, its result |
//! | `GET /api/solve/{id}/events` | the same as server-sent events |
//! | `POST /api/solve/{id}/stop` | stop it; the best dissection so far is kept |
//! | `POST /api/export/{format}` | a download made from a solution (svg, png, cut-sheet, stl, ldraw) |
//! | `POST /api/rasterize?lattice=L&cells=N` | a picture (body) made into a figure of N cells |
//!
//! See `crates/web/openapi.yaml` for the request and response shapes.

use std::convert::Infallible;
use std::sync::Arc;
use std::time::Duration;

use axum::body::Bytes;
use axum::extract::rejection::{BytesRejection, QueryRejection};
use axum::extract::{DefaultBodyLimit, Path, Query, State};
use axum::http::{header, StatusCode, Uri};
use axum::response::sse::{Event as SseEvent, KeepAlive, Sse};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::{Json, Router};
use dissect_engine::{EngineError, OptionsError, Rank, RunConfig, RunOptions, TimeLimit};
use futures_util::Stream;
use serde::de::DeserializeOwned;
use serde::Deserialize;
use serde_json::{json, Value};

use crate::error::ApiError;
use crate::figures::{self, FigureInput};
use crate::jobs::{Job, Jobs, Request, State as JobState};
use crate::limits::Limits;
use crate::security::{self, Access};
use crate::{assets, examples, export, lattices, picture, puzzle};

/// The largest request body, in bytes.
pub const MAX_BODY: usize = 8 * 1024 * 1024;

/// What every handler shares.
#[derive(Clone)]
pub struct AppState {
    pub(crate) limits: Arc<Limits>,
    pub(crate) jobs: Arc<Jobs>,
    /// Permits for pictures made at once (rasterizations, downloads).
    pub(crate) pictures: Arc<tokio::sync::Semaphore>,
    pub(crate) access: Arc<Access>,
}

impl AppState {
    /// A fresh state with no job.
    pub fn new(limits: Limits, access: Access) -> AppState {
        AppState {
            jobs: Arc::new(Jobs::new(limits.max_concurrent_solves())),
            pictures: Arc::new(tokio::sync::Semaphore::new(
                limits.max_concurrent_pictures(),
            )),
            limits: Arc::new(limits),
            access: Arc::new(access),
        }
    }

    /// A permit to make a picture, or 429 when as many are being made as allowed.
    fn picture_permit(&self) -> Result<tokio::sync::OwnedSemaphorePermit, ApiError> {
        Arc::clone(&self.pictures)
            .try_acquire_owned()
            .map_err(|_| ApiError::PicturesBusy(self.limits.max_concurrent_pictures()))
    }
}

/// The whole application for the given limits, open to anyone who reaches
/// it (for loopback servers).
pub fn router(limits: Limits) -> Router {
    router_with_state(AppState::new(limits, Access::open()))
}

/// The whole application for the given limits and access rule.
pub fn router_with_access(limits: Limits, access: Access) -> Router {
    router_with_state(AppState::new(limits, access))
}

pub(crate) fn router_with_state(state: AppState) -> Router {
    Router::new()
        .route("/api/info", get(info))
        .route("/api/lattices", get(list_lattices))
        .route("/api/examples", get(list_examples))
        .route("/api/figures", post(read_figures))
        .route("/api/solve", post(start_solve))
        .route("/api/solve/{id}", get(solve_status))
        .route("/api/solve/{id}/events", get(solve_events))
        .route("/api/solve/{id}/stop", post(stop_solve))
        .route("/api/export/{format}", post(export_file))
        .route("/api/rasterize", post(rasterize_picture))
        .fallback(static_or_404)
        .method_not_allowed_fallback(|| async { ApiError::MethodNotAllowed })
        .layer(DefaultBodyLimit::max(MAX_BODY))
        .layer(axum::middleware::from_fn_with_state(
            Arc::clone(&state.access),
            security::guard,
        ))
        .layer(tower_http::catch_panic::CatchPanicLayer::custom(
            |_: Box<dyn std::any::Any + Send>| {
                ApiError::Internal("the request made the server fail".into()).into_response()
            },
        ))
        .with_state(state)
}

/// Reads a JSON body into `T`, with clear errors for every way it can fail.
fn parse<T: DeserializeOwned>(body: Result<Bytes, BytesRejection>) -> Result<T, ApiError> {
    let body = body.map_err(|e| {
        if e.status() == StatusCode::PAYLOAD_TOO_LARGE {
            ApiError::TooLarge(format!("request body over {MAX_BODY} bytes"))
        } else {
            ApiError::BadValue(format!("cannot read the request body: {e}"))
        }
    })?;
    if body.iter().all(|b| b.is_ascii_whitespace()) {
        return Err(ApiError::BadJson {
            line: 1,
            column: 0,
            message: "the request body is empty; a JSON object is expected".into(),
        });
    }
    serde_json::from_slice(&body).map_err(|e| ApiError::from_json(&e))
}

async fn info(State(s): State<AppState>) -> Json<Value> {
    let l = &s.limits;
    Json(json!({
        "name": "dissect",
        "version": env!("CARGO_PKG_VERSION"),
        "lattices": dissect_core::LatticeKind::ALL.map(|k| k.name()),
        "limits": {
            "max_cells": l.max_cells(),
            "max_extent": l.max_extent(),
            "max_figures": l.max_figures(),
            "max_concurrent_solves": l.max_concurrent_solves(),
            "max_time_limit": l.max_time_limit(),
            "max_body_bytes": MAX_BODY,
        },
        "exports": export::FORMATS,
    }))
}

async fn list_lattices() -> Json<Value> {
    Json(lattices::list())
}

async fn list_examples() -> Json<Value> {
    Json(examples::list())
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FiguresRequest {
    lattice: String,
    figures: Vec<FigureInput>,
}

async fn read_figures(
    State(s): State<AppState>,
    body: Result<Bytes, BytesRejection>,
) -> Result<Json<Value>, ApiError> {
    let req: FiguresRequest = parse(body)?;
    let lattice = figures::lattice(&req.lattice)?;
    let figs = figures::read_all(&req.figures, lattice, &s.limits)?;
    let counts: Vec<usize> = figs.iter().map(|f| f.len()).collect();
    let described: Vec<Value> = req
        .figures
        .iter()
        .zip(&figs)
        .enumerate()
        .map(|(i, (inp, f))| figures::describe(&figures::name_of(inp, i), f))
        .collect();
    Ok(Json(json!({
        "lattice": lattice.name(),
        "figures": described,
        "equal_areas": counts.windows(2).all(|w| w[0] == w[1]),
    })))
}

/// The body of `POST /api/solve`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SolveRequest {
    lattice: String,
    figures: Vec<FigureInput>,
    #[serde(default)]
    mirror: Option<bool>,
    #[serde(default)]
    seed: Option<u64>,
    #[serde(default)]
    area_weight: Option<f64>,
    #[serde(default)]
    time_limit: Option<f64>,
    #[serde(default)]
    explorations: Option<usize>,
    #[serde(default)]
    max_pieces: Option<usize>,
    /// How many different solutions with the fewest pieces (`--solutions`).
    #[serde(default)]
    solutions: Option<usize>,
    /// How they are ranked (`--rank`).
    #[serde(default)]
    rank: Option<String>,
    /// Keep-whole regions (`--keep N:REGIONS.txt`).
    #[serde(default)]
    keep: Option<Vec<puzzle::KeepInput>>,
    /// `--min-piece`.
    #[serde(default)]
    min_piece: Option<usize>,
    /// `--max-piece`.
    #[serde(default)]
    max_piece: Option<usize>,
    /// `--checkerboard`.
    #[serde(default)]
    checkerboard: Option<bool>,
    /// `--symmetry-weight`.
    #[serde(default)]
    symmetry_weight: Option<f64>,
    /// `--assemblable`.
    #[serde(default)]
    assemblable: Option<bool>,
    /// `--min-level`.
    #[serde(default)]
    min_level: Option<usize>,
    /// "All solutions": every dissection with the fewest pieces, counted
    /// (`dissect enumerate`), instead of a solve.
    #[serde(default)]
    enumerate: Option<bool>,
}

impl SolveRequest {
    /// The settings an enumeration does not take, by their API names.
    fn solve_only_settings(&self) -> Vec<&'static str> {
        let set = [
            ("seed", self.seed.is_some()),
            ("explorations", self.explorations.is_some()),
            ("max_pieces", self.max_pieces.is_some()),
            ("solutions", self.solutions.is_some_and(|n| n != 1)),
            ("keep", self.keep.as_ref().is_some_and(|k| !k.is_empty())),
            ("min_piece", self.min_piece.is_some()),
            ("max_piece", self.max_piece.is_some()),
            ("checkerboard", self.checkerboard == Some(true)),
            ("assemblable", self.assemblable == Some(true)),
            ("min_level", self.min_level.is_some()),
            (
                "symmetry_weight",
                self.symmetry_weight.is_some_and(|w| w != 0.0),
            ),
        ];
        set.iter().filter(|(_, on)| *on).map(|(n, _)| *n).collect()
    }
}

/// The time limit of a request: more than 0 and at most the server's.
fn time_limit_of(requested: Option<f64>, limits: &Limits) -> Result<TimeLimit, ApiError> {
    let max_t = limits.max_time_limit();
    let seconds = requested.unwrap_or(max_t);
    // The engine's rule (NaN and negatives refused), then the server's cap.
    TimeLimit::new(seconds)
        .ok()
        .filter(|l| seconds > 0.0 && l.seconds().is_some_and(|t| t <= max_t))
        .ok_or_else(|| {
            ApiError::BadValue(format!(
                "time_limit must be more than 0 and at most {max_t} seconds, got {seconds}"
            ))
        })
}

/// `POST /api/solve` with `"enumerate": true`: every dissection with the
/// fewest pieces ([`crate::enumerate`]), on figures of at most
/// [`crate::enumerate::MAX_CELLS`] cells, without the solve's settings.
fn start_enumerate(
    s: &AppState,
    req: SolveRequest,
    lattice: dissect_core::LatticeKind,
    figs: Vec<dissect_core::Figure>,
) -> Result<Arc<Job>, ApiError> {
    let refused = req.solve_only_settings();
    if !refused.is_empty() {
        return Err(ApiError::BadValue(format!(
            "enumerate counts every dissection with the fewest pieces and takes no {}",
            refused.join(", ")
        )));
    }
    let cells = figs[0].len();
    if cells > crate::enumerate::MAX_CELLS {
        return Err(ApiError::BadValue(format!(
            "enumerate is for small figures: at most {} cells on this server, the figures have {cells}",
            crate::enumerate::MAX_CELLS
        )));
    }
    let rank = req
        .rank
        .as_deref()
        .map(str::parse::<Rank>)
        .transpose()
        .map_err(|e| ApiError::BadValue(format!("rank: {e}")))?;
    let config = dissect_engine::EnumerateConfig {
        mirror: req.mirror.unwrap_or(RunConfig::default().mirror),
        pieces: None,
        time_limit: time_limit_of(req.time_limit, &s.limits)?,
        rank,
        unique: false,
    };
    let names = req
        .figures
        .iter()
        .enumerate()
        .map(|(i, f)| figures::name_of(f, i))
        .collect();
    s.jobs.start(Request {
        lattice,
        figures: figs,
        names,
        // Not used by an enumeration (its settings are `config`).
        options: RunOptions::new(RunConfig::default())
            .map_err(|e| ApiError::Internal(e.to_string()))?,
        enumerate: Some(config),
    })
}

async fn start_solve(
    State(s): State<AppState>,
    body: Result<Bytes, BytesRejection>,
) -> Result<Response, ApiError> {
    let req: SolveRequest = parse(body)?;
    let lattice = figures::lattice(&req.lattice)?;
    if req.figures.len() < 2 {
        return Err(ApiError::BadValue(format!(
            "a dissection needs at least two figures, got {}",
            req.figures.len()
        )));
    }
    let as_given = figures::read_all_as_given(&req.figures, lattice, &s.limits)?;
    let figs: Vec<_> = as_given.iter().map(figures::normalized).collect();
    figures::check_equal_areas(&req.figures, &figs)?;
    if req.enumerate == Some(true) {
        let job = start_enumerate(&s, req, lattice, figs)?;
        return Ok(accepted(job.id()));
    }
    let time_limit = time_limit_of(req.time_limit, &s.limits)?;
    let explorations = req
        .explorations
        .unwrap_or(RunConfig::default().explorations);
    if explorations > 10_000 {
        return Err(ApiError::BadValue(format!(
            "explorations must be from 1 to 10000 on this server, got {explorations}"
        )));
    }
    let solutions = req.solutions.unwrap_or(1);
    if solutions > puzzle::MAX_SOLUTIONS {
        return Err(ApiError::BadValue(format!(
            "solutions must be from 1 to {} on this server, got {solutions}",
            puzzle::MAX_SOLUTIONS
        )));
    }
    let rank = match &req.rank {
        None => Rank::default(),
        Some(r) => r
            .parse::<Rank>()
            .map_err(|e| ApiError::BadValue(format!("rank: {e}")))?,
    };
    let constraints = puzzle::constraints(
        &puzzle::ConstraintInput {
            keep: req.keep.clone().unwrap_or_default(),
            min_piece: req.min_piece,
            max_piece: req.max_piece,
            checkerboard: req.checkerboard.unwrap_or(false),
            symmetry_weight: req.symmetry_weight,
            assemblable: req.assemblable.unwrap_or(false),
            min_level: req.min_level,
        },
        lattice,
        &as_given,
        &figs,
        &s.limits,
    )?;
    // Every other rule on the settings is the engine's.
    let defaults = RunConfig::default();
    let options = RunOptions::new(RunConfig {
        mirror: req.mirror.unwrap_or(defaults.mirror),
        seed: req.seed.unwrap_or(defaults.seed),
        threads: s.limits.threads(),
        area_weight: req.area_weight.unwrap_or(defaults.area_weight),
        explorations,
        max_pieces: req.max_pieces,
        time_limit,
        solutions,
        rank,
        constraints,
        ..defaults
    })
    .map_err(|e| match e {
        OptionsError::Constraints(c) => puzzle::constraint_error(&c),
        e => ApiError::BadValue(api_name(&e.to_string())),
    })?;
    // What the run would refuse at its start (constraints that do not fit
    // these figures or cannot hold for them) is refused here, at once.
    dissect_engine::check(&figs, &options).map_err(|e| match e {
        EngineError::Constraints(c) => puzzle::constraint_error(&c),
        e => ApiError::BadFigure(e.to_string()),
    })?;
    let names = req
        .figures
        .iter()
        .enumerate()
        .map(|(i, f)| figures::name_of(f, i))
        .collect();
    let job = s.jobs.start(Request {
        lattice,
        figures: figs,
        names,
        options,
        enumerate: None,
    })?;
    Ok(accepted(job.id()))
}

/// `202 {"id", "status", "events", "stop"}` for a started job.
fn accepted(id: u64) -> Response {
    (
        StatusCode::ACCEPTED,
        [(header::LOCATION, format!("/api/solve/{id}"))],
        Json(json!({
            "id": id,
            "status": format!("/api/solve/{id}"),
            "events": format!("/api/solve/{id}/events"),
            "stop": format!("/api/solve/{id}/stop"),
        })),
    )
        .into_response()
}

fn job(s: &AppState, id: &str) -> Result<Arc<Job>, ApiError> {
    id.parse::<u64>()
        .ok()
        .and_then(|n| s.jobs.get(n))
        .ok_or_else(|| ApiError::NotFound(format!("no solve with id {id:?}")))
}

async fn solve_status(
    State(s): State<AppState>,
    Path(id): Path<String>,
) -> Result<Json<Value>, ApiError> {
    let job = job(&s, &id)?;
    Ok(Json(json!(job.snapshot())))
}

async fn stop_solve(
    State(s): State<AppState>,
    Path(id): Path<String>,
) -> Result<Json<Value>, ApiError> {
    let job = job(&s, &id)?;
    job.stop();
    Ok(Json(json!(job.snapshot())))
}

/// Server-sent events: `progress` while running (at most ten a second, at
/// least one a second), then one `done` event with the result, then the end.
async fn solve_events(
    State(s): State<AppState>,
    Path(id): Path<String>,
) -> Result<Sse<impl Stream<Item = Result<SseEvent, Infallible>>>, ApiError> {
    let job = job(&s, &id)?;
    let rx = job.subscribe();
    let stream = futures_util::stream::unfold(
        (job, rx, true, false),
        |(job, mut rx, first, ended)| async move {
            if ended {
                return None;
            }
            if !first {
                tokio::time::sleep(Duration::from_millis(100)).await;
                if let Ok(Err(_)) = tokio::time::timeout(Duration::from_secs(1), rx.changed()).await
                {
                    // The job is gone: report where it was and end.
                    let snap = job.snapshot();
                    let ev = SseEvent::default()
                        .event("done")
                        .data(json!(snap).to_string());
                    return Some((Ok(ev), (job, rx, false, true)));
                }
            }
            rx.borrow_and_update();
            let snap = job.snapshot();
            let done = snap.state != JobState::Running;
            let ev = SseEvent::default()
                .event(if done { "done" } else { "progress" })
                .data(json!(snap).to_string());
            Some((Ok(ev), (job, rx, false, done)))
        },
    );
    Ok(Sse::new(stream).keep_alive(KeepAlive::default()))
}

async fn static_or_404(uri: Uri) -> Response {
    let path = uri.path();
    if !path.starts_with("/api/") {
        if let Some((ty, bytes)) = assets::find(path.trim_start_matches('/')) {
            return (
                [
                    (header::CONTENT_TYPE, ty),
                    (header::CACHE_CONTROL, "no-cache"),
                ],
                bytes,
            )
                .into_response();
        }
    }
    ApiError::NotFound(format!("nothing at {path}")).into_response()
}

async fn export_file(
    State(s): State<AppState>,
    Path(format): Path<String>,
    body: Result<Bytes, BytesRejection>,
) -> Result<Response, ApiError> {
    let req: export::ExportRequest = parse(body)?;
    let limits = Arc::clone(&s.limits);
    let permit = s.picture_permit()?;
    // Drawing and meshing take CPU time: off the async workers.
    let file = tokio::task::spawn_blocking(move || {
        let _permit = permit;
        export::export(&format, &req, &limits)
    })
    .await
    .map_err(|e| ApiError::Internal(format!("the exporter failed: {e}")))??;
    Ok((
        [
            (header::CONTENT_TYPE, file.content_type.to_string()),
            (
                header::CONTENT_DISPOSITION,
                format!("attachment; filename=\"{}\"", file.name),
            ),
        ],
        file.bytes,
    )
        .into_response())
}

async fn rasterize_picture(
    State(s): State<AppState>,
    query: Result<Query<picture::RasterQuery>, QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> Result<Json<Value>, ApiError> {
    let Query(q) =
        query.map_err(|e| ApiError::BadValue(format!("bad query: {}", e.body_text())))?;
    let bytes = body.map_err(|e| {
        if e.status() == StatusCode::PAYLOAD_TOO_LARGE {
            ApiError::TooLarge(format!("request body over {MAX_BODY} bytes"))
        } else {
            ApiError::BadValue(format!("cannot read the request body: {e}"))
        }
    })?;
    let limits = Arc::clone(&s.limits);
    let permit = s.picture_permit()?;
    let v = tokio::task::spawn_blocking(move || {
        let _permit = permit;
        picture::rasterize_picture(&q, &bytes, &limits)
    })
    .await
    .map_err(|e| ApiError::Internal(format!("the rasterizer failed: {e}")))??;
    Ok(Json(v))
}

/// An engine message about a setting (`--area-weight must ...`) with the
/// setting named as the API spells it (`area_weight must ...`).
fn api_name(message: &str) -> String {
    let m = message.strip_prefix("--").unwrap_or(message);
    match m.split_once(' ') {
        Some((name, rest)) => format!("{} {rest}", name.replace('-', "_")),
        None => m.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use axum::body::Body;
    use axum::http::{Request, StatusCode};
    use tower::ServiceExt;

    use super::*;

    /// Past the limit on pictures made at once, a rasterization gets 429
    /// at once, and works again when a slot frees.
    #[tokio::test]
    async fn pictures_past_the_limit_get_429() {
        let limits = Limits::default().with_max_concurrent_pictures(1);
        let state = AppState::new(limits, Access::open());
        let app = router_with_state(state.clone());
        let request = || {
            Request::post("/api/rasterize?lattice=square&cells=4")
                .header("host", "127.0.0.1:7878")
                .header("content-type", "image/svg+xml")
                .body(Body::from(
                    r#"<svg xmlns="http://www.w3.org/2000/svg" width="20" height="20"><rect width="20" height="20"/></svg>"#,
                ))
                .unwrap()
        };
        let held = state.picture_permit().expect("a free slot");
        let r = app.clone().oneshot(request()).await.unwrap();
        assert_eq!(r.status(), StatusCode::TOO_MANY_REQUESTS);
        drop(held);
        let r = app.oneshot(request()).await.unwrap();
        assert_eq!(r.status(), StatusCode::OK);
    }
}
