#!/usr/bin/env bash
# A contact never lies beyond the end of a drawn contour, whatever reader made the contour.
#   usage: contact_domain.sh PATH/TO/rollkin
# The same upper half circle (radius 10 mm, drawn counter-clockwise from (10, 0) to (-10, 0)) is given as each
# contour type that can draw it: circle arc, bezier, samples, nurbs, svg (an arc command) and dxf (an ARC
# written by python3-ezdxf). A roller (radius 2) on an arm of length 12 pivoted at the centre rolls on it:
#  - arm at 60 deg: the contact is on the drawn half; solved, exit 0;
#  - arm at -90 deg (pointing down): the contact would be on the undrawn half; refused, exit 2, naming the
#    contour, within a few seconds;
#  - the contact's value given far beyond the end (150 on a unitless parameter of range 2): refused at once.
# Prints one line per check and "N passed, N failed" last.
set -u
BIN=${1:?usage: contact_domain.sh ROLLKIN_BINARY}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
WORK=$(mktemp -d "${TMPDIR:-/tmp}/rollkin_domain.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1
passed=0
failed=0
check() {  # check NAME CONDITION-EXIT-STATUS
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); echo "ok   $1"; else failed=$((failed + 1)); echo "FAIL $1"; fi
}

python3 - <<'PY'
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
for kind, contour in contours.items():
    for arm in (60, -90):
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
                {"name": "C", "type": "rolling", "contours": ["ground.arc", "roller.rim"], "variables": ["u", "v"]}],
            "inputs": ["O.theta"],
            "sweep": {"from": arm, "to": arm + 10, "step": 5}}
        json.dump(scene, open(f"{kind}_{arm}.json", "w"), indent=1)
    if kind in ("bezier", "nurbs", "svg", "dxf"):  # a unitless parameter of range 2, given as 150 (a length in mm)
        scene["pairs"][2]["values"] = [150, 0]
        scene["pairs"][0]["value"] = scene["sweep"]["from"] = 60
        json.dump(scene, open(f"{kind}_far.json", "w"), indent=1)
PY
check "fixtures written (python3-ezdxf)" $?

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
    check "$kind: a contact value far beyond the end is refused, exit 2 (got $rc)" $([ "$rc" -eq 2 ]; echo $?)
    check "$kind: ... within 10 s (took ${took} s)" $([ "$took" -le 10 ]; echo $?)
    grep -q "beyond the end of contour 'ground.arc'" err.txt || grep -q "cannot be assembled" err.txt
    check "$kind: ... saying why ($(head -c 300 err.txt))" $?
  fi
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
