#!/usr/bin/env bash
# `rollkin solve --forces` from outside (docs/forces.md):
#  - the eccentric cam (tests/data/forces/eccentric_cam.json) at its 500 rpm: exit 0; the CSV has the contract's
#    columns (C.Fx, C.Fy, S.M, C.normal_force, C.friction_force, C.contact_pressure, ..., O.phi.effort, power);
#    C.normal_force equals P + k e (1 - cos th) + m e w^2 cos th computed here in Python at every row to 1e-9;
#    the summary gives the separation speed sqrt((P + 2 k e)/(m e)) in rpm to 10 digits at O.phi = 90 deg;
#  - the same at --speed 1200rpm: exit 1, rows with status separation, a stderr line naming the pair;
#  - the braked disk (disk_brake.json): status slip on every row, exit 1, friction_needed 0.2;
#  - the hypocycloid with masses: the effort column full, the redundant pairs' cells empty, the summary names them;
#  - a scene without "dynamics", --speed without --forces, a bad speed, bad dynamics: exit 2 naming what.
# Prints one line per check and "N passed, N failed" last.
set -u
BIN=${1:?usage: forces.sh ROLLKIN_BINARY SOURCE_DIR [PYTHON]}
SRC=${2:?usage: forces.sh ROLLKIN_BINARY SOURCE_DIR [PYTHON]}
PYTHON=${3:-/usr/bin/python3}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
case "$SRC" in /*) ;; *) SRC="$PWD/$SRC" ;; esac
DATA="$SRC/tests/data/forces"
WORK=$(mktemp -d "${TMPDIR:-/tmp}/rollkin_forces.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1
passed=0
failed=0
check() {  # check NAME CONDITION-EXIT-STATUS
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); echo "ok   $1"; else failed=$((failed + 1)); echo "FAIL $1"; fi
}

"$BIN" solve "$DATA/eccentric_cam.json" --forces --csv cam.csv > cam.out 2> cam.err
check "eccentric cam --forces: exit 0" $(( $? == 0 ? 0 : 1 ))
"$PYTHON" - cam.csv <<'EOF'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
need = ["C.Fx", "C.Fy", "S.Fx", "S.Fy", "S.M", "O.Fx", "O.Fy", "C.normal_force", "C.friction_force",
        "C.contact_pressure", "C.contact_half_width", "C.max_shear", "C.max_shear_depth", "O.phi.effort", "power"]
missing = [c for c in need if c not in rows[0]]
assert not missing, missing
P, k, e, m, w = 30.0, 2000.0, 0.01, 0.5, 500 * 2 * math.pi / 60
worst = 0
for r in rows:
    th = math.radians(float(r["O.phi"]) + 90)
    n = P + k * e * (1 - math.cos(th)) + m * e * w * w * math.cos(th)
    worst = max(worst, abs(float(r["C.normal_force"]) - n) / n)
    assert r["status"] == "ok", r["status"]
    # Hertz, cylinder (R = 40 mm) on a flat, E* = E / (2 (1 - nu^2)), L = 10 mm.
    es = 210000 / (2 * (1 - 0.09))
    b = math.sqrt(4 * n * 40 / (math.pi * 10 * es))
    assert abs(float(r["C.contact_half_width"]) - b) < 1e-9 * b, (r["C.contact_half_width"], b)
    assert abs(float(r["C.max_shear_depth"]) / b - 0.786) < 1e-3
assert worst < 1e-9, worst
EOF
check "eccentric cam: columns, normal force against the closed form, Hertz half-width" $?
grep -q "separation speed of pair 'C': 1129.888009 rpm (first at O.phi = 90 deg)" cam.out
check "eccentric cam: separation speed sqrt((P + 2 k e)/(m e)) in rpm at O.phi = 90 deg" $?
grep -q "massless links (no mass in \"dynamics\"): 'cam'" cam.out
check "eccentric cam: the massless cam named" $?

"$BIN" solve "$DATA/eccentric_cam.json" --forces --speed 1200rpm --csv fast.csv > fast.out 2> fast.err
check "eccentric cam at 1200 rpm: exit 1" $(( $? == 1 ? 0 : 1 ))
grep -q ",separation$" fast.csv && grep -q "separation: the contact of pair 'C' opens" fast.err
check "eccentric cam at 1200 rpm: status separation and a stderr line" $?

"$BIN" solve "$DATA/disk_brake.json" --forces --csv disk.csv > disk.out 2> disk.err
check "braked disk: exit 1 (slip)" $(( $? == 1 ? 0 : 1 ))
"$PYTHON" - disk.csv <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows:
    assert r["status"] == "slip", r["status"]
    assert abs(float(r["C.friction_needed"]) - 0.2) < 1e-12, r["C.friction_needed"]
    assert abs(float(r["X.x.effort"]) - 40) < 1e-10, r["X.x.effort"]
EOF
check "braked disk: status slip, friction needed T/(r N) = 0.2, push T/r = 40 N" $?

"$PYTHON" - "$SRC/examples/hypocycloid.json" hypo.json <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
s["dynamics"] = {"speed": {"value": 60, "unit": "rpm"}, "gravity": [0, -9.81],
                 "links": {"arm": {"mass": 1, "centre_of_mass": [1.5, 0], "inertia": 0.2},
                           "planet": {"mass": 2, "inertia": 1}}}
json.dump(s, open(sys.argv[2], "w"))
EOF
"$BIN" solve hypo.json --forces --csv hypo.csv > hypo.out 2> hypo.err
check "hypocycloid with masses: exit 0" $(( $? == 0 ? 0 : 1 ))
"$PYTHON" - hypo.csv <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows:
    assert r["O.phi.effort"] != "" and r["power"] != "", r
    assert r["C.normal_force"] == "" and r["P.Fx"] == "", r
EOF
check "hypocycloid: effort given, the redundant reactions empty" $?
grep -q "not unique: the reactions of pair(s) 'O', 'P', 'C'" hypo.out
check "hypocycloid: the summary names the pairs left open" $?

"$BIN" solve "$SRC/examples/paper_fourbar.json" --forces > nodyn.out 2> nodyn.err
check "no dynamics: exit 2" $(( $? == 2 ? 0 : 1 ))
grep -q "paper_fourbar.json: --forces needs the scene's \"dynamics\"" nodyn.err
check "no dynamics: the message names the file and what is missing" $?
"$BIN" solve "$DATA/eccentric_cam.json" --speed 100rpm > /dev/null 2> nof.err
check "--speed without --forces: exit 2" $(( $? == 2 ? 0 : 1 ))
"$BIN" solve "$DATA/eccentric_cam.json" --forces --speed 100mm/s > /dev/null 2> badspeed.err
check "--speed in a length unit for an angle input: exit 2" $(( $? == 2 ? 0 : 1 ))
grep -q "rpm" badspeed.err
check "bad speed: the units accepted named" $?
sed 's/"mass": 0.5/"mass": -1/' "$DATA/eccentric_cam.json" > badmass.json
"$BIN" solve badmass.json --forces > /dev/null 2> badmass.err
check "negative mass: exit 2" $(( $? == 2 ? 0 : 1 ))
grep -q "badmass.json.*dynamics.links.follower.mass" badmass.err
check "negative mass: file and JSON path named" $?

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
