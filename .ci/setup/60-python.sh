#!/usr/bin/env bash
# The Python package's CI step (.ci/steps/60-python.sh) makes a virtual
# environment with python3's venv module and pip; Debian's python3 needs
# python3-venv for that. Idempotent; everything else comes from PyPI in
# the step itself.
set -euo pipefail
command -v python3 >/dev/null || { echo "python3 is needed by the Python package"; exit 1; }
if ! python3 -c 'import venv, ensurepip' 2>/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends python3-venv python3-pip
fi
