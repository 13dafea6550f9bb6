#!/usr/bin/env bash
# A short bounded fuzz run (issue 17) over every parser: figure text,
# solution JSON, the puzzle fields and the engine commands' inputs (issue
# 27), pictures (PNG, JPEG, SVG), STL meshes and the HTTP API,
# under a 2 GiB address-space cap, 30 s in all. A panic fails the step (the
# inputs are saved under target/fuzz-failures/); an abort or a stack
# overflow ends the process and fails it too. The long runs and their
# counts are in RELIABILITY.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build -q -p dissect-fuzz --release
bin=${CARGO_TARGET_DIR:-target}/release/dissect-fuzz
(ulimit -v 2097152 && "$bin" --seconds 30 --seed "$(date +%s)" --out "${CARGO_TARGET_DIR:-target}/fuzz-failures")
