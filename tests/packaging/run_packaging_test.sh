#!/usr/bin/env bash
# Proves that an installed rollkin works for a downstream project through find_package(rollkin):
#   1. cmake --install BINARY_DIR into BINARY_DIR/pkg-install,
#   2. move the installed tree to a different directory (the package must be relocatable),
#   3. configure, build and run tests/packaging/consumer against it.
# Usage: run_packaging_test.sh SOURCE_DIR BINARY_DIR   (ctest test "packaging")
set -euo pipefail

if [[ $# -ne 2 ]]; then
  echo "usage: $0 SOURCE_DIR BINARY_DIR" >&2
  exit 2
fi
src=$(cd "$1" && pwd)
bin=$(cd "$2" && pwd)
prefix="$bin/pkg-install"
relocated="$bin/pkg-relocated"
work="$bin/pkg-consumer"

rm -rf "$prefix" "$relocated" "$work"
echo "== install into $prefix"
cmake --install "$bin" --prefix "$prefix" >"$bin/pkg-install.log"
test -f "$prefix/include/rollkin/se2.hpp"
config=$(find "$prefix" -name rollkinConfig.cmake -print -quit)
test -n "$config" || { echo "rollkinConfig.cmake was not installed" >&2; exit 1; }
targets=$(dirname "$config")/rollkinTargets.cmake
test -f "$targets" || { echo "rollkinTargets.cmake was not installed" >&2; exit 1; }

# The export must not hard-code paths of the build machine (build tree, source tree, install prefix,
# absolute library paths); dependencies are found again by rollkinConfig.cmake on the consumer's side.
if grep -n -F -e "$bin" -e "$src" -e '/libmpfr' -e '/libgmp' "$(dirname "$config")"/*.cmake; then
  echo "the installed CMake package files contain absolute paths of the build machine (above)" >&2
  exit 1
fi

echo "== relocate $prefix -> $relocated"
mv "$prefix" "$relocated"

echo "== configure consumer"
cmake_args=(-S "$src/tests/packaging/consumer" -B "$work"
  -DCMAKE_PREFIX_PATH="$relocated"
  -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON
  -DCMAKE_BUILD_TYPE=Release)
if [[ -n "${CMAKE_GENERATOR:-}" ]]; then cmake_args+=(-G "$CMAKE_GENERATOR"); fi
if [[ -n "${CXX:-}" ]]; then cmake_args+=(-DCMAKE_CXX_COMPILER="$CXX"); fi
cmake "${cmake_args[@]}"
grep -q "rollkin_DIR:PATH=$relocated" "$work/CMakeCache.txt" || {
  echo "consumer did not pick up rollkin from $relocated:" >&2
  grep rollkin_DIR "$work/CMakeCache.txt" >&2 || true
  exit 1
}

echo "== build consumer"
cmake --build "$work" --parallel 2

echo "== run consumer"
"$work/consumer"
echo "packaging test passed"
