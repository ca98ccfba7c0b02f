#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang, AddressSanitizer and UndefinedBehaviorSanitizer
# into build-fuzz/, then runs each for SECONDS (default 600), one after the other, one process each.
# FUZZ_TARGETS (names separated by spaces) runs only those.
# Corpora grow in build-fuzz/corpus/TARGET (fuzz_read_claims starts from tests/fuzz/claim_seeds and a
# recorded Voronota --link output; fuzz_read_sites from the inputs of tests/data,
# examples/ and tests/fuzz/seeds); crashing, leaking and slow inputs are kept in build-fuzz/artifacts/TARGET/.
# Exits 1 if any target found one. Reproduce one with build-fuzz/tests/fuzz/TARGET FILE; for
# fuzz_vertices, fuzz_vertex_stages and fuzz_diagram, APOLLONIUS_FUZZ_PRINT_SITES=1 also prints its sites
# as balls text.
# FUZZ_OPTIONS adds libFuzzer options to every run, e.g. FUZZ_OPTIONS="-fork=1 -ignore_timeouts=1
# -ignore_ooms=1" to fuzz on past a known slow input.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
scripts/install-deps.sh --fuzz
build_dir=build-fuzz
mkdir -p "$build_dir"
# -O2 without -DNDEBUG: CGAL's assertions stay on, among them its runtime test that interval arithmetic
# sees the rounding modes it sets (-frounding-math, from CMakeLists.txt).
cmake -S . -B "$build_dir" -DCMAKE_CXX_COMPILER=clang++ -DAPOLLONIUS_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g" > "$build_dir/cmake.log" 2>&1 || { cat "$build_dir/cmake.log"; exit 1; }
cmake --build "$build_dir" -j "$(nproc)" --target fuzz_read_sites fuzz_vertices fuzz_vertex_stages fuzz_diagram fuzz_read_claims fuzz_contacts fuzz_box_cells

corpus=$build_dir/corpus
mkdir -p "$corpus/fuzz_read_sites" "$corpus/fuzz_vertices" "$corpus/fuzz_vertex_stages" "$corpus/fuzz_diagram" "$corpus/fuzz_read_claims" "$corpus/fuzz_contacts" "$corpus/fuzz_box_cells"
cp tests/data/*.balls tests/data/vdrc/*.txt tests/data/regression/* examples/*.pdb tests/fuzz/seeds/* \
  "$corpus/fuzz_read_sites/"
cp tests/data/voronota/ANO3_3CONNECT.link.txt tests/fuzz/claim_seeds/* "$corpus/fuzz_read_claims/"

# Per target: extra libFuzzer options and the time limit per input. fuzz_vertices decodes at most 12 sites
# from about 450 bytes: one taking 2 s (the whole diagram: 20 s), sanitizers included, is a finding.
declare -A options=(
  [fuzz_read_sites]="-dict=tests/fuzz/read_sites.dict -timeout=20"
  [fuzz_vertices]="-max_len=512 -timeout=2"
  [fuzz_vertex_stages]="-max_len=512 -timeout=2"
  [fuzz_diagram]="-max_len=512 -timeout=20"
  [fuzz_read_claims]="-max_len=4096 -timeout=20"
  [fuzz_contacts]="-max_len=512 -timeout=2"
  [fuzz_box_cells]="-max_len=512 -timeout=2"
)
status=0
for target in ${FUZZ_TARGETS:-fuzz_read_sites fuzz_vertices fuzz_vertex_stages fuzz_diagram fuzz_read_claims fuzz_contacts fuzz_box_cells}; do
  artifacts=$build_dir/artifacts/$target
  mkdir -p "$artifacts"
  echo "fuzz: $target for $seconds s (log: $build_dir/$target.log)"
  # A slow input is a defect to look at, as much as a crash (-timeout, above).
  # shellcheck disable=SC2086
  if ! "$build_dir/tests/fuzz/$target" ${options[$target]} ${FUZZ_OPTIONS:-} -max_total_time="$seconds" \
      -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus/$target" > "$build_dir/$target.log" 2>&1; then
    status=1
    echo "fuzz: $target FAILED, inputs in $artifacts:"
    ls "$artifacts"
  fi
  grep "cov:" "$build_dir/$target.log" | tail -1 || true
  grep -E "stat::number_of_executed_units|^SUMMARY" "$build_dir/$target.log" || true
done
exit $status
