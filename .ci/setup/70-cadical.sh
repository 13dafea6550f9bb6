#!/usr/bin/env bash
# The certificates' CI step (.ci/steps/37-certificates.sh) re-solves every
# certified formula with a second SAT solver: Debian's cadical. Idempotent.
set -euo pipefail
if ! command -v cadical >/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends cadical
fi
