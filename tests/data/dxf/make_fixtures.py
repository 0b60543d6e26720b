#!/usr/bin/python3
"""DXF fixtures for tests/test_io_dxf.cpp, written by an independent producer (ezdxf, Debian python3-ezdxf).

Run from anywhere:  /usr/bin/python3 tests/data/dxf/make_fixtures.py
It rewrites the .dxf files and, for every selection a test reads, a .txt "answer" next to them:

    <file>.<layer>.txt   header lines "# key value" stating what the fixture is (facts this script knows:
                         entity labels "TYPE HANDLE" in file order, closed 0/1, corner points, $INSUNITS,
                         and for error cases the entities the message must name and the gap), then points
                         "x y" that ezdxf itself evaluates on the drawn entities (arc/circle/ellipse
                         .vertices(), LWPOLYLINE/POLYLINE .virtual_entities() split into LINE/ARC, SPLINE
                         .construction_tool().point(t), a de Boor evaluation of the B-spline). The C++ test
                         projects each point onto the imported contour and requires a distance below 1e-12
                         of the drawing size.

Files and what each exercises:
  chain_mm.dxf      $INSUNITS 4 (mm). STADIUM: LINE, ARC, LINE drawn backwards (reversed when chained), ARC;
                    closed, tangent joins, no corner. KINK: two LINEs at 90 degrees: open, one join corner.
  polyline_in.dxf   $INSUNITS 1 (in). LW_OPEN: LWPOLYLINE with bulges 1 (semicircle), -2 (clockwise arc over
                    180 degrees) and corners at two vertices. LW_CLOSED: closed LWPOLYLINE, a rounded rectangle
                    of exact quarter arcs (bulge tan(pi/8)), no corner. MIRROR: ARC with extrusion (0, 0, -1).
  curves.dxf        $INSUNITS 0 (unitless). CIRCLE, CIRCLE_M (extrusion -z), ELLIPSE_FULL, ELLIPSE_PART,
                    ELLIPSE_M (partial, extrusion -z), TWO_BULGE_CIRCLE (closed LWPOLYLINE of two bulge-1 arcs:
                    a circle of radius 5 about the origin, closed form).
  polyline_r12.dxf  DXF R12 (no $INSUNITS: unitless): P2D, an old-style closed POLYLINE (VERTEX/SEQEND) with
                    bulges; all four vertices are corners (the arcs are not tangent to the lines).
  splines_mm.dxf    $INSUNITS 4. SPLINE_CIRCLE: the exact circle as a rational quadratic NURBS (9 control
                    points, weights 1 and sqrt(2)/2, knots 0 0 0 1/4 1/4 1/2 1/2 3/4 3/4 1 1 1), closed.
                    SPLINE_CUBIC: rational cubic with interior knots (one double). SPLINE_PERIODIC: a closed
                    uniform cubic B-spline as ezdxf writes it (flag closed, 5 points + 3 wrapped, unclamped
                    knots 0..11; the curve is the part on [u_3, u_8]). PARABOLA: the paper's
                    y = 0.5 x^2, x in [-2, 2], as a 2-span polynomial quadratic B-spline (control points
                    (-2, 2), (-1, 0), (1, 0), (2, 2), knots 0 0 0 1 2 2 2; each span's Bezier points are
                    the parabola's end points and tangent intersection, so it is the parabola exactly).
  errors.dxf        GAP: two LINEs 1e-3 apart (two chains). BRANCH: three LINEs meeting at one point. TEXT: a
                    LINE and a TEXT (passed over). INSERT: a LINE and an INSERT of block "B" apart from it (two
                    chains). FITONLY: a SPLINE by fit points only. ORDER: the second LINE meets the first one's
                    start (chained in any order).
  units_miles.dxf   $INSUNITS 3 (miles): refused.
  scenes_mm.dxf     $INSUNITS 4, contours of whole scenes (tests/test_io_cad_scenes.cpp), drawn in millimetres for
                    scenes in metres: PARABOLA_MM the paper's parabola y = 0.5 x^2 (x in metres) as the 2-span
                    quadratic SPLINE of PARABOLA scaled by 1000; DISK_MM a circle of radius 1000 mm about the
                    origin made of two bulge-1 arcs (closed LWPOLYLINE); TRACK_MM a LINE from (-10000, 0) to
                    (10000, 0) mm.
  blocks_mm.dxf     $INSUNITS 4. PARABOLA_INS: the parabola of PARABOLA_MM inside a rotated, mirrored INSERT (the
                    block holds it mapped back). Layer 0: a wheel block (rim of two ARCs, radius 1000, a hub
                    CIRCLE, centre marks) inserted rotated and mirrored at the origin, a TEXT and a LINE track
                    along y = 0 (tests/test_io_cad_scenes.cpp selects the rim and the track by "near").
  straight_mm.dxf   $INSUNITS 4. RUN: a straight LWPOLYLINE from (-5000, 0) to (5000, 0) mm through 2001 collinear
                    vertices spaced 2.5 and 7.5 mm in turn (tests/test_io_cad_scenes.cpp: a disk rolls along it).
"""
import math
import os

