#!/usr/bin/env bash
# End-to-end tests of the rollkin command-line tool.
#   usage: run_cli_tests.sh PATH/TO/rollkin SOURCE_DIR
# Runs in a fresh temporary directory; prints one line per check and "N passed, M failed" last.
set -u
BIN=${1:?usage: run_cli_tests.sh ROLLKIN_BINARY SOURCE_DIR}
SRC=${2:?usage: run_cli_tests.sh ROLLKIN_BINARY SOURCE_DIR}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
case "$SRC" in /*) ;; *) SRC="$PWD/$SRC" ;; esac
EX="$SRC/examples"
BAD="$SRC/tests/cli/bad"

WORK=$(mktemp -d "${TMPDIR:-/tmp}/rollkin_cli.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1

passed=0
failed=0
check() {  # check NAME CONDITION-EXIT-STATUS
  if [ "$2" -eq 0 ]; then
    passed=$((passed + 1)); echo "ok   $1"
  else
    failed=$((failed + 1)); echo "FAIL $1"
  fi
}
run() {  # run ARGS...: sets rc, out, err
  "$BIN" "$@" >out.txt 2>err.txt
  rc=$?
  out=$(cat out.txt)
  err=$(cat err.txt)
}

# ---- help and version ------------------------------------------------------------------------------
run --help
check "--help exits 0" $([ "$rc" -eq 0 ] && grep -q "rollkin solve" out.txt; echo $?)
run --version
check "--version prints the version" $([ "$rc" -eq 0 ] && grep -Eq "^rollkin [0-9]+\.[0-9]+" out.txt; echo $?)
run frobnicate
check "unknown command exits 2" $([ "$rc" -eq 2 ]; echo $?)

# ---- the paper's example -----------------------------------------------------------------------------
run solve "$EX/paper_fourbar.json"
check "paper example exits 0" $([ "$rc" -eq 0 ]; echo $?)
check "paper summary: 151/151 solved, no limits" \
  $(grep -q "paper_fourbar.json: 151/151 poses solved, O_A.theta2 from -50 to 100 deg" out.txt && grep -q "no limits met" out.txt; echo $?)

run solve "$EX/paper_fourbar.json" --csv paper.csv
check "paper --csv exits 0" $([ "$rc" -eq 0 ] && [ -f paper.csv ]; echo $?)
expected="O_A.theta2,A.x,A.theta23,B.theta34,B.theta4,O_B.theta5,link1.x,link1.y,link1.angle,link2.x,link2.y,link2.angle,link3.x,link3.y,link3.angle,link4.x,link4.y,link4.angle,residual,status"
check "CSV header exactly as specified" $([ "$(head -n 1 paper.csv)" = "$expected" ]; echo $?)
check "CSV has 151 data rows" $([ "$(awk 'END { print NR - 1 }' paper.csv)" -eq 151 ]; echo $?)
check "every status ok" $(awk -F, 'NR > 1 && $NF != "ok" { bad = 1 } END { exit bad }' paper.csv; echo $?)
check "residual column < 1e-12" \
  $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "residual") c = i; next }
             { if (c == 0 || !($c + 0 < 1e-12)) bad = 1 } END { exit bad }' paper.csv; echo $?)
check "first input -50, last 100" $(awk -F, 'NR == 2 { a = $1 } END { exit !(a == -50 && $1 == 100) }' paper.csv; echo $?)
check "assembly row: theta2 = 0 with A.x = 0, A.theta23 = 180, link3 at (3, 0)" \
  $(awk -F, '$1 == 0 { f = 1; if (($2 < 0 ? -$2 : $2) > 1e-12 || ($3 - 180 < 0 ? 180 - $3 : $3 - 180) > 1e-9 ||
                         ($13 - 3 < 0 ? 3 - $13 : $13 - 3) > 1e-9) bad = 1 } END { exit bad || !f }' paper.csv; echo $?)

run solve "$EX/paper_fourbar.json" --csv rates.csv --rates
check "--rates adds d(var)/d(input) columns" \
  $(head -n 1 rates.csv | grep -q "O_B.theta5,d(A.x)/d(O_A.theta2),d(A.theta23)/d(O_A.theta2),d(B.theta34)/d(O_A.theta2),d(B.theta4)/d(O_A.theta2),d(O_B.theta5)/d(O_A.theta2),link1.x"; echo $?)

# ---- beyond the limits: exit 1, limits on stderr, rows still written ---------------------------------
run solve "$EX/paper_fourbar.json" --from -70 --to 120 --csv wide.csv --plot wide.svg --draw pose.svg
check "--from -70 --to 120 exits 1" $([ "$rc" -eq 1 ]; echo $?)
check "stderr has a dead-point line" $(grep -q "dead_point: dead point" err.txt; echo $?)
check "stderr has a domain-exit line" $(grep -q "domain_exit: .*leaves the end of contour 'link2.parabola'" err.txt; echo $?)
check "limit lines give the input in degrees" $(grep "dead_point" err.txt | grep -Eq "O_A.theta2 = -5[5-9]\.[0-9]+ deg"; echo $?)
check "rows still written: 191 rows" $([ "$(awk 'END { print NR - 1 }' wide.csv)" -eq 191 ]; echo $?)
check "unsolved rows carry nan and a status" \
  $(awk -F, 'NR > 1 && $NF != "ok" { n++; if ($2 != "nan" || ($NF != "not_reached" && $NF != "dead_point" && $NF != "domain_exit")) bad = 1 }
             END { exit bad || n == 0 }' wide.csv; echo $?)
check "solved rows in the wide sweep" $([ "$(grep -c ',ok$' wide.csv)" -gt 150 ]; echo $?)
check "--plot and --draw write SVG" $(grep -q "<svg" wide.svg && grep -q "<svg" pose.svg; echo $?)

# ---- other examples -----------------------------------------------------------------------------------
for ex in hypocycloid elliptical_gears elliptical_gears_cam cycloid; do
  run solve "$EX/$ex.json"
  check "$ex exits 0 with no limits" $([ "$rc" -eq 0 ] && grep -q "no limits met" out.txt; echo $?)
done
run solve "$EX/hypocycloid.json" --csv hypo.csv
check "hypocycloid: planet turns -3 times the arm" \
  $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "O.phi") a = i; if ($i == "planet.angle") p = i }; next }
             { d = $p + 3 * $a; while (d > 180) d -= 360; while (d < -180) d += 360; if (d < -1e-9 || d > 1e-9) bad = 1 }
             END { exit bad }' hypo.csv; echo $?)
run solve "$EX/paper_fourbar_osculating.json"
check "osculating variant exits 1" $([ "$rc" -eq 1 ]; echo $?)
check "osculating variant explains the singularity" $(grep -q "osculat" err.txt; echo $?)

# ---- bad inputs: exit 2, message names the file, no output file --------------------------------------
for bad in malformed unknown_pair_type missing_contour_file contour_too_short cannot_assemble; do
  rm -f bad.csv bad.csv.tmp
  run solve "$BAD/$bad.json" --csv bad.csv
  check "$bad: exit 2" $([ "$rc" -eq 2 ]; echo $?)
  check "$bad: message names the file" $(grep -q "$bad.json" err.txt; echo $?)
  check "$bad: no output file" $([ ! -e bad.csv ] && [ ! -e bad.csv.tmp ]; echo $?)
done
run solve "$BAD/malformed.json"
check "malformed JSON: line:column" $(grep -q "malformed.json:4:[0-9]*: malformed JSON" err.txt; echo $?)
run solve "$BAD/unknown_pair_type.json"
check "unknown pair type: JSON path and allowed types" $(grep -q 'pairs\[1\].type: unknown pair type "rollin"; expected one of "revolute"' err.txt; echo $?)
run solve "$BAD/missing_contour_file.json"
check "missing contour file: names the point file" $(grep -q "does_not_exist.txt" err.txt; echo $?)
run solve "$WORK/no_such_scene.json"
check "missing scene file: exit 2" $([ "$rc" -eq 2 ] && grep -q "no_such_scene.json" err.txt; echo $?)
run solve "$EX/paper_fourbar.json" --step 0
check "--step 0: exit 2" $([ "$rc" -eq 2 ]; echo $?)
run solve "$EX/paper_fourbar.json" --from 10 --to 0 --step 1
check "step of the wrong sign: exit 2" $([ "$rc" -eq 2 ] && grep -q "wrong sign" err.txt; echo $?)

# ---- never overwrite an input -------------------------------------------------------------------------
cp "$EX/paper_fourbar.json" scene.json
cp scene.json scene.orig
run solve scene.json --csv scene.json
check "--csv onto the scene file is refused (exit 2)" $([ "$rc" -eq 2 ] && grep -q "refusing" err.txt; echo $?)
check "the scene file is unchanged" $(cmp -s scene.json scene.orig; echo $?)
run solve scene.json --plot ./scene.json
check "--plot onto the scene file (other spelling) is refused" $([ "$rc" -eq 2 ] && cmp -s scene.json scene.orig; echo $?)
mkdir -p shapes
awk 'BEGIN { for (i = 0; i < 64; ++i) { t = 2 * 3.141592653589793 * i / 64; printf "%.17g %.17g\n", cos(t), sin(t) } }' > shapes/disk.txt
cp shapes/disk.txt shapes/disk.orig
# Disk 3 as 64 samples: its parameter is then a chord length, so A's and B's values on it are lengths.
sed -e 's|{"name": "rim", "type": "circle", "radius": 1}|{"name": "rim", "type": "samples", "file": "shapes/disk.txt", "closed": true}|' \
    -e 's|"values": \[0, 180\]|"values": [0, 3.14033]|' -e 's|"values": \[-3, 117\]|"values": [-0.05, 117]|' \
  scene.json > sampled.json
run solve sampled.json --csv shapes/disk.txt
check "--csv onto a contour file is refused" $([ "$rc" -eq 2 ] && grep -q "refusing" err.txt && cmp -s shapes/disk.txt shapes/disk.orig; echo $?)
run solve sampled.json --from -10 --to 10 --step 5 --csv sampled.csv
check "sampled disk (point file) solves" $([ "$rc" -eq 0 ] && [ "$(awk 'END { print NR - 1 }' sampled.csv)" -eq 5 ]; echo $?)

# ---- interference along a sweep -----------------------------------------------------------------------
# The cycloid's disk (r = 1, centre (s, 1)) meets a kerb (r = 0.5 at (4, 0.5)) where the centres are closer than
# 1.5: s in (4 - sqrt 2, 4 + sqrt 2). Expected: the first and last grid values k pi/10 inside that interval.
sed 's|"material": "right"}]|"material": "right"}, {"name": "kerb", "type": "circle", "radius": 0.5, "at": {"x": 4, "y": 0.5}}]|' \
  "$EX/cycloid.json" > kerb.json
run solve kerb.json --interference
range=$(awk 'BEGIN { pi = 3.141592653589793; lo = 4 - sqrt(2); hi = 4 + sqrt(2); first = ""; for (k = 0; k <= 20; ++k) { s = k * pi / 10; if (s > lo && s < hi) { if (first == "") first = s; last = s } } printf "from %.8g to %.8g", first, last }')
check "--interference reports the penetration range predicted in closed form (exit 1)" \
  $([ "$rc" -eq 1 ] && grep -q "penetration between 'ground.kerb' and 'disk.rim' for S.s $range" err.txt; echo $?)
run solve "$EX/paper_fourbar.json" --interference
check "--interference on the paper example finds nothing (exit 0)" $([ "$rc" -eq 0 ] && [ ! -s err.txt ]; echo $?)

# ---- reference: the same sweep in MPFR ---------------------------------------------------------------
run reference "$EX/paper_fourbar.json" --from -50 --to 100 --step 25 --csv ref.csv
check "reference exits 0 and writes 7 rows" $([ "$rc" -eq 0 ] && [ "$(awk 'END { print NR - 1 }' ref.csv)" -eq 7 ]; echo $?)
run solve "$EX/paper_fourbar.json" --from -50 --to 100 --step 25 --csv dbl.csv
# Independent of the double path: 50-digit values; the double solve must agree with them to 1e-12 degrees
# (theta5, column 6), and the reference must carry more than 17 significant digits.
check "double theta5 agrees with the 50-digit reference to 1e-12 deg" $(paste -d, ref.csv dbl.csv | awk -F, -v n="$(head -n1 ref.csv | awk -F, '{print NF}')" \
  'NR > 1 { d = $6 - $(n + 6); if (d < 0) d = -d; if (d > 1e-12) bad = 1 } END { exit bad }'; echo $?)
check "reference values have 50 digits" $(awk -F, 'NR == 2 { exit (length($6) < 45) }' ref.csv; echo $?)
run reference "$EX/paper_fourbar.json" --digits 40 --csv x.csv
check "reference --digits 40 is refused (exit 2)" $([ "$rc" -eq 2 ] && [ ! -f x.csv ]; echo $?)

# ---- DXF cam example: a closed SPLINE cam lifting a flat follower ---------------------------------------
run solve "$EX/dxf_cam.json" --csv cam.csv --verbose
check "--verbose states the DXF contour's unit conversion" $(grep -q "^contour DXF .*cam_profile.dxf.*SPLINE.*unit mm.*converted mm -> mm" out.txt; echo $?)
check "dxf_cam.json solves every pose (181 rows)" $([ "$rc" -eq 0 ] && [ "$(awk 'END { print NR - 1 }' cam.csv)" -eq 181 ]; echo $?)
# Independent truth: the flat face touches the cam's highest point, so the lift s(phi) is the maximum of
# x sin(phi) + y cos(phi) over the profile as ezdxf evaluates the SPLINE (dense sampling: error ~1e-8 mm).
check "dxf_cam lift equals the profile's support function by ezdxf (1e-6 mm)" $(/usr/bin/python3 - "$SRC/shapes/cam_profile.dxf" cam.csv <<'PY' >/dev/null 2>&1; echo $?
import csv, math, sys
import ezdxf
pts = list(ezdxf.readfile(sys.argv[1]).modelspace().query("SPLINE")[0].construction_tool().approximate(segments=50000))
worst = 0
for row in list(csv.DictReader(open(sys.argv[2])))[::30]:
    phi = math.radians(float(row["O.phi"]))
    worst = max(worst, abs(max(p.x * math.sin(phi) + p.y * math.cos(phi) for p in pts) - float(row["S.s"])))
sys.exit(0 if worst < 1e-6 else 1)
PY
)

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
