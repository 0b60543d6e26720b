#!/usr/bin/python3
"""A design study of the paper's mechanism on a dask.distributed cluster.

Varies the crank's parabola (coefficient a, JSON path links[1].contours[0].a), the radius of disk 3
(links[2].contours[0].radius) and the ground pivot of disk 4 (pairs[3].at[0].x) over a Latin hypercube (or a
grid), solves every variant over the scene's sweep with the contact analysis, and writes DIR/results.csv, one
row per variant: its parameters, how many poses were solved, the range of the input reached without a break,
the first status that is not "ok", the swing of disk 4, the largest pressure angle at each contact pair (A:
crank on disk 3, B: disk 3 on disk 4; docs/analysis.md) and the worst residual; and DIR/study.png, the
largest pressure angle at B against the swing of disk 4, coloured by a.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/design_study.py --variants 1000 --workers 2 --out study
    ... --scheduler tcp://10.0.0.5:8786        # the same study on a running cluster (docs/python.md)

Without --scheduler a LocalCluster with --workers worker processes runs on this machine. The variants are
built here (rollkin.Scene.modified checks each like a scene file, so a bad value fails before anything is
sent), pickled to the workers in chunks (a Scene pickles as its JSON document), and each chunk is solved by
rollkin.solve_many on its worker. A variant that cannot be assembled is a row with first_problem
"cannot_assemble", not a failure of the study. Both files are written only when every chunk came back, to
temporaries renamed into DIR together; DIR is created if missing, and an existing DIR keeps its other files.
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
# The varied values: JSON path -> (column name, low, high).
PARAMETERS = {
    "links[1].contours[0].a": ("a", 0.35, 0.65),
    "links[2].contours[0].radius": ("radius3", 0.9, 1.1),
    "pairs[3].at[0].x": ("pivot_x", 6.6, 7.4),
}
FIELDS = [name for name, _, _ in PARAMETERS.values()] + [
    "solved", "poses", "reached_from_deg", "reached_to_deg", "first_problem", "swing_deg",
    "max_pressure_angle_A_deg", "max_pressure_angle_B_deg", "worst_residual"]


def design(kind, n, seed):
    """n points in the unit cube of len(PARAMETERS) dimensions: a Latin hypercube (one point in each of n
    slices of every axis, slices paired at random) or the grid with ceil(n^(1/d)) values per axis, first n."""
    d = len(PARAMETERS)
    if kind == "lhs":
        rng = np.random.default_rng(seed)
        return np.column_stack([(rng.permutation(n) + rng.random(n)) / n for _ in range(d)])
    per_axis = max(1, math.ceil(round(n ** (1.0 / d), 9)))
    axis = np.linspace(0.0, 1.0, per_axis) if per_axis > 1 else np.array([0.5])
    mesh = np.stack(np.meshgrid(*[axis] * d, indexing="ij"), axis=-1).reshape(-1, d)
    return mesh[:n]


def values_of(unit_point):
    """The JSON path -> value overrides of one design point."""
    return {path: float(lo + u * (hi - lo)) for (path, (_, lo, hi)), u in zip(PARAMETERS.items(), unit_point)}


def reached(table, input_name):
    """The input range from the sweep's first value up to the last solved one before the first break."""
    ok = table["status"] == "ok"
    if not ok[0]:
        return math.nan, math.nan
    stop = len(ok) if ok.all() else int(np.argmin(ok))
    values = table[input_name][:stop]
    return float(values.min()), float(values.max())


def metrics(table, input_name):
    """The study's numbers for one solved variant (its table as rollkin returns it)."""
    status = table["status"]
    ok = status == "ok"
    problems = [s for s in status if s != "ok"]
    row = {"solved": int(ok.sum()), "poses": len(status), "first_problem": problems[0] if problems else ""}
    row["reached_from_deg"], row["reached_to_deg"] = reached(table, input_name)
    angle = table["link4.angle"][ok]
    row["swing_deg"] = float(angle.max() - angle.min()) if angle.size else math.nan
    for pair in ("A", "B"):
        p = table[pair + ".pressure_angle"][ok]
        p = p[np.isfinite(p)]
        row["max_pressure_angle_%s_deg" % pair] = float(p.max()) if p.size else math.nan
    row["worst_residual"] = float(table["residual"][ok].max()) if ok.any() else math.nan
    return row


def solve_chunk(scenes):
    """Runs on a dask worker: one batch, one thread (dask runs one task per worker thread)."""
    input_name = scenes[0].inputs[0]
    return [metrics(t, input_name) for t in rollkin.solve_many(scenes, threads=1, analysis=True)]


