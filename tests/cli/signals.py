#!/usr/bin/env python3
"""SIGINT and SIGTERM at random moments of rollkin runs with every kind of output: no temporary outlives the
process, no input is touched, and each run's outputs are all old or all new (docs/reliability.md, "Outputs,
signals and messages (issue 37)").

usage: signals.py PATH/TO/rollkin SOURCE_DIR   (env ROLLKIN_SIGNAL_TRIALS: trials per run and signal, default 6;
                                                ROLLKIN_SIGNAL_SEED: the random seed, default 37)

Each run writes over outputs that exist beforehand with known "old" content, in a directory holding nothing but
its inputs and outputs, with TMPDIR a private empty directory. A run is first timed without a signal (it must
exit 0 or 1 and write every output); then, for each signal, rollkin is started again and the signal sent after a
random delay up to 1.2 times that time. After each trial:
  - the process ended by the signal (status -SIG) or finished (0 or 1);
  - the directories hold exactly the inputs and the outputs: no `.NAME.XXXXXX`, no `rollkin-dxf-*` in TMPDIR;
  - every input has its SHA-256 of before;
  - the outputs of one commit are all old or all new (a finished run: all new).
Before the rule, a SIGINT during `solve`'s writing left `.o.csv.XXXXXX` behind.
"""
import hashlib
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

BIN = os.path.abspath(sys.argv[1])
SRC = os.path.abspath(sys.argv[2])
TRIALS = int(os.environ.get("ROLLKIN_SIGNAL_TRIALS", "6"))
rng = random.Random(int(os.environ.get("ROLLKIN_SIGNAL_SEED", "37")))
SANITIZED = bool(os.environ.get("ROLLKIN_SANITIZED"))

failures = []
checks = 0


def check(ok, what):
    global checks
    checks += 1
    if not ok:
        failures.append(what)
        print("FAIL " + what, flush=True)


