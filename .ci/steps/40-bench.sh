#!/usr/bin/env bash
# Smoke run of the benchmark harness (dissect-bench) on two small instances
# and a short scaling series: every dissection it finds is verified in
# process (exit 1 on a failed verification) and, saved, by the independent
# independent checkers (.ci/lib/check.sh). Takes a few seconds.
set -euo pipefail
cd "$(dirname "$0")/../.."
. .ci/lib/check.sh
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cargo run -q -p dissect-bench --release -- \
  --only rect10x7-hole-to-square8,squares-3-4-split-to-5 \
  --seeds 1,2 --time-limit 60 --threads 2 --per-seed --save "$out"
cargo run -q -p dissect-bench --release -- instances \
  --scaling --scale-instance rect10x7-hole-to-square8 --scale-factors 1,2 \
  --seeds 1 --time-limit 60 --threads 2 --save "$out"
n=0
for s in "$out"/*-seed*.json; do
  stem=$(basename "$s" .json)
  inst=${stem%-seed*}
  figdir=instances/$inst
  [ -d "$figdir" ] || figdir=$out/$inst
  if ! res=$(check_solution square "$s" "$figdir/a.txt" "$figdir/b.txt"); then
    echo "$stem: the checkers reject the dissection"; exit 1
  fi
  echo "$stem: $res"
  n=$((n + 1))
done
[ "$n" -eq 6 ] || { echo "expected 6 saved dissections, found $n"; exit 1; }
