#!/usr/bin/env bash
# End-to-end tests of the rollkin command-line tool.
#   usage: run_cli_tests.sh PATH/TO/rollkin SOURCE_DIR [PATH/TO/rollkin_bench]
# (with the benchmark's path, its command-line options are checked too)
# Runs in a fresh temporary directory; prints one line per check and "N passed, M failed" last.
set -u
BIN=${1:?usage: run_cli_tests.sh ROLLKIN_BINARY SOURCE_DIR}
SRC=${2:?usage: run_cli_tests.sh ROLLKIN_BINARY SOURCE_DIR}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
case "$SRC" in /*) ;; *) SRC="$PWD/$SRC" ;; esac
BENCH=${3:-}
case "$BENCH" in ""|/*) ;; *) BENCH="$PWD/$BENCH" ;; esac
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
check "--help lists the commands solve and reference with a description" \
  $(grep -Eq "^ +solve +[a-z]" out.txt && grep -Eq "^ +reference +[a-z]" out.txt; echo $?)
run --version
check "--version prints the version" $([ "$rc" -eq 0 ] && grep -Eq "^rollkin [0-9]+\.[0-9]+" out.txt; echo $?)
run frobnicate
check "unknown command exits 2" $([ "$rc" -eq 2 ]; echo $?)
check "unknown command: named, with the commands expected" $(grep -q 'unknown command "frobnicate"' err.txt && grep -q "solve, reference" err.txt; echo $?)
run solve --help
check "solve --help exits 0 and lists --csv, --max-steps and --interference with a description" \
  $([ "$rc" -eq 0 ] && grep -Eq "^ +--csv FILE +[a-z]" out.txt && grep -q -- "--max-steps" out.txt && grep -q -- "--interference" out.txt; echo $?)
run reference --help
check "reference --help exits 0 and lists --digits and --csv" \
  $([ "$rc" -eq 0 ] && grep -Eq "^ +--digits N +[A-Za-z]" out.txt && grep -q -- "--csv" out.txt && ! grep -q -- "--plot" out.txt; echo $?)
run
check "missing command: exit 2, names the commands" $([ "$rc" -eq 2 ] && grep -q "missing command" err.txt && grep -q "solve, reference" err.txt; echo $?)
run solve "$EX/paper_fourbar.json" --frobnicate 3
check "unknown option: exit 2, names it and the expected options" \
  $([ "$rc" -eq 2 ] && grep -q 'unknown option "--frobnicate" for solve; expected one of --from, --to' err.txt; echo $?)
run reference "$EX/paper_fourbar.json" --csv r.csv --plot r.svg
check "reference --plot: unknown option (reference writes a CSV only)" $([ "$rc" -eq 2 ] && grep -q '"--plot"' err.txt && [ ! -e r.csv ]; echo $?)
run solve
check "solve without a scene: exit 2, says SCENE is required" $([ "$rc" -eq 2 ] && grep -q "SCENE is required" err.txt; echo $?)
run reference "$EX/paper_fourbar.json" "$EX/cycloid.json" --csv two.csv
check "reference with two scene files: exit 2, names the second (solve takes several: --jobs below)" \
  $([ "$rc" -eq 2 ] && grep -q 'unexpected argument ".*cycloid.json"' err.txt && [ ! -e two.csv ]; echo $?)
for bad in "--step 1x" "--from nan" "--to inf" "--step ''" "--from 1e999"; do
  eval run solve "\"$EX/paper_fourbar.json\"" $bad --csv num.csv
  check "solve $bad: exit 2, names the option and expects a number" \
    $([ "$rc" -eq 2 ] && grep -q "rollkin: ${bad%% *}: expects a number" err.txt && [ ! -e num.csv ]; echo $?)
done
run solve "$EX/paper_fourbar.json" --csv
check "--csv without a value: exit 2, names --csv" $([ "$rc" -eq 2 ] && grep -q -- "--csv" err.txt; echo $?)
run solve "$EX/paper_fourbar.json" --csv --rates
check "--csv followed by an option: exit 2, no file named --rates" \
  $([ "$rc" -eq 2 ] && grep -q -- '--csv: expects a file name, got the option "--rates"' err.txt && [ ! -e ./--rates ]; echo $?)
run solve "$EX/paper_fourbar.json" --from=-10 --to -5 --step 5 --csv neg.csv
check "negative values (--from=-10, --to -5) are values, not options" $([ "$rc" -eq 0 ] && [ "$(awk 'END { print NR - 1 }' neg.csv)" -eq 2 ]; echo $?)

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

# ---- --analysis: contact analysis columns (docs/analysis.md) -----------------------------------------
run solve "$EX/paper_fourbar.json" --csv analysis.csv --analysis
check "--analysis exits 0" $([ "$rc" -eq 0 ] && [ -f analysis.csv ]; echo $?)
check "--analysis header: link poses, per contact pair the six quantities, per moving link .accel and .jerk, per unknown d2 and d3, residual" \
  $([ "$(head -n 1 analysis.csv)" = "O_A.theta2,A.x,A.theta23,B.theta34,B.theta4,O_B.theta5,link1.x,link1.y,link1.angle,link2.x,link2.y,link2.angle,link3.x,link3.y,link3.angle,link4.x,link4.y,link4.angle,A.pressure_angle,A.sliding,A.slide_to_roll,A.kappa1,A.kappa2,A.relative_curvature,B.pressure_angle,B.sliding,B.slide_to_roll,B.kappa1,B.kappa2,B.relative_curvature,link2.accel,link3.accel,link4.accel,link2.jerk,link3.jerk,link4.jerk,d2(A.x)/d(O_A.theta2)2,d2(A.theta23)/d(O_A.theta2)2,d2(B.theta34)/d(O_A.theta2)2,d2(B.theta4)/d(O_A.theta2)2,d2(O_B.theta5)/d(O_A.theta2)2,d3(A.x)/d(O_A.theta2)3,d3(A.theta23)/d(O_A.theta2)3,d3(B.theta34)/d(O_A.theta2)3,d3(B.theta4)/d(O_A.theta2)3,d3(O_B.theta5)/d(O_A.theta2)3,residual,status" ]; echo $?)
check "--analysis: sliding at both rolling pairs below 1e-9 on every ok row" \
  $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "A.sliding") a = i; if ($i == "B.sliding") b = i }; next }
             $NF == "ok" { n++; if (a == 0 || b == 0 || !(($a < 0 ? -$a : $a) < 1e-9) || !(($b < 0 ? -$b : $b) < 1e-9)) bad = 1 }
             END { exit bad || n != 151 }' analysis.csv; echo $?)
check "--analysis: parabola curvature 2a/(1+4a^2x^2)^1.5 (a = 0.5), disks 1 and 1/4, pressure angles in [0, 90]" \
  $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
             { x = $c["A.x"]; k = 1 / (1 + x * x) ^ 1.5; d = $c["A.kappa1"] - k; if ((d < 0 ? -d : d) > 1e-12 * k) bad = 1
               for (p = 0; p < 3; ++p) { d = $c[p == 0 ? "A.kappa2" : (p == 1 ? "B.kappa1" : "B.kappa2")] - (p == 2 ? 0.25 : 1)
                                         if ((d < 0 ? -d : d) > 1e-14) bad = 1 }
               for (p = 0; p < 2; ++p) { v = $c[(p ? "B" : "A") ".pressure_angle"]; if (!(v >= 0 && v <= 90)) bad = 1 } }
             END { exit bad || NR != 152 }' analysis.csv; echo $?)
run solve "$EX/paper_fourbar.json" --from 20 --to 21 --step 0.01 --csv fine_analysis.csv --analysis --rates
check "--analysis: per-degree units, d2 = difference of the rate columns, d3 and .jerk = differences of d2 and .accel (1e-6)" \
  $([ "$rc" -eq 0 ] && /usr/bin/python3 - fine_analysis.csv <<'PY' >/dev/null 2>&1; echo $?
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
h = 0.01
pairs = [("d(B.theta4)/d(O_A.theta2)", "d2(B.theta4)/d(O_A.theta2)2"), ("d(A.x)/d(O_A.theta2)", "d2(A.x)/d(O_A.theta2)2"),
         ("d2(B.theta4)/d(O_A.theta2)2", "d3(B.theta4)/d(O_A.theta2)3"), ("d2(A.x)/d(O_A.theta2)2", "d3(A.x)/d(O_A.theta2)3"),
         ("link4.accel", "link4.jerk"), ("link3.accel", "link3.jerk")]
worst = 0
for k in range(1, len(rows) - 1):
    for low, high in pairs:
        fd = (float(rows[k + 1][low]) - float(rows[k - 1][low])) / (2 * h)
        worst = max(worst, abs(fd - float(rows[k][high])) / max(1e-3, abs(float(rows[k][high]))))
sys.exit(0 if len(rows) == 101 and worst < 1e-6 else 1)
PY
)
run reference "$EX/paper_fourbar.json" --csv ref_analysis.csv --analysis
check "reference --analysis is refused (exit 2)" $([ "$rc" -eq 2 ] && [ ! -e ref_analysis.csv ]; echo $?)
run solve "$EX/paper_fourbar.json" --from -70 --to 120 --csv wide_analysis.csv --analysis
check "--analysis beyond the limits: unsolved rows carry nan in the analysis columns" \
  $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
             $NF != "ok" { n++; if ($c["A.pressure_angle"] != "nan" || $c["B.sliding"] != "nan" || $c["link4.accel"] != "nan") bad = 1 }
             END { exit bad || n == 0 }' wide_analysis.csv; echo $?)
# The DXF cam lifts a flat face perpendicular to the stroke: pressure angle 0 wherever the follower moves,
# and the profile's radius of curvature at the contact is s + d^2s/dphi^2 (s the lift, phi in radians).
run solve "$EX/dxf_cam.json" --step 0.5 --csv cam_analysis.csv --analysis
check "--analysis on the DXF cam: flat face perpendicular to the stroke, pressure angle 0 (1e-9 deg) where defined" \
  $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "C.pressure_angle") c = i; next }
             $c == "nan" { nans++; next } { if (c == 0 || !(($c < 0 ? -$c : $c) < 1e-9)) bad = 1 }
             END { exit bad || nans > 2 || NR != 722 }' cam_analysis.csv; echo $?)
# The spline's curvature has kinks at its knots, where the second difference errs most: 95 % of the rows
# within 1e-4, all within 2e-3.
check "--analysis on the DXF cam: kappa1 = 1 / (s + s'') by central differences of the lift (1e-4 relative)" \
  $(awk -F, -v h="$(awk 'BEGIN { printf "%.17g", 0.5 * atan2(0, -1) / 180 }')" '
             NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
             { s[NR] = $c["S.s"]; k[NR] = $c["C.kappa1"] }
             END { for (r = 3; r < NR; ++r) { rho = s[r] + (s[r + 1] - 2 * s[r] + s[r - 1]) / (h * h); n++
                     d = k[r] * rho - 1; d = d < 0 ? -d : d; if (!(d < 2e-3)) bad = 1; if (!(d < 1e-4)) far++ }
                   exit bad || n < 700 || far > 0.05 * n }' cam_analysis.csv; echo $?)
run solve "$EX/dxf_cam.json" --step 5 --csv cam_plot.csv --plot cam_plot.svg --analysis
# The charts' polylines in pixels cannot be compared to the CSV directly; the series names and chart titles
# (one chart per quantity, sliding only at cam pairs) and a well-formed document are what the plot adds.
check "--analysis --plot: well-formed SVG with a chart per quantity (pressure angle, sliding, slide-to-roll, curvature, stroke acceleration and jerk)" \
  $([ "$rc" -eq 0 ] && /usr/bin/python3 -c 'import sys, xml.dom.minidom as d; d.parse(sys.argv[1])' cam_plot.svg &&
    for t in "pressure angle at the contact pairs" "sliding velocity at the cam pairs" "slide-to-roll ratio at the cam pairs" \
             "curvature of the contours at the contact" "acceleration of the sliding pairs" "jerk of the sliding pairs"; do
      grep -q "$t" cam_plot.svg || exit 1; done; echo $?)
check "--analysis --plot on the cam: no angular acceleration chart (cam at constant rate, follower translating)" \
  $(! grep -q "angular acceleration of the links" cam_plot.svg; echo $?)
run solve "$EX/paper_fourbar.json" --plot paper_plot.svg --analysis
check "--analysis --plot on rolling pairs only: no sliding chart (zero by construction), angular acceleration and jerk charts" \
  $([ "$rc" -eq 0 ] && grep -q "pressure angle at the contact pairs" paper_plot.svg && ! grep -q "sliding velocity" paper_plot.svg &&
    grep -q "angular acceleration of the links" paper_plot.svg && grep -q "angular jerk of the links" paper_plot.svg; echo $?)

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
cp out.txt wide.out
cp err.txt wide.err
run solve "$EX/paper_fourbar.json" --from -70 --to 120
check "the wide sweep without output files (its summary alone, no values kept): the same summary, limit lines, exit 1" \
  $([ "$rc" -eq 1 ] && cmp -s out.txt wide.out && cmp -s err.txt wide.err; echo $?)
check "--plot and --draw write SVG" $(grep -q "<svg" wide.svg && grep -q "<svg" pose.svg; echo $?)
# The only contour drawn is a straight line parallel to the x axis: the drawing's box has zero height
# (was exit 2, "SvgDrawing::set_world_box: need finite xmin < xmax").
cat > flat.json <<'JSON'
{"links": [{"name": "ground", "ground": true, "contours": [{"name": "c", "type": "line", "from": 0, "to": 10}]},
           {"name": "slider"}],
 "pairs": [{"name": "S", "type": "prismatic", "links": ["ground", "slider"], "variable": "s", "value": 0}],
 "inputs": ["S.s"], "sweep": {"from": 0, "to": 1, "step": 1}}
JSON
run solve flat.json --draw flat.svg
check "--draw of a single line parallel to an axis: exit 0, drawn" $([ "$rc" -eq 0 ] && grep -q "<polyline" flat.svg; echo $?)

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
  rm -f bad.csv bad.csv.tmp .bad.csv.*
  run solve "$BAD/$bad.json" --csv bad.csv
  check "$bad: exit 2" $([ "$rc" -eq 2 ]; echo $?)
  check "$bad: message names the file" $(grep -q "$bad.json" err.txt; echo $?)
  check "$bad: no output file" $([ ! -e bad.csv ] && [ ! -e bad.csv.tmp ] && ! ls .bad.csv.* >/dev/null 2>&1; echo $?)
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

# ---- several scenes at once (--jobs) -----------------------------------------------------------------
mkdir -p jobs
for s in paper_fourbar antiparallelogram elliptical_gears; do
  "$BIN" solve "$EX/$s.json" --csv "jobs/alone_$s.csv" >/dev/null 2>&1
done
run solve "$EX/paper_fourbar.json" "$EX/antiparallelogram.json" "$EX/elliptical_gears.json" --csv 'jobs/{scene}.csv' --jobs 2
check "--jobs 2 on three scenes: each CSV equals the scene solved alone; exit 1 (the anti-parallelogram's singular poses)" \
  $([ "$rc" -eq 1 ] && cmp -s jobs/paper_fourbar.csv jobs/alone_paper_fourbar.csv &&
    cmp -s jobs/antiparallelogram.csv jobs/alone_antiparallelogram.csv &&
    cmp -s jobs/elliptical_gears.csv jobs/alone_elliptical_gears.csv; echo $?)
check "--jobs: the summaries in the order the scenes were given" \
  $([ "$(cut -d: -f1 out.txt | tr '\n' ' ')" = "paper_fourbar.json antiparallelogram.json elliptical_gears.json " ]; echo $?)
run solve "$EX/paper_fourbar.json" "$EX/cycloid.json" --csv jobs/one.csv
check "several scenes, an output without {scene}: exit 2, names the option, nothing written" \
  $([ "$rc" -eq 2 ] && grep -q -- "--csv 'jobs/one.csv'.*{scene}" err.txt && [ ! -e jobs/one.csv ]; echo $?)
run solve "$EX/paper_fourbar.json" jobs/missing.json "$EX/cycloid.json" --csv 'jobs/m_{scene}.csv'
check "several scenes, one missing: exit 2, it is named, the others are written" \
  $([ "$rc" -eq 2 ] && grep -q "missing.json: cannot open" err.txt && [ -f jobs/m_paper_fourbar.csv ] &&
    [ -f jobs/m_cycloid.csv ] && [ ! -e jobs/m_missing.csv ]; echo $?)
cp "$EX/cycloid.json" jobs/cycloid.json
before=$(cksum < jobs/cycloid.json)
run solve "$EX/paper_fourbar.json" jobs/cycloid.json --csv 'jobs/{scene}.json'
check "several scenes, an output that is one of the scenes: exit 2, the scene untouched, nothing written" \
  $([ "$rc" -eq 2 ] && [ "$(cksum < jobs/cycloid.json)" = "$before" ] && [ ! -e jobs/paper_fourbar.json ]; echo $?)
run solve "$EX/paper_fourbar.json" "$EX/cycloid.json" --jobs -1
check "--jobs -1: exit 2, names the option" $([ "$rc" -eq 2 ] && grep -q -- "--jobs" err.txt; echo $?)
# ---- no run loses a file: every output of every scene against every file any scene reads, and each other ----
# (docs/reliability.md, "Outputs"). Scenes a and b each read a point file, an SVG and a DXF contour. For every
# reader scene s, kind of input k (scene file, point file, SVG, DXF), writer scene t, output option o and name
# pattern p ({scene} once or twice), s's input of kind k is named so that t's output o expands onto it; the run
# must exit 2, name the file, change no input (sha256) and write nothing. Then every ordered pair of options of
# two scenes whose outputs expand to one name ("x" and "x_d"), and a scene given twice.
collision_scene() {  # collision_scene FILE POINTS SVG DXF: the planet on an arm in a ring, contours from files
  set -- "$1" "${2##*/}" "${3##*/}" "${4##*/}"  # contour files are named relative to the scene's directory
  cat > "$1" <<JSON
{"units": {"length": "m", "angle": "deg"},
 "links": [
  {"name": "frame", "ground": true, "contours": [{"name": "ring", "type": "circle", "radius": 4, "material": "outside"}]},
  {"name": "arm", "contours": [
    {"name": "plate", "type": "svg", "file": "$3", "path": "contour", "scale": 0.1},
    {"name": "cam", "type": "dxf", "file": "$4", "layer": "CAM"}]},
  {"name": "planet", "contours": [{"name": "disk", "type": "samples", "file": "$2", "closed": true}]}],
 "pairs": [
  {"name": "O", "type": "revolute", "links": ["frame", "arm"], "variable": "phi", "value": 0},
  {"name": "P", "type": "revolute", "links": ["arm", "planet"], "at": [{"x": 3}, {}], "variable": "psi", "value": 0},
  {"name": "C", "type": "rolling", "contours": ["planet.disk", "frame.ring"], "variables": ["u", "v"], "values": [0, 0]}],
 "inputs": ["O.phi"], "sweep": {"from": 0, "to": 90, "step": 30}}
JSON
}
collision_files() {  # collision_files SCENE POINTS SVG DXF: the scene and its three contour files
  cp "$SRC/shapes/circle_n0032.txt" "$2"
  cp "$SRC/tests/fuzz/corpus/svg/document_closed_square.svg" "$3"
  cp "$SRC/shapes/cam_profile.dxf" "$4"
  collision_scene "$1" "$2" "$3" "$4"
}
mkdir -p collide && cd collide || exit 1
collision_files a.json a_pts.txt a_sq.svg a_cam.dxf
collision_files b.json b_pts.txt b_sq.svg b_cam.dxf
run solve a.json b.json --csv '{scene}-{scene}.csv' --plot '{scene}.svg'
check "collision set-up: two scenes reading a point file, an SVG and a DXF solve (exit 0); {scene} twice: a-a.csv, b-b.csv" \
  $([ "$rc" -eq 0 ] && [ -s a-a.csv ] && [ -s b-b.csv ] && [ -s a.svg ] && [ -s b.svg ] && [ ! -e '{scene}-{scene}.csv' ] &&
    [ ! -e 'a-{scene}.csv' ]; echo $?)
