"""Synthesis in the Python module (python/synthesis_bindings.cpp, docs/synthesis.md) against closed forms
computed here and against the command-line tool.

Run by ctest as part of the test "python" (PYTHONPATH=<build>/python, ROLLKIN_CLI, ROLLKIN_SOURCE_DIR set).
"""
import json
import math
import os
import pathlib
import subprocess

import numpy as np
import pytest

import rollkin

CLI = os.environ["ROLLKIN_CLI"]
SRC = pathlib.Path(os.environ["ROLLKIN_SOURCE_DIR"])
CAM = SRC / "examples" / "synthesis" / "cam_cycloidal_roller.json"


def cycloidal(theta_deg, h=15.0):
    """s, ds/dtheta (per radian) of the example's law: cycloidal rise over 90 deg, dwell, return, dwell."""
    d = theta_deg % 360
    beta = math.pi / 2
    if d <= 90 or 180 <= d <= 270:
        x = (d if d <= 90 else d - 180) / 90
        y, v = x - math.sin(2 * math.pi * x) / (2 * math.pi), 1 - math.cos(2 * math.pi * x)
        return (h * y, h * v / beta) if d <= 90 else (h - h * y, -h * v / beta)
    return (h, 0.0) if d < 180 else (0.0, 0.0)


def test_cam_round_trip_and_pressure_angle_against_the_closed_form():
    r = rollkin.synthesize_cam(json.loads(CAM.read_text()), base_dir=str(CAM.parent))
    assert r["folds"] == [] and r["jumps"] == []
    rt = r["round_trip"]
    assert rt["ok"] and rt["solved"] == rt["poses"] == 998
    assert rt["worst_deviation"] <= 1e-9 * 15
    # Offset e = 12, roller 10, base 40, ccw: tan(pressure angle) = |s' - e| / (y0 + s) (the common normal passes
    # through the relative instant centre (s', 0) and the roller's centre).
    e, y0 = 12.0, math.sqrt(50.0 ** 2 - 12.0 ** 2)
    worst = 0.0
    for theta, angle, analysed, prescribed in zip(rt["cam_angle"], rt["pressure_angle_deg"], rt["analysed"], rt["prescribed"]):
        s, ds = cycloidal(theta)
        assert abs(prescribed - s) < 1e-12
        assert abs(analysed - s) <= 1e-9 * 15
        if not math.isnan(angle):
            worst = max(worst, abs(angle - math.degrees(math.atan(abs(ds - e) / (y0 + s)))))
    assert worst < 1e-6


def test_cam_scene_and_contour_dicts():
    r = rollkin.synthesize_cam(json.loads(CAM.read_text()))
    assert r["contour"]["type"] == "samples" and r["contour"]["closed"] is True
    assert np.allclose(np.array(r["contour"]["points"]), r["profile"], rtol=0, atol=0)
    t = r["scene"].solve(0, 360, 1)
    s = np.array([cycloidal(x)[0] for x in t["cam.theta"]])
    assert np.max(np.abs(t["follower.s"] - s)) <= 1e-9 * 15


def test_undercut_is_reported_without_a_scene():
    spec = json.loads(CAM.read_text())
    spec["base_radius"], spec["contact"] = 20, {"roller_radius": 15}
    spec["follower"] = {"motion": "translating"}
    spec["law"] = [{"to": 30, "lift": 30, "kind": "cycloidal"}, {"to": 180, "kind": "dwell"},
                   {"to": 210, "lift": -30, "kind": "cycloidal"}, {"to": 360, "kind": "dwell"}]
    r = rollkin.synthesize_cam(spec)
    assert len(r["folds"]) == 4 and r["scene"] is None and r["round_trip"] is None


def test_bad_spec_is_an_input_error_at_its_path():
    spec = json.loads(CAM.read_text())
    spec["law"][0]["kind"] = "cycloid"
    with pytest.raises(rollkin.InputError) as e:
        rollkin.synthesize_cam(spec)
    assert e.value.location == "law[0].kind"


