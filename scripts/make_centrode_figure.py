#!/usr/bin/env python3
"""README figure: the anti-parallelogram and its crank centrodes at one pose (docs/img/antiparallelogram_centrodes.svg).

Reads what `rollkin centrodes` and `rollkin solve --csv` wrote and places each centrode with its link's pose:
  build/rollkin centrodes examples/antiparallelogram.json --links crank follower --out c
  build/rollkin solve examples/antiparallelogram.json --from 30 --to 30 --csv pose.csv
  python3 scripts/make_centrode_figure.py c.crank.txt c.follower.txt pose.csv OUT.svg
"""
import csv
import math
import sys


def points(path):
    return [tuple(map(float, line.split())) for line in open(path) if line[:1] not in ("#", "x", "")]


def placed(pts, x, y, angle_deg):
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    return [(x + c * px - s * py, y + s * px + c * py) for px, py in pts]


def main(crank_file, follower_file, pose_file, out):
    pose = next(csv.DictReader(open(pose_file)))
    def link(name):
        return float(pose[name + ".x"]), float(pose[name + ".y"]), float(pose[name + ".angle"])
    crank = placed(points(crank_file), *link("crank"))
    follower = placed(points(follower_file), *link("follower"))
    pin_a = placed([(0, 2)], *link("crank"))[0]
    pin_b = placed([(2, 0)], *link("follower"))[0]
    joints = [(0, 0), pin_a, pin_b, (4, 0)]
    scale, ox, oy = 70, 180, 260  # pixels per metre, origin in pixels (y up in the figure)
    def px(p):
        return f"{ox + scale * p[0]:.1f},{oy - scale * p[1]:.1f}"
    def path(pts):
        return "M" + " L".join(px(p) for p in pts) + " Z"
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="640" height="500" viewBox="0 0 640 500">',
           '<rect width="640" height="500" fill="white"/>',
           '<text x="320" y="24" text-anchor="middle" font-family="sans-serif" font-size="15">'
           'anti-parallelogram at theta2 = 30 deg: the cranks\' centrodes (rollkin centrodes) are ellipses</text>',
           f'<path d="{path(crank)}" fill="none" stroke="#1f77b4" stroke-width="2"/>',
           f'<path d="{path(follower)}" fill="none" stroke="#d62728" stroke-width="2"/>',
           f'<polyline points="{" ".join(px(p) for p in joints)}" fill="none" stroke="black" stroke-width="3"/>']
    svg.append(f'<line x1="{px((0, 0)).split(",")[0]}" y1="{oy}" x2="{px((4, 0)).split(",")[0]}" y2="{oy}" '
               'stroke="gray" stroke-width="2" stroke-dasharray="6 4"/>')  # the frame, O2 to O4
    for p in joints:
        svg.append(f'<circle cx="{px(p).split(",")[0]}" cy="{px(p).split(",")[1]}" r="4" fill="black"/>')
    svg += ['<text x="30" y="470" font-family="sans-serif" font-size="13" fill="#1f77b4">crank centrode (moves with the crank)</text>',
            '<text x="330" y="470" font-family="sans-serif" font-size="13" fill="#d62728">follower centrode (moves with the follower)</text>',
            '</svg>']
    open(out, "w").write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main(*sys.argv[1:5])
