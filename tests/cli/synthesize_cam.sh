#!/usr/bin/env bash
# `rollkin synthesize cam` and `rollkin synthesize gears`: the round trip and the contract of their outputs,
# checked from outside.
#   usage: synthesize_cam.sh PATH/TO/rollkin [PYTHON]   (PYTHON: the one with ezdxf, default /usr/bin/python3)
#  - a cycloidal rise-dwell-return-dwell cam with an offset roller follower: exit 0; the four outputs exist (PREFIX differs from the spec's stem: PREFIX.json must not be the spec);
#    `rollkin solve PREFIX.json --csv` has the columns cam.theta and follower.s, and follower.s equals the
#    cycloidal law computed here in Python (independent closed form) to 1e-9 of the stroke at every degree;
#    the DXF holds one closed SPLINE (read by ezdxf) whose points lie within the sag of the point file's polygon
#    (chord^2 / (8 radius): a spline through the points);
#  - PREFIX.txt against the closed-form profile (tests/cli/synthesis_closed_form_cam.py); `synthesize envelope`
#    of the roller under the written scene's sweep gives that profile back;
#  - a clockwise cam, an oscillating roller follower (column follower.phi), a flat face and a mushroom follower
#    given as any contour: exit 0;
#  - a law read from a table file: exit 0;
#  - an undercut (a roller larger than the pitch curve's radius of curvature): exit 1, the cam angles on
#    stderr, nothing written;
#  - bad specs (unknown kind, net lift, unknown key) exit 2 naming the JSON path; an output that would
#    overwrite the spec exits 2 and leaves the spec as it was;
#  - twin elliptical gears: exit 0, convex; the written scene solved by `rollkin solve` keeps gear2.phi on the
#    closed form tan(f/2) = 3 tan(phi1/2) (Python) to 1e-9 of a turn; a table that does not close: exit 1;
#  - usage errors of `synthesize` (no what, an unknown what, an unknown option) exit 2 naming what is expected.
# Prints one line per check and "N passed, N failed" last.
set -u
BIN=${1:?usage: synthesize_cam.sh ROLLKIN_BINARY [PYTHON]}
PYTHON=${2:-/usr/bin/python3}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
HERE=$(cd "$(dirname "$0")" && pwd)
SRC_EXAMPLES="$HERE/../../examples/synthesis"
WORK=$(mktemp -d "${TMPDIR:-/tmp}/rollkin_synth.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1
passed=0
failed=0
check() {  # check NAME CONDITION-EXIT-STATUS
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); echo "ok   $1"; else failed=$((failed + 1)); echo "FAIL $1"; fi
}

LAW='"law": [{"to": 90, "lift": 15, "kind": "cycloidal"}, {"to": 180, "kind": "dwell"},
             {"to": 270, "lift": -15, "kind": "cycloidal"}, {"to": 360, "kind": "dwell"}]'
cat > cam.json <<EOF
{"units": {"length": "mm", "angle": "deg"}, "base_radius": 40, "rotation": "ccw",
 "follower": {"motion": "translating", "offset": 12}, "contact": {"roller_radius": 10}, $LAW}
EOF
"$BIN" synthesize cam cam.json --out c > out.txt 2> err.txt
check "cycloidal offset roller cam: exit 0" $?
grep -q "worst deviation of the follower from the law" out.txt && grep -q "largest pressure angle" out.txt &&
  grep -q "smallest radius of curvature" out.txt
check "the round-trip figures are printed" $?
[ -s c.txt ] && [ -s c.dxf ] && [ -s c.svg ] && [ -s c.json ]
check "PREFIX.txt, .dxf, .svg and .json written" $?
"$BIN" solve c.json --csv c.csv > /dev/null 2>&1
check "rollkin solve PREFIX.json: exit 0" $?
"$PYTHON" - <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open("c.csv")))
h, beta = 15.0, math.pi / 2
def law(t):  # cycloidal rise on [0, 90], dwell, cycloidal return on [180, 270], dwell (degrees)
    if t <= 90: x = t / 90; return h * (x - math.sin(2 * math.pi * x) / (2 * math.pi))
    if t <= 180: return h
    if t <= 270: x = (t - 180) / 90; return h - h * (x - math.sin(2 * math.pi * x) / (2 * math.pi))
    return 0.0