cd .. || exit 1
combos=0 combos_bad=0
for s in a b; do for k in json txt svg dxf; do for t in a b; do for o in --csv --plot --draw --animate; do
  for p in once twice; do
    # a scene's own file is hit by '{scene}.json' only: with {scene} twice the name is longer than its stem
    [ "$k" = json ] && [ "$s" = "$t" ] && [ "$p" = twice ] && continue
    combos=$((combos + 1))
    rm -rf combo && mkdir combo && cd combo || exit 1
    [ "$p" = once ] && stem_t="$t" || stem_t="$t-$t"
    case "$k" in json) [ "$s" = "$t" ] && suffix=.json || suffix=_s.json ;; txt) suffix=_p.txt ;; svg) suffix=_c.svg ;; dxf) suffix=_c.dxf ;; esac
    victim="$stem_t$suffix"
    # the scenes' files; the victim is s's input of kind k, named as t's output o expands
    for r in a b; do
      scene="$r.json"; pts="${r}_pts.txt"; svg="${r}_sq.svg"; dxf="${r}_cam.dxf"
      if [ "$r" = "$s" ]; then
        case "$k" in json) [ "$s" = "$t" ] || scene="$victim" ;; txt) pts="$victim" ;; svg) svg="$victim" ;; dxf) dxf="$victim" ;; esac
      fi
      collision_files "$scene" "$pts" "$svg" "$dxf"
      eval "scene_$r=\$scene"
    done
    [ "$p" = once ] && pattern="{scene}$suffix" || pattern="{scene}-{scene}$suffix"
    # '{scene}.json' is every scene's own file: the first scene's is named
    named="$victim"; [ "$k" = json ] && [ "$s" = "$t" ] && named="it is the scene file 'a.json'"
    others=""
    for x in --csv --plot --draw --animate; do [ "$x" = "$o" ] || others="$others $x {scene}.out${x#--}"; done
    sums=$(sha256sum -- * | sort); names=$(ls -a | sort)
    # shellcheck disable=SC2086
    run solve "$scene_a" "$scene_b" "$o" "$pattern" $others
    if ! { [ "$rc" -eq 2 ] && grep -q -- "$named" err.txt && [ "$(sha256sum -- * | grep -v ' [oe][ur][tr].txt$' | sort)" = "$(echo "$sums" | grep -v ' [oe][ur][tr].txt$')" ] &&
           [ "$(ls -a | grep -v '^[oe][ur][tr].txt$' | sort)" = "$(echo "$names" | grep -v '^[oe][ur][tr].txt$')" ]; }; then
      combos_bad=$((combos_bad + 1)); echo "     collision not refused: $s's $k input '$victim' vs $t's $o '$pattern' (exit $rc)"
    fi
    cd .. || exit 1
  done
