"""The Python module rollkin (python/rollkin_module.cpp, docs/python.md) against the command-line tool.

Run by ctest as the test "python": /usr/bin/python3 -m pytest with PYTHONPATH=<build>/python, ROLLKIN_CLI (the
built tool) and ROLLKIN_SOURCE_DIR set. The independent side of every comparison is a separate process: the
CLI run on a scene file (`rollkin solve SCENE --from --to --step --csv`), its CSV parsed here by Python's csv
module, its stderr for the messages.
"""
import csv
import json
import math
import os
import pathlib
import pickle
import pydoc
import re
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import rollkin

CLI = os.environ["ROLLKIN_CLI"]
SRC = pathlib.Path(os.environ["ROLLKIN_SOURCE_DIR"])
EXAMPLES = sorted((SRC / "examples").glob("*.json"))
PAPER = SRC / "examples" / "paper_fourbar.json"


def cli_csv(scene_file, start, stop, step, tmp_path, *flags):
    """Runs `rollkin solve` on the file; returns (header, rows) of its CSV and the completed process."""
    out = tmp_path / ("cli_%d.csv" % time.monotonic_ns())
    proc = subprocess.run([CLI, "solve", str(scene_file), "--from", repr(start), "--to", repr(stop), "--step", repr(step),
                           "--csv", str(out), *flags], capture_output=True, text=True)
    assert proc.returncode in (0, 1), proc.stderr
    with open(out, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:], proc


def assert_table_equals_csv(table, header, rows):
    """Same column names in the same order; every numeric column to 1e-12 (relative to the value's size, NaN
    where the CSV has nan), the status column exactly."""
    assert list(table) == header
    assert all(len(r) == len(header) for r in rows)
    for j, name in enumerate(header):
        got = table[name]
        assert len(got) == len(rows), name
        if name == "status":
            assert got.dtype.kind == "U"
            assert list(got) == [r[j] for r in rows]
            continue
        assert got.dtype == np.float64 and got.flags["C_CONTIGUOUS"], name
        want = np.array([float(r[j]) for r in rows])
        assert np.array_equal(np.isnan(got), np.isnan(want)), name
        ok = ~np.isnan(want)
        assert np.all(np.abs(got[ok] - want[ok]) <= 1e-12 * np.maximum(1.0, np.abs(want[ok]))), name


def sweep_of(scene):
    s = scene.sweep
    return s["from"], s["to"], s["step"]


def assert_tables_equal(a, b):
    assert list(a) == list(b)
    for k in a:
        if k == "status":
            assert list(a[k]) == list(b[k])
        else:
            assert np.array_equal(a[k], b[k], equal_nan=True), k


# ---- solve: the CLI's CSV, column by column ----------------------------------------------------------------

@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_solve_equals_cli_csv(example, tmp_path):
    scene = rollkin.load_scene(example)
    start, stop, step = sweep_of(scene)
    header, rows, _ = cli_csv(example, start, stop, step, tmp_path)
    assert_table_equals_csv(scene.solve(start, stop, step), header, rows)


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_analysis_and_rates_equal_cli_csv(example, tmp_path):
    scene = rollkin.load_scene(example)
    start, stop, step = sweep_of(scene)
    header, rows, _ = cli_csv(example, start, stop, step, tmp_path, "--analysis", "--rates")
    assert any(h.endswith(".jerk") for h in header)
    assert_table_equals_csv(scene.solve(start, stop, step, analysis=True, rates=True), header, rows)


FORCE_SCENES = sorted((SRC / "tests" / "data" / "forces").glob("*.json"))


@pytest.mark.parametrize("scene_file", FORCE_SCENES, ids=lambda p: p.stem)
def test_forces_equal_cli_csv(scene_file, tmp_path):
    # The force columns of Scene.solve(forces=True) and solve_many(forces=True) are the CLI's --forces columns
    # (docs/forces.md); the CLI's statuses separation and slip are its own (the table keeps the sweep's).
    scene = rollkin.load_scene(scene_file)
    start, stop, step = sweep_of(scene)
    header, rows, _ = cli_csv(scene_file, start, stop, step, tmp_path, "--forces")
    assert "power" in header
    status = header.index("status")
    for r in rows:
        r[status] = "ok" if r[status] in ("separation", "slip") else r[status]
    assert_table_equals_csv(scene.solve(start, stop, step, forces=True), header, rows)
    assert_table_equals_csv(rollkin.solve_many([scene], start, stop, step, forces=True)[0], header, rows)


def test_forces_without_dynamics_is_a_value_error():
    with pytest.raises(ValueError, match="dynamics"):
        rollkin.load_scene(PAPER).solve(forces=True)


def test_solve_with_a_sweep_other_than_the_scenes(tmp_path):
    scene = rollkin.load_scene(PAPER)
    header, rows, _ = cli_csv(PAPER, 80, -20, -2.5, tmp_path)
    table = scene.solve(80, -20, -2.5)
    assert_table_equals_csv(table, header, rows)
    assert table["O_A.theta2"][0] == 80 and table["O_A.theta2"][-1] == -20
    assert_table_equals_csv(scene.solve(), *cli_csv(PAPER, -50, 100, 1, tmp_path)[:2])  # the scene's own sweep


def test_a_limit_gives_statuses_and_nan_like_the_cli(tmp_path):
    # The osculating variant is singular at assembly; the DXF cam runs into no limit. A sweep past the paper
    # example's range: whatever the CLI reports (statuses, NaN rows), the module reports the same.
    scene = rollkin.load_scene(PAPER)
    header, rows, proc = cli_csv(PAPER, -50, 200, 5, tmp_path)
    table = scene.solve(-50, 200, 5)
    assert_table_equals_csv(table, header, rows)
    assert set(table["status"]) - {"ok"}, "expected the sweep to meet a limit beyond 100 deg"
    assert proc.returncode == 1


# ---- modified: overrides by JSON path ------------------------------------------------------------------------

def edited_copy(tmp_path, overrides):
    """The paper example's file with the overrides written into it (no contour files, so it may move)."""
    doc = json.loads(PAPER.read_text())
    for path, value in overrides.items():
        keys = path.replace("]", "").replace("[", ".").split(".")
        at = doc
        for k in keys[:-1]:
            at = at[int(k)] if isinstance(at, list) else at[k]
        last = keys[-1]
        at[int(last) if isinstance(at, list) else last] = value
    out = tmp_path / "edited.json"
    out.write_text(json.dumps(doc))
    return out


