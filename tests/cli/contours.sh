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

# Hidden elements (docs/scene_format.md, "SVG contours"): listed as hidden, selected by an id only; near points
# and numbers of the drawn ones pass them over.
cat > hidden.svg <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" viewBox="0 0 100 40">
  <path d="M 0 0 h 10 v 10 h -10 z"/>
  <path d="M 11 0 h 10 v 10 h -10 z" display="none"/>
  <g id="old_layer" inkscape:groupmode="layer" style="display:none"><path d="M 22 0 h 10 v 10 h -10 z"/><circle cx="50" cy="5" r="4"/></g>
  <g visibility="hidden"><path id="faint" d="M 0 20 h 10 v 10 h -10 z"/><circle cx="30" cy="25" r="4" visibility="visible"/></g>
  <circle cx="30" cy="25" r="4"/>
  <use href="#faint" x="60" visibility="visible"/>
</svg>
SVG

for drawing in clones.svg anonymous.SVG hidden.svg; do
  "$BIN" contours "$drawing" --json >list.json 2>err.txt
  check "$drawing: contours --json exits 0" $?
  "$PYTHON" - "$drawing" <<'PY' >cases.txt
import json, sys
chains = json.load(open("list.json"))
for k, c in enumerate(chains):
    if c["selector"] is None:  # a hidden element without an id of its own: why, and no case
        assert c["no_selector"] and c["hidden"], c
        continue
    scene = {"links": [{"name": "ground", "ground": True, "contours": [dict(name="c", **c["selector"])]},
                       {"name": "slider"}],
             "pairs": [{"name": "S", "type": "prismatic", "links": ["ground", "slider"], "variable": "s", "value": 0}],
             "inputs": ["S.s"], "sweep": {"from": 0, "to": 1, "step": 1}}
    json.dump(scene, open(f"chain{k + 1}.json", "w"))
    print(k + 1, repr(c["length"]), "closed" if c["closed"] else "open", json.dumps(c["selector"], separators=(",", ":")))
PY
  check "$drawing: the list is JSON with a selector, length and closed per chain" $?
  count=$(wc -l <cases.txt)
  check "$drawing: lists several chains ($count)" $([ "$count" -ge 4 ]; echo $?)
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
  cp cases.txt "cases_$drawing.txt"
done
check "anonymous.SVG: an element without an id is selected by near" $(grep -q '"near":\[' cases_anonymous.SVG.txt; echo $?)
check "anonymous.SVG: two coinciding elements without an id are selected by their number in the drawing" \
  $(grep -q '"file":"anonymous.SVG","subpath":8}' cases_anonymous.SVG.txt && grep -q '"file":"anonymous.SVG","subpath":9}' cases_anonymous.SVG.txt; echo $?)
check "anonymous.SVG: a subpath of an element without an id is selected through its group" \
  $(grep -q '"path":"layer","subpath":2' cases_anonymous.SVG.txt; echo $?)

"$BIN" contours hidden.svg --json >hidden.json
"$PYTHON" - <<'PY'
import json
c = json.load(open("hidden.json"))
hidden = [k + 1 for k, x in enumerate(c) if "hidden" in x]
no_selector = [k + 1 for k, x in enumerate(c) if x["selector"] is None]
# 1 drawn; 2 display="none", no id; 3, 4 in the hidden layer (by its id); 5 hidden by visibility (its id);
# 6 drawn (visibility="visible" inside the hidden group); 7 drawn (the same circle: "subpath" among the drawn);
# 8 a clone of "faint" through a <use> with visibility="visible": drawn
assert hidden == [2, 3, 4, 5], hidden
assert no_selector == [2], no_selector
assert 'display="none" on line 3, <path>' in c[1]["hidden"], c[1]
assert c[2]["selector"] == {"type": "svg", "file": "hidden.svg", "path": "old_layer", "subpath": 1}, c[2]
assert c[4]["selector"] == {"type": "svg", "file": "hidden.svg", "path": "faint"}, c[4]
assert c[5]["selector"] == {"type": "svg", "file": "hidden.svg", "subpath": 2}, c[5]
assert c[6]["selector"] == {"type": "svg", "file": "hidden.svg", "subpath": 3}, c[6]
PY
check "hidden.svg: hidden elements marked, selected only by an id, why when there is none" $?
"$BIN" contours hidden.svg >out.txt 2>err.txt
check "hidden.svg: the text listing says hidden and why there is no selector" \
  $(grep -q '^2\. line 3, <path>: path; closed, length 40, box .*, hidden: display="none" on line 3, <path>' out.txt &&
    grep -q '(no selector: it is hidden (display="none" on line 3, <path>)' out.txt; echo $?)

# DXF: a layer with an entity that cannot be read, a chain with a branch (no selector), a layer of one chain.
printf '%s\n' 0 SECTION 2 ENTITIES \
  0 LINE 5 2A 8 OK 10 0 20 0 11 1 21 0 \
  0 ELLIPSE 5 2B 8 BAD 10 0 20 0 11 0 21 0 40 0.5 41 0 42 1 \
  0 LINE 5 2C 8 Y 10 0 20 5 11 1 21 5 \
  0 LINE 5 2D 8 Y 10 1 20 5 11 2 21 5 \
  0 LINE 5 2E 8 Y 10 1 20 5 11 1 21 6 \
  0 ENDSEC 0 EOF >parts.dxf
"$BIN" contours parts.dxf --json >parts.json 2>err.txt
rc=$?
check "a DXF with an unreadable entity: listed, then exit 2 naming it on stderr" \
  $([ "$rc" -eq 2 ] && grep -q "1 entity or element could not be read (listed above as unreadable" err.txt; echo $?)
"$PYTHON" - <<'PY'
import json
c = json.load(open("parts.json"))
assert [x["group"] for x in c] == ["OK", "BAD", "Y"], c
assert c[0]["selector"] == {"type": "dxf", "file": "parts.dxf", "layer": "OK"} and abs(c[0]["length"] - 1) < 1e-12, c[0]
bad = c[1]
assert bad["length"] is None and bad["min"] is None and bad["max"] is None and bad["selector"] is None, bad
assert "ELLIPSE 2B has a zero major axis" in bad["unreadable"] and bad["entities"] == ["ELLIPSE 2B"], bad
y = c[2]
assert y["selector"] is None and "not one contour" in y["no_selector"] and "3 entity ends meet at (1, 5)" in y["no_selector"], y
assert y["entities"] == ["LINE 2C", "LINE 2D", "LINE 2E"] and abs(y["length"] - 3) < 1e-12, y
PY
check "--json: null selector with the reason, unreadable with its message and no length or box" $?
"$BIN" contours parts.dxf --draw parts_picture.svg >out.txt 2>err.txt
rc=$?
check "text listing of unreadable and branching chains; --draw not written on exit 2" \
  $([ "$rc" -eq 2 ] && [ ! -e parts_picture.svg ] && grep -q '^2\. BAD: unreadable: .*ELLIPSE 2B has a zero major axis' out.txt &&
    grep -q '(no selector: not one contour: ' out.txt; echo $?)

# Every help text cites only documents that exist.
missing=""
for cmd in "" solve reference centrodes check contours "synthesize cam" "synthesize gears" "synthesize envelope"; do
  # shellcheck disable=SC2086
  for doc in $("$BIN" $cmd --help 2>&1 | grep -o 'docs/[A-Za-z0-9_./-]*\.md' | sort -u); do
    [ -e "$SRC/$doc" ] || missing="$missing $cmd:$doc"
  done
done
check "every document a --help cites exists (missing:$missing)" $([ -z "$missing" ]; echo $?)

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
