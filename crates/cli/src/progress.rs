//! Progress on stderr: an indicatif bar on a terminal, one plain line per
//! level otherwise, nothing with --quiet.

use std::io::{IsTerminal, Write};
use std::sync::Mutex;
use std::time::Instant;

use dissect_core::solver::{Event, Observer};
use indicatif::{ProgressBar, ProgressStyle};

pub enum Progress {
    Quiet,
    Lines {
        start: Instant,
    },
    Bar {
        start: Instant,
        bar: Mutex<Option<ProgressBar>>,
    },
}

impl Progress {
    pub fn new(quiet: bool) -> Progress {
        let start = Instant::now();
        if quiet {
            Progress::Quiet
        } else if std::io::stderr().is_terminal() {
            Progress::Bar {
                start,
                bar: Mutex::new(None),
            }
        } else {
            Progress::Lines { start }
        }
    }

    /// One line on stderr (above the bar on a terminal); nothing when quiet.
    pub fn line(&self, text: &str) {
        match self {
            Progress::Quiet => {}
            Progress::Lines { .. } => stderr_line(text),
            Progress::Bar { bar, .. } => match bar.lock().expect("bar lock").as_ref() {
                Some(b) => b.suspend(|| stderr_line(text)),
                None => stderr_line(text),
            },
        }
    }

    pub fn finish(&self) {
        if let Progress::Bar { bar, .. } = self {
            if let Some(b) = bar.lock().expect("bar lock").take() {
                b.finish_and_clear();
            }
        }
    }
}

impl Observer for Progress {
    fn on_event(&self, event: &Event) {
        match (self, event) {
            (Progress::Quiet, _) => {}
            (
                Progress::Bar { bar, .. },
                Event::LevelStarted {
                    level,
                    pieces,
                    explorations,
                },
            ) if *level > 0 => {
                // The bar takes the width left, so that the line never wraps
                // on a narrow terminal.
                let style = ProgressStyle::with_template(
                    "{prefix} [{wide_bar}] {pos}/{len} explorations, {msg} ({elapsed})",
                )
                .expect("valid template")
                .progress_chars("=> ");
                let b = ProgressBar::new(*explorations as u64)
                    .with_style(style)
                    .with_prefix(format!("level {level} ({pieces} pieces)"))
                    .with_message("best score: none yet");
                if let Some(old) = bar.lock().expect("bar lock").replace(b) {
                    old.finish_and_clear();
                }
            }
            (
                Progress::Bar { bar, .. },
                Event::Exploration {
                    done,
                    best_score,
                    best_mismatch,
                    ..
                },
            ) => {
                if let Some(b) = bar.lock().expect("bar lock").as_ref() {
                    // Workers report out of order: never step back.
                    if *done as u64 >= b.position() {
                        b.set_position(*done as u64);
                        b.set_message(format!("best E_M {best_mismatch}, E {best_score:.2}"));
                    }
                }
            }
            (Progress::Bar { bar, start }, e @ Event::LevelFinished { .. }) => {
                let line = level_line(e, start);
                if let Some(b) = bar.lock().expect("bar lock").take() {
                    b.finish_and_clear();
                }
                stderr_line(&line);
            }
            (Progress::Lines { start }, e @ Event::LevelFinished { .. }) => {
                stderr_line(&level_line(e, start))
            }
            _ => {}
        }
    }
}

fn level_line(e: &Event, start: &Instant) -> String {
    match e {
        Event::LevelFinished { level, pieces, explorations, best_mismatch, found } => format!(
            "level {level} ({pieces} piece{}): {explorations} exploration{}, best E_M {best_mismatch}{}, {:.1} s",
            if *pieces == 1 { "" } else { "s" },
            if *explorations == 1 { "" } else { "s" },
            if *found { ", dissection found" } else { "" },
            start.elapsed().as_secs_f64()
        ),
        _ => String::new(),
    }
}

/// Writes `text` to stdout. A reader that went away (`dissect ... | head`)
/// is not an error and never a panic: the rest is dropped.
pub fn stdout(text: &str) {
    let mut out = std::io::stdout().lock();
    let _ = out.write_all(text.as_bytes()).and_then(|()| out.flush());
}

/// Writes one line to stderr, ignoring a closed stderr.
pub fn stderr_line(line: &str) {
    let _ = writeln!(std::io::stderr().lock(), "{line}");
}