worst = max(abs(float(r["follower.s"]) - law(float(r["cam.theta"]))) for r in rows)
print("  solve's follower.s against the closed form: worst", worst)
sys.exit(0 if len(rows) == 361 and worst <= 1e-9 * h else 1)
PY
check "follower.s of the written scene follows the closed-form law to 1e-9 of the stroke" $?
"$PYTHON" - <<'PY'
import math, sys
import ezdxf
doc = ezdxf.readfile("c.dxf")
splines = doc.modelspace().query("SPLINE")
pts = [tuple(map(float, l.split())) for l in open("c.txt") if l.strip() and not l.startswith("#")]
size = max(math.hypot(x, y) for x, y in pts)
ok = len(splines) == 1 and splines[0].closed
if ok:
    import numpy as np
    P = np.array(pts)
    A, D = P, np.roll(P, -1, axis=0) - P
    L2 = (D ** 2).sum(1)
    # Every 7th of 20000 spline points, its distance to the closed polygon of the profile's points: at most the
    # polygon's sag, chord^2 / (8 radius), the radius of each chord from the circle through its point and the
    # neighbours (~1e-3 here).
    Pm, Pp = np.roll(P, 1, axis=0), np.roll(P, -1, axis=0)
    a, b, c = np.hypot(*(P - Pm).T), np.hypot(*(Pp - P).T), np.hypot(*(Pp - Pm).T)
    twice_area = np.abs((P - Pm)[:, 0] * (Pp - Pm)[:, 1] - (P - Pm)[:, 1] * (Pp - Pm)[:, 0])
    radius = a * b * c / (2 * np.maximum(twice_area, 1e-300))
    sag = float((b ** 2 / (8 * radius)).max())
    worst = 0.0
    for q in np.array([(v[0], v[1]) for v in splines[0].construction_tool().approximate(20000)])[::7]:
        t = np.clip(((q - A) * D).sum(1) / L2, 0, 1)
        worst = max(worst, float(np.sqrt((((A + t[:, None] * D) - q) ** 2).sum(1)).min()))
    print("  DXF spline: %d control points, worst distance to the profile's polygon %.3g (largest sag %.3g)" % (len(splines[0].control_points), worst, sag))
    ok = worst < 1.5 * sag
sys.exit(0 if ok else 1)
PY
check "PREFIX.dxf: one closed SPLINE along the profile (ezdxf)" $?

# The profile's points against the closed-form profile, and the envelope of the roller under the written
# scene's own motion (rollkin synthesize envelope) against it too: the cam comes back from its analysis.
"$PYTHON" "$HERE/synthesis_closed_form_cam.py" c.txt 12 5e-8
check "PREFIX.txt against the closed-form cycloidal cam profile (to the dense polygon's sag)" $?
"$BIN" synthesize envelope c.json --links cam follower --contour follower.roller --out env --step 0.1 --tolerance 1e-8 > env.out 2>&1 &&
  grep -q "(closed)" env.out && [ -s env.txt ] && [ -s env.dxf ]
check "synthesize envelope of the written scene: exit 0, closed, points and DXF" $?
"$PYTHON" "$HERE/synthesis_closed_form_cam.py" env.txt 12 1e-7
check "the envelope of the roller under the analysed motion is the closed-form cam profile" $?
"$BIN" synthesize envelope c.json --links cam follower --contour follower.nothing --out env2 > /dev/null 2> env2.err
[ $? -eq 2 ] && grep -q 'no contour "follower.nothing" on link "follower"' env2.err && [ ! -e env2.txt ]
check "synthesize envelope with an unknown contour: exit 2, nothing written" $?

sed 's/"ccw"/"cw"/' cam.json > cw.json
"$BIN" synthesize cam cw.json --out cw_out > /dev/null 2>&1
check "clockwise cam: exit 0" $?
cat > osc.json <<EOF
{"units": {"length": "mm", "angle": "deg"}, "base_radius": 40,
 "follower": {"motion": "oscillating", "pivot": [80, 50], "arm": 80, "start_angle": 180}, "contact": {"roller_radius": 10},
 "law": [{"to": 120, "lift": 15, "kind": "poly345"}, {"to": 180, "kind": "dwell"},
         {"to": 300, "lift": -15, "kind": "modified_sine"}, {"to": 360, "kind": "dwell"}]}