done; done; done; done
check "every output vs every input of every scene ($combos combinations): exit 2, the file named, inputs byte-identical, nothing written" \
  $([ "$combos_bad" -eq 0 ] && [ "$combos" -eq 120 ]; echo $?)
pairs=0 pairs_bad=0
for o1 in --csv --plot --draw --animate; do for o2 in --csv --plot --draw --animate; do
  [ "$o1" = "$o2" ] && continue
  pairs=$((pairs + 1))
  rm -rf combo && mkdir combo && cd combo || exit 1
  collision_files x.json x_pts.txt x_sq.svg x_cam.dxf
  collision_files x_d.json d_pts.txt d_sq.svg d_cam.dxf
  echo "an older file" > x_d.out
  names=$(ls -a | sort)
  run solve x.json x_d.json "$o1" '{scene}_d.out' "$o2" '{scene}.out'
  if ! { [ "$rc" -eq 2 ] && grep -q "x_d.json's $o2 'x_d.out' and x.json's $o1 'x_d.out' name the same file" err.txt &&
         [ "$(cat x_d.out)" = "an older file" ] && [ "$(ls -a | grep -v '^[oe][ur][tr].txt$' | sort)" = "$(echo "$names" | grep -v '^[oe][ur][tr].txt$')" ]; }; then
    pairs_bad=$((pairs_bad + 1)); echo "     output collision not refused: x.json $o1 vs x_d.json $o2 (exit $rc)"
  fi
  cd .. || exit 1
done; done
check "two scenes' outputs expanding to one file ($pairs option pairs): exit 2 naming both, nothing written" \
  $([ "$pairs_bad" -eq 0 ] && [ "$pairs" -eq 12 ]; echo $?)
rm -rf combo && mkdir -p combo/d1 combo/d2 && cd combo || exit 1
collision_files d1/a.json d1/a_pts.txt d1/a_sq.svg d1/a_cam.dxf
collision_files d2/a.json d2/a_pts.txt d2/a_sq.svg d2/a_cam.dxf
run solve d1/a.json d2/a.json --csv '{scene}.csv'
check "two scenes with one name in two directories: exit 2, their --csv named, nothing written" \
  $([ "$rc" -eq 2 ] && grep -q "d2/a.json's --csv 'a.csv' and d1/a.json's --csv 'a.csv' name the same file" err.txt && [ ! -e a.csv ]; echo $?)
run solve d1/a.json d1/a.json --csv '{scene}.csv'
check "one scene given twice: exit 2, nothing written" $([ "$rc" -eq 2 ] && grep -q "name the same file" err.txt && [ ! -e a.csv ]; echo $?)
mkdir -p d3 && collision_files d3/b.json d3/b_pts.txt d3/b_sq.svg d3/b_cam.dxf
ln d1/a_pts.txt a_link.txt
run solve d1/a.json d3/b.json --csv '{scene}_link.txt'
check "an output that is a hard link to another name of a point file: exit 2, the file and its scene named" \
  $([ "$rc" -eq 2 ] && grep -q "refusing to write d1/a.json's --csv 'a_link.txt': it is the contour file 'd1/a_pts.txt' read by scene 'd1/a.json'" err.txt &&
    cmp -s d1/a_pts.txt "$SRC/shapes/circle_n0032.txt"; echo $?)