@pytest.mark.parametrize("overrides", [
    {"links[1].contours[0].a": 0.6},
    {"links[1].contours[0].a": 0.45, "pairs[3].at[0].x": 6.8, "links[3].contours[0].radius": 4.1},
])
def test_modified_equals_cli_run_of_the_edited_file(overrides, tmp_path):
    scene = rollkin.load_scene(PAPER)
    edited = edited_copy(tmp_path, overrides)
    header, rows, _ = cli_csv(edited, -50, 100, 1, tmp_path, "--analysis")
    variant = scene.modified(overrides)
    table = variant.solve(-50, 100, 1, analysis=True)
    assert_table_equals_csv(table, header, rows)
    assert not np.array_equal(table["B.theta4"], scene.solve(-50, 100, 1)["B.theta4"])  # the override took effect
    assert variant.file.endswith("(modified)")
    assert scene.document()["links"][1]["contours"][0]["a"] == 0.5  # the original is unchanged


@pytest.mark.parametrize("path,value,expected", [
    ("links[9].contours[0].a", 1.0, "no element [9]"),                 # index beyond the array
    ("links[1].contour[0].a", 1.0, "no key \"contour\""),               # key that does not exist on the way
    ("links[1].name[0]", "x", "not an array"),                          # a step into a string
    ("links[1].contours[0].a", "0.6", "expected the coefficient a"),    # wrong type, checked like the file
    ("links[1].contours[0].a", 0, None),                                # a = 0 is not a parabola
    ("links[1].contours[0].zz", 1.0, "unknown key \"zz\""),             # a new key the reader does not know
    ("links[1].contours[0].a", float("nan"), "not finite"),             # not a JSON number
    ("links[1].contours[0].a", float("inf"), "not finite"),
    ("links[1].contours[0].a", object(), "cannot be a scene value"),    # not a JSON value
    ("links..a", 1.0, "not a JSON path"),                               # malformed paths
    ("links[x].a", 1.0, "not a JSON path"),
    ("links[1]name", 1.0, "not a JSON path"),
])
def test_bad_override_raises_input_error_naming_the_path(path, value, expected):
    scene = rollkin.load_scene(PAPER)
    with pytest.raises(rollkin.InputError) as info:
        scene.modified({path: value})
    e = info.value
    assert isinstance(e, ValueError)
    assert path in str(e) and e.location == path, str(e)
    assert e.file == str(PAPER) + " (modified)"
    if expected:
        assert expected in str(e)


def test_override_value_error_message_equals_the_clis_for_the_edited_file(tmp_path):
    edited = edited_copy(tmp_path, {"pairs[1].values": [0, "x"]})
    proc = subprocess.run([CLI, "solve", str(edited)], capture_output=True, text=True)
    assert proc.returncode == 2
    with pytest.raises(rollkin.InputError) as info:
        rollkin.load_scene(PAPER).modified({"pairs[1].values": [0, "x"]})
    e = info.value
    cli_line = proc.stderr.strip()
    assert cli_line.startswith(str(edited) + ":")
    assert cli_line[len(str(edited)):] == str(e)[len(e.file):]  # the same location and message


# ---- load_scene: the CLI's messages ---------------------------------------------------------------------

