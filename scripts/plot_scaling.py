#!/usr/bin/env python3
"""Log-log plot of us per pose against the number of loops N, from the CSV of build/rollkin_bench_scaling.

    build/rollkin_bench_scaling --csv out/scaling.csv
    python3 scripts/plot_scaling.py out/scaling.csv docs/img/scaling.svg

One panel per family (gear_train, four_bar_chain, cam_gear_train), one line per factorisation; plain SVG (no plotting
library needed).
"""
import csv
import math
import sys

COLOURS = {"dense": "#d62728", "eigen_sparselu": "#2ca02c", "klu": "#1f77b4", "automatic": "#000000"}
LABELS = {"dense": "dense (SmallLU / COD)", "eigen_sparselu": "Eigen SparseLU", "klu": "KLU",
          "automatic": "automatic (what SolveData picks)"}


def read(path):
    data = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            value = float(row["us_per_pose"])
            if math.isfinite(value):
                data.setdefault(row["family"], {}).setdefault(row["method"], []).append((int(row["N"]), value))
    return data


def panel(family, series, x0, width, height, ymin, ymax, nmin, nmax):
    left, top, plot_w, plot_h = x0 + 60, 40, width - 80, height - 100
    lx = lambda n: left + plot_w * (math.log(n) - math.log(nmin)) / (math.log(nmax) - math.log(nmin))
    ly = lambda v: top + plot_h * (math.log(ymax) - math.log(v)) / (math.log(ymax) - math.log(ymin))
    out = [f'<text x="{left + plot_w / 2}" y="{top - 14}" text-anchor="middle" font-size="14">{family}</text>',
           f'<rect x="{left}" y="{top}" width="{plot_w}" height="{plot_h}" fill="none" stroke="#888"/>']
    n = nmin
    while n <= nmax:
        out.append(f'<line x1="{lx(n):.1f}" y1="{top}" x2="{lx(n):.1f}" y2="{top + plot_h}" stroke="#eee"/>')
        out.append(f'<text x="{lx(n):.1f}" y="{top + plot_h + 16}" text-anchor="middle" font-size="11">{n}</text>')
        n *= 2
    decade = 10 ** math.floor(math.log10(ymin))
    while decade <= ymax:
        if decade >= ymin:
            out.append(f'<line x1="{left}" y1="{ly(decade):.1f}" x2="{left + plot_w}" y2="{ly(decade):.1f}" stroke="#eee"/>')
            out.append(f'<text x="{left - 6}" y="{ly(decade) + 4:.1f}" text-anchor="end" font-size="11">{decade:g}</text>')
        decade *= 10
    out.append(f'<text x="{left + plot_w / 2}" y="{top + plot_h + 34}" text-anchor="middle" font-size="12">loops N</text>')
    out.append(f'<text x="{x0 + 14}" y="{top + plot_h / 2}" text-anchor="middle" font-size="12" '
               f'transform="rotate(-90 {x0 + 14} {top + plot_h / 2})">us per pose</text>')
    for k, (method, points) in enumerate(series.items()):
        colour = COLOURS.get(method, "#999")
        dash = ' stroke-dasharray="5,3"' if method == "automatic" else ""
        path = " ".join(f"{'M' if i == 0 else 'L'}{lx(n):.1f},{ly(v):.1f}" for i, (n, v) in enumerate(sorted(points)))
        out.append(f'<path d="{path}" fill="none" stroke="{colour}" stroke-width="2"{dash}/>')
        for n, v in points:
            out.append(f'<circle cx="{lx(n):.1f}" cy="{ly(v):.1f}" r="2.5" fill="{colour}"/>')
        y = top + 14 + 16 * k
        out.append(f'<line x1="{left + 10}" y1="{y - 4}" x2="{left + 30}" y2="{y - 4}" stroke="{colour}" stroke-width="2"{dash}/>')
        out.append(f'<text x="{left + 36}" y="{y}" font-size="11">{LABELS.get(method, method)}</text>')
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_scaling.py SCALING.csv OUT.svg")
    data = read(sys.argv[1])
    values = [v for fam in data.values() for pts in fam.values() for _, v in pts]
    sizes = [n for fam in data.values() for pts in fam.values() for n, _ in pts]
    ymin, ymax = 10 ** math.floor(math.log10(min(values))), 10 ** math.ceil(math.log10(max(values)))
    width, height = 460, 380
    body = []
    for k, (family, series) in enumerate(sorted(data.items(), reverse=True)):
        body += panel(family, series, k * width, width, height, ymin, ymax, min(sizes), max(sizes))
    svg = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width * len(data)}" height="{height}" '
           f'font-family="sans-serif">\n<rect width="100%" height="100%" fill="white"/>\n' + "\n".join(body) + "\n</svg>\n")
    with open(sys.argv[2], "w") as f:
        f.write(svg)


if __name__ == "__main__":
    main()
