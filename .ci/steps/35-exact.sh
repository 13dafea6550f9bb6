#!/usr/bin/env bash
# The exact mode (issue 6) on the instances of instances/, as its contract writes
# it: `dissect bound` must end with the lower bounds of the issue's table
# (each well within 120 s), and `dissect solve --exact` must find verified
# optimal dissections of squares-3-4-split-to-5 (4) and
# tri-triangle8-to-rect4x8 (2). About 15 s.
set -euo pipefail
cd "$(dirname "$0")/../.."
. .ci/lib/check.sh
cargo build -q -p dissect-cli --release
bin=${CARGO_TARGET_DIR:-target}/release/dissect
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
instances=instances
bound() { # instance expected-bound max-pieces lattice
  local inst=$1 want=$2 max=$3 lattice=$4
  local last
  last=$("$bin" bound -q --lattice "$lattice" --max-pieces "$max" --time-limit 120 \
    "$instances/$inst/a.txt" "$instances/$inst/b.txt" | tail -1)
  case "$last" in
    "lower bound: $want ("*) echo "$inst: $last" ;;
    *) echo "$inst: expected lower bound $want, got: $last"; exit 1 ;;
  esac
}
bound squares-3-4-split-to-5 4 3 square
bound rect15x10-hole-to-square12 3 2 square
bound squares-12-5-joined-to-13 3 2 square
bound squares-6-6-7-split-to-11 5 4 square
bound cube4-cavity-to-7x4x2 4 3 cubic
bound sierpinski9-to-square8 4 3 square
bound cubes-3-4-5-to-6 8 7 cubic
exact() { # instance lattice pieces
  local inst=$1 lattice=$2 want=$3 sol=$out/$1.json
  local last
  last=$("$bin" solve --exact -q --lattice "$lattice" --time-limit 120 \
    "$instances/$inst/a.txt" "$instances/$inst/b.txt" -o "$sol" | tail -1)
  case "$last" in
    "$want pieces — optimal"*) ;;
    *) echo "$inst: expected an optimal $want-piece dissection, got: $last"; exit 1 ;;
  esac
  local res
  res=$(check_solution "$lattice" "$sol" "$instances/$inst/a.txt" "$instances/$inst/b.txt")
  [ "$res" = "valid: $want pieces" ] || { echo "$inst: the checkers say: $res"; exit 1; }
  echo "$inst: $last; checkers: $res"
}
exact squares-3-4-split-to-5 square 4
exact tri-triangle8-to-rect4x8 tri4 2
