#!/usr/bin/env bash
# One-step set-up shared by the README commands and CI (.ci/run):
#   1. install the Debian 12 packages the build needs, only those missing (apt-get as root, else sudo);
#   2. configure with CMake into build/ (Release);
#   3. build everything (library, command-line tool build/rollkin, tests) with -j2.
# Run from anywhere:  bash scripts/setup.sh        everything, with the packages the tests use
#                     bash scripts/setup.sh cli    only the command-line tool build/rollkin and what it needs
#                                                  (README command 1: the quickest first run)
# Environment: ROLLKIN_BUILD_DIR (default build), ROLLKIN_JOBS (default 2), ROLLKIN_BUILD_TYPE (default
# Release), ROLLKIN_SKIP_APT=1 to never call apt-get (e.g. on a non-Debian system with the libraries present).
# ROLLKIN_SANITIZE=1 configures the AddressSanitizer/UBSan build (CMake option ROLLKIN_SANITIZE; .ci/run uses it
# with ROLLKIN_BUILD_DIR=build-asan).
set -euo pipefail

what=${1:-all}
if [[ "$what" != all && "$what" != cli ]]; then
  echo "[setup] error: unknown argument \"$what\"; expected nothing (build everything) or \"cli\" (only build/rollkin)" >&2
  exit 2
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
build_dir=${ROLLKIN_BUILD_DIR:-build}
jobs=${ROLLKIN_JOBS:-2}
build_type=${ROLLKIN_BUILD_TYPE:-Release}

log() { echo "[setup] $*" >&2; }

# ---- 1. packages ---------------------------------------------------------------------------------------
# Compiler and build tools, then the libraries (headers + CMake package files): Eigen 3.4, Boost 1.74 headers
# and Boost.Test, CGAL 5.5 (header-only), GMP and MPFR, nlohmann/json; libdxflib (DXF) and pugixml (SVG/XML)
# readers; CLI11 (command-line parsing of build/rollkin and the benchmark); SuiteSparse (KLU, the sparse LU of
# large mechanisms; optional for the build). For the tests only: ezdxf (with mpmath for its bulge arcs in
# 60 digits) and svgelements, independent producers and readers of the CAD test files; chromium, its driver and selenium for
# the browser test of the --animate page (tests/browser/test_animation.py).
packages=(
  g++ cmake make ccache
  libeigen3-dev libboost-dev libboost-test-dev libcgal-dev libgmp-dev libmpfr-dev nlohmann-json3-dev
  libdxflib-dev libpugixml-dev libcli11-dev
  libsuitesparse-dev
  python3
)
if [[ "$what" == all ]]; then
  packages+=(python3-ezdxf python3-mpmath python3-svgelements chromium chromium-driver python3-selenium)
  packages+=(pybind11-dev python3-pybind11 python3-numpy python3-pytest)  # the Python module and its test
  packages+=(python3-scipy python3-distributed python3-matplotlib)  # examples/python (fit_profile.py, design_study.py), tested
fi

installed() { dpkg -s "$1" 2>/dev/null | grep -q '^Status: install ok installed'; }

if [[ "${ROLLKIN_SKIP_APT:-0}" == 1 ]]; then
  log "ROLLKIN_SKIP_APT=1: not checking packages"
elif ! command -v dpkg >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  log "no dpkg/apt-get (not Debian?): not installing packages, the build needs: ${packages[*]}"
else
  missing=()
  for p in "${packages[@]}"; do
    installed "$p" || missing+=("$p")
  done
  if [[ ${#missing[@]} -eq 0 ]]; then
    log "all build packages are installed"
  else
    log "installing missing packages: ${missing[*]}"
    if [[ $(id -u) -eq 0 ]]; then
      as_root=(env DEBIAN_FRONTEND=noninteractive)
    elif command -v sudo >/dev/null 2>&1; then
      as_root=(sudo env DEBIAN_FRONTEND=noninteractive)
    else
      log "error: not root and sudo is not available; install as root: apt-get install ${missing[*]}"
      exit 1
    fi
    "${as_root[@]}" apt-get update
    # --force-unsafe-io: dpkg does not fsync every file it unpacks (as in Debian's build chroots and container
    # images). Measured on a fresh Debian 12 root (docs/benchmark.md, "Build times"): libboost1.74-dev alone
    # is 15,000 files, whose fsyncs were most of the install's time.
    "${as_root[@]}" apt-get install -y --no-install-recommends -o Dpkg::Options::=--force-unsafe-io "${missing[@]}"
    for p in "${missing[@]}"; do
      installed "$p" || { log "error: package $p is still not installed"; exit 1; }
    done
  fi
fi

# ---- 2. configure --------------------------------------------------------------------------------------
log "configuring $build_type build in $root/$build_dir"
sanitize=OFF
if [[ "${ROLLKIN_SANITIZE:-0}" == 1 ]]; then sanitize=ON; fi
# The compiler cache (ccache, installed above): a rebuild after a change, a second build directory or a fresh
# clone in another folder compiles only what changed. CCACHE_BASEDIR makes the cached compile commands relative
# to the repository, and CCACHE_NOHASHDIR leaves the build directory out of the key of the sanitizer build's
# -g1 objects, so clones in different folders share the cache; CCACHE_SLOPPINESS lets it cache the files that
# include the precompiled header (src/precompiled.hpp; docs/benchmark.md, "Build times").
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=("-DCMAKE_CXX_COMPILER_LAUNCHER=env;CCACHE_BASEDIR=$root;CCACHE_NOHASHDIR=1;CCACHE_SLOPPINESS=pch_defines,time_macros;ccache")
  ccache --max-size=20G >/dev/null 2>&1 || true
fi
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE="$build_type" -DROLLKIN_SANITIZE="$sanitize" "${launcher[@]}"

# ---- 3. build ------------------------------------------------------------------------------------------
if [[ "$what" == cli ]]; then
  log "building the command-line tool only (rollkin_cli) with $jobs jobs"
  cmake --build "$build_dir" --parallel "$jobs" --target rollkin_cli
else
  log "building with $jobs jobs"
  cmake --build "$build_dir" --parallel "$jobs"
fi

# Output directory of the README's example command (the writers do not create directories).
mkdir -p "$root/out"
log "done: $root/$build_dir"
