#!/usr/bin/env bash
# Certificates (issue 30): for every optimal claim of the public suite's
# small instances (the lower bound meets the best known count, manifest.json),
# `dissect bound --certificate` writes the refuted formulas kK.cnf with their
# DRAT proofs; the project's independent checker (`dissect check-proof`)
# must verify every one, the certificate of "no (optimum - 1)-piece
# dissection" must be among them, and a second SAT solver (cadical) must
# answer UNSAT on every formula and write a DRAT proof of it that
# check-proof verifies as well. About a minute.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build -q -p dissect-cli --release
bin=${CARGO_TARGET_DIR:-target}/release/dissect
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
certify() { # instance optimum lattice
  local inst=$1 opt=$2 lattice=$3 dir=$out/$1 k=$(($2 - 1))
  local last
  last=$("$bin" bound -q --lattice "$lattice" --max-pieces "$k" --time-limit 120 \
    --certificate "$dir" "instances/$inst/a.txt" "instances/$inst/b.txt" | tail -1)
  case "$last" in
    "lower bound: $opt ("*) ;;
    *) echo "$inst: expected lower bound $opt, got: $last"; exit 1 ;;
  esac
  [ -f "$dir/k$k.cnf" ] && [ -f "$dir/k$k.drat" ] \
    || { echo "$inst: no certificate of k$k in $dir"; ls "$dir"; exit 1; }
  last=$("$bin" check-proof "$dir" | tail -1)
  case "$last" in
    "verified: "*) ;;
    *) echo "$inst: check-proof says: $last"; exit 1 ;;
  esac
  local second=""
  if command -v cadical >/dev/null; then
    # The second solver refutes every formula and writes its own DRAT
    # proof, which check-proof must verify too.
    local other=$out/$inst-cadical
    mkdir -p "$other"
    for cnf in "$dir"/k*.cnf; do
      local rc=0 name
      name=$(basename "$cnf" .cnf)
      cp "$cnf" "$other/$name.cnf"
      cadical -q --no-binary "$cnf" "$other/$name.drat" >/dev/null || rc=$?
      [ "$rc" = 20 ] || { echo "$inst: cadical answers $rc (not 20, UNSAT) on $name.cnf"; exit 1; }
    done
    local theirs
    theirs=$("$bin" check-proof "$other" | tail -1)
    case "$theirs" in
      "verified: "*) ;;
      *) echo "$inst: check-proof on cadical's proofs says: $theirs"; exit 1 ;;
    esac
    second="; cadical: UNSAT, its proofs verified"
  elif [ "${CI:-}" = true ]; then
    echo "cadical is missing (.ci/setup/70-cadical.sh installs it)"; exit 1
  fi
  echo "$inst: optimum $opt; $last$second"
}
certify rect10x7-hole-to-square8 2 square
certify rect15x10-hole-to-square12 3 square
certify squares-3-4-split-to-5 4 square
certify squares-12-5-joined-to-13 3 square
certify squares-6-6-7-split-to-11 5 square
certify tri-triangle8-to-rect4x8 2 tri4
certify cube4-cavity-to-7x4x2 4 cubic
certify cubes-3-4-5-to-6 8 cubic
