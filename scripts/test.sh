#!/usr/bin/env bash
# Installs, builds, and runs the whole test suite with ctest: the doctest programs and the Python module's
# pytest suite (python/pytest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
cd "${BUILD_DIR:-build}"
# install-deps.sh installed what the module needs: a suite without it would test less than it says (but
# sanitizer and fuzz builds leave the module out, and -DAPOLLONIUS_PYTHON=OFF asks to).
if ! grep -qE "^APOLLONIUS_(SANITIZE|FUZZ):BOOL=ON|^APOLLONIUS_PYTHON:BOOL=OFF" CMakeCache.txt; then
  listed=$(ctest -N)  # not piped into grep -q, which would stop ctest early and fail the pipe
  grep -q "python/pytest" <<< "$listed" || { echo "test: the Python module was not built (see cmake.log)"; exit 1; }
fi
ctest -j "$(nproc)" --output-on-failure
