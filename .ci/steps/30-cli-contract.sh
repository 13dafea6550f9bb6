#!/usr/bin/env bash
# The acceptance command lines of issues 3 and 4, run as written on the
# quick instances of instances/: `dissect solve --seed 1 --time-limit 300` must exit
# 0 at the manifest's reference piece count, and both `dissect verify` and
# the independent checkers (.ci/lib/check.sh) must accept what it wrote. Takes a few seconds.
set -euo pipefail
cd "$(dirname "$0")/../.."
. .ci/lib/check.sh
cargo build -q -p dissect-cli --release
bin=${CARGO_TARGET_DIR:-target}/release/dissect
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
instances=instances
check() { # lattice instance
  local lattice=$1 inst=$2
  local a=$instances/$inst/a.txt b=$instances/$inst/b.txt sol=$out/$inst.json
  local ref
  ref=$(python3 -c "import json,sys; print(next(m['reference'] for m in json.load(open('$instances/manifest.json')) if m['name']=='$inst'))")
  "$bin" solve --lattice "$lattice" --seed 1 --time-limit 300 -q "$a" "$b" -o "$sol"
  "$bin" verify --lattice "$lattice" --solution "$sol" "$a" "$b" >/dev/null
  local res
  res=$(check_solution "$lattice" "$sol" "$a" "$b")
  [ "$res" = "valid: $ref pieces" ] || { echo "$inst: expected $ref pieces, the checkers say: $res"; exit 1; }
  echo "$inst ($lattice): $res"
}
check square rect10x7-hole-to-square8
check square squares-3-4-split-to-5
check square squares-12-5-joined-to-13
check tri4 tri-triangle8-to-rect4x8
