#!/usr/bin/python3
"""Timings of the Python module rollkin (rows of docs/benchmark.md, "Python module").

    PYTHONPATH=build/python /usr/bin/python3 bench/python_bench.py [--repeat 7]

Prints one Markdown table row per case, each the median (min-max) of --repeat readings of wall time:
  - load_scene of the paper example, and Scene.modified (copy the document, set one value, build and check);
  - Scene.solve of the paper example in 1-degree and in 0.01-degree steps, per pose, everything included
    (worker thread, sweep, table, NumPy arrays), and the same with analysis=True;
  - solve_many of 16 variants on 1 thread and on 2, and the ratio of the two (the machine's other load
    shows here: the load average is printed).
"""
import argparse
import os
import pathlib
import statistics
import time

import rollkin

SCENE = pathlib.Path(__file__).resolve().parent.parent / "examples" / "paper_fourbar.json"


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


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    r = args.repeat
    print("load average before: %s; %d CPUs" % (" ".join(open("/proc/loadavg").read().split()[:3]), os.cpu_count()))
    print("| case | median (min-max) |")
    print("|---|---:|")
    sc = rollkin.load_scene(SCENE)
    row("load_scene(paper_fourbar.json)", readings(lambda: rollkin.load_scene(SCENE), r), "ms", 1e3)
    row("Scene.modified, one value", readings(lambda: sc.modified({"links[1].contours[0].a": 0.6}), r), "ms", 1e3)
    for step, poses in ((1.0, 151), (0.01, 15001)):
        for analysis in (False, True):
            row("Scene.solve, %d poses%s, per pose" % (poses, ", analysis" if analysis else ""),
                readings(lambda: sc.solve(-50, 100, step, analysis=analysis), r), "us", 1e6 / poses)
    variants = [sc.modified({"links[1].contours[0].a": 0.45 + 0.01 * k}) for k in range(16)]
    one = readings(lambda: rollkin.solve_many(variants, -50, 100, 0.01, threads=1), r)
    two = readings(lambda: rollkin.solve_many(variants, -50, 100, 0.01, threads=2), r)
    row("solve_many, 16 x 15001 poses, threads=1", one, "s", 1)
    row("solve_many, 16 x 15001 poses, threads=2", two, "s", 1)
    print("| speed-up of 2 threads (medians) | %.2f |" % (statistics.median(one) / statistics.median(two)))
    print("load average after: %s" % " ".join(open("/proc/loadavg").read().split()[:3]))


if __name__ == "__main__":
    main()
