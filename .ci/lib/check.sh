# Sourced by the CI steps. check_solution LATTICE SOLUTION FIGURE...: checks a
# solution file with the repository's own tools/check_solution.py and, when
# present, the external oracle verify.py ($DISSECT_VERIFY, default
# ../shared/tools/verify.py beside the repository); prints the final line
# (`valid: N pieces`) and fails when either rejects it or they disagree.
check_solution() {
  local lattice=$1 sol=$2
  shift 2
  local here own ext verify
  here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
  own=$(python3 "$here/tools/check_solution.py" --lattice "$lattice" --solution "$sol" "$@") || {
    echo "check_solution.py rejects $sol: $own" >&2; return 1; }
  own=$(tail -n 1 <<<"$own")
  verify=${DISSECT_VERIFY:-$here/../shared/tools/verify.py}
  if [ -f "$verify" ]; then
    ext=$(python3 "$verify" --lattice "$lattice" --solution "$sol" "$@") || {
      echo "verify.py rejects $sol: $ext" >&2; return 1; }
    ext=$(tail -n 1 <<<"$ext")
    [ "$ext" = "$own" ] || { echo "$sol: verify.py says '$ext', check_solution.py '$own'" >&2; return 1; }
  elif [ -z "${_CHECK_SOLUTION_SKIP_SAID:-}" ]; then
    _CHECK_SOLUTION_SKIP_SAID=1
    echo "note: $verify not found: the external oracle's checks are skipped" >&2
  fi
  echo "$own"
}