def test_elliptical_gears_come_back():
    g = rollkin.synthesize_gears({"units": {"length": "mm"}, "centre_distance": 80,
                                  "transmission": {"kind": "elliptical", "eccentricity": 0.5}})
    assert g["closes"] and g["round_trip"]["ok"]
    a, e = 40.0, 0.5
    for xy in (g["gear1"], g["gear2"]):
        theta = np.arctan2(xy[:, 1], xy[:, 0])
        rho = np.hypot(xy[:, 0], xy[:, 1])
        assert np.max(np.abs(rho - a * (1 - e * e) / (1 - e * np.cos(theta)))) < 1e-10 * a


def test_envelope_of_the_roller_gives_the_cam_back(tmp_path):
    r = rollkin.synthesize_cam(json.loads(CAM.read_text()))
    env = rollkin.envelope(r["scene"], "cam", "follower", "follower.roller", tolerance=1e-7)
    assert env["closed"] and env["defects"] == [] and env["max_midpoint_deviation"] <= 1e-7
    # Every envelope point on the profile's polygon, within its sag (chord^2 / (8 radius), radius >= 28 here).
    P = r["profile"]
    A, D = P, np.roll(P, -1, axis=0) - P
    L2 = (D ** 2).sum(1)
    sag = float(L2.max()) / (8 * 28)
    for q in env["points"]:
        t = np.clip(((q - A) * D).sum(1) / L2, 0, 1)
        assert np.sqrt((((A + t[:, None] * D) - q) ** 2).sum(1)).min() < sag + 1e-8
    # The same as the command line's envelope of the scene it writes.
    prefix = tmp_path / "cam"
    subprocess.run([CLI, "synthesize", "cam", str(CAM), "--out", str(prefix)], check=True, capture_output=True)
    out = tmp_path / "env"
    subprocess.run([CLI, "synthesize", "envelope", str(prefix) + ".json", "--links", "cam", "follower", "--contour",
                    "follower.roller", "--tolerance", "1e-7", "--out", str(out)], check=True, capture_output=True)
    cli = np.loadtxt(str(out) + ".txt")
    assert cli.shape == env["points"].shape
    assert np.max(np.abs(cli - env["points"])) < 1e-12


def test_nurbs_output_is_the_same_cam():
    """The profile as an exact nurbs dict in place of the samples one: the analysed follower still follows the law."""
    r = rollkin.synthesize_cam(json.loads(CAM.read_text()))
    n = r["nurbs"]
    assert n["type"] == "nurbs" and n["degree"] == 3 and n["closed"] is True and n["parameter"] == "arc_length"
    assert len(n["knots"]) == len(n["points"]) + 4
    doc = r["scene"].document()
    doc["links"][1]["contours"][0] = n
    t = rollkin.scene(doc).solve(0, 360, 0.7)
    s = np.array([cycloidal(x)[0] for x in t["cam.theta"]])
    assert np.max(np.abs(t["follower.s"] - s)) <= 1e-9 * 15
    env = rollkin.envelope(r["scene"], "cam", "follower", "follower.roller", tolerance=1e-7)
    assert env["nurbs"]["type"] == "nurbs" and env["nurbs"]["closed"] is True


def _polygons_and_circles(svg):
    """The <polygon> point lists ((n, 2) arrays, pixels) and <circle> (cx, cy, r) of an SVG document, by xml.etree."""
    import xml.etree.ElementTree as ET
    root = ET.fromstring(svg)
    polygons = [np.array([[float(c) for c in p.split(",")] for p in e.get("points").split()])
                for e in root.iter() if e.tag.endswith("polygon")]
    assert all(e.get("id") for e in root.iter() if e.tag.endswith("polygon"))  # selectable: {"type": "svg", "path": id}
    circles = [(float(e.get("cx")), float(e.get("cy")), float(e.get("r")))
               for e in root.iter() if e.tag.endswith("circle") and e.get("class") != "point"]
    return polygons, circles


