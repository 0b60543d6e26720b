"""rollkin.contours (python/scene_bindings.cpp, docs/python.md): the chains of an SVG drawing against closed
forms of tests/data/svg/clones.svg and against `rollkin contours --json` run as a separate process.

Run by ctest as part of the test "python" (PYTHONPATH=<build>/python, ROLLKIN_CLI, ROLLKIN_SOURCE_DIR set).
"""
import json
import math
import os
import pathlib
import shutil
import subprocess

import pytest

import rollkin

CLI = os.environ["ROLLKIN_CLI"]
SRC = pathlib.Path(os.environ["ROLLKIN_SOURCE_DIR"])
CLONES = SRC / "tests" / "data" / "svg" / "clones.svg"


def ellipse_perimeter(a, b, n=200000):
    """Perimeter of an ellipse of semi-axes a, b by the midpoint rule on its periodic integrand (spectrally exact)."""
    h = 2 * math.pi / n
    return sum(math.hypot(a * math.sin((k + 0.5) * h), b * math.cos((k + 0.5) * h)) for k in range(n)) * h


def test_contours_of_an_svg_drawing_match_closed_forms(tmp_path):
    drawing = tmp_path / "clones.svg"
    shutil.copy(CLONES, drawing)
    chains = rollkin.contours(drawing)
    assert len(chains) == 11
    plate_outline, plate_hole = chains[0], chains[1]
    # The outline: 100 x 80 in the group's scale(1.25, 0.8), i.e. 125 x 64, at (10, 10) + translate(20, 15); y up.
    assert plate_outline["entities"] == ["subpath 1"] and plate_outline["closed"]
    assert plate_outline["length"] == pytest.approx(2 * (125 + 64), rel=1e-14)
    assert plate_outline["min"] == pytest.approx((32.5, -87), rel=1e-14)
    assert plate_outline["max"] == pytest.approx((157.5, -23), rel=1e-14)
    assert plate_outline["corners"] == 4
    # The hole: a circle of radius 12 under scale(1.25, 0.8), an ellipse of semi-axes 15 and 9.6.
    assert plate_hole["length"] == pytest.approx(ellipse_perimeter(15, 9.6), rel=1e-12)
    assert plate_hole["corners"] == 0
    assert plate_outline["selector"] == {"type": "svg", "file": str(drawing), "path": "plate", "subpath": 1}
    # The open polyline of the symbol, cloned with scale(1.5): two edges of 3 sqrt(2) each, scaled by
    # (1.25 * 1.5, 0.8 * 1.5) = (1.875, 1.2).
    # The symbol's ellipse (rx 4, ry 2.5, rotate(-30)) cloned with scale(1.5) at (60, 200): its box is exact,
    # half-extents sqrt((4 L[i][0])^2 + (2.5 L[i][1])^2) of the linear map L = diag(1.25, 0.8) 1.5 R(-30 deg).
    c, s_ = math.cos(math.radians(-30)), math.sin(math.radians(-30))
    L = [[1.25 * 1.5 * c, -1.25 * 1.5 * s_], [0.8 * 1.5 * s_, 0.8 * 1.5 * c]]
    half = [math.hypot(4 * L[i][0], 2.5 * L[i][1]) for i in range(2)]
    centre = (20 + 1.25 * 1.5 * 60, -(15 + 0.8 * 1.5 * 200))
    ring = chains[8]
    assert ring["min"] == pytest.approx((centre[0] - half[0], centre[1] - half[1]), rel=1e-13)
    assert ring["max"] == pytest.approx((centre[0] + half[0], centre[1] + half[1]), rel=1e-13)
    tick = chains[9]
    assert not tick["closed"] and tick["corners"] == 1
    assert tick["length"] == pytest.approx(2 * math.hypot(3 * 1.875, 3 * 1.2), rel=1e-14)
    assert tick["selector"] == {"type": "svg", "file": str(drawing), "path": "marks", "subpath": 2}


def test_contours_is_what_the_command_line_lists(tmp_path):
    drawing = tmp_path / "clones.svg"
    shutil.copy(CLONES, drawing)
    listed = json.loads(subprocess.run([CLI, "contours", str(drawing), "--json"], capture_output=True, text=True,
                                       check=True).stdout)
    mine = rollkin.contours(str(drawing))
    assert len(mine) == len(listed)
    for a, b in zip(mine, listed):
        assert a["group"] == b["group"] and a["entities"] == b["entities"] and a["closed"] == b["closed"]
        assert a["length"] == b["length"] and list(a["min"]) == b["min"] and list(a["max"]) == b["max"]
        assert a["corners"] == b["corners"] and a["selector"] == b["selector"]


