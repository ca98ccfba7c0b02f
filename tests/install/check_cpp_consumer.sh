#!/usr/bin/env bash
# Installs the build tree into a fresh prefix, builds examples/cpp_consumer against it with find_package,
# and checks that it prints the same vertices as the apollonius3d binary. Usage: SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1 build_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$source_dir/examples/cpp_consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
printf '1 1 1 1\n1 -1 -1 1\n-1 1 -1 1\n-1 -1 1 1\n0 0 3 0.5\n' > "$work/five.balls"
"$work/prefix/bin/apollonius3d" vertices "$work/five.balls" > "$work/expected.txt"
"$work/build/cpp_consumer" > "$work/actual.txt"
[ -s "$work/expected.txt" ] || { echo "no vertices"; exit 1; }
diff "$work/expected.txt" "$work/actual.txt"
# The predicates' floating-point flags reach the consumer through the installed target.
targets=$(find "$work/prefix" -name apollonius3dTargets.cmake)
grep -q -- "-frounding-math" "$targets"
grep -q -- "-ffp-contract=off" "$targets"
echo "cpp_consumer: $(wc -l < "$work/actual.txt") vertices, equal to the binary's"
