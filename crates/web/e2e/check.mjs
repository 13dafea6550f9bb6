// The independent checks of a solution file the studio wrote: the
// repository's own tools/check_solution.py always, and the external oracle
// verify.py (DISSECT_VERIFY) when it is set and present; otherwise one line
// on stderr says that check is skipped.

import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import { fileURLToPath } from 'node:url';

const CHECK = fileURLToPath(new URL('../../../tools/check_solution.py', import.meta.url));
const VERIFY = process.env.DISSECT_VERIFY;
let skipped = false;

function lastLine(out) {
  return out.trim().split('\n').pop();
}

/** Checks `solution` against `figures` on `lattice`; returns check_solution.py's output. */
export function checkSolution(lattice, solution, figures) {
  const args = ['--lattice', lattice, '--solution', solution, ...figures];
  const own = execFileSync('python3', [CHECK, ...args], { encoding: 'utf8' });
  if (VERIFY && fs.existsSync(VERIFY)) {
    const ext = execFileSync('python3', [VERIFY, ...args], { encoding: 'utf8' });
    assert.equal(lastLine(ext), lastLine(own), `verify.py and check_solution.py disagree on ${solution}`);
  } else if (!skipped) {
    skipped = true;
    process.stderr.write(`note: verify.py not found (DISSECT_VERIFY=${VERIFY ?? ''}): the external oracle's checks are skipped\n`);
  }
  return own;
}