def test_a_listed_selector_builds_a_scene(tmp_path):
    drawing = tmp_path / "clones.svg"
    shutil.copy(CLONES, drawing)
    chain = rollkin.contours(drawing)[2]
    scene = rollkin.scene({"links": [{"name": "ground", "ground": True, "contours": [dict(name="c", **chain["selector"])]},
                                     {"name": "slider"}],
                           "pairs": [{"name": "S", "type": "prismatic", "links": ["ground", "slider"], "variable": "s",
                                      "value": 0}],
                           "inputs": ["S.s"]})
    assert scene.inputs == ["S.s"]


def test_contours_errors(tmp_path):
    (tmp_path / "notes.odt").write_text("x")
    with pytest.raises(rollkin.InputError, match="expected a file ending in .txt, .csv, .svg or .dxf"):
        rollkin.contours(tmp_path / "notes.odt")
    (tmp_path / "cycle.svg").write_text('<svg xmlns="http://www.w3.org/2000/svg"><use id="a" href="#b"/>'
                                        '<use id="b" href="#a"/></svg>')
    with pytest.raises(rollkin.InputError, match="is part of a <use> cycle"):
        rollkin.contours(tmp_path / "cycle.svg")


def dxf(*entities):
    """A DXF text of the ENTITIES given as (type, handle, layer, {group: value})."""
    lines = ["0", "SECTION", "2", "ENTITIES"]
    for kind, handle, layer, groups in entities:
        lines += ["0", kind, "5", handle, "8", layer]
        for code, value in groups.items():
            lines += [str(code), str(value)]
    return "\n".join(lines + ["0", "ENDSEC", "0", "EOF", ""])


def test_chains_without_a_selector_and_unreadable_entities(tmp_path):
    """A branch (no selector: None, with the reason), an unreadable entity (its message, no length or box) and a
    hidden SVG element without an id, in a valid drawing: listed, as `rollkin contours --json` lists them."""
    drawing = tmp_path / "parts.dxf"
    line = lambda h, layer, a, b: ("LINE", h, layer, {10: a[0], 20: a[1], 11: b[0], 21: b[1]})
    drawing.write_text(dxf(line("2A", "OK", (0, 0), (1, 0)),
                           ("ELLIPSE", "2B", "BAD", {10: 0, 20: 0, 11: 0, 21: 0, 40: 0.5, 41: 0, 42: 1}),
                           line("2C", "Y", (0, 5), (1, 5)), line("2D", "Y", (1, 5), (2, 5)), line("2E", "Y", (1, 5), (1, 6))))
    chains = rollkin.contours(drawing)
    assert [c["group"] for c in chains] == ["OK", "BAD", "Y"]
    assert chains[0]["selector"] == {"type": "dxf", "file": str(drawing), "layer": "OK"} and "no_selector" not in chains[0]
    assert chains[1]["selector"] is None and chains[1]["length"] is None and chains[1]["min"] is None
    assert "ELLIPSE 2B has a zero major axis" in chains[1]["unreadable"]
    assert chains[2]["selector"] is None and "3 entity ends meet at (1, 5)" in chains[2]["no_selector"]
    assert chains[2]["length"] == pytest.approx(3, rel=1e-12)
    assert chains[2]["min"] == pytest.approx((0, 5), abs=1e-12) and chains[2]["max"] == pytest.approx((2, 6), abs=1e-12)
    listed = json.loads(subprocess.run([CLI, "contours", str(drawing), "--json"], capture_output=True, text=True).stdout)
    for mine, cli in zip(chains, listed):
        assert {k: (list(v) if isinstance(v, tuple) else v) for k, v in mine.items()} == cli
    svg = tmp_path / "hidden.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg"><path d="M 0 0 h 1 v 1 z"/>'
                   '<path style="display:none" d="M 2 0 h 1 v 1 z"/></svg>')
    shown, hidden = rollkin.contours(svg)
    assert "hidden" not in shown and "near" in shown["selector"]
    assert hidden["hidden"] == 'style="display:none" on line 1, <path>' and hidden["selector"] is None
    assert "give it an id" in hidden["no_selector"]
