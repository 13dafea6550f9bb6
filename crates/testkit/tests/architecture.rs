//! The architecture invariants of ARCHITECTURE.md that no type can hold,
//! checked on the sources: which crates may do I/O or print, which may
//! speak HTTP or name the SAT backend, and what the verifier may import.

use std::path::{Path, PathBuf};

fn crates() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every `.rs` file below `dir`, with its text up to its first
/// `#[cfg(test)]` (unit tests may print).
fn sources(dir: &Path) -> Vec<(PathBuf, String)> {
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display())) {
            let p = e.expect("a directory entry").path();
            if p.is_dir() {
                if p.file_name().is_some_and(|n| n != "tests") {
                    todo.push(p);
                }
            } else if p.extension().is_some_and(|x| x == "rs") {
                let text = std::fs::read_to_string(&p).expect("a source file");
                let code = text.split("#[cfg(test)]").next().unwrap_or("").to_string();
                out.push((p, code));
            }
        }
    }
    assert!(!out.is_empty(), "no source below {}", dir.display());
    out
}

/// Lines of code (not comments) of `text` that contain one of `words`.
fn uses(text: &str, words: &[&str]) -> Vec<String> {
    text.lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .filter(|l| words.iter().any(|w| l.contains(w)))
        .map(|l| l.trim().to_string())
        .collect()
}

const IO_AND_PRINTING: &[&str] = &[
    "std::fs",
    "std::net",
    "std::process",
    "std::env",
    "stdin()",
    "stdout()",
    "stderr()",
    "File::",
    "println!",
    "eprintln!",
    "print!(",
    "eprint!(",
    "dbg!(",
];

/// `dissect-core`, `-engine`, `-exact`, `-puzzle`, `-render` and `-proof`
/// do no I/O and never print: strings and bytes in, strings and bytes out.
#[test]
fn the_libraries_do_no_io_and_never_print() {
    for krate in ["core", "engine", "exact", "puzzle", "render", "proof"] {
        for (path, code) in sources(&crates().join(krate).join("src")) {
            let bad = uses(&code, IO_AND_PRINTING);
            assert!(bad.is_empty(), "{}: {bad:?}", path.display());
        }
    }
}

/// The verifier is independent: it imports the dissection, figures and
/// lattice definitions only (not the solver, not the file formats).
#[test]
fn the_verifier_imports_only_definitions() {
    let text = std::fs::read_to_string(crates().join("core/src/verify.rs")).expect("verify.rs");
    let code = text.split("#[cfg(test)]").next().unwrap_or("");
    for line in uses(code, &["crate::", "super::"]) {
        assert!(
            ["crate::dissection", "crate::figure", "crate::lattice"]
                .iter()
                .any(|ok| line.contains(ok)),
            "verify.rs uses {line}"
        );
    }
}

/// Only `crates/exact/src/sat_backend.rs` names the SAT backend.
#[test]
fn only_the_sat_backend_module_names_batsat() {
    for krate in std::fs::read_dir(crates()).expect("crates/") {
        let dir = krate.expect("an entry").path();
        let manifest = std::fs::read_to_string(dir.join("Cargo.toml")).unwrap_or_default();
        let is_exact = dir.ends_with("exact");
        assert_eq!(
            manifest.contains("batsat"),
            is_exact,
            "{}: only dissect-exact depends on batsat",
            dir.display()
        );
        if !dir.join("src").is_dir() {
            continue;
        }
        for (path, code) in sources(&dir.join("src")) {
            if path.ends_with("exact/src/sat_backend.rs") {
                continue;
            }
            let bad = uses(&code, &["batsat"]);
            assert!(bad.is_empty(), "{}: {bad:?}", path.display());
        }
    }
}

/// The certificate checker (`dissect-proof`) is independent of what it
/// checks: it depends on no other crate of the workspace (so shares no code
/// with the encoder or the SAT solver) and on no SAT solver.
#[test]
fn the_proof_checker_shares_no_code_with_the_encoder_or_the_solver() {
    let manifest = std::fs::read_to_string(crates().join("proof/Cargo.toml")).expect("manifest");
    let deps = manifest
        .split("[dependencies]")
        .nth(1)
        .expect("a [dependencies] table")
        .split("\n[")
        .next()
        .unwrap_or("");
    let names: Vec<&str> = deps
        .lines()
        .filter_map(|l| l.split(['=', ' ', '.']).next())
        .filter(|n| !n.is_empty())
        .collect();
    // Errors, and a fast hash for the deletion index: no encoder, no solver.
    assert_eq!(
        names,
        ["rustc-hash", "thiserror"],
        "dissect-proof depends on {names:?}"
    );
    for (path, code) in sources(&crates().join("proof").join("src")) {
        let bad = uses(&code, &["dissect_", "batsat"]);
        assert!(bad.is_empty(), "{}: {bad:?}", path.display());
    }
}

/// HTTP is the studio's (`dissect-web`); the fuzz loop drives its router
/// in-process and is the only other crate with an HTTP stack.
#[test]
fn only_the_studio_and_its_fuzzer_speak_http() {
    for krate in std::fs::read_dir(crates()).expect("crates/") {
        let dir = krate.expect("an entry").path();
        let Ok(manifest) = std::fs::read_to_string(dir.join("Cargo.toml")) else {
            continue;
        };
        let deps = manifest.split("[dev-dependencies]").next().unwrap_or("");
        let http = ["axum", "hyper", "tower-http", "tokio"]
            .into_iter()
            .filter(|d| deps.lines().any(|l| l.starts_with(&format!("{d} "))))
            .collect::<Vec<_>>();
        let allowed = dir.ends_with("web") || dir.ends_with("fuzz");
        assert!(
            allowed || http.is_empty(),
            "{} depends on {http:?}",
            dir.display()
        );
    }
}

