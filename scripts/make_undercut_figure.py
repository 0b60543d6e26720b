#!/usr/bin/env python3
"""README figure: the undercut that `rollkin check` reports (docs/img/undercut.svg).

The scene tests/data/undercut_ellipse.json: a roller of radius r = 1.5 inside an elliptical groove (semi-axes
a = 3, b = 2). Drawn from the closed forms: the groove p(t) = (a cos t, b sin t), the path of the roller's
centre c(t) = p(t) + r n(t) (n the inward unit normal), which folds back on itself (a swallowtail) where the
groove's radius of curvature falls below r; the roller at the vertex (3, 0); and the points that
`rollkin check` printed on stderr (the cusps and the vertex), read from the lines given on standard input:
  build/rollkin check tests/data/undercut_ellipse.json 2>&1 | python3 scripts/make_undercut_figure.py OUT.svg
"""
import math
import re
import sys

a, b, r = 3.0, 2.0, 1.5


def groove(t):
    return a * math.cos(t), b * math.sin(t)


def centre(t):
    x, y = groove(t)
    nx, ny = -b * math.cos(t), -a * math.sin(t)
    k = math.hypot(nx, ny)
    return x + r * nx / k, y + r * ny / k


def main(out):
    report = sys.stdin.read()
    points = [(float(x), float(y)) for x, y in re.findall(r"\(point (-?[0-9.e+-]+), (-?[0-9.e+-]+)\)", report)]
    scale, ox, oy = 110, 360, 250
    def px(p):
        return f"{ox + scale * p[0]:.1f},{oy - scale * p[1]:.1f}"
    n = 720
    ts = [2 * math.pi * k / n for k in range(n)]
    svg = ['<svg xmlns="http://www.w3.org/2000/svg" width="720" height="550" viewBox="0 0 720 550">',
           '<rect width="720" height="550" fill="white"/>',
           '<text x="360" y="24" text-anchor="middle" font-family="sans-serif" font-size="15">'
           'rollkin check: a roller of radius 1.5 cannot enter the groove\'s ends (radius 4/3)</text>',
           f'<path d="M{" L".join(px(groove(t)) for t in ts)} Z" fill="#f3e3c3" fill-opacity="0.0" stroke="#8c564b" stroke-width="2"/>',
           f'<path d="M{" L".join(px(centre(t)) for t in ts)} Z" fill="none" stroke="#1f77b4" stroke-width="1.5" stroke-dasharray="5 3"/>']
    cx, cy = px((a - r, 0)).split(",")
    svg.append(f'<circle cx="{cx}" cy="{cy}" r="{scale * r:.1f}" fill="none" stroke="#2ca02c" stroke-width="2"/>')
    for p in points:
        x, y = px(p).split(",")
        svg.append(f'<circle cx="{x}" cy="{y}" r="5" fill="#d62728"/>')
    svg += ['<text x="20" y="510" font-family="sans-serif" font-size="13" fill="#8c564b">groove (ellipse 3 x 2, material outside)</text>',
            '<text x="20" y="530" font-family="sans-serif" font-size="13" fill="#1f77b4">path of the roller centre: folds back near the ends</text>',
            '<text x="380" y="510" font-family="sans-serif" font-size="13" fill="#2ca02c">roller at the vertex (3, 0)</text>',
            '<text x="380" y="530" font-family="sans-serif" font-size="13" fill="#d62728">points named by rollkin check (stderr)</text>',
            '</svg>']
    open(out, "w").write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main(sys.argv[1])
