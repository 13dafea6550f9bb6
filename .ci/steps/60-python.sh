#!/usr/bin/env bash
# The Python package (python/): fmt and clippy of its Rust crate (its own
# cargo workspace, so `cargo test --workspace` needs no Python), then the
# release wheel built once by `maturin build --release` (abi3: one wheel for
# every CPython >= 3.9), installed into a fresh virtual environment (deps
# from PyPI, pinned in python/ci-requirements.txt), `mypy --strict` over
# python/examples and python/tests against the installed package (its
# stubs and py.typed), and its pytest suite: figures, every solve option
# checked by dissect.verify and the independent checkers
# (tools/check_solution.py, and ../shared/tools/verify.py when present), several
# solutions, assemblies, progress, the same answer as the CLI, Ctrl-C,
# pictures with the one palette (Agg), and Ray on a local 2-CPU cluster.
# Takes about 5 minutes (the Rust build of the extension is most of it).
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
target=${CARGO_TARGET_DIR:-target}
case "$target" in /*) ;; *) target="$PWD/$target" ;; esac
export DISSECT_BIN="$target/release/dissect"
if ! wait "$deps"; then
  cat "$venv.log"
  echo "python: installing python/ci-requirements.txt failed"
  exit 1
fi
rm -f "$venv.log"
echo "python: fmt, clippy and dependencies in $(($(date +%s) - start)) s"
start=$(date +%s)
wheels="$venv/wheels"
"$venv/bin/maturin" build -q --release -m python/Cargo.toml -o "$wheels"
wheel=$(ls "$wheels"/dissect-*.whl)
case "$wheel" in
  *-abi3-*) ;;
  *) echo "python: $wheel is not an abi3 wheel"; exit 1 ;;
esac
"$venv/bin/pip" install -q "$wheel[test,ray]"
echo "python: built and installed $(basename "$wheel") in $(($(date +%s) - start)) s"

# From the repository root, so that `import dissect` finds the installed
# wheel, not the source folder python/dissect (which has no extension).
"$venv/bin/mypy" --config-file python/pyproject.toml python/examples python/tests
export MPLBACKEND=Agg DISSECT_REQUIRE_RAY=1
# The external oracle, when the project's shared folder is beside the
# checkout (the tests skip it visibly otherwise).
if [ -z "${DISSECT_VERIFY:-}" ] && [ -f ../shared/tools/verify.py ]; then
  export DISSECT_VERIFY="$PWD/../shared/tools/verify.py"
fi
"$venv/bin/python" -m pytest -q -p no:cacheprovider python/tests
"$venv/bin/python" python/examples/design_puzzle.py --out "$venv/example"
test -s "$venv/example/puzzle.json"
