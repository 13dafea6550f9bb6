#!/usr/bin/env bash
# End-to-end test of the browser studio: `dissect serve` on a free port,
# crates/web/e2e/studio.test.mjs in Debian's headless chromium
# (playwright-core), solutions checked by crates/web/e2e/check.mjs
# (tools/check_solution.py, and ../shared/tools/verify.py when present).
# The tests write docs/studio-*.png and docs/motion-*.png (the motion
# player and the shared HTML page: crates/web/e2e/motion.test.mjs); the
# tri3 and hex studio: crates/web/e2e/lattices.test.mjs.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
target=${CARGO_TARGET_DIR:-$root/target}
cargo build --release -p dissect-cli --quiet
bin=$target/release/dissect

[ -x /usr/bin/chromium ] || { echo "chromium missing: run .ci/setup/50-web.sh" >&2; exit 1; }
[ -d crates/web/e2e/node_modules/playwright-core ] || (cd crates/web/e2e && npm ci --no-audit --no-fund --ignore-scripts)

log=$(mktemp -d)
"$bin" serve --port 0 --max-solves 2 >"$log/out" 2>"$log/err" &
pid=$!
trap 'kill "$pid" 2>/dev/null || true; wait "$pid" 2>/dev/null || true; rm -rf "$log"' EXIT
for _ in $(seq 1 100); do
  [ -s "$log/out" ] && break
  kill -0 "$pid" 2>/dev/null || { cat "$log/err" >&2; exit 1; }
  sleep 0.1
done
url=$(head -n 1 "$log/out")
case "$url" in http://127.0.0.1:*) ;; *) echo "unexpected first line: $url" >&2; exit 1 ;; esac
echo "studio at $url"

verify=${DISSECT_VERIFY:-$root/../shared/tools/verify.py}
cd crates/web/e2e
DISSECT_URL=$url DISSECT_VERIFY=$verify DISSECT_DOCS=$root/docs \
  timeout 420 node --test --test-concurrency=1 studio.test.mjs lattices.test.mjs motion.test.mjs