/// The longest a function may be, in lines from its `fn` to its closing
/// brace.
const MAX_FUNCTION_LINES: usize = 150;

/// Every `.rs` file below `dir` (all of it, unit tests included).
fn all_sources(dir: &Path) -> Vec<(PathBuf, String)> {
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display())) {
            let p = e.expect("a directory entry").path();
            if p.is_dir() {
                todo.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                let text = std::fs::read_to_string(&p).expect("a source file");
                out.push((p, text));
            }
        }
    }
    out
}

/// Whether `line` (trimmed) starts a function item: `fn`, with any of
/// `pub`, `pub(crate)`, `const`, `async`, `unsafe`, `extern "C"` before it.
fn starts_fn(line: &str) -> bool {
    let mut rest = line;
    loop {
        if rest.starts_with("fn ") {
            return true;
        }
        let words = [
            "pub(crate) ",
            "pub(super) ",
            "pub ",
            "const ",
            "async ",
            "unsafe ",
            "extern \"C\" ",
            "default ",
        ];
        match words.iter().find(|w| rest.starts_with(*w)) {
            Some(w) => rest = &rest[w.len()..],
            None => return false,
        }
    }
}

/// `(name, first line, lines)` of every function with a body in `text`:
/// from its `fn` line to the first line after it that is a closing brace
/// at the `fn` line's indentation (rustfmt's layout).
fn functions(text: &str) -> Vec<(String, usize, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let body = line.trim_start();
        if !starts_fn(body) {
            continue;
        }
        let indent = &line[..line.len() - body.len()];
        let name: String = body[body.find("fn ").expect("fn") + 3..]
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        // The signature ends at `{` (a body), `;` (none) or `}` (a body
        // on the same line).
        let Some(open) = (i..lines.len()).find(|&j| {
            let t = lines[j].trim_end();
            t.ends_with('{') || t.ends_with(';') || t.ends_with('}')
        }) else {
            continue;
        };
        let t = lines[open].trim_end();
        if t.ends_with(';') {
            continue;
        }
        if t.ends_with('}') && t.contains('{') {
            out.push((name, i + 1, open - i + 1));
            continue;
        }
        let close = format!("{indent}}}");
        if let Some(end) = (open + 1..lines.len()).find(|&j| lines[j].trim_end() == close) {
            out.push((name, i + 1, end - i + 1));
        }
    }
    out
}

/// No function in `crates/*/src` or `python/src` is over
/// [`MAX_FUNCTION_LINES`] lines (ARCHITECTURE.md: a long function is split
/// into named steps).
#[test]
fn no_function_is_over_150_lines() {
    let mut dirs: Vec<PathBuf> = std::fs::read_dir(crates())
        .expect("the crates folder")
        .map(|e| e.expect("an entry").path().join("src"))
        .filter(|p| p.is_dir())
        .collect();
    dirs.push(crates().join("../python/src"));
    let mut long = Vec::new();
    let mut seen = 0;
    for dir in dirs {
        for (path, text) in all_sources(&dir) {
            for (name, line, n) in functions(&text) {
                seen += 1;
                if n > MAX_FUNCTION_LINES {
                    long.push(format!("{}:{line}: fn {name}: {n} lines", path.display()));
                }
            }
        }
    }
    assert!(
        seen > 1000,
        "only {seen} functions found: the scan is broken"
    );
    long.sort();
    assert!(
        long.is_empty(),
        "functions over {MAX_FUNCTION_LINES} lines:\n{}",
        long.join("\n")
    );
}

#[test]
fn the_function_scan_measures_bodies() {
    let text = "fn a() {}\n\npub(crate) fn b(\n    x: u8,\n) -> u8 {\n    x\n}\n\nimpl T {\n    pub fn c(&self) {\n        if true {\n        }\n    }\n    fn d(&self);\n}\n";
    assert_eq!(
        functions(text),
        vec![
            ("a".to_string(), 1, 1),
            ("b".to_string(), 3, 5),
            ("c".to_string(), 10, 4)
        ]
    );
}

/// The engine owns every long operation: the front ends (CLI, studio,
/// bench, Python) never set up the exact search or call the assembly
/// counter themselves; they call `dissect_engine::{run, bound,
/// assemblies}`.
#[test]
fn the_front_ends_leave_long_operations_to_the_engine() {
    let words = [
        "ExactOptions",
        "dissect_exact::search",
        "search(&",
        "assemblies::count",
        "assemblies::{count",
        "CountLimits",
        "RepairOptions",
    ];
    let mut found = Vec::new();
    for dir in ["cli/src", "web/src", "bench/src", "../python/src"] {
        for (path, text) in sources(&crates().join(dir)) {
            for line in uses(&text, &words) {
                found.push(format!("{}: {line}", path.display()));
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
}

/// One Ctrl-C handler: the CLI's `stop` module.
#[test]
fn one_module_catches_ctrl_c() {
    let mut found = Vec::new();
    for (path, text) in sources(&crates().join("cli/src")) {
        if !uses(&text, &["ctrlc::"]).is_empty() && !path.ends_with("stop.rs") {
            found.push(path.display().to_string());
        }
    }
    assert!(
        found.is_empty(),
        "Ctrl-C handlers outside stop.rs: {found:?}"
    );
}
