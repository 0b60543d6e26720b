#!/usr/bin/env python3
# The closed-form profile of the cam of tests/cli/synthesize_cam.sh (cycloidal 15 mm rise over 90 deg, dwell,
# cycloidal return, dwell; roller 10, base circle 40, counter-clockwise; offset argv[2]), sampled at 200000 cam
# angles, against the points of argv[1]: exit 0 when every point is within argv[3] of that dense polygon (whose
# sag, about 1e-8, is the floor of the comparison).
#   usage: synthesis_closed_form_cam.py POINTS.txt OFFSET LIMIT
import math, sys
import numpy as np
# Closed-form cam profile of cam.json (cycloidal 15 mm over 90 deg, dwell, return, dwell; offset e = 12, roller r = 10,
# base 40, ccw): pitch curve c = R(-theta) (e, y0 + s), profile c + r n, n the unit normal toward the cam centre.
h, e, r, Rb = 15.0, float(sys.argv[2]), 10.0, 40.0
y0 = math.sqrt((Rb + r) ** 2 - e * e)
def law(t):
    d = math.degrees(t) % 360
    def cyc(x): return (x - math.sin(2 * math.pi * x) / (2 * math.pi), (1 - math.cos(2 * math.pi * x)))
    if d <= 90: y, v = cyc(d / 90); return h * y, h * v / (math.pi / 2)
    if d <= 180: return h, 0.0
    if d <= 270: y, v = cyc((d - 180) / 90); return h - h * y, -h * v / (math.pi / 2)
    return 0.0, 0.0
pts = []
N = 200000
for k in range(N):
    t = 2 * math.pi * k / N
    s, ds = law(t)
    c, sn = math.cos(-t), math.sin(-t)
    vx, vy = e, y0 + s
    cx, cy = c * vx - sn * vy, sn * vx + c * vy
    # c' = R(-t) (v' - J v), v' = (0, ds), J v = (-vy, vx)
    wx, wy = 0 + vy, ds - vx
    dx, dy = c * wx - sn * wy, sn * wx + c * wy
    nx, ny = -dy, dx
    L = math.hypot(nx, ny); nx, ny = nx / L, ny / L
    if nx * cx + ny * cy > 0: nx, ny = -nx, -ny
    pts.append((cx + r * nx, cy + r * ny))
P = np.array(pts)
Q = np.array([tuple(map(float, l.split())) for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")])
A, D = P, np.roll(P, -1, axis=0) - P
L2 = (D ** 2).sum(1)
worst = 0.0
for q in Q:
    i = int(np.argmin(((P - q) ** 2).sum(1)))
    idx = [(i + j) % N for j in (-2, -1, 0, 1)]
    best = min(float(np.hypot(*((A[j] + np.clip(((q - A[j]) @ D[j]) / L2[j], 0, 1) * D[j]) - q))) for j in idx)
    worst = max(worst, best)
print("  envelope against the closed-form profile: %d points, worst %.3g" % (len(Q), worst))
sys.exit(0 if worst < float(sys.argv[3]) else 1)