@pytest.mark.parametrize("text", [
    '{"links": [], "links": []}',                                       # duplicate key (JSON level)
    '{"links": [{"name": "a", "ground": true}, {"name": "a"}]}',        # duplicate link name (scene level)
    '{"links": [1, 2',                                                  # malformed JSON
    '[1, 2]',                                                           # not an object
])
def test_load_scene_raises_the_clis_message(text, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text(text)
    proc = subprocess.run([CLI, "solve", str(bad)], capture_output=True, text=True)
    assert proc.returncode == 2
    with pytest.raises(rollkin.InputError) as info:
        rollkin.load_scene(bad)
    assert str(info.value) == proc.stderr.strip()
    assert isinstance(info.value, ValueError)


def test_load_scene_missing_file():
    with pytest.raises(rollkin.InputError, match="cannot open the scene file"):
        rollkin.load_scene("/nonexistent/scene.json")


def test_cannot_assemble_is_the_clis_input_error(tmp_path):
    overrides = {"pairs[3].at[0].x": 100}  # disk 4's pivot far away: the loop cannot close
    edited = edited_copy(tmp_path, overrides)
    proc = subprocess.run([CLI, "solve", str(edited)], capture_output=True, text=True)
    assert proc.returncode == 2 and "cannot be assembled" in proc.stderr
    with pytest.raises(rollkin.InputError) as info:
        rollkin.load_scene(PAPER).modified(overrides).solve()
    assert str(info.value)[len(info.value.file):] == proc.stderr.strip()[len(str(edited)):]
    assert info.value.location == "pairs"


def test_bad_sweep_arguments():
    scene = rollkin.load_scene(PAPER)
    with pytest.raises(ValueError, match="start/stop/step"):
        scene.solve(0, 10, -1)
    with pytest.raises(ValueError, match="max_steps"):
        scene.solve(-50, 100, 1, max_steps=10)
    doc = scene.document()
    del doc["sweep"]
    with pytest.raises(ValueError, match="no \"sweep\""):
        rollkin.scene(doc).solve()


# ---- scenes as dicts, contours from NumPy -----------------------------------------------------------------

def test_scene_from_its_document_solves_like_the_file():
    scene = rollkin.load_scene(PAPER)
    again = rollkin.scene(scene.document(), base_dir=PAPER.parent, name="paper")
    assert_tables_equal(again.solve(), scene.solve())
    with pytest.raises(rollkin.InputError) as info:
        rollkin.scene({"links": "none"}, name="mine")
    assert info.value.file == "mine" and info.value.location == "links"


def test_dict_scene_with_a_samples_contour_equals_the_cli_on_the_same_file(tmp_path):
    # A cam disk given as samples of an offset circle, lifting a flat follower: built in Python, then written
    # as JSON for the CLI.
    doc, scene = sampled_cam_scene()
    cams = [c for l in doc["links"] for c in l.get("contours", []) if c["type"] == "samples"]
    assert len(cams) == 1 and len(cams[0]["points"]) == 72
    written = tmp_path / "cam_samples.json"
    written.write_text(json.dumps(scene.document()))  # the document holds the points as lists (doc: the array)
    header, rows, _ = cli_csv(written, 0, 360, 10, tmp_path)
    table = scene.solve(0, 360, 10)
    assert_table_equals_csv(table, header, rows)
    assert np.count_nonzero(table["status"] == "ok") >= 1


def test_samples_checks_its_array():
    with pytest.raises(ValueError, match="shape"):
        rollkin.samples(np.zeros((5, 3)))
    with pytest.raises(ValueError, match="row 2"):
        rollkin.samples(np.array([[0, 0], [1, 0], [np.nan, 1], [0, 1.0]]))
    c = rollkin.samples(np.asfortranarray(np.arange(8.0).reshape(4, 2)), name="p", smoothing=0.0)
    assert np.array_equal(c["points"], [(0.0, 1.0), (2.0, 3.0), (4.0, 5.0), (6.0, 7.0)]) and c["smoothing"] == 0.0
    xy = np.arange(8.0).reshape(4, 2)
    assert rollkin.samples(xy)["points"] is xy  # a contiguous float64 array is taken as it is, not copied
    with pytest.raises(rollkin.InputError) as info:  # a value that went bad after samples() checked it
        doc, _ = sampled_cam_scene()
        doc["links"][1]["contours"][0]["points"] = np.array([[0.0, 0.0], [1.0, np.inf], [0.0, 1.0]])
        rollkin.scene(doc, name="mine")
    assert info.value.location == "links[1].contours[0].points[1][1]"


# ---- solve_many ----------------------------------------------------------------------------------------------

def variants():
    scene = rollkin.load_scene(PAPER)
    return [scene] + [scene.modified({"links[1].contours[0].a": a}) for a in (0.4, 0.45, 0.55, 0.6, 0.65)]


@pytest.mark.parametrize("threads", [0, 1, 2, 3])
def test_solve_many_equals_solving_each_alone(threads):
    scenes = variants()
    alone = [s.solve(-50, 100, 0.5, analysis=True) for s in scenes]
    together = rollkin.solve_many(scenes, -50, 100, 0.5, threads=threads, analysis=True)
    assert len(together) == len(scenes)
    assert rollkin.solve_many([], -50, 100, 1, threads=threads) == []
    for a, b in zip(alone, together):
        assert_tables_equal(a, b)


def test_columns_are_separate_arrays_that_outlive_their_table():
    # The columns of a table share one block of memory (docs/python.md): each is its own C-contiguous float64
    # array, writing one changes no other, and a column kept alone stays valid after the rest of its table
    # is gone (the freed memory of other tables would be reused for the arrays made afterwards).
    import gc
    tables = rollkin.solve_many(variants()[:2], -50, 100, 1, threads=1)
    table = tables[1]
    names = [k for k in table if k != "status"]
    copies = {k: table[k].copy() for k in names}
    for k in names:
        assert table[k].dtype == np.float64 and table[k].shape == (151,)
        assert table[k].flags.c_contiguous and table[k].flags.writeable
    table[names[0]][:] = -1.0
    for k in names[1:]:
        assert np.array_equal(table[k], copies[k], equal_nan=True)
    kept = table[names[-1]]
    del table, tables
    gc.collect()
    reused = [np.full(151 * len(names), 7.0) for _ in range(200)]
    assert np.array_equal(kept, copies[names[-1]], equal_nan=True) and len(reused) == 200


def sampled_cam_scene():
    """The DXF cam example with its cam replaced by samples of an offset circle (a spline contour)."""
    phi = np.linspace(0.0, 2 * np.pi, 72, endpoint=False)
    cam = rollkin.samples(np.c_[2.0 * np.cos(phi) + 0.5, 2.0 * np.sin(phi)], name="profile", closed=True)
    doc = json.loads((SRC / "examples" / "dxf_cam.json").read_text())
    for link in doc["links"]:
        for k, c in enumerate(link.get("contours", [])):
            if c.get("type") == "dxf":
                cam.update({key: v for key, v in c.items() if key in ("material", "at")}, name=c["name"])
                link["contours"][k] = cam
    doc.pop("units", None)
    return doc, rollkin.scene(doc)


def test_one_scene_shared_by_several_threads_gives_what_it_gives_alone():
    # Every example and a spline contour, each three times in one batch: the same Scene object is solved by
    # several threads at once.
    scenes = [rollkin.load_scene(p) for p in EXAMPLES] + [sampled_cam_scene()[1]]
    alone = [s.solve() for s in scenes]
    batch = rollkin.solve_many(scenes * 3, threads=3)
    for k, table in enumerate(batch):
        assert_tables_equal(table, alone[k % len(scenes)])


def test_a_variant_that_cannot_assemble_does_not_stop_the_batch():
    scenes = variants()
    broken = scenes[0].modified({"pairs[3].at[0].x": 100})
    batch = scenes[:2] + [broken] + scenes[2:]
    results = rollkin.solve_many(batch, -50, 100, 1, threads=2)
    assert len(results) == len(batch)
    bad = results[2]
    assert [k for k in bad if k != "error"] == list(results[0])  # the same columns, and the reason
    with pytest.raises(rollkin.InputError) as info:
        broken.solve(-50, 100, 1)
    assert bad["error"] == str(info.value) and "cannot be assembled" in bad["error"]
    assert "error" not in results[0]
    assert set(bad["status"]) == {"cannot_assemble"} and len(bad["status"]) == 151
    assert all(np.isnan(bad[k]).all() for k in bad if k not in ("status", "O_A.theta2", "error"))
    assert np.array_equal(bad["O_A.theta2"], np.arange(-50.0, 101.0))
    assert set(results[0]["status"]) == {"ok"}
    for s, r in zip(batch, results):
        if s is not broken:
            assert "cannot_assemble" not in set(r["status"])
            assert_tables_equal(r, s.solve(-50, 100, 1))


def batch_lasting(seconds, step, at_least):
    """Copies of variants() (at least `at_least`) that take about `seconds` on one core to sweep from -50 to 100
    by `step`, sized from one scene's measured solve on this machine."""
    scenes = variants()
    t0 = time.monotonic()
    scenes[0].solve(-50, 100, step)
    per_scene = max(time.monotonic() - t0, 1e-4)
    copies = max(at_least, int(math.ceil(seconds / per_scene)))
    return (scenes * copies)[:copies]


def test_solve_many_releases_the_gil():
    counter = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counter[0] += 1

    # About half a second of work (a fixed batch became too short to tell once the solver got faster).
    batch = batch_lasting(0.5, 0.01, at_least=6)  # every variant at least once
    t = threading.Thread(target=count)
    t.start()
    try:
        time.sleep(0.05)
        before = counter[0]
        start = time.monotonic()
        rollkin.solve_many(batch, -50, 100, 0.01, threads=1)
        elapsed = time.monotonic() - start
        during = counter[0] - before
    finally:
        stop.set()
        t.join()
    assert elapsed > 0.2, "the batch is too short to tell"
    assert during > 1000, "the counting thread did not run while the batch was solved"


def test_ctrl_c_during_a_long_solve_many_returns_within_a_second():
    batch = batch_lasting(20.0, 0.002, at_least=8)  # about 20 s of work on one core
    sent = []

    def interrupt():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(0.5, interrupt)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            rollkin.solve_many(batch, -50, 100, 0.002, threads=2)
        returned = time.monotonic()
    finally:
        timer.cancel()
    assert sent, "the batch ended before the interrupt"
    assert returned - sent[0] < 1.0, "returned %.3f s after Ctrl-C" % (returned - sent[0])
    # The module works again afterwards.
    assert set(batch[0].solve(-50, 100, 10)["status"]) == {"ok"}


def test_ctrl_c_during_a_long_single_solve():
    scene = rollkin.load_scene(PAPER)
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    sent = time.monotonic() + 0.3
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            scene.solve(-50, 100, 0.0002)  # 750001 poses: about 3 s alone
        returned = time.monotonic()
    finally:
        timer.cancel()
    assert returned - sent < 1.0


# ---- documentation -----------------------------------------------------------------------------------------

def test_help_shows_the_docstrings():
    text = pydoc.render_doc(rollkin, renderer=pydoc.plaintext)
    for word in ("load_scene", "solve_many", "modified", "samples", "InputError", "threads", "KeyboardInterrupt",
                 "JSON path", "analysis"):
        assert word in text, word
    assert issubclass(rollkin.InputError, ValueError)


# ---- the examples under examples/python -------------------------------------------------------------------

def run_example(name, *args):
    env = dict(os.environ)
    return subprocess.run([sys.executable, str(SRC / "examples" / "python" / name), *args], capture_output=True,
                          text=True, env=env, timeout=300)


def test_fit_profile_recovers_the_design():
    pytest.importorskip("scipy")
    proc = run_example("fit_profile.py", "--target-a", "0.6", "--target-x", "6.9")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    fitted = re.search(r"fitted a = ([-0-9.e]+), pivot x = ([-0-9.e]+)", proc.stdout)
    assert abs(float(fitted.group(1)) - 0.6) < 1e-8 and abs(float(fitted.group(2)) - 6.9) < 1e-8, proc.stdout


def test_design_study_on_dask_equals_the_same_variants_solved_here(tmp_path):
    pytest.importorskip("dask.distributed")
    out = tmp_path / "study"
    proc = run_example("design_study.py", "--variants", "27", "--design", "grid", "--workers", "1", "--out", str(out))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    with open(out / "results.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 27 and (out / "study.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    base = rollkin.load_scene(PAPER)
    for r in rows:
        t = base.modified({"links[1].contours[0].a": float(r["a"]), "links[2].contours[0].radius": float(r["radius3"]),
                           "pairs[3].at[0].x": float(r["pivot_x"])}).solve(analysis=True)
        ok = t["status"] == "ok"
        assert int(r["solved"]) == ok.sum() and int(r["poses"]) == len(ok)
        assert r["first_problem"] == next((s for s in t["status"] if s != "ok"), "")
        assert float(r["swing_deg"]) == t["link4.angle"][ok].max() - t["link4.angle"][ok].min()
        assert float(r["max_pressure_angle_B_deg"]) == np.nanmax(t["B.pressure_angle"][ok])
        assert float(r["worst_residual"]) == t["residual"][ok].max()
        first_break = len(ok) if ok.all() else int(np.argmin(ok))
        assert float(r["reached_to_deg"]) == t["O_A.theta2"][first_break - 1]
    assert {r["first_problem"] for r in rows} >= {"", "domain_exit"}  # the grid spans both outcomes
    assert len({(r["a"], r["radius3"], r["pivot_x"]) for r in rows}) == 27
    # A file where the directory should be: refused, the file untouched.
    blocker = tmp_path / "file"
    blocker.write_text("mine")
    proc = run_example("design_study.py", "--variants", "2", "--workers", "1", "--out", str(blocker))
    assert proc.returncode == 2 and "is a file" in proc.stderr and blocker.read_text() == "mine"


def test_design_study_on_a_running_cluster_by_its_address(tmp_path):
    # A scheduler and a worker started as separate processes, as on a cluster (docs/python.md); the study is
    # given only the scheduler's address and must give what the LocalCluster run gives.
    pytest.importorskip("dask.distributed")
    info = tmp_path / "scheduler.json"
    common = ["--no-dashboard"]
    scheduler = subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1",
                                  "--port", "0", "--scheduler-file", str(info), *common],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    worker = None
    try:
        deadline = time.monotonic() + 60
        while not info.exists() and time.monotonic() < deadline:
            time.sleep(0.1)
        address = json.loads(info.read_text())["address"]
        worker = subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", address, "--nthreads", "1",
                                   *common], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=dict(os.environ))
        remote = run_example("design_study.py", "--variants", "12", "--out", str(tmp_path / "remote"), "--scheduler",
                             address)
        assert remote.returncode == 0, remote.stdout + remote.stderr
    finally:
        for p in (worker, scheduler):
            if p is not None:
                p.terminate()
                p.wait(timeout=30)
    local = run_example("design_study.py", "--variants", "12", "--workers", "1", "--out", str(tmp_path / "local"))
    assert local.returncode == 0, local.stdout + local.stderr
    assert (tmp_path / "remote" / "results.csv").read_text() == (tmp_path / "local" / "results.csv").read_text()
    assert len((tmp_path / "remote" / "results.csv").read_text().splitlines()) == 13


