#!/usr/bin/python3
"""Drawings as CAD programs write them, written by ezdxf (Debian python3-ezdxf), with ezdxf's own
world-coordinate points on every entity of the chain each selector picks, for tests/test_io_dxf_cad.cpp.

    /usr/bin/python3 tests/data/dxf/ezdxf_cad.py OUTDIR

writes OUTDIR/*.dxf and prints, per selection, one block

    case PATH
    select layer NAME | select near X Y [layer NAME] | select handles H1 H2 ...
    closed 0|1
    entity LABEL                the label rollkin gives it ("ARC 2B", "LINE 31 in INSERT 40 in INSERT 3F")
    p X Y                       ezdxf's world (WCS) points on it, repr() of the double

and, for a selection that must be refused, "error TEXT" lines (texts the message must contain).

Drawings:
  layers.dxf   several chains on layer "0": an open chain of LINEs, ARCs (extrusion +Z and -Z), an ELLIPSE with
               axis ratio > 1, a SPLINE with repeated control points and a zero-length LINE, listed out of order and
               drawn either way; a closed LWPOLYLINE with extrusion -Z; a 2D POLYLINE with extrusion -Z and a
               CIRCLE with extrusion -Z; a periodic SPLINE stored with n + 1 knots; a TEXT, a VIEWPORT and a
               MULTILEADER; text after 0 EOF.
  tilt.dxf     an ARC with a tilted extrusion (an error) and a LINE on its layer; a tilted CIRCLE, ELLIPSE,
               LWPOLYLINE, POLYLINE and INSERT, each on a layer of its own (errors).
  blocks.dxf   INSERTs of a block (LINE, ARC with extrusion -Z, ELLIPSE, SPLINE) with rotation, negative and
               non-uniform scale and a base point; a nested INSERT (a block holding a rotated, mirrored INSERT);
               a MINSERT array of a closed block (ARC + LINE), one copy picked by "near"; a block inserting
               itself (an error).

ezdxf's points: LINE start.lerp(end), arc/circle/ellipse .vertices() (WCS), spline construction_tool().point(),
polyline bulges by ezdxf_random.bulge_points (ezdxf's bulge_to_arc in 60 digits); entities of blocks from
ezdxf's Insert.virtual_entities() (MINSERT: multi_insert()), which applies the block transformation (a
non-uniformly scaled ARC becomes an ELLIPSE); through a nested INSERT, ezdxf's points on the block's
entities mapped by the product of ezdxf's Insert.matrix44(); a periodic SPLINE with n + 1 knots (which
ezdxf's BSpline cannot evaluate: it takes knots as clamped) by de Boor's algorithm on the wrapped form.
"""
import math
import os
import sys

import ezdxf
from ezdxf.math import BSpline, Vec2, Vec3

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ezdxf_random import bulge_points, save_with_ratios, to_ocs  # noqa: E402

SAMPLES = 40


def label(e):
    return f"{e.dxftype()} {e.dxf.handle}"


def lerp(a, b, n=SAMPLES):
    a, b = Vec3(a), Vec3(b)
    return [a.lerp(b, i / (n - 1)) for i in range(n)]