def _pixel_map(world, pixels):
    """The uniform scale s and offset (ox, oy) with pixels = (ox + s x, oy - s y), fitted by least squares, and the
    largest distance of a pixel from that image of its world point (the canvas rounds to 0.01 px)."""
    n = len(world)
    a = np.zeros((2 * n, 3))
    a[:n, 0], a[:n, 1] = world[:, 0], 1.0
    a[n:, 0], a[n:, 2] = -world[:, 1], 1.0
    (s, ox, oy), *_ = np.linalg.lstsq(a, np.concatenate([pixels[:, 0], pixels[:, 1]]), rcond=None)
    image = np.column_stack([ox + s * world[:, 0], oy - s * world[:, 1]])
    return s, ox, oy, np.max(np.abs(image - pixels))


def test_cam_picture_draws_the_profile_and_the_roller_as_the_cli_writes_it(tmp_path):
    """The picture Python returns is the file `rollkin synthesize cam` writes (one function draws both), and it
    draws the profile and the roller where they are, to the canvas's two decimals."""
    r = rollkin.synthesize_cam(str(CAM))
    subprocess.run([CLI, "synthesize", "cam", str(CAM), "--out", str(tmp_path / "c")], check=True, capture_output=True)
    assert (tmp_path / "c.svg").read_text() == r["svg"]
    polygons, circles = _polygons_and_circles(r["svg"])
    assert len(polygons) == 1 and len(polygons[0]) == len(r["profile"])
    s, ox, oy, worst = _pixel_map(np.asarray(r["profile"]), polygons[0])
    assert worst <= 0.01
    # The roller (radius 10) at the law's start: centre (e, y0) = (12, sqrt(50^2 - 12^2)).
    (cx, cy, radius), = circles
    assert abs(radius - 10 * s) <= 0.01
    assert abs(cx - (ox + 12 * s)) <= 0.01 and abs(cy - (oy - math.sqrt(50.0 ** 2 - 12.0 ** 2) * s)) <= 0.01


def test_gear_picture_draws_both_pitch_curves_at_the_assembly_pose(tmp_path):
    spec = SRC / "examples" / "synthesis" / "gears_elliptical.json"
    g = rollkin.synthesize_gears(str(spec))
    subprocess.run([CLI, "synthesize", "gears", str(spec), "--out", str(tmp_path / "g")], check=True, capture_output=True)
    assert (tmp_path / "g.svg").read_text() == g["svg"]
    polygons, _ = _polygons_and_circles(g["svg"])
    assert len(polygons) == 2
    # Elliptical: f(0) = 0, so gear 2 is its pitch curve moved to its pivot (80, 0), not turned.
    world = np.vstack([g["gear1"], np.asarray(g["gear2"]) + [80.0, 0.0]])
    s, _, _, worst = _pixel_map(world, np.vstack(polygons))
    assert worst <= 0.01


def test_envelope_start_and_tolerance_are_checked_by_the_command_lines_rule():
    """One rule for the CLI's --start/--tolerance and Python's start=/tolerance= (synthesis/scene_envelope.hpp):
    start=nan was accepted and returned no points while the CLI refused --start nan."""
    r = rollkin.synthesize_cam(json.loads(CAM.read_text()))
    for kwargs, word in [({"start": float("nan")}, "start"), ({"start": float("inf")}, "start"),
                         ({"tolerance": float("nan")}, "tolerance"), ({"tolerance": -1.0}, "tolerance")]:
        with pytest.raises(ValueError) as e:
            rollkin.envelope(r["scene"], "cam", "follower", "follower.roller", **kwargs)
        assert word in str(e.value) and "expected" in str(e.value)
    cli = subprocess.run([CLI, "synthesize", "envelope", str(SRC / "examples" / "cycloid.json"), "--links", "ground", "disk",
                          "--contour", "disk.rim", "--start", "nan", "--out", "never"], capture_output=True, text=True)
    assert cli.returncode == 2 and "expected a contour parameter" in cli.stderr