def test_latin_hypercube_has_one_point_in_every_slice():
    sys.path.insert(0, str(SRC / "examples" / "python"))
    try:
        import design_study
    finally:
        sys.path.pop(0)
    points = design_study.design("lhs", 50, seed=3)
    assert points.shape == (50, 3)
    for axis in points.T:  # each of the 50 slices of [0, 1) holds exactly one point
        assert sorted(np.floor(axis * 50).astype(int)) == list(range(50))


def test_scenes_pickle_as_their_document(tmp_path):
    scene = rollkin.load_scene(SRC / "examples" / "dxf_cam.json")  # with a relative contour file
    variant = scene.modified({"sweep.step": 10})
    copy = pickle.loads(pickle.dumps(variant))
    assert copy.file == variant.file and copy.document() == variant.document()
    cwd = os.getcwd()
    try:
        os.chdir(tmp_path)  # elsewhere: the contour file is still found
        assert_tables_equal(pickle.loads(pickle.dumps(variant)).solve(), variant.solve())
    finally:
        os.chdir(cwd)


# ---- nurbs, reference, centrodes and files (the rest of the CLI from Python) ----------------------------------

def nurbs_rim_scene():
    """The paper example with link4's rim (a circle of radius 4 about (2, 0)) given as the exact rational
    quadratic NURBS circle, parameterised by arc length from its point at angle 0."""
    doc = json.loads(PAPER.read_text())
    w = math.sqrt(0.5)
    corners = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    doc["links"][3]["contours"][0] = rollkin.nurbs(
        4.0 * np.array(corners, dtype=float), degree=2, knots=[0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4],
        weights=[1, w, 1, w, 1, w, 1, w, 1], name="rim", closed=True, parameter="arc_length", at={"x": 2, "y": 0})
    doc["pairs"][2]["values"] = [-3, 4.0 * math.radians(117)]  # theta4 = 117 deg as arc length on the rim
    return rollkin.scene(doc, name="nurbs_rim")