run solve d1/a.json d3/b.json --csv '../combo/d3/{scene}_pts.txt'
check "an output through another spelling of b's point file (../combo/d3/b_pts.txt): exit 2, named" \
  $([ "$rc" -eq 2 ] && grep -q "it is the contour file 'd3/b_pts.txt' read by scene 'd3/b.json'" err.txt &&
    cmp -s d3/b_pts.txt "$SRC/shapes/circle_n0032.txt"; echo $?)
cd .. || exit 1
# One scene: --jobs is the number of threads that format its CSV rows (in blocks of 1024); the file is the
# same bytes with any number, here past a dead point (not_reached rows) and over several blocks.
for j in 1 3; do
  run solve "$EX/paper_fourbar.json" --from -50 --to 130 --step 0.02 --rates --csv "jobs/threads_$j.csv" --jobs "$j"
  cp err.txt "jobs/threads_$j.err"
done
check "one scene, --csv with --jobs 3 and --jobs 1: the same file (9,001 rows), exit 1 for the dead point" \
  $([ "$rc" -eq 1 ] && [ "$(awk 'END { print NR - 1 }' jobs/threads_3.csv)" -eq 9001 ] &&
    cmp -s jobs/threads_1.csv jobs/threads_3.csv && cmp -s jobs/threads_1.err jobs/threads_3.err; echo $?)

# ---- reference: the same sweep in MPFR ---------------------------------------------------------------
run reference "$EX/paper_fourbar.json" --from -50 --to 100 --step 25 --csv ref.csv
check "reference exits 0 and writes 7 rows" $([ "$rc" -eq 0 ] && [ "$(awk 'END { print NR - 1 }' ref.csv)" -eq 7 ]; echo $?)
run solve "$EX/paper_fourbar.json" --from -50 --to 100 --step 25 --csv dbl.csv
# Independent of the double path: 50-digit values; the double solve must agree with them to 1e-12 degrees
# (theta5, column 6), and the reference must carry more than 17 significant digits.
check "double theta5 agrees with the 50-digit reference to 1e-12 deg" $(paste -d, ref.csv dbl.csv | awk -F, -v n="$(head -n1 ref.csv | awk -F, '{print NF}')" \
  'NR > 1 { d = $6 - $(n + 6); if (d < 0) d = -d; if (d > 1e-12) bad = 1 } END { exit bad }'; echo $?)
check "reference values have 50 digits" $(awk -F, 'NR == 2 { exit (length($6) < 45) }' ref.csv; echo $?)
run reference "$EX/paper_fourbar.json" --from -50 --to -49.99 --step 0.001 --digits 30 --csv grid.csv
check "reference on the decimal grid: row 2 is exactly -49.999 deg, not the double nearest it (30 digits)" \
  $([ "$rc" -eq 0 ] && awk -F, 'NR == 3 { exit !($1 ~ /^-49\.9990*$/) }' grid.csv; echo $?)
run reference "$EX/paper_fourbar.json" --digits 40 --csv x.csv
check "reference --digits 40 is refused (exit 2)" $([ "$rc" -eq 2 ] && [ ! -f x.csv ]; echo $?)

# ---- deep JSON nesting: a located error at any depth, never a crash (docs/reliability.md, "How it is tested") --
for levels in 1000 100000 1000000; do
  python3 -c "import sys; n = int(sys.argv[1]); print('{\"description\": ' + '[' * n + ']' * n + '}')" $levels > deep$levels.json
  run solve deep$levels.json --csv deep.csv
  check "$levels nested arrays: exit 2, located 'nested deeper than 256 levels'" \
    $([ "$rc" -eq 2 ] && grep -q "deep$levels.json:1:[0-9]*: arrays and objects nested deeper than 256 levels at description\[0\]" err.txt && [ ! -e deep.csv ]; echo $?)
done
# Inside a contour of a valid scene (crashed with a segmentation fault before the bound).
python3 -c "import sys; n = 10**6; sys.stdout.write(open(sys.argv[1]).read().replace('\"radius\": 4,', '\"radius\": 4, \"x\": ' + '[' * n + ']' * n + ',', 1))" \
  "$EX/paper_fourbar.json" > deep_contour.json
run solve deep_contour.json --csv deep.csv
check "10^6 nested arrays in a contour: exit 2, located message, no crash" \
  $([ "$rc" -eq 2 ] && grep -q "deep_contour.json:10:[0-9]*: .*nested deeper than 256 levels at links\[3\].contours\[0\].x\[0\]" err.txt && [ ! -e deep.csv ]; echo $?)
python3 -c "print('{\"description\": ' + '{\"a\": ' * 1000000 + '1' + '}' * 1000000 + '}')" > deep_objects.json
run solve deep_objects.json
check "10^6 nested objects: exit 2, located message" $([ "$rc" -eq 2 ] && grep -q "deep_objects.json:1:[0-9]*: .*nested deeper than 256 levels at description.a.a" err.txt; echo $?)

# ---- messages that help (defect 7) --------------------------------------------------------------------------
sed 's/"radius": 4,/"radius": 1e400,/' "$EX/paper_fourbar.json" > huge.json
run solve huge.json
check "1e400: exit 2 with file, line:column and JSON path" \
  $([ "$rc" -eq 2 ] && grep -q "huge.json:10:[0-9]*: number 1e400 at links\[3\].contours\[0\].radius is out of the range" err.txt; echo $?)
sed 's/"radius": 4,/"radius": 4, "radius": 5,/' "$EX/paper_fourbar.json" > dupkey.json
run solve dupkey.json
check "duplicate key: full JSON path with array indices" \
  $([ "$rc" -eq 2 ] && grep -q 'dupkey.json:10:[0-9]*: duplicate key "radius" at links\[3\].contours\[0\].radius' err.txt; echo $?)
sed 's/"values": \[-3, 117\]/"hold": [true, false]/' "$EX/paper_fourbar.json" > hold.json
run solve hold.json
check "hold without values: exit 2, says hold needs values" \
  $([ "$rc" -eq 2 ] && grep -q 'hold.json:pairs\[2\].hold: "hold" needs "values"' err.txt; echo $?)
run solve "$BAD/cannot_assemble.json" --verbose
check "--verbose on an assembly that cannot close: exit 2, no report left on stdout" $([ "$rc" -eq 2 ] && [ ! -s out.txt ]; echo $?)
long=$(head -c 5000 /dev/zero | tr '\0' 'x')
printf '0 0\n1 %s\n' "$long" > long_line.txt
sed 's|{"name": "rim", "type": "circle", "radius": 1}|{"name": "rim", "type": "samples", "file": "long_line.txt", "closed": true}|' "$EX/paper_fourbar.json" > long_line.json
run solve long_line.json
check "a 5000-character bad value is cut in the message" $([ "$rc" -eq 2 ] && grep -q 'long_line.txt:2: .*xxx\.\.\.' err.txt && [ "$(wc -c < err.txt)" -lt 600 ]; echo $?)
# Control characters and markup in names: the plot stays well-formed XML, the CSV one line per row.
sed -e 's/link2/li\\u0001nk<\&>\\n2/g' -e 's/O_A/O\\u0007_A/g' "$EX/paper_fourbar.json" > ctrl.json
run solve ctrl.json --from 0 --to 10 --step 5 --csv ctrl.csv --plot ctrl.svg --draw ctrl_draw.svg
check "control characters in names: solves (exit 0)" $([ "$rc" -eq 0 ]; echo $?)
check "control characters in names: plot and drawing parse as XML" \
  $(python3 -c "import sys, xml.etree.ElementTree as E; [E.parse(f) for f in sys.argv[1:]]" ctrl.svg ctrl_draw.svg 2>/dev/null; echo $?)
check "control characters in names: escaped in the CSV (3 rows + header, one line each)" \
  $([ "$(wc -l < ctrl.csv)" -eq 4 ] && head -n 1 ctrl.csv | grep -q 'O\\x07_A.theta2,' && head -n 1 ctrl.csv | grep -q 'li\\x01nk<&>\\n2.x'; echo $?)

