#!/usr/bin/env bash
# fuzz-smoke: runs every file of tests/fuzz/corpus/<area>/ once through fuzz_<area> (libFuzzer replays files
# given as arguments, without mutating them). Any crash, sanitizer report or undocumented exception fails.
# Usage: replay_corpora.sh HARNESS_DIR CORPUS_DIR fuzz_scene fuzz_point_file ...
set -euo pipefail
harness_dir=$1
corpus_dir=$2
shift 2
failed=0
for harness in "$@"; do
  area=${harness#fuzz_}
  mapfile -t files < <(find "$corpus_dir/$area" -type f | sort)
  if [[ ${#files[@]} -eq 0 ]]; then
    echo "FAIL $harness: no corpus files in $corpus_dir/$area"
    failed=1
    continue
  fi
  if "$harness_dir/$harness" -runs=1 "${files[@]}" >"$harness_dir/$harness.replay.log" 2>&1; then
    echo "ok   $harness: ${#files[@]} corpus files"
  else
    echo "FAIL $harness (log: $harness_dir/$harness.replay.log):"
    tail -n 40 "$harness_dir/$harness.replay.log"
    failed=1
  fi
done
exit $failed