def test_a_nurbs_circle_moves_the_mechanism_like_the_analytic_circle():
    nurbs = nurbs_rim_scene().solve(-50, 100, 1)
    circle = rollkin.load_scene(PAPER).solve(-50, 100, 1)
    assert set(nurbs["status"]) == {"ok"}
    for k in circle:
        if k.startswith("link"):  # the links' poses: lengths 1e-12, angles 1e-10 deg
            assert np.max(np.abs(nurbs[k] - circle[k])) <= (1e-10 if k.endswith("angle") else 1e-12), k
    # Closed form of the contact parameter: arc length on a circle of radius 4 is 4 theta (mod the perimeter).
    s = np.mod(nurbs["B.theta4"], 8 * math.pi)
    assert np.max(np.abs(s - np.mod(4 * np.radians(circle["B.theta4"]), 8 * math.pi))) < 1e-9


def test_nurbs_default_knots_and_checks():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    c = rollkin.nurbs(square, degree=2)
    assert list(c["knots"]) == [0, 0, 0, 1, 2, 2, 2] and "weights" not in c and c["type"] == "nurbs"
    assert list(rollkin.nurbs(square, degree=1)["knots"]) == [0, 0, 1, 2, 3, 3]
    with pytest.raises(ValueError, match="degree \\+ 1 = 5"):
        rollkin.nurbs(square, degree=4)
    with pytest.raises(ValueError, match="shape"):
        rollkin.nurbs(np.zeros(6))
    doc = json.loads(PAPER.read_text())
    doc["links"][3]["contours"][0] = rollkin.nurbs(square, degree=2, knots=[0, 0, 1, 2, 2, 2], name="rim")
    with pytest.raises(rollkin.InputError) as info:
        rollkin.scene(doc)
    assert info.value.location == "links[3].contours[0].knots" and "need points + degree + 1 = 7" in str(info.value)