import ezdxf
from ezdxf.math import Vec3, closed_uniform_bspline

HERE = os.path.dirname(os.path.abspath(__file__))
SAMPLES = 64


def label(e):
    return f"{e.dxftype()} {e.dxf.handle}"


def linspace(a, b, n=SAMPLES):
    return [a + (b - a) * i / (n - 1) for i in range(n)]


def arc_points(arc):
    """WCS points of an ARC entity by ezdxf (start to end angle, counter-clockwise in its OCS)."""
    a0, a1 = arc.dxf.start_angle, arc.dxf.end_angle
    while a1 <= a0:
        a1 += 360.0
    return list(arc.vertices(linspace(a0, a1)))


def points_of(e):
    t = e.dxftype()
    if t == "LINE":
        s, f = Vec3(e.dxf.start), Vec3(e.dxf.end)
        return [s.lerp(f, k / (SAMPLES - 1)) for k in range(SAMPLES)]
    if t == "ARC":
        return arc_points(e)
    if t == "CIRCLE":
        return list(e.vertices(linspace(0.0, 360.0)))
    if t == "ELLIPSE":
        t0, t1 = e.dxf.start_param, e.dxf.end_param
        while t1 <= t0:
            t1 += 2 * math.pi
        return list(e.vertices(linspace(t0, t1)))
    if t in ("LWPOLYLINE", "POLYLINE"):
        pts = []
        for v in e.virtual_entities():
            pts += points_of(v)
        return pts
    if t == "SPLINE":
        bs = e.construction_tool()
        p = bs.degree
        knots = bs.knots()
        lo, hi = knots[p], knots[len(knots) - p - 1]
        return [bs.point(u) for u in linspace(lo, hi, 4 * SAMPLES)]
    raise ValueError(t)


def answer(doc_name, layer, entities, header, points=True):
    path = os.path.join(HERE, f"{doc_name}.{layer}.txt")
    doc = entities[0].doc
    with open(path, "w") as f:
        f.write(f"# written by make_fixtures.py (ezdxf {ezdxf.__version__}); do not edit\n")
        f.write(f"# file {doc_name}.dxf\n# layer {layer}\n")
        f.write(f"# insunits {doc.header.get('$INSUNITS', 0) if doc.dxfversion > 'AC1009' else 0}\n")
        f.write("# entities " + ", ".join(label(e) for e in entities) + "\n")
        for key, value in header:
            f.write(f"# {key} {value}\n")
        if points:
            for e in entities:
                for q in points_of(e):
                    f.write(f"{q.x!r} {q.y!r}\n")


def new_doc(version, insunits=None):
    doc = ezdxf.new(version)
    if insunits is not None:
        doc.header["$INSUNITS"] = insunits
    return doc


def save(doc, name):
    doc.saveas(os.path.join(HERE, name + ".dxf"))


def chain_mm():
    doc = new_doc("R2010", 4)
    msp = doc.modelspace()
    at = {"layer": "STADIUM"}
    stadium = [
        msp.add_line((0, 0), (40, 0), dxfattribs=at),
        msp.add_arc((40, 10), 10, -90, 90, dxfattribs=at),
        msp.add_line((0, 20), (40, 20), dxfattribs=at),  # drawn backwards: its end meets the chain
        msp.add_arc((0, 10), 10, 90, 270, dxfattribs=at),
    ]
    at = {"layer": "KINK"}
    kink = [msp.add_line((0, 0), (10, 0), dxfattribs=at), msp.add_line((10, 0), (10, 10), dxfattribs=at)]
    save(doc, "chain_mm")
    answer("chain_mm", "STADIUM", stadium, [("closed", 1)])
    answer("chain_mm", "KINK", kink, [("closed", 0), ("corner", "10 0")])