EOF
"$BIN" synthesize cam osc.json --out osc_out > /dev/null 2>&1 && "$BIN" solve osc_out.json --csv osc.csv > /dev/null 2>&1 &&
  head -1 osc.csv | grep -q "^cam.theta,follower.phi,"
check "oscillating roller follower: exit 0, the scene's CSV has cam.theta and follower.phi" $?
cat > flat.json <<EOF
{"units": {"length": "mm", "angle": "deg"}, "base_radius": 40, "follower": {"motion": "translating"},
 "contact": {"flat": true}, $LAW}
EOF
"$BIN" synthesize cam flat.json --out flat_out > /dev/null 2>&1
check "flat-faced follower: exit 0" $?
"$BIN" synthesize cam "$SRC_EXAMPLES/cam_mushroom.json" --out mushroom > /dev/null 2>&1 && [ -s mushroom.json ] &&
  grep -q '"arc"' mushroom.json && "$BIN" solve mushroom.json > /dev/null 2>&1
check "any contour (examples/synthesis/cam_mushroom.json): exit 0, the contour in the scene, the scene solves" $?
"$PYTHON" -c '
import math
with open("law.csv", "w") as f:
    for k in range(0, 361, 2):
        f.write("%r %r\n" % (k, 6 * (1 - math.cos(math.radians(k)))))'
cat > table.json <<EOF
{"units": {"length": "mm"}, "base_radius": 40, "follower": {"motion": "translating"},
 "contact": {"roller_radius": 10}, "law": {"file": "law.csv"}}
EOF
"$BIN" synthesize cam table.json --out table_out > /dev/null 2>&1
check "law from a table file: exit 0" $?

cat > under.json <<EOF
{"units": {"length": "mm", "angle": "deg"}, "base_radius": 20, "follower": {"motion": "translating"},
 "contact": {"roller_radius": 15},
 "law": [{"to": 30, "lift": 30, "kind": "cycloidal"}, {"to": 180, "kind": "dwell"},
         {"to": 210, "lift": -30, "kind": "cycloidal"}, {"to": 360, "kind": "dwell"}]}
EOF
"$BIN" synthesize cam under.json --out under_out > /dev/null 2> under.err
status=$?
[ "$status" -eq 1 ] && grep -q "undercut: at cam angle" under.err && [ ! -e under_out.txt ] && [ ! -e under_out.json ]
check "undercut: exit 1, located on stderr, nothing written" $?

sed 's/"cycloidal"/"cycloid"/' cam.json > bad_kind.json
"$BIN" synthesize cam bad_kind.json --out bad > /dev/null 2> bad.err
[ $? -eq 2 ] && grep -q 'bad_kind.json:law\[0\].kind: unknown kind "cycloid"' bad.err
check "unknown kind: exit 2 at law[0].kind" $?
sed 's/"lift": -15/"lift": -14/' cam.json > bad_lift.json
"$BIN" synthesize cam bad_lift.json --out bad > /dev/null 2> bad.err
[ $? -eq 2 ] && grep -q "bad_lift.json:law: the lifts add up to" bad.err
check "net lift: exit 2 at law" $?
sed 's/"base_radius"/"base_radus"/' cam.json > bad_key.json
"$BIN" synthesize cam bad_key.json --out bad > /dev/null 2> bad.err
[ $? -eq 2 ] && grep -q "base_radus" bad.err
check "unknown key: exit 2 naming it" $?
cp cam.json keep.json
"$BIN" synthesize cam keep.json --out keep > /dev/null 2> keep.err
[ $? -eq 2 ] && cmp -s cam.json keep.json && [ ! -e keep.txt ] && grep -q "keep.json" keep.err
check "an output that would overwrite the spec: exit 2, spec unchanged, nothing written" $?

# ---- rollkin synthesize gears ------------------------------------------------------------------------------
cat > ell.json <<EOF
{"units": {"length": "mm", "angle": "deg"}, "centre_distance": 80, "transmission": {"kind": "elliptical", "eccentricity": 0.5}}
EOF
"$BIN" synthesize gears ell.json --out gears > gears.out 2>&1 && [ -s gears.1.txt ] && [ -s gears.2.txt ] && [ -s gears.dxf ] && [ -s gears.svg ] &&
  grep -q "gear 1: convex" gears.out && "$BIN" solve gears.json --csv gears.csv > /dev/null 2>&1 &&
  head -1 gears.csv | grep -q "^gear1.phi,gear2.phi,"
