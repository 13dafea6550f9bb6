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

import os
from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Tuple, Union

try:
    import ray
except ImportError as e:  # pragma: no cover - depends on the environment
    raise ImportError(
        "dissect.ray needs Ray: pip install './python[ray]' (or pip install ray)"
    ) from e

import dissect
from dissect import Dissection, Figure, _dissect

__all__ = ["solve_many", "solve", "RayBatch"]

Problem = Union[Sequence[Figure], Dict[str, Any]]


class RayBatch(NamedTuple):
    """One batch of explorations ``dissect.ray.solve`` sent to Ray."""

    #: The round, level and descent of the level search it belongs to.
    round: int
    level: int
    descent: bool
    #: How many explorations it held.
    explorations: int
    #: How many Ray tasks it was cut into.
    tasks: int
    #: The process ids of the Ray workers that ran them.
    workers: Tuple[int, ...]


@ray.remote
def _solve_task(figures: List[Figure], options: Dict[str, Any]) -> Dissection:
    return dissect.solve(figures, **options)


def _split(problem: Problem, options: Dict[str, Any]) -> Tuple[List[Figure], Dict[str, Any]]:
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
    its exception in the list; otherwise the first failure is raised (the
    other tasks still run to their end).
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
            cause: Exception = e.as_instanceof_cause()  # type: ignore[no-untyped-call]
            if not return_exceptions:
                # The other tasks are left to finish: cancelling a task as it
                # completes crashes the driver in Ray 2.60 ("Tried to complete
                # task that was not pending"), and each task ends by itself.
                raise cause from None
            out.append(cause)
    return out


# One Explorer per problem per worker process: building it (shapes, layout,
# moved point sets) costs more than an exploration of a small figure.
_explorers: Dict[bytes, Any] = {}


@ray.remote
def _explore_task(
    key: bytes,
    problem: Tuple[List[Figure], int, Dict[str, Any]],
    round_: int,
    level: int,
    descent: bool,
    indices: List[int],
    parents: List[bytes],
) -> Tuple[int, List[bytes]]:
    explorer = _explorers.get(key)
    if explorer is None:
        figures, seed, options = problem
        explorer = _dissect.Explorer(figures, seed=seed, **options)
        _explorers.clear()
        _explorers[key] = explorer
    return os.getpid(), explorer.explore(round_, level, descent, indices, parents)


class _RayExecutor:
    """Sends each batch of explorations to Ray as ``tasks`` tasks of
    consecutive indices, returns their results in index order, and records
    every batch it sent (``batches``)."""

    def __init__(
        self, figures: List[Figure], seed: int, options: Dict[str, Any], tasks: int
    ) -> None:
        import hashlib
        import pickle

        problem = (figures, seed, options)
        self.key = hashlib.sha256(pickle.dumps(problem)).digest()
        self.problem = ray.put(problem)
        self.tasks = tasks
        self._parents: Tuple[Any, Any] = (None, None)
        self.batches: List[RayBatch] = []

    def __call__(
        self, round_: int, level: int, descent: bool, start: int, end: int, parents: List[bytes]
    ) -> List[bytes]:
        # The parents are the same for every batch of a level: put them once.
        key = (round_, level, descent, len(parents), parents[:1])
        if self._parents[0] != key:
            self._parents = (key, ray.put(parents))
        parents_ref = self._parents[1]
        indices = list(range(start, end))
        n = max(1, min(self.tasks, len(indices)))
        chunks = [indices[i * len(indices) // n:(i + 1) * len(indices) // n] for i in range(n)]
        refs = [
            _explore_task.remote(self.key, self.problem, round_, level, descent, c, parents_ref)
            for c in chunks
        ]
        out: List[bytes] = []
        workers = []
        for pid, part in ray.get(refs):
            workers.append(pid)
            out.extend(part)
        self.batches.append(
            RayBatch(round_, level, descent, len(indices), len(refs), tuple(sorted(set(workers))))
        )
        return out


def solve(
    figures: Sequence[Figure],
    seed: int = 1,
    time_limit: Optional[float] = None,
    tasks: Optional[int] = None,
    **options: Any,
) -> Dissection:
    """``dissect.solve`` with the search's explorations spread over the Ray
    cluster: every batch of explorations is cut into ``tasks`` Ray tasks
    (default: the cluster's CPU count) of consecutive explorations. The
    level loop (and the exact lower bound and repair beside it) runs here
    and gets the results back in index order, so the answer is the same as
    ``dissect.solve``'s for the same seed and options when no time limit
    (or Ctrl-C) stops the search. Worth it when explorations are expensive
    (large figures, many explorations, many machines); on small figures
    Ray's per-batch overhead dominates (see BENCHMARKS.md).

    The dissection records what Ray did: ``ray_tasks`` (tasks per batch)
    and ``ray_batches`` (every batch sent, a ``RayBatch`` each).
    """
    figures = dissect._figures(figures)
    if tasks is None:
        cpus = ray.cluster_resources().get("CPU", 1)  # type: ignore[no-untyped-call]
        tasks = max(1, int(cpus))
    if tasks < 1:
        raise dissect.OptionError(f"tasks must be at least 1, got {tasks}")
    options.pop("threads", None)  # the workers run one exploration at a time
    progress = options.pop("progress", None)
    # Checks the options here, with the problem, before anything is sent.
    _dissect.Explorer(figures, seed=seed, **options)
    executor = _RayExecutor(figures, seed, options, tasks)
    result = _dissect.solve(
        figures,
        seed=seed,
        time_limit=time_limit,
        threads=1,
        executor=executor,
        progress=progress,
        **options,
    )
    d = Dissection(figures, result)
    d.ray_tasks = tasks
    d.ray_batches = list(executor.batches)
    return d
