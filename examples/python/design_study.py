#!/usr/bin/python3
"""A design study of the paper's mechanism on a dask.distributed cluster.

Varies the crank's parabola (coefficient a, JSON path links[1].contours[0].a) and the ground pivot of disk 4
(pairs[3].at[0].x) over a grid, solves every variant over the scene's sweep with the contact analysis, and
writes one CSV row per variant: how many poses were solved, the first status that is not "ok", the swing of
disk 4 (range of link4.angle over the solved poses) and the largest pressure angle at each contact pair (A:
crank on disk 3, B: disk 3 on disk 4; docs/analysis.md).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/design_study.py --out study.csv [--grid 8] [--workers 2]

The variants are built here (rollkin.Scene.modified checks each like a scene file, so a bad value fails before
anything is sent), pickled to the workers (a Scene pickles as its JSON document) in chunks, and each chunk is
solved by rollkin.solve_many on its worker. A variant that cannot be assembled is a row with status
"cannot_assemble", not a failure of the study. The CSV is written only when every chunk came back, to a
temporary file renamed onto --out (never onto the scene file).
"""
import argparse
import csv
import math
import os
import pathlib
import sys
import tempfile

import numpy as np
import rollkin
from dask.distributed import Client, LocalCluster

HERE = pathlib.Path(__file__).resolve().parent
SCENE = HERE.parent / "paper_fourbar.json"
FIELDS = ["a", "pivot_x", "solved", "poses", "first_problem", "swing_deg", "max_pressure_angle_A_deg",
          "max_pressure_angle_B_deg"]


def metrics(table):
    """The study's numbers for one solved variant (its table as rollkin returns it)."""
    status = table["status"]
    ok = status == "ok"
    problems = [s for s in status if s != "ok"]
    row = {"solved": int(ok.sum()), "poses": len(status), "first_problem": problems[0] if problems else ""}
    angle = table["link4.angle"][ok]
    row["swing_deg"] = float(angle.max() - angle.min()) if angle.size else math.nan
    for pair in ("A", "B"):
        p = table[pair + ".pressure_angle"][ok]
        p = p[np.isfinite(p)]
        row["max_pressure_angle_%s_deg" % pair] = float(p.max()) if p.size else math.nan
    return row


def solve_chunk(scenes):
    """Runs on a dask worker: one batch, one thread (the cluster provides the parallelism)."""
    return [metrics(t) for t in rollkin.solve_many(scenes, threads=1, analysis=True)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="the CSV to write (one row per variant)")
    parser.add_argument("--grid", type=int, default=8, help="values per parameter (grid x grid variants)")
    parser.add_argument("--workers", type=int, default=2, help="dask worker processes")
    parser.add_argument("--chunk", type=int, default=8, help="variants per task")
    args = parser.parse_args()
    if args.grid < 1 or args.workers < 1 or args.chunk < 1:
        parser.error("--grid, --workers and --chunk must be at least 1")
    out = pathlib.Path(args.out)
    if out.exists() and out.resolve() == SCENE:
        parser.error("--out names the scene file; choose another file")

    base = rollkin.load_scene(SCENE)
    grid = [(a, x) for a in np.linspace(0.35, 0.65, args.grid) for x in np.linspace(6.6, 7.4, args.grid)]
    variants = [base.modified({"links[1].contours[0].a": float(a), "pairs[3].at[0].x": float(x)}) for a, x in grid]
    chunks = [variants[i:i + args.chunk] for i in range(0, len(variants), args.chunk)]

    with LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        results = client.gather(client.map(solve_chunk, chunks, pure=False))
    rows = [dict(a=float(a), pivot_x=float(x), **m) for (a, x), m in zip(grid, (m for chunk in results for m in chunk))]

    fd, tmp = tempfile.mkstemp(dir=out.parent if str(out.parent) else ".", prefix=out.name + ".", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", newline="") as f:
            w = csv.DictWriter(f, FIELDS)
            w.writeheader()
            for r in rows:
                w.writerow({k: (repr(v) if isinstance(v, float) else v) for k, v in r.items()})
        os.replace(tmp, out)
    except BaseException:
        os.unlink(tmp)
        raise

    whole = [r for r in rows if r["solved"] == r["poses"]]
    print("%d variants, %d solved over the whole sweep, written to %s" % (len(rows), len(whole), out))
    if whole:
        best = max(whole, key=lambda r: r["swing_deg"])
        print("largest swing of disk 4 with every pose solved: %.4f deg at a = %.4f, pivot x = %.4f "
              "(largest pressure angle at B %.2f deg)" % (best["swing_deg"], best["a"], best["pivot_x"],
                                                   best["max_pressure_angle_B_deg"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