def sha(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def tree(root):
    """Every file below root, relative paths."""
    out = set()
    for d, _, files in os.walk(root):
        for f in files:
            out.add(os.path.relpath(os.path.join(d, f), root))
    return out


def make_work():
    """work/ with the inputs (examples and the shapes they read), tmp/ for TMPDIR."""
    base = tempfile.mkdtemp(prefix="rollkin_signals.")
    work = os.path.join(base, "work")
    os.makedirs(os.path.join(work, "scenes"))
    os.makedirs(os.path.join(work, "shapes"))
    os.makedirs(os.path.join(work, "out"))
    for f in ["paper_fourbar.json", "dxf_cam.json"]:
        shutil.copy(os.path.join(SRC, "examples", f), os.path.join(work, "scenes", f))
    shutil.copy(os.path.join(SRC, "shapes", "cam_profile.dxf"), os.path.join(work, "shapes", "cam_profile.dxf"))
    for f in ["cam_flat_table.json", "cam_flat_table_law.txt", "gears_elliptical.json", "cam_oscillating.json"]:
        shutil.copy(os.path.join(SRC, "examples", "synthesis", f), os.path.join(work, "scenes", f))
    tmp = os.path.join(base, "tmp")
    os.makedirs(tmp)
    return base, work, tmp


# Each run: the arguments (relative to work/) and its commits (lists of outputs written all or nothing together).
fine = "0.002" if not SANITIZED else "0.05"
RUNS = [
    ("solve, every output",
     ["solve", "scenes/paper_fourbar.json", "--step", fine, "--csv", "out/o.csv", "--plot", "out/o.svg",
      "--draw", "out/o_d.svg", "--animate", "out/o.html", "--rates", "--analysis"],
     [["out/o.csv", "out/o.svg", "out/o_d.svg", "out/o.html"]]),
    ("solve, several scenes",
     ["solve", "scenes/paper_fourbar.json", "scenes/dxf_cam.json", "--step", fine, "--csv", "out/{scene}.csv",
      "--plot", "out/{scene}.svg", "--jobs", "2"],
     [["out/paper_fourbar.csv", "out/paper_fourbar.svg"], ["out/dxf_cam.csv", "out/dxf_cam.svg"]]),
    ("centrodes with DXF",
     ["centrodes", "scenes/paper_fourbar.json", "--step", "0.01", "--links", "link1", "link3", "--out", "out/c",
      "--dxf", "out/c.dxf"],
     [["out/c.link1.txt", "out/c.link3.txt", "out/c.dxf"]]),
    ("synthesize cam (law table)",
     ["synthesize", "cam", "scenes/cam_flat_table.json", "--out", "out/flat"],
     [["out/flat.txt", "out/flat.dxf", "out/flat.svg", "out/flat.json"]]),
    ("synthesize cam (oscillating)",
     ["synthesize", "cam", "scenes/cam_oscillating.json", "--out", "out/osc"],
     [["out/osc.txt", "out/osc.dxf", "out/osc.svg", "out/osc.json"]]),
    ("synthesize gears",
     ["synthesize", "gears", "scenes/gears_elliptical.json", "--out", "out/g"],
     [["out/g.1.txt", "out/g.2.txt", "out/g.dxf", "out/g.svg", "out/g.json"]]),
]


def prepare(work, commits):
    for group in commits:
        for o in group:
            with open(os.path.join(work, o), "w") as f:
                f.write("old " + o + "\n")


def old(work, o):
    try:
        with open(os.path.join(work, o)) as f:
            return f.read() == "old " + o + "\n"
    except (OSError, UnicodeDecodeError):
        return False


def after(work, tmp, name, commits, inputs, rc, sig, expected_files):
    label = "%s (%s)" % (name, "no signal" if sig is None else signal.Signals(sig).name)
    ended = rc in (0, 1) or (sig is not None and rc == -sig)
    check(ended, "%s: exit status %s (expected 0, 1 or -%s)" % (label, rc, sig))
    left = tree(work) - expected_files
    check(not left, "%s: files left behind: %s" % (label, sorted(left)))
    left_tmp = tree(tmp)
    check(not left_tmp, "%s: files left in TMPDIR: %s" % (label, sorted(left_tmp)))
    changed = [p for p, h in inputs.items() if not os.path.exists(os.path.join(work, p)) or sha(os.path.join(work, p)) != h]
    check(not changed, "%s: inputs changed: %s" % (label, changed))
    for group in commits:
        olds = [old(work, o) for o in group]
        if rc in (0, 1):
            check(not any(olds), "%s: finished but outputs still old: %s" % (label, [o for o, b in zip(group, olds) if b]))
        else:
            check(all(olds) or not any(olds), "%s: outputs half committed: old %s" % (label, [o for o, b in zip(group, olds) if b]))


def run(work, tmp, args, sig=None, delay=0.0):
    env = dict(os.environ, TMPDIR=tmp)
    p = subprocess.Popen([BIN] + args, cwd=work, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if sig is not None:
        time.sleep(delay)
        try:
            p.send_signal(sig)
        except ProcessLookupError:
            pass
    _, err = p.communicate(timeout=600)
    return p.returncode, err.decode(errors="replace")


def main():
    base, work, tmp = make_work()
    try:
        inputs = {p: sha(os.path.join(work, p)) for p in tree(work)}
        for name, args, commits in RUNS:
            expected = set(inputs) | {o for g in commits for o in g}
            prepare(work, commits)
            start = time.monotonic()
            rc, err = run(work, tmp, args)
            took = time.monotonic() - start
            check(rc in (0, 1), "%s: unsignalled run exit %d: %s" % (name, rc, err.strip()[-300:]))
            after(work, tmp, name, commits, inputs, rc, None, expected)
            print("%-30s %.2f s unsignalled" % (name, took), flush=True)
            killed = 0
            for sig in (signal.SIGINT, signal.SIGTERM):
                for _ in range(TRIALS):
                    prepare(work, commits)
                    delay = rng.uniform(0, 1.2 * took)
                    rc, err = run(work, tmp, args, sig, delay)
                    killed += rc == -sig
                    after(work, tmp, name, commits, inputs, rc, sig, expected)
            print("%-30s %d of %d trials ended by the signal" % (name, killed, 2 * TRIALS), flush=True)
            for o in expected - set(inputs):  # the next run's directory holds its own files only
                os.remove(os.path.join(work, o))
    finally:
        shutil.rmtree(base, ignore_errors=True)
    print("%d checks, %d failed" % (checks, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
