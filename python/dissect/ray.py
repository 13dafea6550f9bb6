"""``dissect`` on a Ray cluster (``pip install ./python[ray]``).

* ``solve_many(problems, **options)``: many independent problems as Ray
  tasks on whatever cluster ``ray.init()`` connected to (locally: all
  cores); results in the order of ``problems``.
* ``solve(figures, ...)``: one search whose explorations are spread over
  the cluster's workers; the same answer as ``dissect.solve`` for the same
  seed when no time limit stops it.

Every worker needs the ``dissect`` package installed (on a local cluster it
shares the driver's environment).
"""

from __future__ import annotations

from typing import Any, Dict, List, Optional, Sequence, Union

import ray

import dissect
from dissect import Dissection, Figure

__all__ = ["solve_many", "solve"]

Problem = Union[Sequence[Figure], Dict[str, Any]]


@ray.remote
def _solve_task(figures: List[Figure], options: Dict[str, Any]) -> Dissection:
    return dissect.solve(figures, **options)


def _split(problem: Problem, options: Dict[str, Any]):
    if isinstance(problem, dict):
        problem = dict(problem)
        try:
            figures = problem.pop("figures")
        except KeyError:
            raise dissect.ProblemError("a problem given as a dict needs a 'figures' key") from None
        return list(figures), {**options, **problem}
    return list(problem), dict(options)


def solve_many(
    problems: Sequence[Problem],
    return_exceptions: bool = False,
    **options: Any,
) -> List[Union[Dissection, Exception]]:
    """Solves every problem as its own Ray task; returns the dissections in
    the order of ``problems``.

    A problem is a list of figures, or a dict with ``figures`` and options
    that override ``options`` for that problem (e.g. ``{"figures": [a, b],
    "seed": 7}``). ``options`` are ``dissect.solve``'s. Each task asks Ray
    for ``threads`` CPUs and runs the solver with that many threads
    (default 1: one problem per core). With ``return_exceptions=True`` a
    problem that fails (``NoDissectionFound``, ``ProblemError``, ...) gets
    its exception in the list; otherwise the first failure is raised.
    """
    options.setdefault("threads", 1)
    refs = []
    for p in problems:
        figures, opts = _split(p, options)
        figures = dissect._figures(figures)  # bad input fails here, not on a worker
        cpus = max(1, int(opts.get("threads") or 1))
        refs.append(_solve_task.options(num_cpus=cpus).remote(figures, opts))
    out: List[Union[Dissection, Exception]] = []
    for ref in refs:
        try:
            out.append(ray.get(ref))
        except ray.exceptions.RayTaskError as e:
            cause = e.as_instanceof_cause()
            if not return_exceptions:
                for r in refs:
                    ray.cancel(r)
                raise cause from None
            out.append(cause)
    return out