check "elliptical gears: exit 0, point files, DXF and picture written, convex, the scene's CSV has gear1.phi and gear2.phi" $?
"$PYTHON" - <<'PY'
import csv, math, sys
k = 3.0  # (1 + e) / (1 - e), e = 0.5: tan(f / 2) = k tan(phi1 / 2), gear 2 turning back (gear2.phi = -f)
worst = 0.0
for r in csv.DictReader(open("gears.csv")):
    p1, f = math.radians(float(r["gear1.phi"])), -math.radians(float(r["gear2.phi"]))
    closed = 2 * math.atan2(k * math.sin(p1 / 2), math.cos(p1 / 2))
    worst = max(worst, abs(math.remainder(f - closed, 2 * math.pi)))
print("  gear2.phi against the closed form: worst %.3g rad" % worst)
sys.exit(0 if worst < 1e-9 * 2 * math.pi else 1)
PY
check "gear2.phi of the written scene follows the elliptical closed form to 1e-9 of a turn" $?
"$PYTHON" -c '
import math
with open("open_f.txt", "w") as f:
    for d in range(0, 361, 10):
        f.write("%d %r\n" % (d, d * 1.01 + 5 * math.sin(math.radians(d))))'
cat > open.json <<EOF
{"units": {"angle": "deg"}, "centre_distance": 50, "transmission": {"file": "open_f.txt"}}
EOF
"$BIN" synthesize gears open.json --out open_out > /dev/null 2> open.err
[ $? -eq 1 ] && grep -q "does not close" open.err && [ ! -e open_out.1.txt ]
check "a transmission that does not close: exit 1, reported, nothing written" $?

printf 'theta,s\n0 0\n90 1\n180 2\n270 1\n' > hdr_law.txt
cat > hdr.json <<EOF
{"base_radius": 40, "follower": {"motion": "translating"}, "contact": {"roller_radius": 10}, "law": {"file": "hdr_law.txt"}}
EOF
"$BIN" synthesize cam hdr.json --out hdr_out > /dev/null 2> hdr.err
check "a law file with a header naming its columns (theta,s): taken, exit 0" $?
printf 'theta s extra\n0 0\n90 1\n180 2\n270 1\n' > hdr_law.txt
"$BIN" synthesize cam hdr.json --out hdr_out3 > /dev/null 2> hdr.err
[ $? -eq 2 ] && grep -q "hdr_law.txt:1:" hdr.err && grep -q "a law file is read as a point file" hdr.err && [ ! -e hdr_out3.json ]
check "a law file whose header names three columns: exit 2 at its line, saying what the columns are" $?
echo '{"centre_distance": 80, "transmission": {"kind": "elliptical", "eccentricity": 1}}' > g_bad1.json
"$BIN" synthesize gears g_bad1.json --out g1_out > /dev/null 2> g.err
[ $? -eq 2 ] && grep -q "g_bad1.json:transmission.eccentricity: expected a number in \[0, 1)" g.err
check "gears: eccentricity 1 is refused at its path" $?
echo '{"centre_distance": 80, "transmission": {"kind": "sinusoidal", "k": 0.2}, "extra": 1}' > g_bad2.json
"$BIN" synthesize gears g_bad2.json --out g2_out > /dev/null 2> g.err
[ $? -eq 2 ] && grep -q 'g_bad2.json:extra: unknown key "extra"' g.err
check "gears: an unknown key is refused" $?

# ---- command-line usage ----------------------------------------------------------------------------------
"$BIN" synthesize > /dev/null 2> use.err
[ $? -eq 2 ] && grep -q "expected what to synthesize: cam, gears or envelope" use.err
check "synthesize without what: exit 2 naming cam, gears, envelope" $?
"$BIN" synthesize bogus x > /dev/null 2> use.err
[ $? -eq 2 ] && grep -q 'unknown synthesize command "bogus"; expected one of cam, gears, envelope' use.err
check "synthesize with an unknown what: exit 2 naming it and the three" $?
"$BIN" synthesize cam cam.json --out u --bogus > /dev/null 2> use.err
[ $? -eq 2 ] && grep -q 'unknown option "--bogus" for synthesize cam' use.err && grep -q "rollkin synthesize cam --help" use.err
check "synthesize cam with an unknown option: exit 2 naming it" $?

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