def points_of(e):
    """ezdxf's WCS points on a (possibly virtual) entity."""
    t = e.dxftype()
    if t == "LINE":
        return [(v.x, v.y) for v in lerp(e.dxf.start, e.dxf.end)]
    if t in ("ARC", "CIRCLE"):
        s, f = (e.dxf.start_angle, e.dxf.end_angle) if t == "ARC" else (0.0, 360.0)
        while f <= s:
            f += 360.0
        return [(v.x, v.y) for v in e.vertices([s + (f - s) * i / (SAMPLES - 1) for i in range(SAMPLES)])]
    if t == "ELLIPSE":
        s, f = e.dxf.start_param, e.dxf.end_param
        while f <= s:
            f += 2 * math.pi
        return [(v.x, v.y) for v in e.vertices([s + (f - s) * i / (SAMPLES - 1) for i in range(SAMPLES)])]
    if t == "SPLINE":
        bs = e.construction_tool()
        ks = bs.knots()
        lo, hi = ks[bs.order - 1], ks[len(ks) - bs.order]
        return [(v.x, v.y) for v in (bs.point(lo + (hi - lo) * i / (3 * SAMPLES - 1)) for i in range(3 * SAMPLES))]
    if t in ("LWPOLYLINE", "POLYLINE"):
        mirrored = e.dxf.extrusion[2] < 0
        if t == "LWPOLYLINE":
            vs = [(x, y, k) for x, y, _, _, k in e.get_points("xyseb")]
        else:
            vs = [(v.dxf.location.x, v.dxf.location.y, v.dxf.bulge) for v in e.vertices]
        pairs = list(zip(vs, vs[1:] + (vs[:1] if (e.dxf.flags & 1) else [])))
        pts = []
        for (x0, y0, k), (x1, y1, _) in pairs:
            pts += [to_ocs(q, mirrored) for q in bulge_points((x0, y0), (x1, y1), k, SAMPLES)]
        return pts
    raise ValueError(t)


def de_boor(points, p, knots, u):
    """The B-spline point at u (de Boor's algorithm, The NURBS Book A3.1 in its triangular form), for any knot
    vector: ezdxf's BSpline evaluates clamped knot vectors only."""
    k = max(i for i in range(p, len(points)) if knots[i] <= u)
    d = [list(points[j + k - p]) for j in range(p + 1)]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            a = (u - knots[j + k - p]) / (knots[j + 1 + k - r] - knots[j + k - p])
            d[j] = [(1 - a) * d[j - 1][0] + a * d[j][0], (1 - a) * d[j - 1][1] + a * d[j][1]]
    return tuple(d[p])


def periodic_points(control, degree, knots):
    """A periodic spline of n control points and n + 1 knots, as AutoCAD documents it: its first `degree`
    control points repeated after the last, the knots extended periodically by `degree` on either side."""
    n, p = len(control), degree
    period = knots[n] - knots[0]
    ext = [knots[n - p + i] - period for i in range(p)] + list(knots) + [knots[i] + period for i in range(1, p + 1)]
    wrapped = list(control) + list(control[:p])
    lo, hi = knots[0], knots[n]
    return [de_boor(wrapped, p, ext, lo + (hi - lo) * i / (3 * SAMPLES - 1)) for i in range(3 * SAMPLES)]


class Out:
    def __init__(self):
        self.lines = []

    def case(self, path, select, closed, entities):
        """entities: [(label, points)]"""
        self.lines += [f"case {path}", f"select {select}", f"closed {int(closed)}"]
        for lab, pts in entities:
            self.lines.append(f"entity {lab}")
            self.lines += [f"p {x!r} {y!r}" for x, y in pts]

    def error(self, path, select, texts):
        self.lines += [f"case {path}", f"select {select}"] + [f"error {t}" for t in texts]


