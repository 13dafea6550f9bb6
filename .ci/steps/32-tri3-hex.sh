#!/usr/bin/env bash
# Issue 13's acceptance command lines on the three tri3/hex instances, as
# written: `dissect solve --lattice tri3|hex --seed 1 --time-limit 120` must
# exit 0 with a dissection that `dissect verify` and the independent
# checkers (.ci/lib/check.sh) accept, and the hexagon-to-parallelogram instance must come out in 3 pieces
# proved optimal (`--prove`; `--exact` finds the same). `dissect info` and
# `dissect bound` run on each. A few seconds each.
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
  "$bin" info --lattice "$lattice" "$a" "$b" >/dev/null
  "$bin" solve --lattice "$lattice" --seed 1 --time-limit 120 -q "$a" "$b" -o "$sol"
  "$bin" verify --lattice "$lattice" --solution "$sol" "$a" "$b" >/dev/null
  local res
  res=$(check_solution "$lattice" "$sol" "$a" "$b")
  case "$res" in valid:*) ;; *) echo "$inst: the checkers say: $res"; exit 1 ;; esac
  echo "$inst ($lattice): $res"
}
check tri3 tri3-hexagon2-to-parallelogram4x3
check tri3 tri3-triangles-6-8-split-to-10
check hex hex-hexagon6-to-rhombus13x7

# 3 pieces, proved optimal, by the anytime search with --prove and by SAT alone.
inst=tri3-hexagon2-to-parallelogram4x3
a=$instances/$inst/a.txt b=$instances/$inst/b.txt
line=$("$bin" solve --lattice tri3 --seed 1 --time-limit 120 --prove -q "$a" "$b" -o "$out/p.json" | tail -1)
case "$line" in "3 pieces — optimal"*) ;; *) echo "$inst --prove: $line"; exit 1 ;; esac
[ "$(check_solution tri3 "$out/p.json" "$a" "$b")" = "valid: 3 pieces" ]
"$bin" solve --lattice tri3 --exact --time-limit 120 -q "$a" "$b" -o "$out/e.json" >/dev/null
[ "$(check_solution tri3 "$out/e.json" "$a" "$b")" = "valid: 3 pieces" ]
"$bin" bound --lattice tri3 -q "$a" "$b" | grep -q "^lower bound: 3 "
echo "$inst: 3 pieces, proved optimal (--prove, --exact, bound)"
"$bin" bound --lattice hex -q --time-limit 20 $instances/hex-hexagon6-to-rhombus13x7/{a,b}.txt | grep -q "^lower bound: "
