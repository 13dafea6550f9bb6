//! The rules every front end shares on how long an operation may run and
//! how many threads it may use: [`TimeLimit`] (parsed once, by
//! [`TimeLimit::new`] or [`str::parse`]) and [`check_threads`].
//!
//! The CLI's `--time-limit` of every subcommand, the studio's `time_limit`
//! and Python's `time_limit=` all go through [`TimeLimit`], so that the
//! same value gets the same verdict everywhere.

use std::fmt;
use std::str::FromStr;
use std::time::{Duration, Instant};

/// The most worker threads a run may ask for (0 means one per core).
pub const MAX_THREADS: usize = dissect_core::solver::MAX_THREADS;

/// Occurs when a time limit or a thread count is out of range; the message
/// names the setting as the command line spells it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LimitError {
    /// A time limit that is negative or not a number.
    #[error("--time-limit must be a number of seconds >= 0, got {0}")]
    TimeLimit(f64),
    /// A time limit that does not read as a number.
    #[error("--time-limit must be a number of seconds >= 0, got {0:?}")]
    NotANumber(String),
    /// A thread count over [`MAX_THREADS`].
    #[error("--threads must be from 0 to {MAX_THREADS} (0: one per core), got {0}")]
    Threads(usize),
}

/// How long an operation may run: a number of seconds, or no limit.
///
/// # Validity
/// Built from a finite number of seconds >= 0; infinity, and a number of
/// seconds too large for a [`Duration`], mean no limit; NaN and negative
/// numbers are refused ([`LimitError::TimeLimit`]). `Default` is no limit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct TimeLimit(Option<Duration>);

impl TimeLimit {
    /// No limit: the operation ends by its own work rule.
    pub const NONE: TimeLimit = TimeLimit(None);

    /// `seconds` as a limit (see the type's validity rule).
    pub fn new(seconds: f64) -> Result<TimeLimit, LimitError> {
        if seconds.is_nan() || seconds < 0.0 {
            return Err(LimitError::TimeLimit(seconds));
        }
        // Too far away to be a duration (infinity included): no limit.
        Ok(TimeLimit(Duration::try_from_secs_f64(seconds).ok()))
    }

    /// An optional number of seconds (`None`: no limit).
    pub fn from_option(seconds: Option<f64>) -> Result<TimeLimit, LimitError> {
        seconds.map_or(Ok(TimeLimit::NONE), TimeLimit::new)
    }

    /// A limit of `d`.
    pub fn from_duration(d: Duration) -> TimeLimit {
        TimeLimit(Some(d))
    }

    /// The limit (`None`: no limit).
    pub fn duration(self) -> Option<Duration> {
        self.0
    }

    /// The limit in seconds (`None`: no limit).
    pub fn seconds(self) -> Option<f64> {
        self.0.map(|d| d.as_secs_f64())
    }

    /// Whether there is a limit.
    pub fn is_limited(self) -> bool {
        self.0.is_some()
    }

    /// The instant the limit ends for an operation started at `start`
    /// (`None`: no limit, or one beyond what an [`Instant`] holds).
    pub fn deadline_from(self, start: Instant) -> Option<Instant> {
        self.0.and_then(|d| start.checked_add(d))
    }

    /// The instant the limit ends for an operation starting now.
    pub fn deadline(self) -> Option<Instant> {
        self.deadline_from(Instant::now())
    }

    /// The shorter of this limit and `other`.
    pub fn min(self, other: TimeLimit) -> TimeLimit {
        match (self.0, other.0) {
            (Some(a), Some(b)) => TimeLimit(Some(a.min(b))),
            (a, b) => TimeLimit(a.or(b)),
        }
    }
}

impl FromStr for TimeLimit {
    type Err = LimitError;

    /// A number of seconds as the command line gives it (`1.5`, `1e300`,
    /// `inf`), by the rule of [`TimeLimit::new`].
    fn from_str(s: &str) -> Result<TimeLimit, LimitError> {
        match s.trim().parse::<f64>() {
            Ok(v) => TimeLimit::new(v),
            Err(_) => Err(LimitError::NotANumber(s.to_string())),
        }
    }
}

impl fmt::Display for TimeLimit {
    /// `1.5 s`, or `none`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Some(d) => write!(f, "{} s", d.as_secs_f64()),
            None => f.write_str("none"),
        }
    }
}

/// Checks a worker thread count: from 0 (one per core) to [`MAX_THREADS`].
pub fn check_threads(threads: usize) -> Result<usize, LimitError> {
    if threads > MAX_THREADS {
        return Err(LimitError::Threads(threads));
    }
    Ok(threads)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_rule_for_every_time_limit() {
        assert_eq!(
            "0.5".parse(),
            Ok(TimeLimit(Some(Duration::from_millis(500))))
        );
        assert_eq!("0".parse(), Ok(TimeLimit(Some(Duration::ZERO))));
        for none in ["inf", "infinity", "1e300", "1e20"] {
            assert_eq!(none.parse(), Ok(TimeLimit::NONE), "{none}");
        }
        for bad in ["nan", "-1", "-inf", "-0.001"] {
            let e = bad.parse::<TimeLimit>().expect_err(bad);
            assert!(matches!(e, LimitError::TimeLimit(_)), "{bad}: {e}");
            assert!(e.to_string().starts_with("--time-limit must be"), "{e}");
        }
        assert!(matches!(
            "soon".parse::<TimeLimit>(),
            Err(LimitError::NotANumber(_))
        ));
        assert_eq!(TimeLimit::new(f64::INFINITY), Ok(TimeLimit::NONE));
        assert!(TimeLimit::new(1e300).unwrap().deadline().is_none());
        assert!(TimeLimit::new(1.0).unwrap().deadline().is_some());
        let one = TimeLimit::new(1.0).unwrap();
        assert_eq!(TimeLimit::NONE.min(one), one);
        assert_eq!(one.min(TimeLimit::new(2.0).unwrap()), one);
    }

    #[test]
    fn thread_counts() {
        assert_eq!(check_threads(0), Ok(0));
        assert_eq!(check_threads(MAX_THREADS), Ok(MAX_THREADS));
        assert_eq!(
            check_threads(MAX_THREADS + 1),
            Err(LimitError::Threads(MAX_THREADS + 1))
        );
    }
}
