#!/usr/bin/env python3
"""Independent reference for rollkin's SVG reader (tests/test_io_svg_reader.cpp).

Usage: svgelements_points.py FILE.svg ID[,ID...] [PPI [map]]

Parses FILE.svg with svgelements (python3-svgelements), which applies every transform of the element and
of its ancestors and the root viewBox with width/height (at PPI px per inch, default 96), and prints the
element's segments in viewport px, y down, one per line, full precision (repr round-trips doubles).
With PPI = 25.4 a px of svgelements is a millimetre: the test compares millimetre drawings that way.
svgelements converts mm and cm with a rounded factor (0.0393701 in per mm, 5.4e-7 too large), so the root's
width and height in mm or cm are handed to it as the same lengths in inches (exact in binary to 1 ulp);
everything else (transforms, viewBox, preserveAspectRatio, shapes, arcs) is svgelements' own work.
    L x0 y0 x1 y1                 line (a non-zero-length close counts as a line)
    Q x0 y0 x1 y1 x2 y2           quadratic Bezier control points
    C x0 y0 x1 y1 x2 y2 x3 y3     cubic Bezier control points
    A sx sy ex ey cx cy ux uy vx vy delta
                                  elliptical arc from s to e on c + u cos(t) + v sin(t) (u, v: svgelements'
                                  transformed semi-axis points prx - c, pry - c, conjugate semi-diameters),
                                  eccentric sweep delta (signed, from s to e: t runs the way svgelements'
                                  sweep turns when (u, v) is positively oriented, the other way otherwise)
    Z                             the subpath is closed
Moves and zero-length closes are left out; a second Move is printed as "M" (more than one subpath).
With several ids (comma-separated), each element's lines follow a line "P ID".
With ID "*", every shape the document draws (svgelements expands <use> clones, the referenced content drawn
as children of the <use>), in document order, each after a line "P ID" (its own id, repeated for clones).
There svgelements deviates from SVG (svgelements 1.7.2; these cases are checked by hand in
test_io_svg_reader.cpp, "use_symbol_viewbox_and_transform_origin_by_hand" and the <switch> tests): the second
and later <use> of the same group are offset by the earlier clones' x/y; a clone of a clone is misplaced; a
<use> of an element defined later in the file draws nothing; a <symbol>'s viewBox is not applied; every child
of a <switch> is drawn; transform-origin is ignored.
With "map", svgelements reads the path data (arc centres and sweeps by its own F.6.5) and composes the
element's transforms, and the script maps the untransformed segments by that matrix: control points, and an
arc's centre and semi-axis end points (an affine map keeps the eccentric parameterisation, so the sweep is
the untransformed one). svgelements' own transformed arcs (reify) can be the wrong arc of the ellipse under a
skew or non-uniform scale with a reflection (seeded random test in test_io_svg_reader.cpp, path r8: F.6.5
computed by hand and rollkin agree, svgelements' reified arc runs elsewhere).
"""
import io
import math
import re
import sys

from svgelements import SVG, Arc, Close, CubicBezier, Line, Move, Path, QuadraticBezier, Shape


def pts(*points):
    return " ".join(f"{p.x!r} {p.y!r}" for p in points)


def eccentric_angle(p, c, u, v):
    """t with p = c + u cos t + v sin t (solved as a 2x2 linear system)."""
    det = u.x * v.y - u.y * v.x
    dx, dy = p.x - c.x, p.y - c.y
    cos_t = (dx * v.y - dy * v.x) / det
    sin_t = (u.x * dy - u.y * dx) / det
    return math.atan2(sin_t, cos_t)


def exact_root_size(text):
    """The root <svg>'s width/height in mm or cm rewritten in inches (see the module comment)."""
    root = re.search(r"<svg\b[^>]*>", text)
    per_inch = {"mm": 25.4, "cm": 2.54}

    def to_inches(m):
        return f'{m.group(1)}="{float(m.group(2)) / per_inch[m.group(3)]!r}in"'

    tag = re.sub(r'\b(width|height)\s*=\s*"\s*([-+0-9.eE]+)\s*(mm|cm)\s*"', to_inches, root.group(0))
    return text[: root.start()] + tag + text[root.end() :]


def main(file, element_id, ppi, mapped=False):
    with open(file, encoding="utf-8") as f:
        text = exact_root_size(f.read())
    svg = SVG.parse(io.StringIO(text), reify=not mapped, ppi=ppi)
    if element_id == "*":
        for element in svg.elements():
            if isinstance(element, Shape):
                print("P", element.id)
                print_segments(element, mapped)
        return
    ids = element_id.split(",")
    for one in ids:
        element = svg.get_element_by_id(one)
        if element is None:
            sys.exit(f"svgelements: no element with id {one!r} in {file}")
        if len(ids) > 1:
            print("P", one)
        print_segments(element, mapped)


def print_segments(element, mapped=False):
    """The element's segments: as svgelements transforms them, or (mapped) its untransformed segments mapped
    by its transform (see "map" in the module comment)."""
    m = element.transform
    at = (lambda p: p * m) if mapped else (lambda p: p)
    moves = 0
    for s in Path(element).segments(transformed=not mapped):
        if isinstance(s, Move):
            moves += 1
            if moves > 1:
                print("M")
        elif isinstance(s, Close):
            if s.start != s.end:
                print("L", pts(at(s.start), at(s.end)))
            print("Z")
        elif isinstance(s, Line):
            print("L", pts(at(s.start), at(s.end)))
        elif isinstance(s, QuadraticBezier):
            print("Q", pts(at(s.start), at(s.control), at(s.end)))
        elif isinstance(s, CubicBezier):
            print("C", pts(at(s.start), at(s.control1), at(s.control2), at(s.end)))
        elif isinstance(s, Arc) and mapped:
            c = s.center * m
            print("A", pts(s.start * m, s.end * m, c, s.prx * m - c, s.pry * m - c), repr(float(s.sweep)))
        elif isinstance(s, Arc):
            c = s.center
            u = s.prx - c
            v = s.pry - c
            t0 = eccentric_angle(s.start, c, u, v)
            t1 = eccentric_angle(s.end, c, u, v)
            delta = (t1 - t0) % (2 * math.pi)
            oriented = u.x * v.y - u.y * v.x > 0
            if (s.sweep > 0) != oriented:
                delta -= 2 * math.pi
            print("A", pts(s.start, s.end, c, u, v), repr(delta))
        else:
            sys.exit(f"svgelements: unexpected segment {type(s).__name__}")


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4, 5) or (len(sys.argv) == 5 and sys.argv[4] != "map"):
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], float(sys.argv[3]) if len(sys.argv) >= 4 else 96.0, len(sys.argv) == 5)
