//! API errors: every failure leaves the server as an HTTP status with a JSON
//! body `{"error": {"code": "...", "message": "..."}}` (plus `details` where
//! it helps, e.g. each figure's cell count).

use axum::http::StatusCode;
use axum::response::{IntoResponse, Response};
use serde_json::{json, Value};

/// Occurs when a request cannot be served.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ApiError {
    /// Occurs when the body is not JSON, or not JSON of the expected shape.
    #[error("invalid JSON at line {line}, column {column}: {message}")]
    BadJson {
        /// 1-based line of the body.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What serde said.
        message: String,
    },
    /// Occurs when a lattice name is not `square`, `tri4` or `cubic`.
    #[error("{0}")]
    UnknownLattice(String),
    /// Occurs when a field has a value out of its range (a negative seed, a
    /// NaN area weight, a cell of the wrong form, ...).
    #[error("{0}")]
    BadValue(String),
    /// Occurs when a figure (file text or cell list) is not a valid figure;
    /// the message names the figure (and line/column for texts).
    #[error("{0}")]
    BadFigure(String),
    /// Occurs when the designer's constraints of a solve are malformed
    /// (a region name that is not a letter, a cell outside its figure, a
    /// size bound of 0, a checkerboard on a lattice without one, ...).
    #[error("{0}")]
    BadConstraints(String),
    /// Occurs when the constraints are well formed but cannot all hold for
    /// these figures (a smallest piece larger than the largest, a region
    /// larger than `max_piece`, figures with different numbers of black
    /// cells under `checkerboard`, ...).
    #[error("{0}")]
    ImpossibleConstraints(String),
    /// Occurs when a solution (for a download) cannot be read or drawn.
    #[error("{0}")]
    BadSolution(String),
    /// Occurs when the figures do not have equal areas.
    #[error("figures have different areas: {}", list(.0))]
    UnequalAreas(Vec<(String, usize)>),
    /// Occurs when a request is larger than the server's limits.
    #[error("{0}")]
    TooLarge(String),
    /// Occurs when the server is already running as many solves as allowed.
    #[error("{0} solve(s) are already running; stop one or try again later")]
    Busy(usize),
    /// Occurs when the server is already making as many pictures
    /// (rasterizations, picture downloads) as allowed.
    #[error("{0} picture(s) are already being made; try again in a moment")]
    PicturesBusy(usize),
    /// Occurs when a server started with an access token gets a request
    /// without it.
    #[error("{0}")]
    Unauthorized(String),
    /// Occurs when a path names no route or no solve.
    #[error("{0}")]
    NotFound(String),
    /// Occurs when a request names the server by a host name other than
    /// `localhost` (a DNS rebinding attempt by another web site).
    #[error("{0}")]
    Forbidden(String),
    /// Occurs when a JSON route gets a body of another content type.
    #[error("{0}")]
    UnsupportedMediaType(String),
    /// Occurs when a route exists but not for this HTTP method.
    #[error("method not allowed here")]
    MethodNotAllowed,
    /// Occurs when a request's head and body did not arrive within the
    /// server's request timeout (`--request-timeout`).
    #[error("{0}")]
    RequestTimeout(String),
    /// Occurs on a failure that is the server's own fault.
    #[error("internal error: {0}")]
    Internal(String),
}

fn list(areas: &[(String, usize)]) -> String {
    areas
        .iter()
        .map(|(n, a)| format!("{n}: {a} cells"))
        .collect::<Vec<_>>()
        .join(", ")
}

impl ApiError {
    /// The HTTP status.
    pub fn status(&self) -> StatusCode {
        match self {
            ApiError::BadJson { .. }
            | ApiError::UnknownLattice(_)
            | ApiError::BadValue(_)
            | ApiError::BadConstraints(_) => StatusCode::BAD_REQUEST,
            ApiError::BadFigure(_)
            | ApiError::BadSolution(_)
            | ApiError::UnequalAreas(_)
            | ApiError::ImpossibleConstraints(_) => StatusCode::UNPROCESSABLE_ENTITY,
            ApiError::TooLarge(_) => StatusCode::PAYLOAD_TOO_LARGE,
            ApiError::Busy(_) | ApiError::PicturesBusy(_) => StatusCode::TOO_MANY_REQUESTS,
            ApiError::Unauthorized(_) => StatusCode::UNAUTHORIZED,
            ApiError::NotFound(_) => StatusCode::NOT_FOUND,
            ApiError::MethodNotAllowed => StatusCode::METHOD_NOT_ALLOWED,
            ApiError::Forbidden(_) => StatusCode::FORBIDDEN,
            ApiError::UnsupportedMediaType(_) => StatusCode::UNSUPPORTED_MEDIA_TYPE,
            ApiError::RequestTimeout(_) => StatusCode::REQUEST_TIMEOUT,
            ApiError::Internal(_) => StatusCode::INTERNAL_SERVER_ERROR,
        }
    }

    /// A short machine-readable code.
    pub fn code(&self) -> &'static str {
        match self {
            ApiError::BadJson { .. } => "bad_json",
            ApiError::UnknownLattice(_) => "unknown_lattice",
            ApiError::BadValue(_) => "bad_value",
            ApiError::BadFigure(_) => "bad_figure",
            ApiError::BadSolution(_) => "bad_solution",
            ApiError::BadConstraints(_) => "bad_constraints",
            ApiError::ImpossibleConstraints(_) => "impossible_constraints",
            ApiError::UnequalAreas(_) => "unequal_areas",
            ApiError::TooLarge(_) => "too_large",
            ApiError::Busy(_) | ApiError::PicturesBusy(_) => "busy",
            ApiError::Unauthorized(_) => "unauthorized",
            ApiError::NotFound(_) => "not_found",
            ApiError::MethodNotAllowed => "method_not_allowed",
            ApiError::Forbidden(_) => "forbidden",
            ApiError::UnsupportedMediaType(_) => "unsupported_media_type",
            ApiError::RequestTimeout(_) => "request_timeout",
            ApiError::Internal(_) => "internal",
        }
    }

    /// The JSON body.
    pub fn body(&self) -> Value {
        let mut err = json!({"code": self.code(), "message": self.to_string()});
        match self {
            ApiError::UnequalAreas(a) => {
                let max = a.iter().map(|x| x.1).max().unwrap_or(0);
                err["details"] = json!({
                    "areas": a.iter().map(|(n, c)| json!({"name": n, "cells": c, "short_by": max - c})).collect::<Vec<_>>()
                });
            }
            ApiError::BadJson { line, column, .. } => {
                err["details"] = json!({"line": line, "column": column});
            }
            _ => {}
        }
        json!({ "error": err })
    }

    /// The error of a body that serde could not read.
    pub fn from_json(e: &serde_json::Error) -> ApiError {
        ApiError::BadJson {
            line: e.line(),
            column: e.column(),
            message: strip_position(&e.to_string()),
        }
    }
}

/// serde_json appends " at line L column C": we report those apart.
fn strip_position(s: &str) -> String {
    match s.rfind(" at line ") {
        Some(i) => s[..i].to_string(),
        None => s.to_string(),
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        (self.status(), axum::Json(self.body())).into_response()
    }
}
