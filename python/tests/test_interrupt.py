"""Ctrl-C: a SIGINT to the process stops the search, which returns the best
dissection found so far (or raises KeyboardInterrupt when it has none)."""

import signal
import subprocess
import sys
import time
from typing import Tuple

SCRIPT = r"""
import sys, dissect
a = dissect.Figure.from_text("####\n####\n####\n")
b = dissect.Figure.from_text("######\n######\n")
mode = sys.argv[1]
print("started", flush=True)
try:
    if mode == "found":
        # The paper's level 1 finds a 2-piece dissection at once, then goes
        # on through a million explorations (full_level) until it is stopped.
        d = dissect.solve([a, b], paper=True, prove=False, explorations=10**6,
                          full_level=True, threads=1)
    else:
        # A 3x3 and a 4x4 square into a 5x5 take 4 pieces: level 1 (2
        # pieces) finds nothing and runs until stopped.
        squares = dissect.Figure.from_text("###.####\n###.####\n###.####\n....####\n")
        five = dissect.Figure.from_text("#####\n" * 5)
        d = dissect.solve([squares, five], paper=True, prove=False, max_pieces=2,
                          explorations=10**6, threads=1)
except KeyboardInterrupt:
    print("KeyboardInterrupt", flush=True)
    sys.exit(3)
d.verify()
print("result", d.piece_count, d.stopped, d.interrupted, flush=True)
"""


def run_and_interrupt(mode: str, wait: float = 1.5) -> Tuple[int, str, str, float]:
    p = subprocess.Popen([sys.executable, "-c", SCRIPT, mode], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    assert p.stdout is not None
    assert p.stdout.readline().strip() == "started"
    time.sleep(wait)
    assert p.poll() is None, "the search ended before it was interrupted"
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=60)
    return p.returncode, out, err, time.monotonic() - sent


def test_ctrl_c_returns_the_best_found() -> None:
    code, out, err, took = run_and_interrupt("found")
    assert code == 0, err
    assert out.strip().splitlines()[-1] == "result 2 True True"
    assert took < 10


def test_ctrl_c_with_nothing_found_raises_keyboard_interrupt() -> None:
    code, out, err, took = run_and_interrupt("none")
    assert code == 3, (out, err)
    assert "KeyboardInterrupt" in out
    assert took < 10
