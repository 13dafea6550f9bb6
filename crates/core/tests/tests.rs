//! Integration tests of `dissect-core` through its public API, built as one
//! test binary (ripgrep-style): every topic is a module of `suite/`.
//!
//! Figures are written as ASCII strings in a compact notation (see
//! [`suite::util`]): `|` ends a row and `/` ends a cubic z layer.

mod suite;
