#!/usr/bin/env bash
# Browser end-to-end tests of `dissect serve` (crates/web/e2e): Debian's
# chromium and the pinned npm package playwright-core (no browser download).
# Idempotent.
set -euo pipefail
cd "$(dirname "$0")/../.."
if ! [ -x /usr/bin/chromium ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends chromium fonts-dejavu-core
fi
if ! [ -d crates/web/e2e/node_modules/playwright-core ]; then
  (cd crates/web/e2e && npm ci --no-audit --no-fund --ignore-scripts)
fi