def csv_text(rows):
    lines = [",".join(FIELDS)]
    for r in rows:
        lines.append(",".join(repr(r[k]) if isinstance(r[k], float) else str(r[k]) for k in FIELDS))
    return "\n".join(lines) + "\n"


def write_png(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.4), dpi=100)
    swing = [r["swing_deg"] for r in rows]
    pressure = [r["max_pressure_angle_B_deg"] for r in rows]
    whole = np.array([r["solved"] == r["poses"] for r in rows])
    a = np.array([r["a"] for r in rows])
    dots = ax.scatter(np.array(swing)[whole], np.array(pressure)[whole], c=a[whole], s=12, cmap="viridis")
    fig.colorbar(dots, ax=ax, label="parabola coefficient a")
    ax.set_xlabel("swing of disk 4 over the sweep (deg)")
    ax.set_ylabel("largest pressure angle at B (deg)")
    ax.set_title("%d variants, %d solved over the whole sweep" % (len(rows), whole.sum()))
    fig.tight_layout()
    fig.savefig(path, format="png")
    plt.close(fig)


def write_all(directory, files):
    """Writes {name: writer(path)} into directory all or nothing: each to a temporary in the directory, then
    renamed only when every one is complete; on any failure the temporaries are removed."""
    directory.mkdir(parents=True, exist_ok=True)
    umask = os.umask(0)
    os.umask(umask)
    temporaries = {}
    try:
        for name, writer in files.items():
            fd, tmp = tempfile.mkstemp(dir=directory, prefix="." + name + ".", suffix=".tmp")
            os.close(fd)
            temporaries[name] = tmp
            os.chmod(tmp, 0o666 & ~umask)  # the mode of a normally created file, not mkstemp's 0600
            writer(tmp)
        for name, tmp in temporaries.items():
            os.replace(tmp, directory / name)
    except BaseException:
        for tmp in temporaries.values():
            if os.path.exists(tmp):
                os.unlink(tmp)
        raise


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--variants", type=int, default=1000, help="number of variants (default 1000)")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (without --scheduler)")
    parser.add_argument("--out", required=True, help="directory for results.csv and study.png")
    parser.add_argument("--scheduler", help="address of a running dask scheduler, e.g. tcp://10.0.0.5:8786")
    parser.add_argument("--design", choices=["lhs", "grid"], default="lhs", help="Latin hypercube (default) or grid")
    parser.add_argument("--seed", type=int, default=1, help="seed of the Latin hypercube")
    parser.add_argument("--chunk", type=int, default=0, help="variants per task (default: about 4 tasks per worker)")
    args = parser.parse_args()
    if args.variants < 1 or args.workers < 1 or args.chunk < 0:
        parser.error("--variants and --workers must be at least 1, --chunk at least 0")
    out = pathlib.Path(args.out)
    if out.exists() and not out.is_dir():
        parser.error("--out %s is a file; it names the directory for results.csv and study.png" % out)
    if out.resolve() in (SCENE.parent.resolve(), HERE):
        parser.error("--out %s is a source directory; choose another directory" % out)

    base = rollkin.load_scene(SCENE)
    points = design(args.design, args.variants, args.seed)
    variants = [base.modified(values_of(p)) for p in points]

    cluster = None if args.scheduler else LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                                                       dashboard_address=None)
    try:
        with Client(args.scheduler or cluster) as client:
            workers = max(1, len(client.scheduler_info()["workers"]))
            chunk = args.chunk or max(1, math.ceil(len(variants) / (4 * workers)))
            chunks = [variants[i:i + chunk] for i in range(0, len(variants), chunk)]
            results = client.gather(client.map(solve_chunk, chunks, pure=False))
    finally:
        if cluster is not None:
            cluster.close()

    rows = []
    for p, m in zip(points, (m for part in results for m in part)):
        row = {PARAMETERS[path][0]: v for path, v in values_of(p).items()}
        row.update(m)
        rows.append(row)
    text = csv_text(rows)

    def write_csv(path):
        with open(path, "w", newline="") as f:
            f.write(text)

    write_all(out, {"results.csv": write_csv, "study.png": lambda path: write_png(rows, path)})

    whole = [r for r in rows if r["solved"] == r["poses"]]
    print("%d variants on %d worker(s), %d solved over the whole sweep, written to %s" %
          (len(rows), workers, len(whole), out / "results.csv"))
    if whole:
        best = max(whole, key=lambda r: r["swing_deg"])
        print("largest swing of disk 4 with every pose solved: %.4f deg at a = %.4f, disk 3 radius %.4f, pivot x = "
              "%.4f (largest pressure angle at B %.2f deg)" % (best["swing_deg"], best["a"], best["radius3"],
                                                             best["pivot_x"], best["max_pressure_angle_B_deg"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
