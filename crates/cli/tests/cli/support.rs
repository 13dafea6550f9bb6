//! Running the built `dissect` binary in a temporary folder, and checking
//! what it wrote.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use tempfile::TempDir;

/// A figure file of a benchmark instance of the repository's `instances/`.
pub fn instance(name: &str, file: &str) -> PathBuf {
    dissect_testkit::repo::instance_file(name, file)
}

/// What one run of the binary did.
#[derive(Debug)]
pub struct Run {
    /// The exit code (`None` when killed by a signal).
    pub code: Option<i32>,
    pub stdout: String,
    pub stderr: String,
    pub elapsed: Duration,
}

impl Run {
    /// Asserts the exit code, showing the run's output when it differs.
    #[track_caller]
    pub fn expect_code(&self, code: i32) -> &Run {
        assert_eq!(
            self.code,
            Some(code),
            "expected exit code {code}\n--- stdout\n{}\n--- stderr\n{}",
            clip(&self.stdout),
            clip(&self.stderr)
        );
        self
    }

    /// Asserts that stderr contains every piece of text.
    #[track_caller]
    pub fn stderr_has(&self, parts: &[&str]) -> &Run {
        for p in parts {
            assert!(
                self.stderr.contains(p),
                "stderr lacks {p:?}\n--- stderr\n{}",
                clip(&self.stderr)
            );
        }
        self
    }

    /// Asserts that stdout contains every piece of text.
    #[track_caller]
    pub fn stdout_has(&self, parts: &[&str]) -> &Run {
        for p in parts {
            assert!(
                self.stdout.contains(p),
                "stdout lacks {p:?}\n--- stdout\n{}",
                clip(&self.stdout)
            );
        }
        self
    }
}

/// At most the first 40 lines of an output, for failure messages.
pub fn clip(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    if lines.len() <= 40 {
        return text.to_string();
    }
    format!(
        "{}\n... ({} more lines)",
        lines[..40].join("\n"),
        lines.len() - 40
    )
}

/// A temporary working folder for the binary.
pub struct Sandbox {
    dir: TempDir,
}

impl Sandbox {
    pub fn new() -> Sandbox {
        Sandbox {
            dir: tempfile::tempdir().expect("temporary folder"),
        }
    }

    /// A path inside the sandbox.
    pub fn path(&self, name: &str) -> PathBuf {
        self.dir.path().join(name)
    }

    /// Writes a file (a figure drawn as text, a solution ...) and returns
    /// its name, relative to the sandbox.
    pub fn write(&self, name: &str, text: &str) -> String {
        std::fs::write(self.path(name), text).expect("write test file");
        name.to_string()
    }

    /// Copies a benchmark instance's figure into the sandbox under `as_name`.
    pub fn copy_instance(&self, name: &str, file: &str, as_name: &str) -> String {
        std::fs::copy(instance(name, file), self.path(as_name)).expect("copy instance");
        as_name.to_string()
    }

    /// Reads a file the binary wrote.
    pub fn read(&self, name: &str) -> String {
        std::fs::read_to_string(self.path(name))
            .unwrap_or_else(|e| panic!("cannot read {name}: {e}"))
    }

    /// The binary, ready to run in the sandbox without a terminal.
    pub fn command(&self, args: &[&str]) -> Command {
        let mut c = Command::new(env!("CARGO_BIN_EXE_dissect"));
        c.args(args)
            .current_dir(self.dir.path())
            .stdin(Stdio::null())
            .env_remove("RUST_BACKTRACE");
        c
    }

    /// Runs the binary to its end. Panics if it panicked.
    pub fn run(&self, args: &[&str]) -> Run {
        let start = Instant::now();
        let out = self.command(args).output().expect("run dissect");
        let run = Run {
            code: out.status.code(),
            stdout: String::from_utf8(out.stdout).expect("UTF-8 stdout"),
            stderr: String::from_utf8(out.stderr).expect("UTF-8 stderr"),
            elapsed: start.elapsed(),
        };
        assert_no_panic(&run);
        run
    }

