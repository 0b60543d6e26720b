#!/usr/bin/python3
"""Timings of the Python module rollkin (rows of docs/benchmark.md, "Python module").

    PYTHONPATH=build/python /usr/bin/python3 bench/python_bench.py [--repeat 7] [--variants 2000]

Prints Markdown table rows, each the median (min-max) of --repeat readings of wall time:
  - load_scene of the paper example, and Scene.modified (copy the document, set one value, build and check);
  - Scene.solve of the paper example in 1-degree and in 0.01-degree steps, per pose, everything included
    (worker thread, sweep, table, NumPy arrays), and the same with analysis=True;
  - a design-study batch: --variants variants of the paper example (151 poses each) as variants per second,
    through the bare C++ loop (assembly and sweep, no table: rollkin._sweep_seconds), the C++ loop that also
    makes the table solve() returns (io::sweep_columns, made and dropped: _sweep_seconds(table=True)),
    solve_many on one thread, solve_many on all cores (with the speed-up against one thread and its ratio to the number of
    cores), and dask.distributed with 2 local worker processes (cluster start excluded); then the overhead
    per variant of Python and of dask against the C++ loop, and the CPU time per variant of solve_many over
    that of each C++ loop (over the bare solve: what the table and Python add; over the loop with the
    table: what Python adds);
  - a batch of few long sweeps: --long-variants variants of 15,001 poses each (0.01-degree steps) through
    solve_many on one thread and on all cores, and its speed-up (its work per variant is large, so the
    speed-up shows what the threads share rather than the calls' fixed costs).
The load average before and after, and the process's CPU time over wall time on all cores, show how much of
the machine was free: on a shared machine the all-cores speed-up is bounded by the idle cores.
"""
import argparse
import os
import pathlib
import statistics
import time

import rollkin

SCENE = pathlib.Path(__file__).resolve().parent.parent / "examples" / "paper_fourbar.json"
SWEEP = (-50, 100, 1)  # the scene's own sweep: 151 poses


def readings(f, repeat):
    out = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        out.append(time.perf_counter() - t0)
    return out


def row(case, values, unit, scale):
    v = [x * scale for x in values]
    print("| %s | %.3g (%.3g-%.3g) %s |" % (case, statistics.median(v), min(v), max(v), unit))


def rate_row(case, seconds, n):
    """Variants per second: n / each reading (the median of the rates is n / the median time)."""
    v = sorted(n / s for s in seconds)
    print("| %s | %.0f (%.0f-%.0f) variants/s |" % (case, statistics.median(v), v[0], v[-1]))


def cpu_seconds(f):
    """Process CPU time (all threads) of f()."""
    t0 = time.process_time()
    f()
    return time.process_time() - t0


def load():
    return " ".join(open("/proc/loadavg").read().split()[:3])


def solve_chunk(scenes):
    return len(rollkin.solve_many(scenes, *SWEEP, threads=1))