def layers(outdir, out):
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    a0 = {"layer": "0"}
    # chain 1, open: P0 -LINE-> P1 -ARC(-Z, drawn backwards)-> P2 -ELLIPSE(ratio 2.5)-> P3 -zero LINE- P3
    # -SPLINE(repeated control points)-> P4 -LINE-> P5, written out of order.
    p0, p1 = (0.0, 0.0), (40.0, 0.0)
    line1 = msp.add_line(p1, p0, dxfattribs=a0)  # reversed
    # ARC with extrusion -Z: centre (OCS) cx, radius 10, from P1 up a half turn (WCS counter-clockwise seen from
    # +Z is clockwise in the mirrored OCS)
    arc = msp.add_arc(to_ocs((40.0, 10.0), True), 10.0, 90.0, 270.0, dxfattribs={**a0, "extrusion": (0, 0, -1)})
    arc_pts = points_of(arc)
    p2 = (40.0, 20.0)
    ell = msp.add_ellipse((30.0, 20.0), (10.0, 0, 0), 0.5, 0.0, math.pi / 2, dxfattribs=a0)
    ell.dxf.unprotected_set("ratio", 2.5)  # QCAD 2 writes ratios above 1: the minor axis (N x M) 2.5 is the longer one
    ell.dxf.major_axis = (4.0, 0, 0)
    ell.dxf.center = (p2[0] - 4.0, p2[1])
    ell_pts = points_of(ell)
    p3 = ell_pts[-1]
    zero = msp.add_line(p3, p3, dxfattribs=a0)
    ctrl = [p3, (p3[0] - 5, p3[1] + 5), (p3[0] - 5, p3[1] + 5), (p3[0] - 5, p3[1] + 5), (p3[0] - 5, p3[1] + 5),
            (p3[0] - 12, p3[1] + 2), (p3[0] - 15, p3[1] + 8)]
    spl = msp.add_open_spline(ctrl, degree=3)
    spl.dxf.layer = "0"
    spl_pts = points_of(spl)
    p4 = spl_pts[-1]
    line2 = msp.add_line(p4, (p4[0] - 10, p4[1] - 30), dxfattribs=a0)
    # chain 2, closed LWPOLYLINE with extrusion -Z, far away
    lw = msp.add_lwpolyline([to_ocs(q, True) + (k,) for q, k in (((200, 0), 0.4), ((230, 0), 0), ((230, 20), -0.3), ((200, 20), 0))],
                            format="xyb", close=True, dxfattribs={**a0, "extrusion": (0, 0, -1)})
    # chain 3: 2D POLYLINE with extrusion -Z from (100, 100) and a CIRCLE (-Z) elsewhere
    pl = msp.add_polyline2d([to_ocs(q, True) + (k,) for q, k in (((100, 100), 0.7), ((120, 110), -2.0), ((140, 100), 0))],
                            format="xyb", dxfattribs={**a0, "extrusion": (0, 0, -1)})
    circle = msp.add_circle(to_ocs((100, -80), True), 15.0, dxfattribs={**a0, "extrusion": (0, 0, -1)})
    # chain 4: periodic SPLINE, n control points and n + 1 knots
    pctrl = [(300, 0), (320, 10), (330, 30), (310, 45), (290, 30), (285, 10)]
    pknots = [0, 1, 2, 3.5, 4, 5, 6.25]
    per = msp.add_spline(dxfattribs=a0)
    per.dxf.degree = 3
    per.control_points = [(x, y, 0) for x, y in pctrl]
    per.knots = pknots
    per.dxf.flags = per.PERIODIC | per.CLOSED | per.PLANAR
    # never curves: TEXT, VIEWPORT (paper space), MULTILEADER
    msp.add_text("cam", dxfattribs={"layer": "0", "insert": (10, 10)})
    try:
        ml = msp.add_multileader_mtext("Standard")
        ml.set_content("note")
        ml.add_leader_line(ezdxf.render.mleader.ConnectionSide.left, [Vec2(60, 60)])
        ml.build(insert=Vec2(70, 70))
    except Exception as exc:  # pragma: no cover - older ezdxf
        print(f"# no MULTILEADER: {exc}", file=sys.stderr)
    psp = doc.layout("Layout1")
    vp = psp.add_viewport(center=(100, 100), size=(200, 150), view_center_point=(0, 0), view_height=300)
    vp.dxf.status = 1
    vp.dxf.flags = 557152
    path = os.path.join(outdir, "layers.dxf")
    save_with_ratios(doc, path, {ell.dxf.handle: 2.5})
    with open(path, "a") as f:  # what some exporters leave after EOF
        f.write("this is not DXF\n  garbage line 2\n")

    chain1 = [(label(line1), points_of(line1)), (label(arc), arc_pts), (label(ell), ell_pts), (label(spl), spl_pts),
              (label(line2), points_of(line2))]
    mid_arc = arc_pts[SAMPLES // 2]
    out.case(path, f"near {mid_arc[0] + 0.5!r} {mid_arc[1]!r} layer 0", False, chain1)
    out.case(path, "handles " + " ".join(e.dxf.handle for e in (spl, line2, zero, arc, ell, line1)), False, chain1)
    out.case(path, f"near 215.0 -3.0", True, [(label(lw), points_of(lw))])
    out.case(path, f"near 121.0 112.0 layer 0", False, [(label(pl), points_of(pl))])
    out.case(path, f"handles {circle.dxf.handle}", True, [(label(circle), points_of(circle))])
    out.case(path, f"near 330.0 30.0", True, [(label(per), periodic_points(pctrl, 3, pknots))])
    out.error(path, "layer 0", ["form 5 chains", label(circle), label(lw), "near", "rollkin contours"])
    # an ARC with a tilted extrusion: an error when considered (a drawing of its own: "near" without a layer
    # considers every entity)
    doc = ezdxf.new("R2010")
    tilt = doc.modelspace().add_arc((0, 0), 5, 0, 90, dxfattribs={"layer": "TILT", "extrusion": (0, 0.6, 0.8)})
    doc.modelspace().add_line((10, 0), (20, 0), dxfattribs={"layer": "TILT"})  # listed, selected by its handle
    # every entity type with an extrusion, tilted, on a layer of its own (the heavy POLYLINE's own extrusion, not
    # its VERTEXes': it was read flattened in its OCS)
    tilted = (0.6, 0, 0.8)
    m = doc.modelspace()
    kinds = {
        "T_CIRCLE": m.add_circle((0, 0), 5, dxfattribs={"layer": "T_CIRCLE", "extrusion": tilted}),
        "T_ELLIPSE": m.add_ellipse((0, 0), (0, 5, 0), 0.5, 0, 1, dxfattribs={"layer": "T_ELLIPSE", "extrusion": tilted}),
        "T_LWPOLYLINE": m.add_lwpolyline([(0, 0, 0.5), (5, 0, 0)], format="xyb",
                                         dxfattribs={"layer": "T_LWPOLYLINE", "extrusion": tilted}),
        "T_POLYLINE": m.add_polyline2d([(0, 0, 0.5), (5, 0, 0)], format="xyb",
                                       dxfattribs={"layer": "T_POLYLINE", "extrusion": tilted}),
    }
    blk = doc.blocks.new("TB")
    blk.add_line((0, 0), (1, 0))
    kinds["T_INSERT"] = m.add_blockref("TB", (0, 0), dxfattribs={"layer": "T_INSERT", "extrusion": tilted})
    path = os.path.join(outdir, "tilt.dxf")
    doc.saveas(path)
    out.error(path, "layer TILT", [label(tilt), "extrusion direction (0, 0.6, 0.8)"])
    out.error(path, "near 1.0 1.0", [label(tilt), "extrusion direction (0, 0.6, 0.8)"])
    for layer, e in kinds.items():
        out.error(path, f"layer {layer}", [label(e), "extrusion direction (0.6, 0, 0.8)"])


def blocks(outdir, out):
    doc = ezdxf.new("R2010")
    msp = doc.modelspace()
    part = doc.blocks.new("PART", base_point=(5, 2))
    part.add_line((0, 0), (10, 0))
    part.add_arc(to_ocs((10, 5), True), 5, 90, 270, dxfattribs={"extrusion": (0, 0, -1)})  # (10,0) -> (10,10)
    part.add_ellipse((5, 10), (5, 0, 0), 0.4, 0, math.pi)  # (10,10) -> (0,10)
    part.add_open_spline([(0, 10), (-3, 7), (-2, 3), (0, 0)], degree=3)  # (0,10) -> (0,0): closed
    sub = doc.blocks.new("SUB", base_point=(0, 0))
    sub.add_blockref("PART", (0, 0), dxfattribs={"rotation": 30, "xscale": -1, "yscale": 2})
    cell = doc.blocks.new("CELL", base_point=(0, 0))
    cell.add_arc((0, 0), 2, 0, 180)
    cell.add_line((-2, 0), (2, 0))
    loop = doc.blocks.new("LOOP")
    loop.add_line((0, 0), (1, 0))
    loop.add_blockref("LOOP", (2, 0))

    cases = [("ROT", {"rotation": 37.5, "xscale": 1.5, "yscale": 1.5}, (100, 0)),
             ("NEG", {"rotation": -120, "xscale": -2, "yscale": 0.5}, (0, 100)),
             ("MIRZ", {"rotation": 15, "xscale": 1, "yscale": 3, "extrusion": (0, 0, -1)}, (-100, -100))]
    inserts = []
    for layer, attribs, at in cases:
        ocs_at = to_ocs(at, attribs.get("extrusion", (0, 0, 1))[2] < 0)
        inserts.append((layer, msp.add_blockref("PART", ocs_at, dxfattribs={"layer": layer, **attribs})))
    nested = msp.add_blockref("SUB", (300, 50), dxfattribs={"layer": "NEST", "rotation": 200, "xscale": 0.7, "yscale": -1.3})
    grid = msp.add_blockref("CELL", (500, 0), dxfattribs={"layer": "GRID", "rotation": 10, "xscale": 2, "yscale": 1})
    grid.dxf.column_count, grid.dxf.row_count = 3, 2
    grid.dxf.column_spacing, grid.dxf.row_spacing = 20, 15
    bad = msp.add_blockref("LOOP", (0, -300), dxfattribs={"layer": "LOOP"})
    path = os.path.join(outdir, "blocks.dxf")
    doc.saveas(path)

    def placed(insert, suffix):
        """[(label, points)] of the block's entities placed by `insert`: ezdxf's virtual entities."""
        block = doc.blocks.get(insert.dxf.name)
        originals = [e for e in block if e.dxftype() != "ATTDEF"]
        virtual = list(insert.virtual_entities())
        assert len(originals) == len(virtual), (len(originals), len(virtual))
        here = f" in INSERT {insert.dxf.handle}{suffix}"
        return [(f"{o.dxftype()} {o.dxf.handle}{here}", points_of(v)) for o, v in zip(originals, virtual)]

    def nested_placed(outer):
        """The same through a nested INSERT: ezdxf's points on the innermost block's entities mapped by the
        product of ezdxf's Insert.matrix44() (a virtual INSERT of a rotated INSERT under a non-uniform scale
        would need a shear, which an INSERT cannot hold)."""
        result = []
        for inner in doc.blocks.get(outer.dxf.name):
            m = inner.matrix44() @ outer.matrix44()
            here = f" in INSERT {inner.dxf.handle} in INSERT {outer.dxf.handle}"
            for o in doc.blocks.get(inner.dxf.name):
                pts = [m.transform(Vec3(x, y, 0)) for x, y in points_of(o)]
                result.append((f"{o.dxftype()} {o.dxf.handle}{here}", [(v.x, v.y) for v in pts]))
        return result

    for layer, ins in inserts:
        out.case(path, f"layer {layer}", True, placed(ins, ""))
    out.case(path, f"handles {nested.dxf.handle}", True, nested_placed(nested))
    copies = list(grid.multi_insert())
    k = 0
    for row in range(2):
        for col in range(3):
            v = copies[k]
            k += 1
            v.dxf.handle = grid.dxf.handle
            ents = placed(v, "")
            ents = [(lab.replace(f"INSERT {grid.dxf.handle}", f"INSERT {grid.dxf.handle} (column {col}, row {row})"), pts)
                    for lab, pts in ents]
            mid = ents[0][1][SAMPLES // 2]
            out.case(path, f"near {mid[0]!r} {mid[1]!r} layer GRID", True, ents)
    out.error(path, "layer GRID", ["form 6 chains"])
    out.error(path, "layer LOOP", [label(bad), "into itself"])


def main():
    outdir = sys.argv[1]
    os.makedirs(outdir, exist_ok=True)
    out = Out()
    layers(outdir, out)
    blocks(outdir, out)
    print("\n".join(out.lines))


if __name__ == "__main__":
    main()
