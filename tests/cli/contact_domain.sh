#!/usr/bin/env bash
# A contact never lies beyond the end of a drawn contour, whatever reader made the contour.
#   usage: contact_domain.sh PATH/TO/rollkin [PYTHON]   (PYTHON: the one with ezdxf, default /usr/bin/python3)
# The same upper half circle (radius 10 mm, drawn counter-clockwise from (10, 0) to (-10, 0)) is given as each
# contour type that can draw it: circle arc, bezier, samples, nurbs, svg (an arc command) and dxf (an ARC
# written by python3-ezdxf). A roller (radius 2) on an arm of length 12 pivoted at the centre rolls on it:
#  - arm at 60 deg: the contact is on the drawn half; solved, exit 0;
#  - arm at -90 deg (pointing down): the contact would be on the undrawn half; refused, exit 2, naming the
#    contour, within a few seconds;
#  - the contact's value given far beyond the end (150 on a unitless parameter of range 2): refused at once.
# Prints one line per check and "N passed, N failed" last.
set -u
BIN=${1:?usage: contact_domain.sh ROLLKIN_BINARY [PYTHON]}
PYTHON=${2:-/usr/bin/python3}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
WORK=$(mktemp -d "${TMPDIR:-/tmp}/rollkin_domain.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1
passed=0
failed=0
check() {  # check NAME CONDITION-EXIT-STATUS; returns that status
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); echo "ok   $1"; else failed=$((failed + 1)); echo "FAIL $1"; fi
  return "$2"
}

"$PYTHON" - <<'PY'
import json, math
import ezdxf
doc = ezdxf.new("R2010")
doc.header["$INSUNITS"] = 4  # mm
doc.modelspace().add_arc((0, 0), 10, 0, 180, dxfattribs={"layer": "ARC"})
doc.saveas("arc.dxf")
with open("arc.svg", "w") as f:
    f.write('<svg xmlns="http://www.w3.org/2000/svg" viewBox="-12 -12 24 24">'
            '<path id="arc" d="M 10 0 A 10 10 0 0 0 -10 0"/></svg>\n')
w = math.sqrt(0.5)
contours = {
    "circle": {"type": "circle", "radius": 10, "arc": [0, 180]},
    "bezier": {"type": "bezier", "segments": [
        {"points": [[10, 0], [10, 10], [0, 10]], "weights": [1, w, 1]},
        {"points": [[0, 10], [-10, 10], [-10, 0]], "weights": [1, w, 1]}]},
    "samples": {"type": "samples", "points": [[10 * math.cos(math.radians(a)), 10 * math.sin(math.radians(a))]
                                              for a in range(0, 181, 5)]},
    "nurbs": {"type": "nurbs", "degree": 2, "knots": [0, 0, 0, 1, 1, 2, 2, 2],
              "points": [[10, 0], [10, 10], [0, 10], [-10, 10], [-10, 0]], "weights": [1, w, 1, w, 1]},
    "svg": {"type": "svg", "file": "arc.svg", "path": "arc"},
    "dxf": {"type": "dxf", "file": "arc.dxf", "layer": "ARC"},
}
# The contact parameter on the drawn half at 60 deg and at its end (180 deg): degrees on the circle, the
# unitless segment parameter of the quarter-arc paths (approximate: a guess), the chord length of the samples.
chord = 2 * 10 * math.sin(math.radians(2.5))
at = {"circle": (60, 180), "samples": (12 * chord, 36 * chord)}
for kind, contour in contours.items():
    u60, uend = at.get(kind, (0.6, 2))
    for arm, u in ((60, u60), (-90, uend)):
        scene = {
            "units": {"length": "mm", "angle": "deg"},
            "links": [
                {"name": "ground", "ground": True, "contours": [dict(name="arc", **contour)]},
                {"name": "arm"},
                {"name": "roller", "contours": [{"name": "rim", "type": "circle", "radius": 2}]}],
            "pairs": [
                {"name": "O", "type": "revolute", "links": ["ground", "arm"], "variable": "theta", "value": arm},
                {"name": "P", "type": "revolute", "links": ["arm", "roller"], "at": [{"x": 12}, {}],
                 "variable": "psi", "value": 0},
                {"name": "C", "type": "rolling", "contours": ["ground.arc", "roller.rim"], "variables": ["u", "v"],
                 "values": [u, arm + 180]}],
            "inputs": ["O.theta"],
            "sweep": {"from": arm, "to": arm + 10, "step": 5}}
        json.dump(scene, open(f"{kind}_{arm}.json", "w"), indent=1)
    if kind in ("bezier", "nurbs", "svg", "dxf"):  # a unitless parameter of range 2, given as 150 (a length in mm)
        scene["pairs"][2]["values"] = [150, 240]
        scene["pairs"][0]["value"] = 60
        scene["sweep"] = {"from": 60, "to": 70, "step": 5}
        json.dump(scene, open(f"{kind}_far.json", "w"), indent=1)
PY
if ! check "fixtures written (python3-ezdxf)" $?; then echo "$passed passed, $failed failed"; exit 1; fi

for kind in circle bezier samples nurbs svg dxf; do
  timeout 60 "$BIN" solve "${kind}_60.json" >out.txt 2>err.txt
  check "$kind: the contact on the drawn half solves (exit 0)" $?
  start=$(date +%s)
  timeout 60 "$BIN" solve "${kind}_-90.json" >out.txt 2>err.txt
  rc=$?
  took=$(( $(date +%s) - start ))
  check "$kind: the arm pointing down is refused, exit 2 (got $rc)" $([ "$rc" -eq 2 ]; echo $?)
  check "$kind: the message says the mechanism cannot be assembled" $(grep -q "cannot be assembled" err.txt; echo $?)
  check "$kind: refused within 10 s (took ${took} s)" $([ "$took" -le 10 ]; echo $?)
  if [ -f "${kind}_far.json" ]; then
    start=$(date +%s)
    timeout 60 "$BIN" solve "${kind}_far.json" >out.txt 2>err.txt
    rc=$?
    took=$(( $(date +%s) - start ))
    # Either refused (exit 2, saying the mechanism cannot be assembled) or solved with the contact on the
    # drawn half (Newton may come back from the far guess to the true contact): never an answer off it.
    check "$kind: a contact value far beyond the end answers within 10 s (took ${took} s, exit $rc)" \
      $([ "$took" -le 10 ] && { [ "$rc" -eq 2 ] || [ "$rc" -eq 0 ]; }; echo $?)
    if [ "$rc" -eq 0 ]; then
      timeout 60 "$BIN" solve "${kind}_far.json" --csv far.csv >/dev/null 2>&1
      "$PYTHON" -c "
import csv, sys
rows = list(csv.DictReader(open('far.csv')))
sys.exit(0 if rows and all(0 <= float(r['C.u']) <= 2 for r in rows) else 1)"
      check "$kind: ... solved with the contact on the drawn contour" $?
    else
      check "$kind: ... refused saying the mechanism cannot be assembled" $(grep -q "cannot be assembled" err.txt; echo $?)
    fi
  fi
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
