#!/usr/bin/env bash
# dissect-exact builds the CaDiCaL SAT solver from source (the `cadical`
# crate) with the C++ compiler: install g++ when it is missing. Idempotent.
set -euo pipefail
if ! command -v g++ >/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends g++
fi