    /// Runs the binary with a stdout whose reader went away at once (as in
    /// `dissect ... | head -0`). Panics if it panicked.
    pub fn run_with_closed_stdout(&self, args: &[&str]) -> Run {
        let start = Instant::now();
        let mut child = self
            .command(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("start dissect");
        drop(child.stdout.take());
        let out = child.wait_with_output().expect("wait for dissect");
        let run = Run {
            code: out.status.code(),
            stdout: String::new(),
            stderr: String::from_utf8(out.stderr).expect("UTF-8 stderr"),
            elapsed: start.elapsed(),
        };
        assert_no_panic(&run);
        run
    }

    /// Starts the binary with piped output; returns it once it has printed
    /// its first line on stderr (so its Ctrl-C handler is in place), with
    /// that line.
    pub fn spawn_until_first_line(&self, args: &[&str]) -> Running {
        let start = Instant::now();
        let mut child = self
            .command(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("start dissect");
        let (tx, rx) = std::sync::mpsc::channel();
        let stderr = child.stderr.take().expect("piped stderr");
        let reader = std::thread::spawn(move || {
            let mut all = String::new();
            for line in BufReader::new(stderr).lines() {
                let line = line.expect("UTF-8 stderr");
                let _ = tx.send(line.clone());
                all += &line;
                all.push('\n');
            }
            all
        });
        let first = rx
            .recv_timeout(Duration::from_secs(20))
            .expect("a first progress line on stderr");
        Running {
            child,
            reader,
            start,
            first,
        }
    }
}

/// A binary started by [`Sandbox::spawn_until_first_line`].
pub struct Running {
    child: Child,
    reader: std::thread::JoinHandle<String>,
    start: Instant,
    pub first: String,
}

impl Running {
    /// Sends a signal (`INT`, `TERM`) with the shell's `kill` builtin (`sh`
    /// is on every Debian; the `kill` program is not always).
    pub fn signal(&self, name: &str) {
        let ok = Command::new("sh")
            .args(["-c", &format!("kill -{name} {}", self.child.id())])
            .status()
            .expect("run sh");
        assert!(ok.success(), "kill -{name} failed");
    }

    /// Waits for the end, at most `limit` (then kills it and fails).
    pub fn wait(mut self, limit: Duration) -> Run {
        let signalled = Instant::now();
        let status = loop {
            if let Some(s) = self.child.try_wait().expect("wait for dissect") {
                break s;
            }
            if signalled.elapsed() > limit {
                let _ = self.child.kill();
                let _ = self.child.wait();
                panic!("dissect did not stop within {limit:?}");
            }
            std::thread::sleep(Duration::from_millis(20));
        };
        let elapsed = self.start.elapsed();
        let mut stdout = String::new();
        if let Some(mut o) = self.child.stdout.take() {
            std::io::Read::read_to_string(&mut o, &mut stdout).expect("UTF-8 stdout");
        }
        let stderr = self.first.clone() + "\n" + &self.reader.join().expect("stderr reader");
        let run = Run {
            code: status.code(),
            stdout,
            stderr,
            elapsed,
        };
        assert_no_panic(&run);
        run
    }
}

#[track_caller]
fn assert_no_panic(run: &Run) {
    assert!(
        !run.stderr.contains("panicked") && !run.stdout.contains("panicked"),
        "dissect panicked:\n{}",
        clip(&run.stderr)
    );
    assert_ne!(run.code, Some(101), "exit code 101 is a panic");
}

/// Parses a solution file the binary wrote.
pub fn json(text: &str) -> serde_json::Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("bad JSON ({e}):\n{text}"))
}

/// The number of pieces of a solution JSON (checking that every figure
/// lists the same number).
pub fn piece_count(solution: &serde_json::Value) -> usize {
    let figs = solution["figures"].as_array().expect("figures array");
    let counts: Vec<usize> = figs
        .iter()
        .map(|f| f["pieces"].as_array().expect("pieces array").len())
        .collect();
    assert!(counts.iter().all(|c| *c == counts[0]), "{counts:?}");
    counts[0]
}

/// Checks a written solution with `dissect verify`, with the repository's
/// independent `tools/check_solution.py` and, when present, with the
/// external `verify.py` ([`dissect_testkit::repo::assert_checked`]);
/// returns the piece count.
#[track_caller]
pub fn assert_valid(sb: &Sandbox, lattice: &str, solution: &str, figures: &[&str]) -> usize {
    let mut args = vec!["verify", "--lattice", lattice, "--solution", solution];
    args.extend_from_slice(figures);
    let run = sb.run(&args);
    run.expect_code(0);
    let n = piece_count(&json(&sb.read(solution)));
    assert_eq!(
        run.stdout.trim(),
        format!("valid: {n} piece{}", if n == 1 { "" } else { "s" })
    );

    let checked = dissect_testkit::repo::assert_checked(&sb.path("."), lattice, solution, figures);
    assert_eq!(
        checked, n,
        "the checkers count {checked} pieces in {solution}"
    );
    n
}