def dask_readings(variants, repeat, workers):
    from dask.distributed import Client, LocalCluster
    chunk = max(1, len(variants) // (4 * workers))
    chunks = [variants[i:i + chunk] for i in range(0, len(variants), chunk)]
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        client.gather(client.map(solve_chunk, chunks[:workers], pure=False))  # warm the workers (import rollkin)
        return readings(lambda: client.gather(client.map(solve_chunk, chunks, pure=False)), repeat)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--variants", type=int, default=2000)
    parser.add_argument("--long-variants", type=int, default=8, help="variants of 15,001 poses (0: no such rows)")
    parser.add_argument("--no-dask", action="store_true", help="leave out the dask row")
    args = parser.parse_args()
    r, n = args.repeat, args.variants
    cores = len(os.sched_getaffinity(0))
    print("load average before: %s; %d CPUs" % (load(), cores))
    print("| case | median (min-max) |")
    print("|---|---:|")
    sc = rollkin.load_scene(SCENE)
    row("load_scene(paper_fourbar.json)", readings(lambda: rollkin.load_scene(SCENE), r), "ms", 1e3)
    row("Scene.modified, one value", readings(lambda: sc.modified({"links[1].contours[0].a": 0.6}), r), "ms", 1e3)
    for step, poses in ((1.0, 151), (0.01, 15001)):
        for analysis in (False, True):
            row("Scene.solve, %d poses%s, per pose" % (poses, ", analysis" if analysis else ""),
                readings(lambda: sc.solve(-50, 100, step, analysis=analysis), r), "us", 1e6 / poses)

    variants = [sc.modified({"links[1].contours[0].a": 0.45 + 0.1 * k / n}) for k in range(n)]
    bare_cpu, table_cpu, one_cpu = [], [], []
    bare = readings(lambda: bare_cpu.append(cpu_seconds(lambda: [rollkin._sweep_seconds(v, *SWEEP) for v in variants])), r)
    table = readings(lambda: table_cpu.append(cpu_seconds(
        lambda: [rollkin._sweep_seconds(v, *SWEEP, table=True) for v in variants])), r)
    one = readings(lambda: one_cpu.append(cpu_seconds(lambda: rollkin.solve_many(variants, *SWEEP, threads=1))), r)
    cpu0 = time.process_time()
    every = readings(lambda: rollkin.solve_many(variants, *SWEEP, threads=0), r)
    cpu_share = (time.process_time() - cpu0) / sum(every)
    rate_row("%d variants x 151 poses: C++ loop (assembly + sweep), one thread" % n, bare, n)
    rate_row("... C++ loop with the table (assembly + sweep + io::sweep_columns), one thread", table, n)
    rate_row("... solve_many, threads=1", one, n)
    rate_row("... solve_many, threads=0 (%d cores)" % cores, every, n)
    speedup = statistics.median(one) / statistics.median(every)
    print("| speed-up of all cores (medians) | %.2f = %.2f x cores (CPU time / wall time %.2f) |" %
          (speedup, speedup / cores, cpu_share))
    per_variant = lambda t: statistics.median(t) / n * 1e6
    print("| overhead of Python per variant (solve_many threads=1 - C++ loop) | %.1f us (C++ loop %.1f us) |" %
          (per_variant(one) - per_variant(bare), per_variant(bare)))
    print("| CPU time per variant (process CPU time: the other jobs of a shared machine do not count): solve_many "
          "threads=1 %.1f us, C++ loop %.1f us, ratio %.2f; C++ loop with the table %.1f us, ratio %.2f |" %
          (per_variant(one_cpu), per_variant(bare_cpu), per_variant(one_cpu) / per_variant(bare_cpu),
           per_variant(table_cpu), per_variant(one_cpu) / per_variant(table_cpu)))
    if args.long_variants:
        m = args.long_variants
        long_variants = variants[:: max(1, n // m)][:m]
        fine = (-50, 100, 0.01)
        one_cpu, every_cpu = [], []
        one = readings(lambda: one_cpu.append(cpu_seconds(lambda: rollkin.solve_many(long_variants, *fine, threads=1))), r)
        every = readings(lambda: every_cpu.append(cpu_seconds(lambda: rollkin.solve_many(long_variants, *fine, threads=0))), r)
        rate_row("%d variants x 15001 poses: solve_many, threads=1" % m, one, m)
        rate_row("... solve_many, threads=0 (%d cores)" % cores, every, m)
        speedup = statistics.median(one) / statistics.median(every)
        print("| speed-up of all cores, %d x 15001 poses (medians) | %.2f = %.2f x cores (CPU time per variant: "
              "%.2f ms on one thread, %.2f ms on all) |" % (m, speedup, speedup / cores, statistics.median(one_cpu) / m * 1e3,
                                                            statistics.median(every_cpu) / m * 1e3))
    if not args.no_dask:
        dask = dask_readings(variants, r, 2)
        rate_row("... dask.distributed, 2 local workers", dask, n)
        print("| overhead of dask per variant (2 workers x wall time per variant - C++ loop) | %.1f us |" %
              (2 * per_variant(dask) - per_variant(bare)))
    print("load average after: %s" % load())


if __name__ == "__main__":
    main()
