#!/usr/bin/python3
"""What a user would write instead of rollkin for the paper example (docs/method.md section 4): the same two
equations as bench/hand_paper.hpp, solved pose by pose with scipy.optimize.fsolve (its own finite-difference
Jacobian), the parabola's arc length by scipy.integrate.quad of sqrt(1 + (2 a t)^2), each pose started from
the previous one.

    /usr/bin/python3 bench/scipy_paper.py [--from -50] [--step 0.1] [--poses 1501] [--repeat 3]

Prints "us_per_pose MEDIAN MIN MAX" (wall time of the sweep over the poses, per pose) and, as a check of the
result, "phi_first_deg V": disk 4's angle at the first pose (the library's O_B.theta5 at -50 degrees is
78.18509790019236).
"""
import argparse
import math
import statistics
import time
import warnings

from scipy.integrate import quad
from scipy.optimize import fsolve

A, R3, R4, L2, L4, OBX, OBY = 0.5, 1.0, 4.0, 2.0, 2.0, 7.0, -2.0


def arc_length(x):
    return quad(lambda t: math.sqrt(1 + (2 * A * t) ** 2), 0.0, x)[0]


def equations(u, t, k):
    x, phi = u
    w = math.sqrt(1 + 4 * A * A * x * x)
    cx, cy = L2 - A * x * x + R3 / w, x + 2 * A * R3 * x / w
    c3x, c3y = math.cos(t) * cx - math.sin(t) * cy, math.sin(t) * cx + math.cos(t) * cy
    dx, dy = OBX + L4 * math.cos(phi) - c3x, OBY + L4 * math.sin(phi) - c3y
    psi3 = t + math.atan(2 * A * x) + arc_length(x) / R3
    return [dx * dx + dy * dy - (R3 + R4) ** 2, (R3 + R4) * math.atan2(dy, dx) - R3 * psi3 - R4 * phi - k]


def assembly():
    c3x, c3y, r = L2 + R3, 0.0, R3 + R4
    ex, ey = OBX - c3x, OBY - c3y
    d = math.hypot(ex, ey)
    along = (r * r - L4 * L4 + d * d) / (2 * d)
    h = math.sqrt(r * r - along * along)
    mx, my = c3x + along * ex / d, c3y + along * ey / d
    candidates = [(mx - h * ey / d, my + h * ex / d), (mx + h * ey / d, my - h * ex / d)]
    px, py = max(candidates, key=lambda p: p[1])
    phi, gamma = math.atan2(py - OBY, px - OBX), math.atan2(py - c3y, px - c3x)
    return [0.0, phi], (R3 + R4) * gamma - R4 * phi


def sweep(start, step, poses):
    u, k = assembly()
    t = 0.0
    while t > start:  # from the assembly (theta2 = 0) to the first pose in 1-degree steps
        t = max(t - 1, start)
        u = list(fsolve(equations, u, args=(math.radians(t), k), xtol=1e-12))
    out = []
    for i in range(poses):
        u = list(fsolve(equations, u, args=(math.radians(start + step * i), k), xtol=1e-12))
        out.append(u)
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--from", dest="start", type=float, default=-50.0)
    p.add_argument("--step", type=float, default=0.1)
    p.add_argument("--poses", type=int, default=1501)
    p.add_argument("--repeat", type=int, default=3)
    a = p.parse_args()
    warnings.simplefilter("ignore", RuntimeWarning)  # fsolve's "not making good progress" near the tolerance
    times, result = [], None
    for _ in range(a.repeat):
        t0 = time.perf_counter()
        result = sweep(a.start, a.step, a.poses)
        times.append((time.perf_counter() - t0) / a.poses * 1e6)
    print("us_per_pose %.3f %.3f %.3f" % (statistics.median(times), min(times), max(times)))
    # Check: disk 4's angle at theta2 = -50 (the library's O_B.theta5 there, 78.18509790019236 degrees).
    print("phi_first_deg %.15g" % math.degrees(result[0][1]))


if __name__ == "__main__":
    main()
