#!/usr/bin/env bash
# The solver-only binary (issue 18): `dissect-cli --no-default-features`
# builds without the web server and the renderers, still solves, verifies
# and bounds, and is under 4 MB once stripped. Built in its own target
# directory so the full binary the other steps use is left alone.
set -euo pipefail
cd "$(dirname "$0")/../.."
target=${CARGO_TARGET_DIR:-$PWD/target}/lean
cargo build -q --release -p dissect-cli --no-default-features --target-dir "$target"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
bin=$out/dissect
cp "$target/release/dissect" "$bin"
strip "$bin"
size=$(stat -c %s "$bin")
echo "stripped solver-only binary: $size bytes"
[ "$size" -lt $((4 * 1024 * 1024)) ] || { echo "over 4 MB"; exit 1; }
a=examples/squares-3-4.txt b=examples/square-5.txt
"$bin" solve -q --threads 2 --time-limit 60 "$a" "$b" -o "$out/s.json"
"$bin" verify --solution "$out/s.json" "$a" "$b"
"$bin" bound -q --time-limit 60 "$a" "$b" | tail -1
# The heavy subcommands are not there.
for cmd in serve render rasterize voxelize; do
  if "$bin" "$cmd" --help >/dev/null 2>&1; then
    echo "the solver-only binary has '$cmd'"; exit 1
  fi
done
# And the default build has every one of them.
cargo build -q --release -p dissect-cli
for cmd in solve verify info bound serve render rasterize voxelize; do
  "${CARGO_TARGET_DIR:-target}/release/dissect" "$cmd" --help >/dev/null
done
echo "lean binary ok"
