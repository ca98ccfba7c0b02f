#!/usr/bin/env bash
# Where the lifted triangulation beats the octree (Octree_options::lifted_at_most_sites, the size below
# which `vertices --algorithm auto` takes it at once): `vertices --threads 1 --algorithm octree` against
# `--algorithm lifted` on generated families and on the first N atoms of 1j3h, and `voronota
# calculate-vertices` on the same balls. Wall milliseconds, process start included, median of REPEAT
# interleaved runs; the ratio is octree / lifted (above 1: lifted is faster). Both write the same bytes,
# which the script checks. Voronota's column says "failed" where it crashed (wide-range) or passed
# VORONOTA_TIME_LIMIT seconds (default 20).
# Usage: bench/lifted_crossover.sh [BINARY (default build/apollonius3d)] [SIZES (default "20 50 128 256 512")]
#        [FAMILIES (default "uniform lattice lattice-noise far-vertices wide-range sphere-tangent two-spheres
#        circle-tangent circle circle-mixed shells protein")] [REPEAT (default 5)]
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-build/apollonius3d} sizes=${2:-20 50 128 256 512} repeat=${4:-5}
families=${3:-uniform lattice lattice-noise far-vertices wide-range sphere-tangent two-spheres circle-tangent circle circle-mixed shells protein}
voronota=${VORONOTA:-voronota} voronota_limit=${VORONOTA_TIME_LIMIT:-20}  # s per run: it runs for minutes on tangent balls
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
protein="$work/1j3h.balls"
[ -x "$binary" ] || { echo "no binary $binary (scripts/build.sh)" >&2; exit 2; }
# Voronota's radii, as bench/run_benchmark.sh takes them; the first N atoms of the chain.
"$voronota" get-balls-from-atoms-file < bench/data/pdb/1j3h.pdb | awk '{print $1, $2, $3, $4}' > "$protein"
milliseconds() {  # command... -> wall ms of one run, or "failed" (Voronota crashes on wide-range)
  local start=$EPOCHREALTIME status=0
  "$@" > /dev/null 2>&1 || status=$?
  local end=$EPOCHREALTIME
  if [ "$status" -ne 0 ]; then echo failed; else echo "$(( (${end/./} - ${start/./}) / 1000 ))"; fi
}
median() { sort -n | awk '$1 == "failed" {failed = 1} {a[NR] = $1} END {print failed ? "failed" : a[int((NR + 1) / 2)]}'; }
printf "| family | sites | octree ms | lifted ms | octree / lifted | voronota ms |\n|---|--:|--:|--:|--:|--:|\n"
for family in $families; do
  for n in $sizes; do
    input="$work/in.balls"
    if [ "$family" = protein ]; then head -n "$n" "$protein" > "$input"
    else "$binary" generate "$family" --n "$n" --seed 3 -o "$input"; fi
    "$binary" vertices "$input" --threads 1 --algorithm octree -o "$work/octree.txt"
    "$binary" vertices "$input" --threads 1 --algorithm lifted -o "$work/lifted.txt"
    cmp -s "$work/octree.txt" "$work/lifted.txt" || { echo "octree and lifted differ on $family $n" >&2; exit 1; }
    : > "$work/o"; : > "$work/l"; : > "$work/v"
    for _ in $(seq "$repeat"); do
      milliseconds "$binary" vertices "$input" --threads 1 --algorithm octree -o /dev/null >> "$work/o"
      milliseconds "$binary" vertices "$input" --threads 1 --algorithm lifted -o /dev/null >> "$work/l"
      milliseconds timeout "$voronota_limit" sh -c "'$voronota' calculate-vertices < '$input'" >> "$work/v"
    done
    o=$(median < "$work/o") l=$(median < "$work/l") v=$(median < "$work/v")
    printf "| %s | %d | %d | %d | %.2f | %s |\n" "$family" "$n" "$o" "$l" "$(echo "$o / ($l + 0.0001)" | bc -l)" "$v"
  done
done
