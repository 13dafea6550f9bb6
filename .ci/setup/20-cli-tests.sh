#!/usr/bin/env bash
# The CLI integration tests (crates/cli/tests) run `dissect` on a terminal
# with util-linux `script` (package bsdutils, essential on Debian, so this
# normally does nothing) and check solutions with python3. Idempotent.
set -euo pipefail
if ! command -v script >/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends bsdutils
fi
command -v python3 >/dev/null || { echo "python3 is needed by the CLI tests"; exit 1; }