# ---- out of memory: exit 3 and what it was doing (not "bad input") ----------------------------------------
# 9.4 million poses in 150 MB of address space: the poses go to a temporary file (output/sweep_file.hpp), but the
# requested inputs alone take 75 MB twice.
if (ulimit -v 150000; "$BIN" --version >/dev/null 2>&1); then  # not under AddressSanitizer (needs more)
  (ulimit -v 150000; "$BIN" solve "$EX/paper_fourbar.json" --step 0.000016 --csv oom.csv >out.txt 2>err.txt); rc=$?
  check "allocation failure: exit 3, 'out of memory while', nothing written" \
    $([ "$rc" -eq 3 ] && grep -q "^rollkin: out of memory while " err.txt && [ ! -e oom.csv ]; echo $?)
fi

# ---- outputs never destroy inputs (defect 3) ---------------------------------------------------------------
cp "$EX/paper_fourbar.json" out.csv.tmp
cp out.csv.tmp tmp.orig
run solve out.csv.tmp --from 0 --to 10 --step 5 --csv out.csv
check "--csv out.csv leaves a scene named out.csv.tmp intact" $([ "$rc" -eq 0 ] && cmp -s out.csv.tmp tmp.orig && [ -s out.csv ]; echo $?)
mkdir -p real
echo "old" > real/data.csv
ln -s real/data.csv link.csv
run solve "$EX/paper_fourbar.json" --from 0 --to 10 --step 5 --csv link.csv
check "a symlink output is written to its target and stays a link" \
  $([ "$rc" -eq 0 ] && [ -L link.csv ] && head -n 1 real/data.csv | grep -q "^O_A.theta2," && [ "$(ls -A real)" = "data.csv" ]; echo $?)
ln -s scene.json scene_link.csv
run solve scene.json --csv scene_link.csv
check "an output that is a link to the scene is refused (exit 2)" $([ "$rc" -eq 2 ] && grep -q "refusing" err.txt && cmp -s scene.json scene.orig; echo $?)
ln scene.json scene_hard.svg
run solve scene.json --plot scene_hard.svg
check "an output that is a hard link to the scene is refused (exit 2)" $([ "$rc" -eq 2 ] && grep -q "refusing" err.txt && cmp -s scene.json scene.orig; echo $?)
(umask 027; "$BIN" solve "$EX/paper_fourbar.json" --from 0 --to 10 --step 5 --csv mode.csv >/dev/null 2>&1)
check "a new output gets the umask's mode (0640 under umask 027)" $([ "$(stat -c %a mode.csv)" = "640" ]; echo $?)
chmod 604 mode.csv
run solve "$EX/paper_fourbar.json" --from 0 --to 10 --step 5 --csv mode.csv
check "a replaced output keeps its mode" $([ "$rc" -eq 0 ] && [ "$(stat -c %a mode.csv)" = "604" ]; echo $?)

# ---- several outputs: all or nothing (defect 4) -----------------------------------------------------------
mkdir -p aon && cd aon || exit 1
printf 'old csv\n' > keep.csv
printf 'old svg\n' > keep.svg
cp keep.csv keep.csv.orig && cp keep.svg keep.svg.orig
run solve "$EX/paper_fourbar.json" --csv keep.csv --draw keep.svg --plot no_such_dir/x.svg
check "one output in a missing directory: exit 2, nothing written" \
  $([ "$rc" -eq 2 ] && grep -q "no_such_dir" err.txt && cmp -s keep.csv keep.csv.orig && cmp -s keep.svg keep.svg.orig; echo $?)
run solve "$EX/paper_fourbar.json" --csv new.csv --plot keep.csv.orig/x.svg
check "one output under a file: exit 2, the other not created" $([ "$rc" -eq 2 ] && [ ! -e new.csv ]; echo $?)
run solve "$EX/paper_fourbar.json" --csv same.csv --plot ./same.csv
check "two outputs naming one file: exit 2" $([ "$rc" -eq 2 ] && grep -q "name the same file" err.txt && [ ! -e same.csv ]; echo $?)
check "no temporaries left after the failed runs" \
  $([ "$(ls -A | sort | tr '\n' ' ')" = "err.txt keep.csv keep.csv.orig keep.svg keep.svg.orig out.txt " ]; echo $?)
cd .. || exit 1

# ---- --animate: one self-contained HTML page, one of the all-or-nothing outputs ------------------------------
mkdir -p anim && cd anim || exit 1
run solve "$EX/paper_fourbar.json" --from 0 --to 10 --step 5 --animate anim.html
check "--animate writes an HTML page with the inline SVG, a play button and a slider over the 3 poses" \
  $([ "$rc" -eq 0 ] && grep -q "^<!DOCTYPE html>" anim.html && grep -q "<svg " anim.html && grep -q '<button id="play"' anim.html &&
    grep -q '<input id="pose" type="range" min="0" max="2"' anim.html; echo $?)
check "--animate page: well-formed XML, nothing external (no URL, src=, href=)" \
  $(python3 -c "import sys, xml.etree.ElementTree as E; E.fromstring(open(sys.argv[1]).read().split(chr(10), 1)[1])" anim.html 2>/dev/null &&
    ! grep -Eqi "https?:|src=|href=" anim.html; echo $?)
run solve "$EX/paper_fourbar.json" --csv a.csv --draw a.svg --animate no_such_dir/a.html
check "--animate in a missing directory: exit 2, names it, the other outputs not written" \
  $([ "$rc" -eq 2 ] && grep -q "no_such_dir" err.txt && [ ! -e a.csv ] && [ ! -e a.svg ]; echo $?)
run solve "$EX/paper_fourbar.json" --animate --csv x.csv
check "--animate followed by an option: exit 2, no file named --csv" \
  $([ "$rc" -eq 2 ] && grep -q -- '--animate: expects a file name, got the option "--csv"' err.txt && [ ! -e ./--csv ]; echo $?)
run solve --help
check "solve --help lists --animate FILE" $(grep -Eq "^ +--animate FILE +[a-z]" out.txt; echo $?)

# ---- outputs at any size (docs/reliability.md): charts at their resolution, the page in bounded frames -------
# 150,001 poses: the chart holds at most 4 points per pixel column (plus a few per break) and still shows each
# series' extremes: the lowest and highest points drawn, read back through the chart's own y ticks, are the
# CSV column's minimum and maximum (to a pixel's hundredth, the document's precision).
run solve "$EX/paper_fourbar.json" --from -50 --to 100 --step 0.001 --csv big.csv --plot big.svg --animate big.html
check "150,001 poses: exit 0, every CSV row, chart under 2 MB, page under 5 MB" \
  $([ "$rc" -eq 0 ] && [ "$(wc -l < big.csv)" -eq 150002 ] && [ "$(stat -c %s big.svg)" -lt 2000000 ] &&
    [ "$(stat -c %s big.html)" -lt 5000000 ]; echo $?)
check "150,001 poses: each series at most 4 points per pixel column, its extremes those of the CSV column" \
  $(/usr/bin/python3 - big.svg big.csv <<'PY'
import csv, sys, xml.etree.ElementTree as ET
ns = "{http://www.w3.org/2000/svg}"
chart = ET.parse(sys.argv[1]).getroot()
chart = chart.find(ns + "svg") if chart.find(ns + "svg") is not None else chart  # the first of the stacked charts
rows = list(csv.DictReader(open(sys.argv[2])))
# The y ticks: the labels (right-aligned texts) and, in the same order, the 5 px tick marks left of the axis.
labels = [float(t.text) for t in chart.iter(ns + "text") if t.get("text-anchor") == "end"]
marks = [float(l.get("y1")) for l in chart.iter(ns + "line")
         if l.get("y1") == l.get("y2") and abs(float(l.get("x2")) - float(l.get("x1")) - 5) < 1e-9]
ticks = list(zip(labels, marks))
(v0, p0), (v1, p1) = ticks[0], ticks[-1]
to_value = lambda py: v0 + (py - p0) * (v1 - v0) / (p1 - p0)
per_pixel = abs((v1 - v0) / (p1 - p0))
bad = 0
for g in chart.iter(ns + "g"):
    if g.get("class") != "series":
        continue
    pts = [tuple(map(float, p.split(","))) for l in g.iter(ns + "polyline") for p in l.get("points").split()]
    column = [float(r[g.get("data-name")]) for r in rows]
    width = float(chart.get("width"))
    bad += len(pts) > 4 * width or len(pts) < 100
    bad += abs(max(to_value(y) for _, y in pts) - max(column)) > 0.011 * per_pixel
    bad += abs(min(to_value(y) for _, y in pts) - min(column)) > 0.011 * per_pixel
sys.exit(1 if bad else 0)
PY
echo $?)
check "150,001 poses: the page's slider has 2000 frames and the title says so" \
  $(grep -q '<input id="pose" type="range" min="0" max="1999"' big.html && grep -q "150001 poses of the sweep of .*, 2000 of them shown" big.html; echo $?)
rm -f big.csv big.svg big.html
cd .. || exit 1

