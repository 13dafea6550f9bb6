"""The overhead of spreading one search's explorations over Ray
(dissect.ray.solve) against the local search (dissect.solve), on a local
Ray cluster. Prints a Markdown table for BENCHMARKS.md.

    python python/benchmarks/ray_overhead.py [--cpus 2] [--repeat 3] INSTANCE:LATTICE...

Every run is checked: the Ray answer must equal the local one.
"""

import argparse
import os
import statistics
import sys
import time

import ray

import dissect
import dissect.ray as dray

HERE = os.path.dirname(os.path.abspath(__file__))
INSTANCES = os.environ.get("DISSECT_INSTANCES", os.path.join(HERE, "..", "..", "instances"))


def figures(name, lattice):
    d = os.path.join(INSTANCES, name)
    return [dissect.read_figure(os.path.join(d, f), lattice) for f in sorted(os.listdir(d)) if f.endswith(".txt")]


def timed(f):
    t = time.perf_counter()
    r = f()
    return time.perf_counter() - t, r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cpus", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("instances", nargs="+")
    a = ap.parse_args()
    t_init, _ = timed(lambda: ray.init(num_cpus=a.cpus, include_dashboard=False, log_to_driver=False))
    print(f"ray.init(num_cpus={a.cpus}): {t_init:.1f} s; load {os.getloadavg()[0]:.1f}", file=sys.stderr)
    print("| instance | pieces | explorations | local, 1 thread | local, %d threads | Ray, %d tasks | Ray / local (%d threads) | batches |"
          % (a.cpus, a.cpus, a.cpus))
    print("|---|---|---|---|---|---|---|---|")
    for spec in a.instances:
        name, lattice = spec.split(":")
        figs = figures(name, lattice)
        one, many, spread = [], [], []
        for _ in range(a.repeat):
            t1, d1 = timed(lambda: dissect.solve(figs, seed=a.seed, threads=1))
            tn, dn = timed(lambda: dissect.solve(figs, seed=a.seed, threads=a.cpus))
            tr, dr = timed(lambda: dray.solve(figs, seed=a.seed, tasks=a.cpus))
            assert d1.pieces == dn.pieces == dr.pieces, "Ray and local answers differ"
            one.append(t1)
            many.append(tn)
            spread.append(tr)
        m1, mn, mr = (statistics.median(x) for x in (one, many, spread))
        print(f"| {name} | {dr.piece_count} | {dr._extra['explorations']} | {m1:.2f} s | {mn:.2f} s | {mr:.2f} s | {mr / mn:.1f}× | {len(dr.ray_batches or [])} |")
        sys.stdout.flush()
    ray.shutdown()


if __name__ == "__main__":
    main()
