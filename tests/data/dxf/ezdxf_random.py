#!/usr/bin/python3
"""Random valid DXF drawings written by ezdxf (Debian python3-ezdxf), with ezdxf's own world-coordinate points
on every entity, for the differential test tests/test_io_dxf_differential.cpp.

    /usr/bin/python3 tests/data/dxf/ezdxf_random.py OUTDIR SEED COUNT

writes OUTDIR/random_SEED_I.dxf for I < COUNT (seeded: the same arguments give the same files) and prints,
for each drawing, one block

    case PATH
    layer NAME                  one chain of entities, end to end, in the order rollkin walks it
    start X Y                   where that walk starts, when not at the first point of the first entity
    entity TYPE HANDLE          an entity of the chain (for a block's: TYPE HANDLE in INSERT H [in INSERT H2]),
                                then the points on it in its own direction:
    p X Y                       world (WCS) coordinates, repr() of the double
    onearc X Y                  an inner vertex of a polyline whose arcs are one circle (modelspace only):
                                rollkin reads them as one arc, with no joint there

A quarter of the chains are drawn in a block and placed by an INSERT (rotation, x/y scale +-0.3 .. 3,
negative and non-uniform, extrusion +-Z, the block's base point), a third of those through a nested INSERT;
their points are ezdxf's on the block's entities mapped by the product of ezdxf's Insert.matrix44(). ELLIPSEs
are written with axis ratio > 1 now and then (QCAD 2); MULTILEADER, TEXT, a paper-space VIEWPORT and text
after EOF appear in some drawings; half the drawings list their modelspace entities in a random order.

Each drawing has 1 to 4 layers ("several chains per layer" as rollkin reads them: one chain per layer), each
a closed entity alone (CIRCLE, full ELLIPSE, closed LWPOLYLINE with bulges; 15 %) or a chain of 1 to 4
entities: LINE (drawn either way), ARC (either way), partial ELLIPSE, LWPOLYLINE and 2D POLYLINE with bulges
0 or +-10^u for u in [-18, 3] (a fifth of them 2 to 30 arcs of one circle turning one way, which rollkin
reads as one arc; a fifth 2 to 6 tangent arcs of different circles: unequal radii, radii 1e-6 apart, or an S
of equal radii, which rollkin keeps apart), rational SPLINE (degree 2 or 3, random weights and interior knots, clamped); ARC,
ELLIPSE and the polylines have extrusion (0, 0, 1) or (0, 0, -1) at random.
The drawing's scale runs from 1e-2 to 1e4 and its offset is up to 10 times its scale.

The points are ezdxf's: arc.vertices(), ellipse.vertices(), spline.construction_tool().point(u) (in double,
each correct to a few ulps), and for polyline bulges ezdxf's bulge_to_arc (ezdxf.math.bulge) evaluated with
mpmath at 60 digits: in double it finds the centre (1 - b^2) / (4 b) chords away and loses the arc for small
bulges, so the same formula is carried out exactly and only the points are rounded.
"""
import math
import os
import random
import sys

import ezdxf
import mpmath
from ezdxf.math import Vec2, Vec3

mpmath.mp.dps = 60
SAMPLES = 48


def bulge_points(a, b, bulge, n=SAMPLES):
    """ezdxf.math.bulge.bulge_to_arc from a to b (OCS, 2D) in 60 digits, then n points from a to b."""
    ax, ay, bx, by, k = (mpmath.mpf(v) for v in (a[0], a[1], b[0], b[1], bulge))
    if k == 0:
        return [(float(ax + (bx - ax) * i / (n - 1)), float(ay + (by - ay) * i / (n - 1))) for i in range(n)]
    chord = mpmath.sqrt((bx - ax) ** 2 + (by - ay) ** 2)
    r = chord * (1 + k * k) / 4 / k  # signed_bulge_radius
    direction = mpmath.atan2(by - ay, bx - ax) + (mpmath.pi / 2 - mpmath.atan(k) * 2)
    cx, cy = ax + r * mpmath.cos(direction), ay + r * mpmath.sin(direction)
    start = mpmath.atan2(ay - cy, ax - cx)
    sweep = 4 * mpmath.atan(k)  # signed: counter-clockwise for k > 0
    radius = abs(r)
    return [(float(cx + radius * mpmath.cos(start + sweep * i / (n - 1))),
             float(cy + radius * mpmath.sin(start + sweep * i / (n - 1)))) for i in range(n)]