# ---- point files: closed contour with its first point repeated; messages that say what to do (defect 9, 7) ---
{ cat shapes/disk.txt; head -n 1 shapes/disk.txt; } > shapes/disk_repeat.txt
sed 's|shapes/disk.txt|shapes/disk_repeat.txt|' sampled.json > sampled_repeat.json
run solve sampled_repeat.json --from -10 --to 10 --step 5 --csv repeat.csv
check "closed point file with its first point repeated at the end solves like without it" \
  $([ "$rc" -eq 0 ] && cmp -s <(cut -d, -f1-6 repeat.csv) <(cut -d, -f1-6 sampled.csv); echo $?)
tr '\n' '\r' < shapes/disk.txt > shapes/disk_cr.txt
sed 's|shapes/disk.txt|shapes/disk_cr.txt|' sampled.json > sampled_cr.json
run solve sampled_cr.json
check "point file with CR-only line ends: exit 2, says so" $([ "$rc" -eq 2 ] && grep -q "disk_cr.txt:1: line ends are a bare CR" err.txt; echo $?)
python3 -c "import sys; sys.stdout.buffer.write(open('shapes/disk.txt').read().encode('utf-16'))" > shapes/disk_utf16.txt
sed 's|shapes/disk.txt|shapes/disk_utf16.txt|' sampled.json > sampled_utf16.json
run solve sampled_utf16.json
check "UTF-16 point file: exit 2, says UTF-16" $([ "$rc" -eq 2 ] && grep -q "disk_utf16.txt: the file is UTF-16" err.txt; echo $?)
# ---- singular poses, nothing to solve, bounded work (docs/reliability.md, "Numbers") -----------------
# Zero unknowns: one crank on a driven revolute. Forward kinematics only: every row ok, residual 0, and the
# crank's world angle is the input.
cat > crank.json <<'JSON'
{"units": {"length": "m", "angle": "deg"},
 "links": [{"name": "ground", "ground": true}, {"name": "crank"}],
 "pairs": [{"name": "O", "type": "revolute", "links": ["ground", "crank"], "variable": "theta", "value": 0}],
 "inputs": ["O.theta"], "sweep": {"from": 0, "to": 90, "step": 30}}
JSON
run solve crank.json --csv crank.csv --verbose
check "a scene with nothing to solve writes its rows (exit 0)" $([ "$rc" -eq 0 ] && [ "$(awk 'END { print NR - 1 }' crank.csv)" -eq 4 ] &&
  awk -F, 'NR > 1 { if ($NF != "ok" || $(NF - 1) != 0 || ($(NF - 2) - $1) > 1e-12 || ($1 - $(NF - 2)) > 1e-12) bad = 1 } END { exit bad }' crank.csv; echo $?)
check "--verbose says in words that there is nothing to solve" $(grep -q "nothing to solve: every pair variable is an input" out.txt; echo $?)

