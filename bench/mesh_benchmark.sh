#!/usr/bin/env bash
# Times `apollonius3d mesh` against `apollonius3d vertices` and `diagram` on the same input, and reports the
# mesh's size and quality: the cost of meshing against the vertices alone (docs/benchmarks.md, "Meshes").
# Usage: bench/mesh_benchmark.sh [INPUT [MESH OPTIONS...]]   (default: bench/data/pdb/1j3h.pdb)
# Env: APOLLONIUS3D (binary, default build/apollonius3d), BENCH_WORK_DIR (default bench/work/mesh).
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${APOLLONIUS3D:-build/apollonius3d}
input=${1:-bench/data/pdb/1j3h.pdb}
shift || true
work=${BENCH_WORK_DIR:-bench/work/mesh}
mkdir -p "$work"
name=$(basename "$input")
name=${name%.*}

# run LABEL COMMAND...: wall seconds (EPOCHREALTIME) and peak MiB (/usr/bin/time %M).
run() {
  local label=$1
  shift
  local start=$EPOCHREALTIME
  /usr/bin/time -f "%M" -o "$work/$name.$label.time" "$@" > "$work/$name.$label.out" 2> "$work/$name.$label.err"
  local end=$EPOCHREALTIME
  local kb
  kb=$(tail -1 "$work/$name.$label.time")
  printf '%-9s %8.2f s %7.1f MiB\n' "$label" "$(echo "$end - $start" | bc -l)" "$(echo "$kb / 1024" | bc -l)"
}

echo "input: $input   mesh options: ${*:-(defaults)}   $(nproc) cores, $(date -u +%Y-%m-%dT%H:%MZ)"
run vertices "$binary" vertices "$input" -o "$work/$name.vertices.txt"
run diagram "$binary" diagram "$input" -o "$work/$name.diagram.json"
run mesh "$binary" mesh "$input" -o "$work/$name.ply" --quality --stats "$@"
grep -E '^(points|triangles|faces_meshed|edge_samples|step|open_rims|faces_not_remeshed|remesh_abandoned|diagram|sampling|faces|cut|total) ' \
  "$work/$name.mesh.err" | paste -sd' '
echo "file: $(stat -c %s "$work/$name.ply") bytes"
cat "$work/$name.mesh.out"