def save_with_ratios(doc, path, ratios):
    """doc.saveas(path), then the ELLIPSEs whose handles `ratios` maps written with that axis ratio (above 1, as
    QCAD 2 writes them: ezdxf refuses to write them, so they are saved with ratio 1 and group 40 is replaced in
    the text)."""
    entities = {h: e for h, e in ((h, doc.entitydb.get(h)) for h in ratios)}
    for e in entities.values():
        e.dxf.unprotected_set("ratio", 1.0)
    doc.saveas(path)
    for h, e in entities.items():
        e.dxf.unprotected_set("ratio", ratios[h])
    with open(path) as f:
        lines = f.read().split("\n")
    kind = handle = None
    for i in range(0, len(lines) - 1, 2):
        code, value = lines[i].strip(), lines[i + 1].strip()
        if code == "0":
            kind, handle = value, None
        elif code == "5":
            handle = value
        elif code == "40" and kind == "ELLIPSE" and handle in ratios:
            lines[i + 1] = repr(ratios[handle])
    with open(path, "w") as f:
        f.write("\n".join(lines))


def to_ocs(p, mirrored):
    """WCS (x, y) to the OCS of extrusion (0, 0, -1) (arbitrary axis algorithm: Ax = (-1, 0, 0)), or as is."""
    return (-p[0], p[1]) if mirrored else (p[0], p[1])


