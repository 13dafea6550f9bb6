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

/// `dissect-core`, `-engine`, `-exact`, `-puzzle` and `-render` do no I/O
/// and never print: strings and bytes in, strings and bytes out.
#[test]
fn the_libraries_do_no_io_and_never_print() {
    for krate in ["core", "engine", "exact", "puzzle", "render"] {
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