def polyline_in():
    doc = new_doc("R2000", 1)
    msp = doc.modelspace()
    lw_open = msp.add_lwpolyline(
        [(0, 0, 0), (4, 0, 1), (4, 4, 0), (0, 4, 0), (0, 8, -2), (3, 8, 0)], format="xyb",
        dxfattribs={"layer": "LW_OPEN"})
    q = math.tan(math.pi / 8)
    lw_closed = msp.add_lwpolyline(
        [(2, 0, 0), (10, 0, q), (12, 2, 0), (12, 6, q), (10, 8, 0), (2, 8, q), (0, 6, 0), (0, 2, q)], format="xyb",
        close=True, dxfattribs={"layer": "LW_CLOSED"})
    mirror = msp.add_arc((5, 5), 2, 0, 120, dxfattribs={"layer": "MIRROR", "extrusion": (0, 0, -1)})
    save(doc, "polyline_in")
    answer("polyline_in", "LW_OPEN", [lw_open], [("closed", 0), ("corner", "0 4"), ("corner", "0 8")])
    answer("polyline_in", "LW_CLOSED", [lw_closed], [("closed", 1)])
    answer("polyline_in", "MIRROR", [mirror], [("closed", 0)])


def curves():
    doc = new_doc("R2010", 0)
    msp = doc.modelspace()
    m = {"extrusion": (0, 0, -1)}
    items = {
        "CIRCLE": (msp.add_circle((1, 2), 3, dxfattribs={"layer": "CIRCLE"}), 1),
        "CIRCLE_M": (msp.add_circle((1, 2), 3, dxfattribs={"layer": "CIRCLE_M", **m}), 1),
        "ELLIPSE_FULL": (msp.add_ellipse((1, 1), (4, 2), 0.5, dxfattribs={"layer": "ELLIPSE_FULL"}), 1),
        "ELLIPSE_PART": (msp.add_ellipse((0, 0), (0, 3), 0.4, 0.3, 4.0, dxfattribs={"layer": "ELLIPSE_PART"}), 0),
        "ELLIPSE_M": (msp.add_ellipse((2, -1), (3, 1), 0.6, 0.5, 2.5, dxfattribs={"layer": "ELLIPSE_M", **m}), 0),
        "TWO_BULGE_CIRCLE": (msp.add_lwpolyline([(5, 0, 1), (-5, 0, 1)], format="xyb", close=True,
                                                dxfattribs={"layer": "TWO_BULGE_CIRCLE"}), 1),
    }
    save(doc, "curves")
    for layer, (e, closed) in items.items():
        answer("curves", layer, [e], [("closed", closed)])


def polyline_r12():
    doc = new_doc("R12")
    msp = doc.modelspace()
    p = msp.add_polyline2d([(0, 0, 0), (6, 0, 0.5), (6, 4, 0), (0, 4, -0.25)], format="xyb", close=True,
                           dxfattribs={"layer": "P2D"})
    save(doc, "polyline_r12")
    answer("polyline_r12", "P2D", [p], [("closed", 1), ("corner", "6 0"), ("corner", "6 4"), ("corner", "0 4"),
                                       ("corner", "0 0")])


