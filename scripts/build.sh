#!/usr/bin/env bash
# Installs the dependencies and builds apollonius3d and its tests into build/ (or $BUILD_DIR).
# Extra arguments go to CMake, e.g. -DAPOLLONIUS_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
build_dir=${BUILD_DIR:-build}
mkdir -p "$build_dir"
cmake -S . -B "$build_dir" "$@" > "$build_dir/cmake.log" 2>&1 || { cat "$build_dir/cmake.log"; exit 1; }
cmake --build "$build_dir" -j "$(nproc)"
