#!/usr/bin/python3
"""Writes shapes/cam_profile.dxf, the DXF cam of examples/dxf_cam.json, with ezdxf (Debian python3-ezdxf).

Run from anywhere:  /usr/bin/python3 scripts/make_cam_profile.py

The profile is a closed uniform cubic B-spline (one SPLINE entity on layer CAM, $INSUNITS 4 = mm, written by
ezdxf with wrapped control points and an unclamped knot vector, as CAD programs save periodic splines). Its
12 control points lie at polar angles k * 30 deg on a base circle of radius 30 mm with a lobe of 16 mm
towards +y; the control polygon is convex (checked below), so the curve is convex and curvature-continuous:
a flat-faced follower stays in single-point contact with it all the way round.
"""
import math
import os

import ezdxf
from ezdxf.math import closed_uniform_bspline

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "shapes", "cam_profile.dxf")


def control_points():
    pts = []
    for k in range(12):
        a = math.radians(30 * k)
        r = 30 + 16 * math.exp(-((a - math.pi / 2) / 0.9) ** 2)
        pts.append((round(r * math.cos(a), 6), round(r * math.sin(a), 6)))
    return pts


def is_convex(pts):
    n = len(pts)
    turns = []
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = pts[i - 1], pts[i], pts[(i + 1) % n]
        turns.append((bx - ax) * (cy - by) - (by - ay) * (cx - bx))
    return all(t > 0 for t in turns)


def main():
    pts = control_points()
    assert is_convex(pts), "control polygon must be convex (counter-clockwise)"
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 4
    spline = doc.modelspace().add_spline(dxfattribs={"layer": "CAM"})
    spline.apply_construction_tool(closed_uniform_bspline(pts, order=4))
    spline.closed = True
    doc.saveas(OUT)
    print(f"wrote {os.path.normpath(OUT)}: SPLINE {spline.dxf.handle}, {len(pts)} control points")


if __name__ == "__main__":
    main()
