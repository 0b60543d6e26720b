#!/usr/bin/env bash
# `rollkin contours` on SVG drawings: every listed selector, pasted into a scene, selects a chain with the listed
# length (and closed/open), as `rollkin solve --verbose` reports the contour it read; --json, --draw, errors.
#   usage: contours.sh PATH/TO/rollkin SOURCE_DIR [PYTHON]   (PYTHON: any Python 3, default /usr/bin/python3)
# The drawings: tests/data/svg/clones.svg (compound path, <use> clones of shapes and groups, a <symbol>) and one
# written here with elements that have no id (selected by "near" or through their group) and a <switch>.
# Prints one line per check and "N passed, N failed" last.
set -u
BIN=${1:?usage: contours.sh ROLLKIN_BINARY SOURCE_DIR [PYTHON]}
SRC=${2:?usage: contours.sh ROLLKIN_BINARY SOURCE_DIR [PYTHON]}
PYTHON=${3:-/usr/bin/python3}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
case "$SRC" in /*) ;; *) SRC="$PWD/$SRC" ;; esac
WORK=$(mktemp -d "${TMPDIR:-/tmp}/rollkin_contours.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1
passed=0
failed=0
check() {  # check NAME CONDITION-EXIT-STATUS
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); echo "ok   $1"; else failed=$((failed + 1)); echo "FAIL $1"; fi
}

cp "$SRC/tests/data/svg/clones.svg" clones.svg
cat > anonymous.SVG <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100" viewBox="0 0 200 100">
  <path d="M 10 10 L 60 10 L 60 40 Z"/>
  <path d="M 100 10 C 120 0 140 30 160 10 M 100 60 h 40 v 20 h -40 z"/>
  <switch>
    <foreignObject requiredExtensions="http://ns.adobe.com/AdobeIllustrator/10.0/" width="1" height="1"/>
    <g><circle cx="30" cy="70" r="12"/><ellipse cx="170" cy="70" rx="15" ry="8" transform="rotate(20, 170, 70)"/></g>
  </switch>
  <g id="layer"><line x1="0" y1="95" x2="200" y2="95"/><rect x="70" y="50" width="20" height="30" rx="0" ry="5"/></g>
  <circle cx="185" cy="30" r="6"/><circle cx="185" cy="30" r="6"/>
</svg>
SVG

for drawing in clones.svg anonymous.SVG; do
  "$BIN" contours "$drawing" --json >list.json 2>err.txt
  check "$drawing: contours --json exits 0" $?
  "$PYTHON" - "$drawing" <<'PY' >cases.txt
import json, sys
chains = json.load(open("list.json"))
for k, c in enumerate(chains):
    scene = {"links": [{"name": "ground", "ground": True, "contours": [dict(name="c", **c["selector"])]},
                       {"name": "slider"}],
             "pairs": [{"name": "S", "type": "prismatic", "links": ["ground", "slider"], "variable": "s", "value": 0}],
             "inputs": ["S.s"], "sweep": {"from": 0, "to": 1, "step": 1}}
    json.dump(scene, open(f"chain{k + 1}.json", "w"))
    print(k + 1, repr(c["length"]), "closed" if c["closed"] else "open", json.dumps(c["selector"], separators=(",", ":")))
PY
  check "$drawing: the list is JSON with a selector, length and closed per chain" $?
  count=$(wc -l <cases.txt)
  check "$drawing: lists several chains ($count)" $([ "$count" -ge 7 ]; echo $?)
  while read -r k length closed selector; do
    "$BIN" solve "chain$k.json" --verbose >out.txt 2>err.txt
    rc=$?
    read_line=$(grep -o "read \(closed\|open\), length [-0-9.e+]*" out.txt)
    got_closed=$(echo "$read_line" | awk '{print $2}' | tr -d ,)
    got_length=$(echo "$read_line" | awk '{print $4}')
    same=$("$PYTHON" -c "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); print(int(abs(a - b) <= 1e-12 * abs(a)))" \
      "$length" "${got_length:-nan}" 2>/dev/null)
    check "$drawing chain $k $selector: selects a $closed chain of length $length (read: $got_closed, $got_length)" \
      $([ "$rc" -eq 0 ] && [ "$got_closed" = "$closed" ] && [ "$same" = 1 ]; echo $?)
  done <cases.txt
done
check "anonymous.SVG: an element without an id is selected by near" $(grep -q '"near":\[' cases.txt; echo $?)
check "anonymous.SVG: two coinciding elements without an id are selected by their number in the drawing" \
  $(grep -q '"file":"anonymous.SVG","subpath":8}' cases.txt && grep -q '"file":"anonymous.SVG","subpath":9}' cases.txt; echo $?)
check "anonymous.SVG: a subpath of an element without an id is selected through its group" \
  $(grep -q '"path":"layer","subpath":2' cases.txt; echo $?)

# Text listing and the picture.
"$BIN" contours clones.svg --draw picture.svg >out.txt 2>err.txt
check "--draw: exit 0, picture written" $([ $? -eq 0 ] && [ -s picture.svg ]; echo $?)
check "--draw: every chain labelled with its number" \
  $("$PYTHON" -c "
import re, sys
t = open('picture.svg').read()
labels = set(re.findall(r'<text[^>]*>(\d+)</text>', t))
sys.exit(0 if labels == {str(k) for k in range(1, 12)} else 1)"; echo $?)
check "text listing: a line per chain with its selector" \
  $(grep -q '^2\. line 24, path "plate": subpath 2; closed, length 78.2170016' out.txt &&
    grep -q '{"type":"svg","file":"clones.svg","path":"plate","subpath":2}' out.txt; echo $?)
before=$(cksum <clones.svg)
"$BIN" contours clones.svg --draw clones.svg >out.txt 2>err.txt
rc=$?
check "--draw onto the drawing itself: refused (exit 2), the drawing unchanged" \
  $([ "$rc" -eq 2 ] && grep -q "inputs are never overwritten" err.txt && [ "$(cksum <clones.svg)" = "$before" ]; echo $?)
"$BIN" contours notes.odt >out.txt 2>err.txt
rc=$?
check "a file of no contour format: exit 2, says what is expected" \
  $([ "$rc" -eq 2 ] && grep -q "expected a file ending in .txt, .csv, .svg or .dxf" err.txt; echo $?)
printf '<svg xmlns="http://www.w3.org/2000/svg"><use id="a" href="#b"/><use id="b" href="#a"/></svg>\n' >cycle.svg
"$BIN" contours cycle.svg >out.txt 2>err.txt
rc=$?
check "a <use> cycle: exit 2, named" $([ "$rc" -eq 2 ] && grep -q "is part of a <use> cycle" err.txt; echo $?)

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