def splines_mm():
    doc = new_doc("R2010", 4)
    msp = doc.modelspace()
    r, w = 7.0, math.sqrt(2) / 2
    ring = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    circle = msp.add_rational_spline([(r * x, r * y) for x, y in ring], [1, w, 1, w, 1, w, 1, w, 1], degree=2,
                                     knots=[0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
                                     dxfattribs={"layer": "SPLINE_CIRCLE"})
    cubic = msp.add_rational_spline([(0, 0), (1, 2), (3, 3), (5, 2), (6, 0), (8, -1), (9, 1), (11, 2)],
                                    [1, 0.75, 0.5, 1.25, 0.25, 1, 0.5, 1], degree=3,
                                    knots=[0, 0, 0, 0, 0.2, 0.4, 0.4, 0.7, 1, 1, 1, 1],
                                    dxfattribs={"layer": "SPLINE_CUBIC"})
    parabola = msp.add_open_spline([(-2, 2), (-1, 0), (1, 0), (2, 2)], degree=2, knots=[0, 0, 0, 1, 2, 2, 2],
                                   dxfattribs={"layer": "PARABOLA"})
    periodic = msp.add_spline(dxfattribs={"layer": "SPLINE_PERIODIC"})
    periodic.apply_construction_tool(closed_uniform_bspline([(0, 0), (4, 0), (5, 3), (2, 5), (-1, 3)], order=4))
    periodic.closed = True
    save(doc, "splines_mm")
    answer("splines_mm", "SPLINE_CIRCLE", [circle], [("closed", 1), ("radius", r)])
    answer("splines_mm", "SPLINE_CUBIC", [cubic], [("closed", 0)])
    answer("splines_mm", "SPLINE_PERIODIC", [periodic], [("closed", 1)])
    answer("splines_mm", "PARABOLA", [parabola], [("closed", 0)])


def blocks_mm():
    """Contours inside blocks and on a layer shared with other geometry (tests/test_io_cad_scenes.cpp)."""
    doc = new_doc("R2010", 4)
    msp = doc.modelspace()
    # The paper's parabola (PARABOLA_MM of scenes_mm) inside an INSERT rotated by 33 degrees and mirrored
    # (x scale -1), base point (700, -300), at (250, 125): the block holds the control points mapped by the
    # inverse placement, q = base + diag(-1, 1) R(-33 deg) (p - insert), so that the INSERT puts them back.
    th = math.radians(33.0)
    base, at = (700.0, -300.0), (250.0, 125.0)

    def unplace(p):
        dx, dy = p[0] - at[0], p[1] - at[1]
        rx, ry = math.cos(th) * dx + math.sin(th) * dy, -math.sin(th) * dx + math.cos(th) * dy
        return (base[0] - rx, base[1] + ry)

    part = doc.blocks.new("PARABOLA_PART", base_point=base)
    part.add_open_spline([unplace(p) for p in ((-2000, 2000), (-1000, 0), (1000, 0), (2000, 2000))], degree=2,
                         knots=[0, 0, 0, 1, 2, 2, 2])
    msp.add_blockref("PARABOLA_PART", at, dxfattribs={"layer": "PARABOLA_INS", "rotation": 33.0, "xscale": -1.0,
                                                        "yscale": 1.0})
    # Layer "0" holds everything: a wheel block (rim of two ARCs, radius 1000 about its base point (500, 300), a hub
    # CIRCLE of radius 200, two centre-mark LINEs crossing at the centre) inserted at the origin, rotated 33
    # degrees and mirrored, a TEXT, and the track, a LINE from (-10000, 0) to (10000, 0) through the wheel: the rim and the
    # track are picked by "near".
    wheel = doc.blocks.new("WHEEL", base_point=(500, 300))
    wheel.add_arc((500, 300), 1000, 0, 180)
    wheel.add_arc((500, 300), 1000, 180, 360)
    wheel.add_circle((500, 300), 200)
    wheel.add_line((350, 300), (650, 300))
    wheel.add_line((500, 150), (500, 450))
    msp.add_blockref("WHEEL", (0, 0), dxfattribs={"layer": "0", "rotation": 33.0, "xscale": -1.0, "yscale": 1.0})
    msp.add_text("wheel", dxfattribs={"layer": "0", "insert": (0, 1200)})
    msp.add_line((-10000, 0), (10000, 0), dxfattribs={"layer": "0"})
    save(doc, "blocks_mm")


def errors():
    doc = new_doc("R2010")
    msp = doc.modelspace()
    gap = [msp.add_line((0, 0), (1, 0), dxfattribs={"layer": "GAP"}),
           msp.add_line((1.001, 0), (2, 0), dxfattribs={"layer": "GAP"})]
    branch = [msp.add_line((0, 0), (1, 0), dxfattribs={"layer": "BRANCH"}),
              msp.add_line((1, 0), (2, 0), dxfattribs={"layer": "BRANCH"}),
              msp.add_line((1, 0), (1, 1), dxfattribs={"layer": "BRANCH"})]
    text = [msp.add_line((0, 0), (1, 0), dxfattribs={"layer": "TEXT"}),
            msp.add_text("cam", dxfattribs={"layer": "TEXT", "insert": (0, 1)})]
    block = doc.blocks.new("B")
    block.add_line((0, 0), (1, 1))
    insert = [msp.add_line((0, 0), (1, 0), dxfattribs={"layer": "INSERT"}),
              msp.add_blockref("B", (2, 0), dxfattribs={"layer": "INSERT"})]
    fit = [msp.add_spline([(0, 0), (1, 1), (2, 0), (3, 1)], dxfattribs={"layer": "FITONLY"})]
    order = [msp.add_line((0, 0), (1, 0), dxfattribs={"layer": "ORDER"}),
             msp.add_line((0, 1), (0, 0), dxfattribs={"layer": "ORDER"})]
    save(doc, "errors")
    answer("errors", "GAP", gap, [("names", label(gap[0])), ("names", label(gap[1])), ("names", "form 2 chains")], False)
    answer("errors", "BRANCH", branch, [("names", label(branch[2])), ("names", label(branch[0])),
                                        ("names", label(branch[1])), ("names", "branch")], False)
    answer("errors", "TEXT", text, [("names", label(text[1])), ("names", "unsupported")], False)
    answer("errors", "INSERT", insert, [("names", label(insert[1])), ("names", "form 2 chains")], False)
    answer("errors", "FITONLY", fit, [("names", label(fit[0])), ("names", "only fit points")], False)
    answer("errors", "ORDER", order, [("names", label(order[1])), ("names", "chain's start")], False)


def units_miles():
    doc = new_doc("R2010", 3)
    line = doc.modelspace().add_line((0, 0), (1, 0), dxfattribs={"layer": "L"})
    save(doc, "units_miles")
    answer("units_miles", "L", [line], [("names", "$INSUNITS"), ("names", "unit code 3")], False)


def scenes_mm():
    doc = new_doc("R2010", 4)
    msp = doc.modelspace()
    parabola = msp.add_open_spline([(-2000, 2000), (-1000, 0), (1000, 0), (2000, 2000)], degree=2,
                                   knots=[0, 0, 0, 1, 2, 2, 2], dxfattribs={"layer": "PARABOLA_MM"})
    disk = msp.add_lwpolyline([(1000, 0, 1), (-1000, 0, 1)], format="xyb", close=True,
                              dxfattribs={"layer": "DISK_MM"})
    track = msp.add_line((-10000, 0), (10000, 0), dxfattribs={"layer": "TRACK_MM"})
    # A table edge: flat from x = -10 m to 3 m, then falling at 45 degrees; a disk rolling on it from x = 0
    # reaches the corner after 3 m (status corner).
    table = msp.add_lwpolyline([(-10000, 0), (3000, 0), (8000, -5000)], dxfattribs={"layer": "TABLE_MM"})
    save(doc, "scenes_mm")
    answer("scenes_mm", "PARABOLA_MM", [parabola], [("closed", 0)])
    answer("scenes_mm", "DISK_MM", [disk], [("closed", 1), ("radius", 1000)])
    answer("scenes_mm", "TRACK_MM", [track], [("closed", 0)])
    answer("scenes_mm", "TABLE_MM", [table], [("closed", 0), ("corner", "3000 0")])


def straight_mm():
    doc = new_doc("R2010", 4)
    msp = doc.modelspace()
    xs = [-5000.0]
    while xs[-1] < 5000:
        xs.append(xs[-1] + (2.5 if len(xs) % 2 else 7.5))
    run = msp.add_lwpolyline([(x, 0) for x in xs], dxfattribs={"layer": "RUN"})
    save(doc, "straight_mm")
    answer("straight_mm", "RUN", [run], [("closed", 0), ("vertices", len(xs)), ("middle_vertex", xs.index(0.0))], False)


if __name__ == "__main__":
    chain_mm()
    polyline_in()
    curves()
    polyline_r12()
    splines_mm()
    errors()
    blocks_mm()
    units_miles()
    scenes_mm()
    straight_mm()