def test_reference_equals_the_clis_reference_csv_and_bounds_the_double_solve(tmp_path):
    scene = rollkin.load_scene(PAPER)
    ref = scene.reference(-50, 100, 5, digits=30)
    out = tmp_path / "ref.csv"
    proc = subprocess.run([CLI, "reference", str(PAPER), "--from", "-50", "--to", "100", "--step", "5", "--digits", "30",
                           "--csv", str(out)], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    with open(out, newline="") as f:
        rows = list(csv.reader(f))
    assert list(ref) == rows[0]
    for j, name in enumerate(rows[0]):  # the decimal strings, each rounded once to a double by Python's float()
        want = [r[j] for r in rows[1:]]
        assert list(ref[name]) == (want if name == "status" else [float(v) for v in want]), name
    solved = scene.solve(-50, 100, 5)
    for name in ref:
        if name not in ("status", "residual"):
            assert np.max(np.abs(solved[name] - ref[name])) < 1e-9, name
    with pytest.raises(ValueError, match="30, 50 or 100"):
        scene.reference(digits=40)


def test_write_gives_the_clis_files_and_never_writes_over_an_input(tmp_path):
    scene = rollkin.load_scene(PAPER)
    mine = {k: tmp_path / ("py." + k) for k in ("csv", "plot", "draw", "animate")}
    table = scene.write(-50, 100, 2, analysis=True, **{k: str(p) for k, p in mine.items()})
    theirs = {k: tmp_path / ("cli." + k) for k in mine}
    proc = subprocess.run([CLI, "solve", str(PAPER), "--from", "-50", "--to", "100", "--step", "2", "--analysis"] +
                          sum([["--" + k, str(p)] for k, p in theirs.items()], []), capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    for k in mine:
        assert mine[k].read_bytes() == theirs[k].read_bytes(), k
    header, rows, _ = cli_csv(PAPER, -50, 100, 2, tmp_path, "--analysis")
    assert_table_equals_csv(table, header, rows)
    # Refused before solving, nothing written: the scene file itself, a missing directory.
    before = PAPER.read_bytes()
    with pytest.raises(rollkin.OutputError, match="input file"):
        scene.modified({"links[1].contours[0].a": 0.6}).write(csv=str(PAPER))
    assert PAPER.read_bytes() == before
    with pytest.raises(OSError, match="no_such_dir"):
        scene.write(csv=str(tmp_path / "new.csv"), plot=str(tmp_path / "no_such_dir" / "x.svg"))
    assert not (tmp_path / "new.csv").exists()


def test_every_output_format_of_the_table_is_a_write_keyword(tmp_path):
    """Scene.write's file keywords come from the table of output formats (output::sweep_formats()): each one
    alone writes the file the CLI's option of that name writes, and nothing else; its docstring lists it."""
    formats = rollkin.output_formats()
    assert {"csv", "plot", "draw", "animate"} <= {name for name, _ in formats}
    scene = rollkin.load_scene(PAPER)
    for name, what in formats:
        assert "  %s: %s" % (name, what) in scene.write.__doc__
        out = tmp_path / name
        out.mkdir()
        scene.write(-50, 100, 25, **{name: str(out / "py")})
        assert os.listdir(out) == ["py"], name
        proc = subprocess.run([CLI, "solve", str(PAPER), "--from", "-50", "--to", "100", "--step", "25",
                               "--" + name, str(out / "cli")], capture_output=True, text=True)
        assert proc.returncode == 0, proc.stderr
        assert (out / "py").read_bytes() == (out / "cli").read_bytes(), name
    known = ", ".join(name for name, _ in formats)
    with pytest.raises(TypeError, match="'cvs'.*" + re.escape(known)):
        scene.write(cvs=str(tmp_path / "typo.csv"))
    assert not (tmp_path / "typo.csv").exists()


def test_centrodes_of_the_anti_parallelogram_are_the_ellipses_and_the_clis_dxf(tmp_path):
    scene = rollkin.load_scene(SRC / "examples" / "antiparallelogram.json")
    c = scene.centrodes("crank", "follower", 0, 360, 0.5, dxf=str(tmp_path / "py.dxf"))
    assert c["finite"].all() and c["a"].shape == (721, 2) and set(c["status"]) <= {"ok", "singular"}
    ax, ay = c["a"].T  # foci (0, 0) and (0, 2), major axis 4 (the CLI test's closed form)
    assert np.max(np.abs(np.hypot(ax, ay) + np.hypot(ax, ay - 2) - 4)) < 1e-8
    bx, by = c["b"].T  # foci (0, 0) and (2, 0)
    assert np.max(np.abs(np.hypot(bx, by) + np.hypot(bx - 2, by) - 4)) < 1e-8
    proc = subprocess.run([CLI, "centrodes", str(SRC / "examples" / "antiparallelogram.json"), "--links", "crank",
                           "follower", "--out", str(tmp_path / "cli"), "--step", "0.5", "--dxf", str(tmp_path / "cli.dxf")],
                          capture_output=True, text=True)
    # exit 1: the sweep has singular poses (the crank and follower in line), as `rollkin solve` reports them
    assert proc.returncode == 1 and "singular" in proc.stderr, proc.stderr
    assert (tmp_path / "py.dxf").read_bytes() == (tmp_path / "cli.dxf").read_bytes()
    points = np.loadtxt(tmp_path / "cli.crank.txt", skiprows=3)  # two comment lines, the header "x y"
    assert np.max(np.abs(points - c["a"])) < 1e-12
    with pytest.raises(ValueError, match="no link \"nope\""):
        scene.centrodes("crank", "nope")


# ---- paths: one conversion for every path argument; no file the scene read is ever written over ----------

def scene_copy(tmp_path, name="scene.json"):
    """A copy of the paper's scene in tmp_path (its contours are analytic: it reads no other file)."""
    copy = tmp_path / name
    copy.write_bytes(PAPER.read_bytes())
    return copy


@pytest.mark.parametrize("form", ["str", "bytes", "pathlike"])
def test_every_path_form_names_the_same_file(form, tmp_path):
    as_form = {"str": str, "bytes": os.fsencode, "pathlike": pathlib.Path}[form]
    scene = rollkin.load_scene(as_form(scene_copy(tmp_path)))
    assert scene.file == str(tmp_path / "scene.json")
    scene.write(-50, 100, 50, csv=as_form(tmp_path / "out.csv"), plot=as_form(tmp_path / "out.svg"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.csv", "out.svg", "scene.json"]  # no "b'out.csv'"
    assert (tmp_path / "out.csv").read_text().startswith("O_A.theta2")
    c = rollkin.load_scene(SRC / "examples" / "antiparallelogram.json").centrodes(
        "crank", "follower", 0, 90, 45, dxf=as_form(tmp_path / "c.dxf"))
    assert c["finite"].all() and (tmp_path / "c.dxf").stat().st_size > 0
    again = rollkin.scene(scene.document(), base_dir=as_form(tmp_path), name=as_form(tmp_path / "named.json"))
    assert again.file == str(tmp_path / "named.json")


def test_a_bytes_path_that_is_not_utf8_is_the_file_of_those_bytes(tmp_path):
    raw = os.fsencode(tmp_path) + b"/scene\xff.json"
    with open(raw, "wb") as f:
        f.write(PAPER.read_bytes())
    scene = rollkin.load_scene(raw)
    assert scene.file == os.fsdecode(raw)  # decoded as os.fsdecode does (a surrogate escape)
    scene.write(-50, 100, 50, csv=os.fsencode(tmp_path) + b"/out\xfe.csv")
    assert os.path.getsize(os.fsencode(tmp_path) + b"/out\xfe.csv") > 0
    with pytest.raises(rollkin.OutputError, match="input file"):
        scene.write(csv=raw)


@pytest.mark.parametrize("argument", ["path", "csv", "dxf", "base_dir", "name"])
def test_a_nul_in_any_path_is_an_error_naming_the_argument(argument, tmp_path):
    copy = scene_copy(tmp_path)
    for bad in (str(copy) + "\0.csv", os.fsencode(copy) + b"\0.csv"):
        scene = rollkin.load_scene(copy)
        calls = {"path": lambda: rollkin.load_scene(bad),  # the part before the NUL is a scene file
                 "csv": lambda: scene.write(csv=bad),
                 "dxf": lambda: rollkin.load_scene(SRC / "examples" / "antiparallelogram.json").centrodes(
                     "crank", "follower", dxf=bad),
                 "base_dir": lambda: rollkin.scene(scene.document(), base_dir=bad),
                 "name": lambda: rollkin.scene(scene.document(), name=bad)}
        with pytest.raises(ValueError, match="^%s: the path .* contains a NUL character" % argument):
            calls[argument]()
    assert copy.read_bytes() == PAPER.read_bytes() and sorted(p.name for p in tmp_path.iterdir()) == ["scene.json"]


def test_a_lone_surrogate_or_a_wrong_type_is_an_error_naming_the_argument(tmp_path):
    with pytest.raises(ValueError, match="^path: the path .* cannot be a file name"):
        rollkin.load_scene(str(tmp_path) + "/\ud800.json")  # no file system encoding can encode it
    with pytest.raises(ValueError, match="^csv: the path .* cannot be a file name"):
        rollkin.load_scene(PAPER).write(csv="\ud800.csv")
    with pytest.raises(TypeError, match="^csv: expected a path \\(str, bytes or os.PathLike\\), got int"):
        rollkin.load_scene(PAPER).write(csv=3)
    with pytest.raises(ValueError, match="^path: the path is empty"):
        rollkin.load_scene("")


def scenes_made_every_way(copy):
    """The scene of the file `copy`, made each way the module makes scenes, named by what made it."""
    loaded = rollkin.load_scene(copy)
    return {"load_scene": loaded,
            "modified": loaded.modified({"links[1].contours[0].a": 0.6}),
            "pickle": pickle.loads(pickle.dumps(loaded)),
            "scene(name=)": rollkin.scene(loaded.document(), name=str(copy)),
            "scene(name=) modified": rollkin.scene(loaded.document(), name=copy).modified({"sweep.step": 2}),
            "scene(name=) pickled": pickle.loads(pickle.dumps(rollkin.scene(loaded.document(), name=os.fsencode(copy))))}


def test_no_way_of_making_a_scene_lets_write_overwrite_the_file_it_came_from(tmp_path):
    copy = scene_copy(tmp_path)
    spellings = [str(copy), os.fsencode(copy), copy, str(tmp_path / "." / "scene.json"),
                 str(tmp_path / ".." / tmp_path.name / "scene.json")]
    os.link(copy, tmp_path / "hard.json")
    os.symlink(copy, tmp_path / "soft.json")
    spellings += [tmp_path / "hard.json", tmp_path / "soft.json"]
    for how, scene in scenes_made_every_way(copy).items():
        for path in spellings:
            for option in ("csv", "plot", "draw", "animate"):
                with pytest.raises(rollkin.OutputError, match="input file"):
                    scene.write(-50, 100, 50, **{option: path})
            with pytest.raises(rollkin.OutputError, match="input file"):
                scene.write(-50, 100, 50, csv=tmp_path / "fine.csv", plot=path)
            assert copy.read_bytes() == PAPER.read_bytes(), (how, path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hard.json", "scene.json", "soft.json"]


def test_a_dict_scene_never_writes_over_its_contour_files(tmp_path):
    points = tmp_path / "disk.txt"
    points.write_bytes((SRC / "shapes" / "circle_n0032.txt").read_bytes())
    doc = rollkin.load_scene(PAPER).document()
    doc["links"][2]["contours"][0] = {"name": "rim", "type": "samples", "file": "disk.txt", "closed": True}
    doc["pairs"][1]["values"], doc["pairs"][2]["values"] = [0, 3.14033], [-0.05, 117]  # chord-length parameters
    scene = rollkin.scene(doc, base_dir=tmp_path)
    for made in (scene, scene.modified({"sweep.step": 2}), pickle.loads(pickle.dumps(scene))):
        with pytest.raises(rollkin.OutputError, match="disk.txt"):
            made.write(-50, 100, 50, csv=points)
    assert points.read_bytes() == (SRC / "shapes" / "circle_n0032.txt").read_bytes()


# ---- max_steps: one rule with the CLI's --max-steps --------------------------------------------------------

@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -1.0, 0.5])
def test_max_steps_must_be_a_finite_number_of_at_least_one(bad, tmp_path):
    scene = rollkin.load_scene(PAPER)
    calls = [lambda: scene.solve(-50, 100, 1, max_steps=bad), lambda: scene.write(-50, 100, 1, max_steps=bad),
             lambda: scene.centrodes("link1", "link2", max_steps=bad), lambda: scene.reference(max_steps=bad),
             lambda: rollkin.solve_many([scene], -50, 100, 1, max_steps=bad)]
    for call in calls:
        with pytest.raises(ValueError, match="^max_steps: expects a finite number of continuation sub-steps, at least 1"):
            call()
    text = "nan" if bad != bad else repr(bad)
    proc = subprocess.run([CLI, "solve", str(PAPER), "--max-steps", text], capture_output=True, text=True)
    assert proc.returncode == 2 and "--max-steps: expects a finite number of continuation sub-steps, at least 1" in proc.stderr


def test_the_number_of_values_is_bounded_by_max_steps_and_raised_with_it():
    scene = rollkin.load_scene(PAPER)
    # 150 / 1e-5 + 1 = 15,000,001 values: above the default 1e7, refused before any value is made
    with pytest.raises(ValueError, match="1.50e\\+07 values, above the limit 1.00e\\+07 \\(max_steps\\)"):
        scene.solve(-50, 100, 1e-5)
    proc = subprocess.run([CLI, "solve", str(PAPER), "--step", "1e-5"], capture_output=True, text=True)
    assert proc.returncode == 2 and "1.50e+07 values, above the limit 1.00e+07 (--max-steps)" in proc.stderr
    # 10 values 50 degrees from the assembly pose (theta2 = 0): 50 / 5 degrees + 10 = 20 sub-steps estimated
    with pytest.raises(ValueError, match="needs an estimated 2.00e\\+01 continuation sub-steps, above the limit 1.90e\\+01"):
        scene.solve(-50, -41, 1, max_steps=19)
    assert len(scene.solve(-50, -41, 1, max_steps=21)["status"]) == 10


def test_more_than_ten_million_values_run_when_max_steps_allows_them():
    # 1 + 1.1e7 values: the old hidden cap of 1e7 values refused them whatever --max-steps said; the summary-only
    # CLI run keeps no table
    args = [CLI, "solve", str(PAPER), "--from", "-50", "--to", "-48.9", "--step", "1e-7"]
    proc = subprocess.run(args, capture_output=True, text=True)
    assert proc.returncode == 2 and "1.10e+07 values, above the limit 1.00e+07 (--max-steps)" in proc.stderr
    proc = subprocess.run(args + ["--max-steps", "2e7"], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert "11000001/11000001 poses solved" in proc.stdout


# ---- centrodes that are one point ---------------------------------------------------------------------------

def test_the_centrode_of_two_links_joined_by_a_revolute_is_one_point(tmp_path):
    anti = SRC / "examples" / "antiparallelogram.json"
    scene = rollkin.load_scene(anti)
    with pytest.warns(RuntimeWarning, match="is one point, \\(0, 2\\) in link 'crank''s frame .* revolute 'A'"):
        c = scene.centrodes("crank", "coupler", 0, 360, 10, dxf=tmp_path / "cc.dxf")
    assert not (tmp_path / "cc.dxf").exists()
    assert np.max(np.abs(c["a"] - [0, 2])) < 1e-12 and np.max(np.abs(c["b"])) < 1e-12
    proc = subprocess.run([CLI, "centrodes", str(anti), "--links", "crank", "coupler", "--out", str(tmp_path / "cc"),
                           "--dxf", str(tmp_path / "cc.dxf")], capture_output=True, text=True)
    assert proc.returncode == 1 and "singular" in proc.stderr, proc.stderr  # the sweep's singular poses, as solve reports them
    assert "is one point, (0, 2) in link 'crank''s frame and (0, 0) in link 'coupler''s frame" in proc.stdout
    assert "--dxf '%s' not written" % (tmp_path / "cc.dxf") in proc.stderr
    assert not (tmp_path / "cc.dxf").exists()
    points = np.loadtxt(tmp_path / "cc.crank.txt", skiprows=3)
    assert points.shape == (361, 2) and np.max(np.abs(points - [0, 2])) < 1e-12


# ---- Ctrl-C while a scene is read ---------------------------------------------------------------------------

# A child process that times CALL alone, then runs it again with SIGINT 0.3 s in, and prints whether it was
# interrupted, how long after the signal it returned, the time alone, and whether the module works afterwards
# (SETUP runs first; sys.argv[1] is the long input, sys.argv[2] the paper example).
INTERRUPTED = """
import os, signal, sys, threading, time
import rollkin
{setup}
began = time.monotonic()
{call}
alone = time.monotonic() - began
timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
sent = time.monotonic() + 0.3
timer.start()
try:
    {call}
    outcome = "returned"
except KeyboardInterrupt:
    outcome = "interrupted"
after = time.monotonic() - sent
ok = rollkin.load_scene(sys.argv[2]).solve(-50, 100, 50)["status"].tolist() == ["ok"] * 4
print(outcome, after, alone, ok)
"""

LOAD_INTERRUPTED = INTERRUPTED.format(setup="", call="rollkin.load_scene(sys.argv[1])")


def test_ctrl_c_during_a_long_load_returns_within_a_second(tmp_path):
    # A unit disk of 4,000,000 samples (docs/python.md: reading is linear, about 0.3 s per million points on an
    # idle machine since the self-intersection check works on runs of segments; the load must outlast the 0.3 s
    # before Ctrl-C and the 1 s allowed after it): the reading, the spline fit and the checks run on a worker
    # thread that Ctrl-C leaves. In a process of its own: a KeyboardInterrupt that comes only after the load
    # would stop this test session.
    n = 4_000_000
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    xy = np.empty(2 * n)
    xy[0::2], xy[1::2] = np.cos(t), np.sin(t)
    (tmp_path / "disk.txt").write_text("x y\n" + ("%.9f %.9f\n" * n) % tuple(xy))
    doc = rollkin.load_scene(PAPER).document()
    doc["links"][2]["contours"][0] = {"name": "rim", "type": "samples", "file": "disk.txt", "closed": True}
    (tmp_path / "big.json").write_text(json.dumps(doc))
    proc = subprocess.run([sys.executable, "-c", LOAD_INTERRUPTED, str(tmp_path / "big.json"), str(PAPER)],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    outcome, after, alone, works = proc.stdout.split()
    assert float(alone) > 1.3, "the load is too short to tell (%s s)" % alone
    assert outcome == "interrupted" and float(after) < 1.0, \
        "%s %s s after Ctrl-C; the load alone takes %s s" % (outcome, after, alone)
    assert works == "True"  # the module works afterwards


# ---- Ctrl-C while a mechanism is assembled ------------------------------------------------------------------

ASSEMBLY_INTERRUPTED = INTERRUPTED.format(setup="scene = rollkin.load_scene(sys.argv[1])",
                                          call='assert scene.solve(60, 60, 1)["status"].tolist() == ["ok"]')


def folded_four_bar_ladder(loops):
    """A scene of `loops` four-bar loops sharing the ground and a crank of length 1 at 60 deg: coupler and rocker
    3 long, the rockers' pivots 3 to 3 + 1e-5 loops from the crank's. Every coupler and rocker starts folded
    (angles 0): the loops' Jacobian is singular at the guess, so the assembly's first steps take the dense
    decomposition (cubic in the unknowns) instead of the sparse LU."""
    links = [{"name": "ground", "ground": True}, {"name": "crank"}]
    pairs = [{"name": "O", "type": "revolute", "links": ["ground", "crank"], "variable": "phi", "value": 60}]
    for i in range(loops):
        c, r = "coupler%d" % i, "rocker%d" % i
        links += [{"name": c}, {"name": r}]
        pairs += [{"name": "A%d" % i, "type": "revolute", "links": ["crank", c], "at": [{"x": 1}, {}],
                   "variable": "a", "value": 0},
                  {"name": "B%d" % i, "type": "revolute", "links": [c, r], "at": [{"x": 3}, {"x": 3}],
                   "variable": "b", "value": 0},
                  {"name": "P%d" % i, "type": "revolute", "links": ["ground", r], "at": [{"x": 3 + 1e-5 * i}, {}],
                   "variable": "p", "value": 0}]
    return {"units": {"length": "m", "angle": "deg"}, "links": links, "pairs": pairs, "inputs": ["O.phi"]}


def test_ctrl_c_during_a_long_assembly_returns_within_a_second(tmp_path):
    # 600 folded loops (1,800 unknowns): the assembly of one pose takes seconds, the sweep of that pose and its
    # table afterwards a few ms. In a process of its own, like the load above: a KeyboardInterrupt that comes
    # only after the solve would stop this test session.
    (tmp_path / "ladder.json").write_text(json.dumps(folded_four_bar_ladder(600)))
    proc = subprocess.run([sys.executable, "-c", ASSEMBLY_INTERRUPTED, str(tmp_path / "ladder.json"), str(PAPER)],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    outcome, after, alone, works = proc.stdout.split()
    assert float(alone) > 1.3, "the assembly is too short to tell (%s s)" % alone
    assert outcome == "interrupted" and float(after) < 1.0, \
        "%s %s s after Ctrl-C; the assembly alone takes %s s" % (outcome, after, alone)
    assert works == "True"  # the module works afterwards


def test_a_lone_surrogate_in_a_document_is_an_input_error_at_its_path():
    doc = rollkin.load_scene(PAPER).document()
    doc["links"][0]["name"] = "x\ud800"
    with pytest.raises(rollkin.InputError, match="lone surrogate") as info:
        rollkin.scene(doc)
    assert info.value.location == "links[0].name"
    with pytest.raises(rollkin.InputError, match="lone surrogate") as info:
        rollkin.load_scene(PAPER).modified({"links[0].name": "a\udcff"})
    assert info.value.location == "links[0].name"
    with pytest.raises(rollkin.InputError, match="lone surrogate"):
        rollkin.load_scene(PAPER).modified({"links[0].n\ud800": 1})
