#!/usr/bin/env bash
# README command 1 or 2 on a fresh Debian 12 machine, phase by phase (docs/benchmark.md, "Build times").
# Copies a base root file system made by debootstrap (a "new machine": Debian 12 with g++, cmake, make, git and
# python3, no package of the project), clones this repository's HEAD into it, runs the README command there
# in a chroot and prints the wall time of each phase: apt-get update, the packages' download and their
# installation, CMake's configure, the build, and the command's run (the example, or ctest).
#   usage (root): bash scripts/fresh_machine.sh BASE_ROOT [cli|all] [--packages-only] [--keep]
#     cli              README command 1 (default); all: README command 2
#     --packages-only  stop when the packages are installed (before CMake's configure)
#     --keep           keep the copy (printed) instead of removing it
# Making a base root (once; about 2 minutes and 700 MB):
#   debootstrap --variant=minbase bookworm BASE http://deb.debian.org/debian
#   cp /etc/apt/sources.list.d/debian.sources BASE/etc/apt/sources.list.d/ && rm BASE/etc/apt/sources.list
#   cp /etc/resolv.conf BASE/etc/ && chroot BASE apt-get update
#   chroot BASE apt-get install -y g++ cmake make git python3 ca-certificates
#   chroot BASE apt-get clean && rm -rf BASE/var/lib/apt/lists/*     (so that every run downloads anew)
# Only a measuring tool: neither CI nor the tests use it. Only the committed HEAD is cloned.
set -euo pipefail

usage() { sed -n '7,10p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2; exit 2; }
[[ $# -ge 1 ]] || usage
base=${1%/}; shift
what=cli; packages_only=0; keep=0
for a in "$@"; do
  case "$a" in
    cli|all) what=$a ;;
    --packages-only) packages_only=1 ;;
    --keep) keep=1 ;;
    *) usage ;;
  esac
done
[[ $(id -u) -eq 0 ]] || { echo "fresh_machine.sh: chroot needs root" >&2; exit 1; }
[[ -x "$base/usr/bin/apt-get" && -x "$base/usr/bin/g++" ]] ||
  { echo "fresh_machine.sh: $base is not a Debian root with g++ (see the comment at the top)" >&2; exit 1; }
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# The README's command, as the README writes it (its "Set-up: two commands").
if [[ "$what" == cli ]]; then pattern='^ *bash scripts/setup.sh cli &&'; else pattern='^ *bash scripts/setup.sh &&'; fi
command=$(grep -m1 -E "$pattern" "$root/README.md" | sed 's/^ *//')
[[ -n "$command" ]] || { echo "fresh_machine.sh: no line matching '$pattern' in README.md" >&2; exit 1; }

copy="$base.run-$what-$$"
mounted=()
cleanup() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -R "${mounted[i]}" 2>/dev/null || umount -l "${mounted[i]}" || true; done
  if [[ $keep == 1 ]]; then echo "kept: $copy" >&2; return; fi
  if grep -q " $copy/" /proc/mounts; then echo "fresh_machine.sh: $copy still has mounts; not removing it" >&2; return; fi
  rm -rf --one-file-system "$copy"
}
trap cleanup EXIT
echo "copying $base to $copy" >&2
cp -a "$base" "$copy"
git clone -q "$root" "$copy/root/rollkin"
mount -t proc proc "$copy/proc" && mounted+=("$copy/proc")
mount --rbind /dev "$copy/dev" && mount --make-rslave "$copy/dev" && mounted+=("$copy/dev")
mount -t sysfs sysfs "$copy/sys" && mounted+=("$copy/sys")
cp /etc/resolv.conf "$copy/etc/resolv.conf"
# The copy's dirty pages to disk first: else dpkg's first fsyncs wait for them (ext4 commits them together).
sync

# Every output line, stamped with the wall clock when it arrives.
log="$copy.log"
stamp() { while IFS= read -r line; do printf '%s %s\n' "$EPOCHREALTIME" "$line"; done; }
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
echo "running in $copy: $command" >&2
t0=$EPOCHREALTIME
setsid chroot "$copy" env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
  LANG=C.UTF-8 bash -c "cd /root/rollkin && $command" > >(stamp | tee "$log" | cut -d' ' -f2- >&2) 2>&1 &
pid=$!
if [[ $packages_only == 1 ]]; then
  while kill -0 "$pid" 2>/dev/null; do
    if grep -q '\[setup\] configuring' "$log" 2>/dev/null; then kill -- "-$pid" 2>/dev/null || true; break; fi
    sleep 0.2
  done
fi
rc=0; wait "$pid" || rc=$?
t_end=$EPOCHREALTIME
sleep 0.5  # the stamping reader's last lines

# Phase boundaries from the lines of scripts/setup.sh and apt-get.
at() { grep -m"${2:-1}" -E "^[0-9.]+ $1" "$log" | tail -1 | cut -d" " -f1 || true; }
after() { awk -v t="$2" -v re="^$1" '$1 > t { s = $0; sub(/^[^ ]+ /, "", s); if (s ~ re) { print $1; exit } }' "$log"; }
t_apt=$(at '\[setup\] (installing missing packages|all build packages)')
t_install=$(at 'Reading package lists' 2)   # the second one: apt-get install starts
t_fetched=$(after 'Fetched ' "${t_install:-0}")  # apt-get install's: the packages are downloaded
t_configure=$(at '\[setup\] configuring')
t_build=$(at '\[setup\] building')
t_done=$(at '\[setup\] done')
need=$(grep -m1 -oE 'Need to get [^ ]+ [kMG]?B' "$log" || true)
count=$(grep -m1 -oE '[0-9]+ newly installed' "$log" || true)

span() { [[ -n "$1" && -n "$2" ]] && awk -v a="$1" -v b="$2" 'BEGIN { printf "%8.1f s", b - a }' || echo "       -"; }
echo
echo "fresh Debian 12 root, README command $([[ $what == cli ]] && echo 1 || echo 2), $(nproc) cores, load before: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-46s %s\n' "phase" "wall"
printf '%-46s %s\n' "apt-get update" "$(span "$t_apt" "$t_install")"
printf '%-46s %s\n' "packages: resolve + download (${need#Need to get })" "$(span "$t_install" "$t_fetched")"
printf '%-46s %s\n' "packages: unpack + set up (${count:-?})" "$(span "$t_fetched" "$t_configure")"
if [[ $packages_only == 0 ]]; then
  printf '%-46s %s\n' "CMake configure" "$(span "$t_configure" "$t_build")"
  printf '%-46s %s\n' "build" "$(span "$t_build" "$t_done")"
  printf '%-46s %s\n' "run ($([[ $what == cli ]] && echo example || echo ctest))" "$(span "$t_done" "$t_end")"
fi
printf '%-46s %s\n' "total" "$(span "$t0" "$t_end")"
echo "log: $log"
if [[ $packages_only == 0 ]]; then exit "$rc"; fi
[[ -n "$t_configure" ]] || { echo "fresh_machine.sh: the packages step did not finish (exit $rc)" >&2; exit 1; }