class Drawing:
    def __init__(self, rng, path):
        self.rng = rng
        self.path = path
        self.doc = ezdxf.new("R2010")
        self.msp = self.doc.modelspace()
        self.space = self.msp  # where the adders draw: the modelspace or a block definition
        self.ratios = {}  # handle -> axis ratio above 1 of an ELLIPSE (save_with_ratios)
        self.scale = 10 ** rng.uniform(-2, 4)
        self.layers = []  # (name, [(label, points)])
        self.one_arcs = {}  # handle -> inner vertices (WCS, in the block's coordinates) of a polyline of one arc

    def step(self):
        """A random vector of length 0.2 .. 1 times the scale."""
        t, length = self.rng.uniform(0, 2 * math.pi), self.scale * self.rng.uniform(0.2, 1)
        return (length * math.cos(t), length * math.sin(t))

    def extrusion(self):
        return (0, 0, -1) if self.rng.random() < 0.5 else (0, 0, 1)

    def bulge(self):
        if self.rng.random() < 0.15:
            return 0.0
        return self.rng.choice((-1, 1)) * 10 ** self.rng.uniform(-18, 3)

    # Each adder draws one entity from the chain's end p (WCS) and returns (entity, points, new end). The first
    # entity of a chain is drawn forwards: rollkin takes the chain's direction from it.
    def line(self, p, attribs, first):
        d = self.step()
        q = (p[0] + d[0], p[1] + d[1])
        backwards = self.rng.random() < 0.5 and not first
        e = self.space.add_line(q if backwards else p, p if backwards else q, dxfattribs=attribs)
        s, f = Vec3(e.dxf.start), Vec3(e.dxf.end)
        pts = [s.lerp(f, i / (SAMPLES - 1)) for i in range(SAMPLES)]
        return e, [(v.x, v.y) for v in pts], q

    def arc(self, p, attribs, first):
        n = self.extrusion()
        mirrored = n[2] < 0
        r, sweep = self.scale * self.rng.uniform(0.2, 1), self.rng.uniform(10, 350)
        backwards = self.rng.random() < 0.5 and not first  # the chain enters at the arc's end angle
        at = self.rng.uniform(0, 360)
        po = to_ocs(p, mirrored)
        c = (po[0] - r * math.cos(math.radians(at)), po[1] - r * math.sin(math.radians(at)))
        a0, a1 = (at - sweep, at) if backwards else (at, at + sweep)
        e = self.space.add_arc(c, r, a0, a1, dxfattribs={**attribs, "extrusion": n})
        s, f = e.dxf.start_angle, e.dxf.end_angle
        while f <= s:
            f += 360.0
        pts = [(v.x, v.y) for v in e.vertices([s + (f - s) * i / (SAMPLES - 1) for i in range(SAMPLES)])]
        return e, pts, pts[0] if backwards else pts[-1]

    def ellipse(self, p, attribs, first):
        n = self.extrusion()
        t = self.rng.uniform(0, 2 * math.pi)
        a = self.scale * self.rng.uniform(0.3, 1)
        major = (a * math.cos(t), a * math.sin(t))
        ratio = self.rng.uniform(0.1, 1)
        minor = (-n[2] * ratio * major[1], n[2] * ratio * major[0])  # ratio (N x M)
        t0 = self.rng.uniform(0, 2 * math.pi)
        t1 = t0 + self.rng.uniform(0.3, 6)
        c = (p[0] - major[0] * math.cos(t0) - minor[0] * math.sin(t0), p[1] - major[1] * math.cos(t0) - minor[1] * math.sin(t0))
        e = self.space.add_ellipse(c, (major[0], major[1], 0), ratio, t0, t1, dxfattribs={**attribs, "extrusion": n})
        self.maybe_swap_axes(e)
        s, f = e.dxf.start_param, e.dxf.end_param
        while f <= s:
            f += 2 * math.pi
        pts = [(v.x, v.y) for v in e.vertices([s + (f - s) * i / (SAMPLES - 1) for i in range(SAMPLES)])]
        return e, pts, pts[-1]

    def maybe_swap_axes(self, e):
        """Now and then the same ellipse written with axis ratio > 1, as QCAD 2 writes them: major axis
        ratio (N x M), ratio 1 / ratio, parameters - pi / 2 (p(t) = c + cos t M + sin t ratio (N x M))."""
        if self.rng.random() < 0.3:
            major, ratio, normal = Vec3(e.dxf.major_axis), e.dxf.ratio, Vec3(e.dxf.extrusion)
            e.dxf.major_axis = normal.cross(major) * ratio
            e.dxf.unprotected_set("ratio", 1 / ratio)  # ezdxf keeps ratios in (0, 1]: written by save_with_ratios
            self.ratios[e.dxf.handle] = 1 / ratio
            e.dxf.start_param = e.dxf.start_param - math.pi / 2
            e.dxf.end_param = e.dxf.end_param - math.pi / 2

    def one_circle(self, p, mirrored):
        """OCS vertices from p on one circle, arcs of random angles turning one way, and their bulges."""
        po = to_ocs(p, mirrored)
        r, at = self.scale * self.rng.uniform(0.2, 1), self.rng.uniform(0, 2 * math.pi)
        c = (po[0] - r * math.cos(at), po[1] - r * math.sin(at))
        sign = self.rng.choice((-1, 1))
        angles = [at]
        for _ in range(self.rng.randint(2, 30)):
            angles.append(angles[-1] + sign * self.rng.uniform(0.001, 5.5) / 30)
        ocs = [po] + [(c[0] + r * math.cos(a), c[1] + r * math.sin(a)) for a in angles[1:]]
        return ocs, [math.tan((b - a) / 4) for a, b in zip(angles, angles[1:])] + [0.0]

    def tangent_arcs(self, p, mirrored):
        """OCS vertices from p of 2 to 6 arcs, each tangent to the one before, and their bulges: radii unequal
        (ratios 1.1 .. 3, or 1 + 1e-6: another circle all the same), or equal and turning the other way (an S:
        two circles), 5 to 120 degrees each. No two consecutive arcs are one circle: rollkin must keep them
        apart (reading such a pair as one arc through the three points gives another radius)."""
        po = to_ocs(p, mirrored)
        heading = self.rng.uniform(0, 2 * math.pi)
        r = self.scale * self.rng.uniform(0.2, 1)
        sign = self.rng.choice((-1, 1))
        ocs, bulges = [po], []
        for i in range(self.rng.randint(2, 6)):
            if i > 0:
                kind = self.rng.random()
                if kind < 0.2:
                    sign = -sign  # an S: the same radius, the other way
                elif kind < 0.35:
                    r *= self.rng.choice((1 + 1e-6, 1 / (1 + 1e-6)))
                else:
                    r *= 10 ** (self.rng.choice((-1, 1)) * self.rng.uniform(0.05, 0.5))
                    r = min(max(r, 0.1 * self.scale), 3 * self.scale)
            sweep = math.radians(self.rng.uniform(5, 120))
            x, y = ocs[-1]
            cx, cy = x - sign * r * math.sin(heading), y + sign * r * math.cos(heading)  # centre to the left (ccw) or right
            a0 = math.atan2(y - cy, x - cx)
            a1 = a0 + sign * sweep
            ocs.append((cx + r * math.cos(a1), cy + r * math.sin(a1)))
            bulges.append(sign * math.tan(sweep / 4))
            heading += sign * sweep
        return ocs, bulges + [0.0]

    def polyline(self, p, attribs, lw):
        n = self.extrusion()
        mirrored = n[2] < 0
        draw = self.rng.random()
        one_arc = draw < 0.2
        if one_arc:  # arcs of one circle (rollkin reads them as one arc)
            ocs, bulges = self.one_circle(p, mirrored)
        elif draw < 0.4:  # tangent arcs of different circles (rollkin keeps them apart)
            ocs, bulges = self.tangent_arcs(p, mirrored)
        else:
            wcs = [p]
            for _ in range(self.rng.randint(1, 4)):
                d = self.step()
                wcs.append((wcs[-1][0] + d[0], wcs[-1][1] + d[1]))
            ocs = [to_ocs(q, mirrored) for q in wcs]
            bulges = [self.bulge() for _ in ocs[:-1]] + [0.0]
        points = [(q[0], q[1], k) for q, k in zip(ocs, bulges)]
        if lw:
            e = self.space.add_lwpolyline(points, format="xyb", dxfattribs={**attribs, "extrusion": n})
            vertices = [(x, y, k) for x, y, _, _, k in e.get_points("xyseb")]
        else:
            e = self.space.add_polyline2d(points, format="xyb", dxfattribs={**attribs, "extrusion": n})
            vertices = [(v.dxf.location.x, v.dxf.location.y, v.dxf.bulge) for v in e.vertices]
        pts = []
        for (x0, y0, k), (x1, y1, _) in zip(vertices, vertices[1:]):
            pts += [to_ocs(q, mirrored) for q in bulge_points((x0, y0), (x1, y1), k)]
        if one_arc and self.space is self.msp:  # the inner vertices, where rollkin's one arc has no joint
            self.one_arcs[e.dxf.handle] = [to_ocs((x, y), mirrored) for x, y, _ in vertices[1:-1]]
        return e, pts, pts[-1]

    def spline(self, p, attribs, first):
        degree = self.rng.choice((2, 3))
        count = degree + 1 + self.rng.randint(0, 3)
        ctrl = [p]
        for _ in range(count - 1):
            d = self.step()
            ctrl.append((ctrl[-1][0] + d[0] / 2, ctrl[-1][1] + d[1] / 2))
        weights = [self.rng.uniform(0.3, 3) for _ in ctrl]
        interior = sorted(round(self.rng.uniform(0.05, 0.95), 3) for _ in range(count - degree - 1))
        knots = [0.0] * (degree + 1) + interior + [1.0] * (degree + 1)
        e = self.space.add_rational_spline(ctrl, weights, degree=degree, knots=knots, dxfattribs=attribs)
        bs = e.construction_tool()
        ks = bs.knots()
        lo, hi = ks[degree], ks[len(ks) - degree - 1]
        pts = [(v.x, v.y) for v in (bs.point(lo + (hi - lo) * i / (3 * SAMPLES - 1)) for i in range(3 * SAMPLES))]
        return e, pts, pts[-1]

    def closed(self, p, attribs):
        """A closed entity, alone on its layer: CIRCLE, full ELLIPSE or closed LWPOLYLINE with bulges."""
        n = self.extrusion()
        kind = self.rng.choice(("circle", "ellipse", "lwpolyline"))
        if kind == "circle":
            e = self.space.add_circle(to_ocs(p, n[2] < 0), self.scale * self.rng.uniform(0.2, 1),
                                    dxfattribs={**attribs, "extrusion": n})
            return e, [(v.x, v.y) for v in e.vertices([360.0 * i / (SAMPLES - 1) for i in range(SAMPLES)])]
        if kind == "ellipse":
            t = self.rng.uniform(0, 2 * math.pi)
            a = self.scale * self.rng.uniform(0.3, 1)
            e = self.space.add_ellipse(p, (a * math.cos(t), a * math.sin(t), 0), self.rng.uniform(0.1, 1), 0, 2 * math.pi,
                                     dxfattribs={**attribs, "extrusion": n})
            self.maybe_swap_axes(e)
            s = e.dxf.start_param
            return e, [(v.x, v.y) for v in e.vertices([s + 2 * math.pi * i / (SAMPLES - 1) for i in range(SAMPLES)])]
        mirrored = n[2] < 0
        # a convex polygon around p (no self-intersection whatever the bulges' signs up to a half turn each)
        count = self.rng.randint(2, 6)
        angles = sorted(self.rng.uniform(0, 2 * math.pi) for _ in range(count))
        r = self.scale * self.rng.uniform(0.3, 1)
        ocs = [to_ocs((p[0] + r * math.cos(a), p[1] + r * math.sin(a)), mirrored) for a in angles]
        bulges = [self.rng.choice((0.0, 10 ** self.rng.uniform(-18, 0), -10 ** self.rng.uniform(-18, -1))) for _ in ocs]
        e = self.space.add_lwpolyline([(q[0], q[1], k) for q, k in zip(ocs, bulges)], format="xyb", close=True,
                                    dxfattribs={**attribs, "extrusion": n})
        vertices = [(x, y, k) for x, y, _, _, k in e.get_points("xyseb")]
        pts = []
        for (x0, y0, k), (x1, y1, _) in zip(vertices, vertices[1:] + vertices[:1]):
            pts += [to_ocs(q, mirrored) for q in bulge_points((x0, y0), (x1, y1), k)]
        return e, pts

    def chain(self, name):
        attribs = {"layer": name}
        span = 10 * self.scale
        p = (self.rng.uniform(-span, span), self.rng.uniform(-span, span))
        entities = []
        block = None
        if self.rng.random() < 0.25:  # drawn in a block, placed by an INSERT
            block = self.doc.blocks.new(f"B_{name}", base_point=(self.rng.uniform(-span, span), self.rng.uniform(-span, span)))
            self.space = block
        if self.rng.random() < 0.15:
            e, pts = self.closed(p, attribs)
            entities.append((e, pts))
        else:
            for k in range(self.rng.randint(1, 4)):
                kind = self.rng.choice(("line", "arc", "ellipse", "lwpolyline", "polyline", "spline"))
                if kind == "lwpolyline" or kind == "polyline":
                    e, pts, p = self.polyline(p, attribs, kind == "lwpolyline")
                else:
                    e, pts, p = getattr(self, kind)(p, attribs, k == 0)
                entities.append((e, pts))
        self.space = self.msp
        if block is None:
            self.layers.append((name, [(f"{e.dxftype()} {e.dxf.handle}", pts) for e, pts in entities], p))
        else:
            self.layers.append((name, self.insert(name, block, entities), None))

    def placement(self, name):
        """Random INSERT attributes: rotation, x/y scale +-0.3 .. 3 (negative, non-uniform), extrusion +-Z."""
        n = self.extrusion()
        sx, sy = (self.rng.choice((-1, 1)) * 10 ** self.rng.uniform(-0.5, 0.5) for _ in range(2))
        if self.rng.random() < 0.3:
            sy = sx  # uniform
        return {"layer": name, "rotation": self.rng.uniform(-360, 360), "xscale": sx, "yscale": sy, "extrusion": n}

    def insert(self, name, block, entities):
        """Places `block` by an INSERT on layer `name` (now and then an INSERT of a block holding that INSERT);
        returns the entities' labels and ezdxf's points mapped by the product of ezdxf's Insert.matrix44()."""
        span = 10 * self.scale
        at = (self.rng.uniform(-span, span), self.rng.uniform(-span, span))
        attribs = self.placement(name)
        if self.rng.random() < 0.3:
            outer_block = self.doc.blocks.new(f"N_{name}", base_point=(self.rng.uniform(-span, span), self.rng.uniform(-span, span)))
            inner = outer_block.add_blockref(block.name, to_ocs(at, attribs["extrusion"][2] < 0), dxfattribs=attribs)
            at2 = (self.rng.uniform(-span, span), self.rng.uniform(-span, span))
            attribs2 = self.placement(name)
            outer = self.msp.add_blockref(outer_block.name, to_ocs(at2, attribs2["extrusion"][2] < 0), dxfattribs=attribs2)
            m = inner.matrix44() @ outer.matrix44()
            suffix = f" in INSERT {inner.dxf.handle} in INSERT {outer.dxf.handle}"
        else:
            ins = self.msp.add_blockref(block.name, to_ocs(at, attribs["extrusion"][2] < 0), dxfattribs=attribs)
            m = ins.matrix44()
            suffix = f" in INSERT {ins.dxf.handle}"
        return [(f"{e.dxftype()} {e.dxf.handle}{suffix}", [(v.x, v.y) for v in (m.transform(Vec3(x, y, 0)) for x, y in pts)])
                for e, pts in entities]

    def extras(self):
        """Now and then what real drawings hold besides the contours: a MULTILEADER on a contour's layer (its group
        90 holds flags such as -1056964608), a paper-space VIEWPORT (group 90: status flags 557152), a TEXT; the
        modelspace entities in a random order (rollkin walks each chain from the free end of its entity first in
        the file: a chain whose last entity comes first is read backwards)."""
        if self.rng.random() < 0.2:
            ml = self.msp.add_multileader_mtext("Standard", dxfattribs={"layer": "CHAIN0"})
            ml.set_content("note")
            ml.add_leader_line(ezdxf.render.mleader.ConnectionSide.left, [Vec2(0, 0)])
            ml.build(insert=Vec2(self.scale, self.scale))
            self.msp.add_text("label", dxfattribs={"layer": "CHAIN0"})
        if self.rng.random() < 0.2:
            vp = self.doc.layout("Layout1").add_viewport(center=(100, 100), size=(200, 150), view_center_point=(0, 0),
                                                          view_height=300)
            vp.dxf.flags = 557152
        if self.rng.random() < 0.5:
            order = list(self.msp)
            self.rng.shuffle(order)
            for e in order:
                self.msp.unlink_entity(e)
                self.msp.add_entity(e)
        position = {e.dxf.handle: i for i, e in enumerate(self.msp)}
        self.starts = {}  # layer -> where rollkin's walk starts, when not at the first entity's first point
        for k, (name, entities, end) in enumerate(self.layers):
            first, last = (position.get(label.split()[1]) for label in (entities[0][0], entities[-1][0]))
            if len(entities) > 1 and first is not None and last < first:
                self.layers[k] = (name, list(reversed(entities)), end)
                self.starts[name] = end

    def write(self):
        self.extras()
        save_with_ratios(self.doc, self.path, self.ratios)
        if self.rng.random() < 0.2:
            with open(self.path, "a") as f:  # what some exporters leave after 0 EOF
                f.write("not DXF after EOF\n999\n")
        out = [f"case {self.path}"]
        for name, entities, _ in self.layers:
            out.append(f"layer {name}")
            if name in self.starts:
                out.append(f"start {self.starts[name][0]!r} {self.starts[name][1]!r}")
            for label, pts in entities:
                out.append(f"entity {label}")
                out += [f"p {x!r} {y!r}" for x, y in pts]
                out += [f"onearc {x!r} {y!r}" for x, y in self.one_arcs.get(label.split()[1], []) if " in " not in label]
        return "\n".join(out)


def main():
    outdir, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    os.makedirs(outdir, exist_ok=True)
    for i in range(count):
        rng = random.Random(seed * 1000003 + i)
        d = Drawing(rng, os.path.join(outdir, f"random_{seed}_{i}.dxf"))
        for k in range(rng.randint(1, 4)):
            d.chain(f"CHAIN{k}")
        print(d.write())


if __name__ == "__main__":
    main()