# Anti-parallelogram (frame 4, coupler 4, cranks 2): theta4 (column 4) must stay on the crossed branch, the
# intersection of the circles about the crank pin (radius 4) and O4 (radius 2) that is not the parallelogram's
# theta4 = theta2 + 90. Rows on the change points (90, 270) are within 1e-9 deg or "singular" with a stderr line.
run solve "$EX/antiparallelogram.json" --csv anti.csv
check "anti-parallelogram stays on the crossed branch over 0..360" $(awk -F, '
  function wrap(a) { while (a > 180) a -= 360; while (a <= -180) a += 360; return a }
  NR > 1 { pi = 3.141592653589793; t = $1 * pi / 180; ax = 2 * cos(t + pi / 2); ay = 2 * sin(t + pi / 2)
    dx = 4 - ax; dy = -ay; d = sqrt(dx * dx + dy * dy); al = (16 - 4 + d * d) / (2 * d); h2 = 16 - al * al
    ac = h2 > 0 ? sqrt(h2) : 0; px = ax + al * dx / d; py = ay + al * dy / d
    b1 = atan2(py + ac * dx / d, px - ac * dy / d - 4) * 180 / pi; b2 = atan2(py - ac * dx / d, px + ac * dy / d - 4) * 180 / pi
    par = $1 + 90; crossed = (wrap(b1 - par) ^ 2 < wrap(b2 - par) ^ 2) ? b2 : b1
    e = wrap($4 - crossed); if (e < 0) e = -e
    if ($NF == "singular") { if ($1 != 90 && $1 != 270) bad = 1; if (e > 1e-6) bad = 1; sing++ }
    else if ($NF != "ok" || e > 1e-9) bad = 1 }
  END { exit bad }' anti.csv; echo $?)
nsing=$(awk -F, 'NR > 1 && $NF == "singular"' anti.csv | wc -l)
check "singular rows: one stderr line each naming the input, exit 1 (else exit 0)" \
  $(if [ "$nsing" -gt 0 ]; then [ "$rc" -eq 1 ] && [ "$(grep -c 'singular pose at O2.theta2 = ' err.txt)" -eq "$nsing" ] &&
    grep -q "the branches meet / Jacobian singular; values follow the branch" err.txt; else [ "$rc" -eq 0 ]; fi; echo $?)
cp out.txt anti.out
cp err.txt anti.err
anti_rc=$rc
run solve "$EX/antiparallelogram.json"
check "anti-parallelogram without output files: the same summary, singular lines in input order and exit status" \
  $([ "$rc" -eq "$anti_rc" ] && cmp -s out.txt anti.out && cmp -s err.txt anti.err; echo $?)
run solve "$EX/antiparallelogram.json" --from 0 --to 360 --step 0.7 --csv anti7.csv
check "anti-parallelogram with step 0.7: every row ok and crossed (theta4 + 90 - theta2 never 0 mod 360 away from 90/270)" \
  $([ "$rc" -eq 0 ] && awk -F, 'NR > 1 { if ($NF != "ok") bad = 1; d = $4 - $1 - 90; while (d > 180) d -= 360; while (d <= -180) d += 360
    if (d < 0) d = -d; s = $1 - 90; if (s < 0) s = -s; u = $1 - 270; if (u < 0) u = -u; if (d < 1 && s > 1 && u > 1) bad = 1 } END { exit bad }' anti7.csv; echo $?)

# Cam gears stepped exactly through the singular vertex pose phi1 = 180: phi2 (column 2) against
# tan(phi2/2) = ((1 - e)/(1 + e)) tan(phi1/2), e = 0.5; the 180 row within 1e-9 deg or "singular".
run solve "$EX/elliptical_gears_cam.json" --from 30 --to 330 --step 5 --csv cam.csv
check "cam gears through 180 deg follow the closed form (no inaccurate ok)" $(awk -F, '
  NR > 1 { pi = 3.141592653589793; t = $1 * pi / 180
    ex = ($1 == 180) ? -180 : -2 * atan2((1 - 0.5) / (1 + 0.5) * sin(t / 2), cos(t / 2)) * 180 / pi
    e = $2 - ex; while (e > 180) e -= 360; while (e <= -180) e += 360; if (e < 0) e = -e
    if ($NF == "singular") { if ($1 != 180 || e > 1e-6) bad = 1 } else if ($NF != "ok" || e > 1e-9) bad = 1 }
  END { exit bad }' cam.csv; echo $?)

# Bounded work: a request estimated above the limit is refused before solving, with the estimate and the way out.
run solve "$EX/elliptical_gears.json" --to 1e12 --step 1e6 --csv huge.csv
check "--to 1e12 --step 1e6 on gears is refused (exit 2, estimate and way out named, nothing written)" \
  $([ "$rc" -eq 2 ] && [ ! -e huge.csv ] && grep -q "continuation sub-steps" err.txt && grep -q -- "--max-steps" err.txt; echo $?)
run solve "$EX/paper_fourbar.json" --max-steps 160 --csv lim.csv
check "--max-steps 160 refuses the paper sweep (181 sub-steps estimated)" $([ "$rc" -eq 2 ] && [ ! -e lim.csv ] && grep -q "1.81e+02" err.txt; echo $?)
run solve "$EX/paper_fourbar.json" --max-steps 150 --csv lim.csv
check "--max-steps 150 refuses the paper sweep's 151 values before making them" \
  $([ "$rc" -eq 2 ] && [ ! -e lim.csv ] && grep -q "has 1.51e+02 values, above the limit 1.50e+02 (--max-steps)" err.txt; echo $?)
for bad in nan inf -inf 0.5 1e400; do
  run solve "$EX/paper_fourbar.json" --max-steps "$bad" --csv lim.csv
  check "--max-steps $bad: exit 2, the rule named (a finite number of at least 1)" \
    $([ "$rc" -eq 2 ] && [ ! -e lim.csv ] && grep -q -- "--max-steps: expects a finite number of continuation sub-steps, at least 1" err.txt; echo $?)
done
run solve "$EX/paper_fourbar.json" --max-steps 200 --csv lim.csv
check "--max-steps 200 lets it run" $([ "$rc" -eq 0 ] && [ -s lim.csv ]; echo $?)
run solve "$EX/paper_fourbar.json" --max-steps 0
check "--max-steps 0 is a usage error" $([ "$rc" -eq 2 ]; echo $?)
# ---- truncated scenes: exit 2, outputs untouched ------------------------------------------------------
# 20 truncations of the examples at pseudo-random lengths (fixed seed), each before the closing brace, so
# never valid JSON. Each run asks for a CSV over an existing file and a new plot: exit 2, the existing file
# byte-identical, no plot and no temporary file left (the directory holds exactly what it held before).
mkdir -p truncated
printf 'input,value\n1,2\n' > truncated/keep.csv
cp truncated/keep.csv keep.orig
for ex in paper_fourbar elliptical_gears_cam hypocycloid cycloid; do
  last_brace=$(grep -bo '}' "$EX/$ex.json" | tail -n 1 | cut -d: -f1)
  for length in $(awk -v n="$last_brace" -v seed="${#ex}" 'BEGIN { srand(seed); print 0; for (i = 0; i < 4; ++i) print int(rand() * (n + 1)) }'); do
    head -c "$length" "$EX/$ex.json" > truncated/scene.json
    before=$(ls -A truncated)
    run solve truncated/scene.json --csv truncated/keep.csv --plot truncated/new.svg
    check "$ex.json truncated to $length bytes: exit 2, located message, outputs untouched" \
      $([ "$rc" -eq 2 ] && grep -q "scene.json" err.txt && cmp -s truncated/keep.csv keep.orig && [ "$(ls -A truncated)" = "$before" ]; echo $?)
  done
done
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

# ---- corners (docs/scene_format.md, "Corners"): a disk rolling over a DXF polyline's vertex (ezdxf, flat to x = 3 m) --
sed -e "s|\"type\": \"line\", \"from\": -10, \"to\": 10,|\"type\": \"dxf\", \"file\": \"$SRC/tests/data/dxf/scenes_mm.dxf\", \"layer\": \"TABLE_MM\", \"parameter\": \"arc_length\",|" \
  "$EX/cycloid.json" > table.json
run solve table.json --csv table.csv
check "corner: exit 1 (a limit met)" $([ "$rc" -eq 1 ] && [ -f table.csv ]; echo $?)
check "corner: stderr names the pair, the contour, the polyline and the input" \
  $(grep -Eq "corner: the contact of pair 'C' reaches a corner of contour 'ground.track' \(entity LWPOLYLINE [0-9A-F]+ at \(3000, 0\) mm in .*scenes_mm.dxf, turning -45 deg; \(3, 0\) in the contour's frame\) at S.s = 3(\.0000000)?[0-9]* m" err.txt; echo $?)
check "corner: rows before s = 3 ok, the next corner, the rest not_reached" \
  $(awk -F, 'NR > 1 { want = ($1 < 3) ? "ok" : (seen++ ? "not_reached" : "corner"); if ($NF != want) bad = 1 } END { exit bad || !seen }' table.csv; echo $?)

# ---- centrodes: the anti-parallelogram's crank centrodes are ellipses; rolled back, the linkage --
run centrodes "$EX/antiparallelogram.json" --links crank follower --out anti --step 0.5 --dxf anti.dxf
check "centrodes: exit 1 for the two singular poses solve reports (one pose, one status), both files and the DXF written" \
  $([ "$rc" -eq 1 ] && [ "$(grep -c "singular pose at" err.txt)" -eq 2 ] && [ -f anti.crank.txt ] && [ -f anti.follower.txt ] && [ -f anti.dxf ]; echo $?)
check "centrodes: 721 points per file, one per input value" \
  $([ "$(grep -Ec '^-?[0-9]' anti.crank.txt)" -eq 721 ] && [ "$(grep -Ec '^-?[0-9]' anti.follower.txt)" -eq 721 ]; echo $?)
# Ellipses with foci at each crank's joints (crank: (0,0), (0,2); follower: (0,0), (2,0)) and major axis 4.
check "centrodes: crank's centrode is the ellipse |PO2| + |PA| = 4 (1e-8)" \
  $(awk '/^-?[0-9]/ { e = sqrt($1^2 + $2^2) + sqrt($1^2 + ($2 - 2)^2) - 4; if (e > 1e-8 || e < -1e-8) bad = 1 } END { exit bad }' anti.crank.txt; echo $?)
check "centrodes: follower's centrode is the ellipse |PO4| + |PB| = 4 (1e-8)" \
  $(awk '/^-?[0-9]/ { e = sqrt($1^2 + $2^2) + sqrt(($1 - 2)^2 + $2^2) - 4; if (e > 1e-8 || e < -1e-8) bad = 1 } END { exit bad }' anti.follower.txt; echo $?)
cat > rolled.json <<'JSON'
{"description": "The anti-parallelogram's crank centrodes (rollkin centrodes) rolling on each other between its pivots.",
 "units": {"length": "m", "angle": "deg"},
 "links": [{"name": "frame", "ground": true},
   {"name": "crank", "contours": [{"name": "centrode", "type": "samples", "file": "anti.crank.txt", "closed": true}]},
   {"name": "follower", "contours": [{"name": "centrode", "type": "samples", "file": "anti.follower.txt", "closed": true}]}],
 "pairs": [{"name": "O2", "type": "revolute", "links": ["frame", "crank"], "variable": "theta2", "value": 0},
   {"name": "R", "type": "rolling", "contours": ["crank.centrode", "follower.centrode"], "variables": ["u", "v"],
    "values": [0, 0], "hold": [true, false]},
   {"name": "O4", "type": "revolute", "links": ["frame", "follower"], "at": [{"x": 4}, {}], "variable": "theta4", "value": -143}],
 "inputs": ["O2.theta2"],
 "sweep": {"from": 0, "to": 360, "step": 1}}
JSON
run solve rolled.json --csv rolled.csv
check "centrodes rolled as a rolling pair: exit 0" $([ "$rc" -eq 0 ]; echo $?)
run solve "$EX/antiparallelogram.json" --csv fourbar.csv
check "centrodes rolled: output angle equals the four-bar's over a full turn (1e-6 deg)" $(/usr/bin/python3 - fourbar.csv rolled.csv <<'PY' >/dev/null 2>&1; echo $?
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
ok = len(a) == len(b) == 361 and all(r["status"] in ("ok", "singular") for r in a) and all(r["status"] == "ok" for r in b)
worst = max(abs(float(x["O4.theta4"]) - float(y["O4.theta4"])) for x, y in zip(a, b))
sys.exit(0 if ok and worst < 1e-6 else 1)
PY
)
# The DXF read by ezdxf (an independent NURBS evaluator): one closed SPLINE per layer, through every centre
# of the point files (1e-12), on the ellipses between them (the cubic's interpolation error, 1e-8 here).
check "centrodes --dxf: ezdxf reads closed SPLINEs on layers crank and follower, through the points (1e-12), on the ellipses (1e-8)" \
  $(/usr/bin/python3 - anti.dxf anti.crank.txt anti.follower.txt <<'PY' >/dev/null 2>&1; echo $?
import math, sys, ezdxf
doc = ezdxf.readfile(sys.argv[1])
foci = {"crank": ((0, 0), (0, 2)), "follower": ((0, 0), (2, 0))}
points = {layer: [tuple(map(float, l.split())) for l in open(f) if l[0] not in "#x"]
          for layer, f in (("crank", sys.argv[2]), ("follower", sys.argv[3]))}
splines = {e.dxf.layer: e for e in doc.modelspace().query("SPLINE")}
assert sorted(splines) == ["crank", "follower"] and doc.header["$INSUNITS"] == 6
for layer, e in splines.items():
    assert e.closed
    bs = e.construction_tool()
    at_knots = [bs.point(k) for k in sorted(set(bs.knots()))]
    assert len(at_knots) == len(points[layer]) == 721
    assert max(math.dist((p.x, p.y), q) for p, q in zip(at_knots, points[layer])) < 1e-12
    f1, f2 = foci[layer]
    assert max(abs(math.dist((p.x, p.y), f1) + math.dist((p.x, p.y), f2) - 4) for p in bs.approximate(20000)) < 1e-8
PY
)
sed -e 's/"type": "samples", "file": "anti.crank.txt", "closed": true/"type": "dxf", "file": "anti.dxf", "layer": "crank"/' \
    -e 's/"type": "samples", "file": "anti.follower.txt", "closed": true/"type": "dxf", "file": "anti.dxf", "layer": "follower"/' rolled.json > rolled_dxf.json
run solve rolled_dxf.json --csv rolled_dxf.csv
check "centrodes --dxf rolled as dxf contours: output angle equals the four-bar's over a full turn (1e-6 deg)" \
  $([ "$rc" -eq 0 ] && grep -q '"type": "dxf"' rolled_dxf.json && /usr/bin/python3 - fourbar.csv rolled_dxf.csv <<'PY' >/dev/null 2>&1; echo $?
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
ok = len(a) == len(b) == 361 and all(r["status"] == "ok" for r in b)
sys.exit(0 if ok and max(abs(float(x["O4.theta4"]) - float(y["O4.theta4"])) for x, y in zip(a, b)) < 1e-6 else 1)
PY
)
run centrodes "$EX/antiparallelogram.json" --links crank crank --out same
check "centrodes: the same link twice is exit 2 naming --links" $([ "$rc" -eq 2 ] && grep -q -- "--links" err.txt && [ ! -e same.crank.txt ]; echo $?)
run centrodes "$EX/antiparallelogram.json" --links crank nolink --out none
check "centrodes: an unknown link is exit 2 listing the links" $([ "$rc" -eq 2 ] && grep -q '"follower"' err.txt; echo $?)
# Two links joined by a revolute: the centrode is the joint, one point; said, the point files written (the
# point at every value: A at (0, 2) in the crank's frame, the coupler's origin), the DXF not, with a line why.
echo "the user's drawing" > cc.dxf
run centrodes "$EX/antiparallelogram.json" --links crank coupler --out cc --dxf cc.dxf
check "centrodes of links joined by a revolute: exit 1 (the sweep's singular poses), 'is one point' named with the revolute, --dxf not written and why" \
  $([ "$rc" -eq 1 ] && grep -q "is one point, (0, 2) in link 'crank''s frame and (0, 0) in link 'coupler''s frame: the links are joined by the revolute 'A'" out.txt &&
    grep -q -- "--dxf 'cc.dxf' not written: a centrode that is one point" err.txt && [ "$(cat cc.dxf)" = "the user's drawing" ]; echo $?)
check "centrodes of links joined by a revolute: 361 points per file, each the joint to 1e-12" \
  $(awk 'FNR > 3 && !/^#/ { n++; dx = $1; dy = (FILENAME == "cc.crank.txt") ? $2 - 2 : $2
      if (dx * dx + dy * dy > 1e-24) bad = 1 } END { exit bad || n != 722 }' cc.crank.txt cc.coupler.txt; echo $?)

# ---- rollkin check: undercut and conformity (docs/analysis.md "Design check") -----------------------------
run check --help
check "check --help exits 0 and describes the exit status" $([ "$rc" -eq 0 ] && grep -q -- "--max-steps" out.txt && grep -q "interpenetrates" out.txt; echo $?)
run check "$EX/paper_fourbar.json"
check "check on the paper example: exit 0, nothing on stderr, no finding" \
  $([ "$rc" -eq 0 ] && [ ! -s err.txt ] && grep -q "no undercut or interpenetration" out.txt; echo $?)
check "check on the paper example: the parabola's smallest radius 1/(2a) = 1 at its vertex, the disks 1 and 4" \
  $(grep -q "link2.parabola: smallest convex radius of curvature 1 at A.x = " out.txt && grep -q "link3.rim: circle of radius 1 (convex)" out.txt \
    && grep -q "link4.rim: circle of radius 4 (convex)" out.txt; echo $?)
run check "$EX/hypocycloid.json"
check "check on the planet inside its ring: the roller (radius 1) fits the ring's concave radius 4, exit 0" \
  $([ "$rc" -eq 0 ] && grep -q "roller 'planet.disk' (radius 1) on 'frame.ring': fits its smallest concave radius 4$" out.txt; echo $?)
UNDERCUT="$SRC/tests/data/undercut_ellipse.json"
run check "$UNDERCUT"
check "check on a roller too large for the groove: exit 1, one located line naming the pair" \
  $([ "$rc" -eq 1 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q "undercut: pair 'C': the roller 'follower.roller' (radius 1.5) is larger than the concave radius 1.333333333 of 'cam.groove'" err.txt; echo $?)
check "check: the undercut is located at the vertex (u = 0, point 3, 0) at phi = 90 deg, with the cusps at +-14.81127 deg" \
  $(grep -q "at C.u = 0 deg (point 3, 0), O.phi = 90.0000" err.txt && grep -q "cusp at C.u = -14.81127" err.txt && grep -q "C.u = 14.81127" err.txt; echo $?)
run check "$UNDERCUT" --from 60 --to 120 --step 1
check "check over a range past the cusps: exit 1, the dead points and the undercut reported" \
  $([ "$rc" -eq 1 ] && grep -q "dead_point" err.txt && grep -q "undercut: pair 'C'" err.txt; echo $?)
sed 's/"type": "circle", "radius": 1.5/"type": "ellipse", "semi_axes": [1.5, 1.5]/' "$UNDERCUT" > round_tip.json
run check round_tip.json
check "check on two non-circular contours that interpenetrate: exit 1, the pair and both contours named" \
  $([ "$rc" -eq 1 ] && grep -q "interpenetration: the contours 'cam.groove' and 'follower.roller' of pair 'C' interpenetrate next to their contact at C.u = 0 deg (point 3, 0)" err.txt; echo $?)
run solve "$UNDERCUT" --verbose
check "solve --verbose prints the design check section with the undercut (solve's exit status unchanged)" \
  $([ "$rc" -eq 0 ] && grep -q "^design check" out.txt && grep -q "undercut: pair 'C'" out.txt; echo $?)
run check "$UNDERCUT" --step 0
check "check --step 0: exit 2 naming --step" $([ "$rc" -eq 2 ] && grep -q -- "--step" err.txt; echo $?)
run check "$UNDERCUT" --csv x.csv
check "check --csv: unknown option, exit 2, nothing written" $([ "$rc" -eq 2 ] && grep -q 'unknown option "--csv" for check' err.txt && [ ! -e x.csv ]; echo $?)

# ---- the input column is the decimal grid asked for (docs/scene_format.md, "Inputs and sweep"); shortest round trip --
run solve "$EX/paper_fourbar.json" --from -50 --to -48.9 --step 0.001 --csv grid.csv
check "decimal grid: row 2 reads -49.999, row 1030 the double nearest to -48.971 (written -48.971)" \
  $([ "$rc" -eq 0 ] && [ "$(sed -n 3p grid.csv | cut -d, -f1)" = "-49.999" ] && [ "$(sed -n 1031p grid.csv | cut -d, -f1)" = "-48.971" ]; echo $?)
run solve "$EX/paper_fourbar.json" --from -5e1 --to -48.9 --step 1e-3 --csv grid2.csv
check "decimal grid: --from -5e1 --step 1e-3 gives the same file as -50 and 0.001" $([ "$rc" -eq 0 ] && cmp -s grid.csv grid2.csv; echo $?)
# Each number has as few significant digits as reading back to its double allows: one digit fewer never
# reads back (awk's printf "%.*g" and strtod are the independent truth).
check "CSV numbers: the shortest text that reads back to the same double (none padded to 17 digits)" \
  $(awk -F, 'NR > 1 { for (i = 1; i < NF; ++i) { v = $i; if (v == "nan") continue;
      m = v; sub(/[eE].*/, "", m); gsub(/[-+.]/, "", m); sub(/^0+/, "", m); if (index(v, ".") == 0 && index(v, "e") == 0) sub(/0+$/, "", m);
      d = length(m); if (d < 2) continue;
      if (sprintf("%.*g", d - 1, v) + 0 == v + 0) bad++ } } END { exit bad > 0 }' grid.csv; echo $?)

# ---- the benchmark's options (only when its path is given: ctest passes it when the benchmark is built) ----
if [ -n "$BENCH" ]; then
  "$BENCH" --help >out.txt 2>err.txt; rc=$?
  check "rollkin_bench --help exits 0 and lists --repeats" $([ "$rc" -eq 0 ] && grep -q -- "--repeats N" out.txt; echo $?)
  for bad in x 3x 0 -2 ""; do
    "$BENCH" --repeats "$bad" --only "no such case" >out.txt 2>err.txt; rc=$?
    check "rollkin_bench --repeats '$bad': exit 2, names --repeats and what it expects" \
      $([ "$rc" -eq 2 ] && grep -q "^rollkin_bench: --repeats: expects a whole number" err.txt; echo $?)
  done
  "$BENCH" --frobnicate >out.txt 2>err.txt; rc=$?
  check "rollkin_bench with an unknown option: exit 2, names it" $([ "$rc" -eq 2 ] && grep -q -- "--frobnicate" err.txt; echo $?)
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
