#!/usr/bin/env bash
# Outputs and messages of issue 37, checked from outside (docs/reliability.md, "Outputs, signals and messages
# (issue 37)"):
#  - synthesize: specs of absurd sizes (a lift, a base radius, a centre distance of 1e300) are bad input naming
#    the key (exit 2), never "undercut", and leave nothing behind (the round trip runs before anything is
#    committed); a valid spec writes its four files and nothing else;
#  - messages in the spec's terms: lifts 15 and -14.9999999 say the sum with its digits; a law that ends at 359
#    degrees says "359 deg"; a pivot at the cam centre is bad geometry (follower.pivot); a truncated cam spec
#    points to docs/synthesis.md; an output prefix "./" or "out/" is refused like '' (no hidden ".txt");
#  - options: --jobs 1e9 names --jobs and its range (not CLI11's "Could not convert"); synthesize envelope
#    --start nan is refused by the library's rule; solve --help says the step has the sign of --to minus --from,
#    and a step of the wrong sign is answered with the step that would be right;
#  - one pose, one status: centrodes on the anti-parallelogram reports the singular poses solve reports and
#    exits 1 as solve does.
#   usage: outputs_messages.sh PATH/TO/rollkin SOURCE_DIR
set -u
BIN=${1:?usage: outputs_messages.sh ROLLKIN_BINARY SOURCE_DIR}
SRC=${2:?usage: outputs_messages.sh ROLLKIN_BINARY SOURCE_DIR}
case "$BIN" in /*) ;; *) BIN="$PWD/$BIN" ;; esac
EX="$SRC/examples"
WORK=$(mktemp -d "${TMPDIR:-/tmp}/rollkin_msgs.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1
passed=0
failed=0
check() {  # check NAME CONDITION-EXIT-STATUS
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); echo "ok   $1"; else failed=$((failed + 1)); echo "FAIL $1"; sed 's/^/     /' err.txt | head -5; fi
}
run() { "$BIN" "$@" > out.txt 2> err.txt; rc=$?; }
only() {  # only FILE...: the directory holds exactly these files (hidden ones included)
  [ "$(ls -A | sort | tr '\n' ' ')" = "$(printf '%s\n' "$@" out.txt err.txt | sort | tr '\n' ' ')" ]
}
cam() {  # cam BASE LIFT1 LIFT2 [FOLLOWER] [LAST_TO]
  local follower='{"motion": "translating", "offset": 12}'
  [ $# -ge 4 ] && follower=$4
  cat > spec.json <<EOF
{"units": {"length": "mm", "angle": "deg"}, "base_radius": $1, "rotation": "ccw",
 "follower": $follower, "contact": {"roller_radius": 10},
 "law": [{"to": 90, "lift": $2, "kind": "cycloidal"}, {"to": 180, "kind": "dwell"},
         {"to": 270, "lift": $3, "kind": "cycloidal"}, {"to": ${5:-360}, "kind": "dwell"}]}
EOF
}

# ---- synthesize: absurd sizes are bad input, nothing is left --------------------------------------------
cam 40 1e300 -1e300
run synthesize cam spec.json --out c
check "lift of 1e300: exit 2 naming law[0].lift, nothing written" \
  $([ "$rc" -eq 2 ] && grep -q 'law\[0\].lift' err.txt && grep -q "1e100" err.txt && only spec.json; echo $?)
cam 1e300 15 -15
run synthesize cam spec.json --out c
check "base radius of 1e300: exit 2 naming base_radius, not an undercut" \
  $([ "$rc" -eq 2 ] && grep -q "base_radius" err.txt && ! grep -q "undercut" err.txt && only spec.json; echo $?)
echo '{"units": {"length": "mm", "angle": "deg"}, "centre_distance": 1e300, "transmission": {"kind": "elliptical", "eccentricity": 0.5}}' > spec.json
run synthesize gears spec.json --out g
check "centre distance of 1e300: exit 2 naming centre_distance, nothing written" \
  $([ "$rc" -eq 2 ] && grep -q "centre_distance" err.txt && only spec.json; echo $?)
cam 40 15 -15
run synthesize cam spec.json --out c
check "a valid cam: exit 0, the four files and nothing else" $([ "$rc" -eq 0 ] && only spec.json c.txt c.dxf c.svg c.json; echo $?)
rm -f c.txt c.dxf c.svg c.json

# ---- messages in the spec's terms ------------------------------------------------------------------------
cam 40 15 -14.9999999
run synthesize cam spec.json --out c
check "lifts 15 and -14.9999999: the sum with its digits, not 0.000000" \
  $([ "$rc" -eq 2 ] && grep -q "15 - 14.9999999 = 9.9999999" err.txt && ! grep -q "0.000000," err.txt && only spec.json; echo $?)
cam 40 15 -15 '{"motion": "translating", "offset": 12}' 359
run synthesize cam spec.json --out c
check "a law that ends at 359 deg says so in degrees" \
  $([ "$rc" -eq 2 ] && grep -q "law\[3\].to.*359 deg" err.txt && grep -q "expected 360 deg" err.txt && ! grep -q "rad" err.txt; echo $?)
cam 40 15 -15 '{"motion": "oscillating", "pivot": [0, 0], "arm": 50, "start_angle": 0}'
run synthesize cam spec.json --out c
check "a pivot at the cam centre: exit 2 naming follower.pivot (bad geometry)" \
  $([ "$rc" -eq 2 ] && grep -q "follower.pivot.*cam centre" err.txt && only spec.json; echo $?)
head -c 60 "$EX/synthesis/cam_cycloidal_roller.json" > spec.json
run synthesize cam spec.json --out c
check "a truncated cam spec points to docs/synthesis.md" \
  $([ "$rc" -eq 2 ] && grep -q "docs/synthesis.md" err.txt && ! grep -q "scene_format" err.txt; echo $?)
cam 40 15 -15
mkdir -p sub
for prefix in ./ sub/ . ''; do
  run synthesize cam spec.json --out "$prefix"
  check "--out '$prefix': exit 2 naming --out, no hidden file written" \
    $([ "$rc" -eq 2 ] && grep -q -- "--out" err.txt && [ -z "$(ls -A sub)" ] && only spec.json sub; echo $?)
done

# ---- options -----------------------------------------------------------------------------------------------
run solve "$EX/paper_fourbar.json" "$EX/cycloid.json" --jobs 1e9 --csv '{scene}.csv'
check "--jobs 1e9: exit 2 naming --jobs and the range, not CLI11's words" \
  $([ "$rc" -eq 2 ] && grep -q -- "--jobs" err.txt && grep -q "0 (one per core) to 4096" err.txt && ! grep -q "Could not convert" err.txt; echo $?)
run synthesize envelope "$EX/cycloid.json" --links ground disk --contour disk.rim --start nan --out env
check "envelope --start nan: exit 2 by the library's rule (a finite contour parameter)" \
  $([ "$rc" -eq 2 ] && grep -q -- "--start.*finite" err.txt && only spec.json sub; echo $?)
run solve --help
check "solve --help: the step has the sign of --to minus --from" $(grep -q "sign of --to minus --from" out.txt; echo $?)
run solve "$EX/paper_fourbar.json" --from 100 --to 0 --step 1
check "a step of the wrong sign: exit 2 with the step that would be right" \
  $([ "$rc" -eq 2 ] && grep -q "wrong sign" err.txt && grep -q "expected -1" err.txt; echo $?)

# ---- one pose, one status ----------------------------------------------------------------------------------
run solve "$EX/antiparallelogram.json"
solve_rc=$rc
solve_singular=$(grep -c "singular pose at" err.txt)
run centrodes "$EX/antiparallelogram.json" --links frame coupler --out cen
check "centrodes reports the $solve_singular singular poses solve reports, and exits $solve_rc as solve does" \
  $([ "$solve_rc" -eq 1 ] && [ "$solve_singular" -eq 2 ] && [ "$rc" -eq 1 ] && [ "$(grep -c "singular pose at" err.txt)" -eq 2 ]; echo $?)

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
