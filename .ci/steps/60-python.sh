#!/usr/bin/env bash
# The Python package (issue 16, python/): fmt and clippy of its Rust crate
# (its own cargo workspace, so `cargo test --workspace` needs no Python),
# then `pip install ./python[test,ray]` in a fresh virtual environment from
# PyPI and this repository alone, and its pytest suite: figures, solve on
# square/tri4/cubic checked by tools/check_solution.py (and
# ../shared/tools/verify.py when present), errors, the same
# answer as the CLI, Ctrl-C, plotting (Agg), and Ray on a local 2-CPU
# cluster. Versions are pinned in python/ci-requirements.txt. Takes about
# 4 minutes (the Rust build of the extension is most of it).
set -euo pipefail
cd "$(dirname "$0")/../.."
echo "python: $(python3 --version)"
venv=$(mktemp -d)
trap 'rm -rf "$venv" "$venv.log"' EXIT
# The dependencies (Ray is most of it) download while the Rust side builds.
(
  python3 -m venv "$venv" &&
  "$venv/bin/pip" install -q -r python/ci-requirements.txt
) > "$venv.log" 2>&1 &
deps=$!
start=$(date +%s)
cargo fmt --manifest-path python/Cargo.toml -- --check
cargo clippy -q --manifest-path python/Cargo.toml --all-targets -- -D warnings
cargo build -q -p dissect-cli --release
export DISSECT_BIN="$PWD/${CARGO_TARGET_DIR:-target}/release/dissect"
if ! wait "$deps"; then
  cat "$venv.log"
  echo "python: installing python/ci-requirements.txt failed"
  exit 1
fi
rm -f "$venv.log"
echo "python: fmt, clippy and dependencies in $(($(date +%s) - start)) s"
start=$(date +%s)
"$venv/bin/pip" install -q "./python[test,ray]"
echo "python: pip install ./python built and installed in $(($(date +%s) - start)) s"

# From the repository root, so that `import dissect` finds the installed
# package, not the source folder python/dissect (which has no extension).
export MPLBACKEND=Agg DISSECT_REQUIRE_RAY=1
"$venv/bin/python" -m pytest -q -p no:cacheprovider python/tests
"$venv/bin/python" python/examples/design_puzzle.py --out "$venv/example"
test -s "$venv/example/puzzle.json"
