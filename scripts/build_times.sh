#!/usr/bin/env bash
# Where the build spends its time: builds everything into a fresh directory without the compiler cache,
# timing every compile (CPU seconds and peak memory per translation unit), then prints the slowest
# translation units, the total and the wall time (docs/benchmark.md, "Build times").
#   usage: bash scripts/build_times.sh [BUILD_DIR [JOBS [TOP]]]   (default build-times, 2, 25)
# Environment: ROLLKIN_SANITIZE=1 times the sanitizer build instead; TARGET=name builds one target only.
set -euo pipefail
if [[ ! -x /usr/bin/time ]]; then
  echo "build_times.sh: needs GNU time (/usr/bin/time): apt-get install time" >&2
  exit 2
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=${1:-build-times}
jobs=${2:-2}
top=${3:-25}
case "$dir" in /*) ;; *) dir="$root/$dir" ;; esac
log="$dir/compile_times.tsv"
rm -rf "$dir"
mkdir -p "$dir"
# The launcher: /usr/bin/time around each compiler call, one line per translation unit into $log.
launcher="$dir/time_compile.sh"
cat >"$launcher" <<LAUNCH
#!/usr/bin/env bash
out=""; prev=""
for a in "\$@"; do [ "\$prev" = "-o" ] && out=\$a; prev=\$a; done
exec /usr/bin/time -a -o "$log" -f "%U	%S	%M	\$out" "\$@"
LAUNCH
chmod +x "$launcher"
sanitize=OFF
[[ "${ROLLKIN_SANITIZE:-0}" == 1 ]] && sanitize=ON
cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DROLLKIN_SANITIZE=$sanitize -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" >/dev/null
start=$(date +%s)
if [[ -n "${TARGET:-}" ]]; then
  cmake --build "$dir" --parallel "$jobs" --target "$TARGET" >"$dir/build.log" 2>&1
else
  cmake --build "$dir" --parallel "$jobs" >"$dir/build.log" 2>&1
fi
wall=$(( $(date +%s) - start ))
echo "slowest translation units (CPU s = user + system; peak memory):"
awk -F'\t' '{printf "%8.1f s %7.0f MB  %s\n", $1 + $2, $3 / 1024, $4}' "$log" | sort -rn | head -n "$top" |
  sed "s|$dir/||; s|CMakeFiles/||; s|\.dir/|: |"
awk -F'\t' '{t += $1 + $2; n++} END {printf "total: %d translation units, %.0f CPU s (%.1f CPU min)\n", n, t, t / 60}' "$log"
echo "wall time with $jobs jobs: $wall s"