/// Compares `actual` with the golden file `tests/golden/<name>`; with
/// `UPDATE_GOLDEN=1` in the environment, (re)writes the file instead.
#[track_caller]
pub fn golden(name: &str, actual: &str) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(name);
    if std::env::var_os("UPDATE_GOLDEN").is_some_and(|v| v == "1") {
        std::fs::write(&path, actual).expect("write golden file");
        return;
    }
    let expected = std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!(
            "cannot read golden file {} ({e}); run with UPDATE_GOLDEN=1 to create it",
            path.display()
        )
    });
    if expected != actual {
        let first = expected
            .lines()
            .zip(actual.lines())
            .position(|(a, b)| a != b)
            .unwrap_or(expected.lines().count().min(actual.lines().count()));
        panic!(
            "output differs from golden file {} from line {} on (UPDATE_GOLDEN=1 rewrites it)\n--- expected\n{expected}\n--- actual\n{actual}",
            path.display(),
            first + 1
        );
    }
}

impl Sandbox {
    /// Runs the binary under a 2 GiB address-space cap (`ulimit -v`, as
    /// `prlimit --as=2147483648`), killing it after `limit`. Panics if it
    /// panicked, overflowed its stack, aborted or ran out of time.
    pub fn run_capped(&self, args: &[&str], limit: Duration) -> Run {
        let start = Instant::now();
        let mut c = Command::new("sh");
        c.arg("-c")
            .arg("ulimit -v 2097152 && exec \"$0\" \"$@\"")
            .arg(env!("CARGO_BIN_EXE_dissect"))
            .args(args)
            .current_dir(self.dir.path())
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .env_remove("RUST_BACKTRACE");
        let mut child = c.spawn().expect("start dissect");
        let mut stdout = child.stdout.take().expect("piped");
        let mut stderr = child.stderr.take().expect("piped");
        let out = std::thread::spawn(move || {
            let mut s = Vec::new();
            let _ = std::io::Read::read_to_end(&mut stdout, &mut s);
            s
        });
        let err = std::thread::spawn(move || {
            let mut s = Vec::new();
            let _ = std::io::Read::read_to_end(&mut stderr, &mut s);
            s
        });
        let status = loop {
            if let Some(s) = child.try_wait().expect("wait for dissect") {
                break s;
            }
            if start.elapsed() > limit {
                let _ = child.kill();
                let _ = child.wait();
                panic!("{args:?} did not end within {limit:?}");
            }
            std::thread::sleep(Duration::from_millis(10));
        };
        let run = Run {
            code: status.code(),
            stdout: String::from_utf8_lossy(&out.join().expect("stdout")).into_owned(),
            stderr: String::from_utf8_lossy(&err.join().expect("stderr")).into_owned(),
            elapsed: start.elapsed(),
        };
        assert_no_panic(&run);
        for bad in [
            "overflowed its stack",
            "memory allocation",
            "fatal runtime error",
            "abort",
        ] {
            assert!(
                !run.stderr.contains(bad),
                "{args:?}: {bad}\n{}",
                clip(&run.stderr)
            );
        }
        assert!(
            run.code.is_some(),
            "{args:?} was killed by a signal\n{}",
            clip(&run.stderr)
        );
        run
    }

    /// Writes bytes into the sandbox and returns the name.
    pub fn write_bytes(&self, name: &str, bytes: &[u8]) -> String {
        std::fs::write(self.path(name), bytes).expect("write test file");
        name.to_string()
    }
}

impl Running {
    /// The first line the binary wrote on stdout.
    pub fn stdout_line(&mut self) -> String {
        let out = self.child.stdout.as_mut().expect("piped stdout");
        let mut line = Vec::new();
        let mut byte = [0u8; 1];
        while std::io::Read::read(out, &mut byte).unwrap_or(0) == 1 && byte[0] != b'\n' {
            line.push(byte[0]);
        }
        String::from_utf8_lossy(&line).into_owned()
    }
}
