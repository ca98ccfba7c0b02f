#!/usr/bin/env bash
# Scaling of `apollonius3d vertices --threads 1` on generated families (issue 21): CPU time (user + sys,
# steadier than wall time on a shared machine) and peak memory at each
# size, and per site as a ratio to the uniform family at the same size (the goal: at most 2). The last
# column divides by the sites that have a vertex instead: uniform's centres fill a fixed cube, so that at
# 10,000 sites most of its balls lie inside others (hidden), while every lattice ball has a cell.
# Usage: bench/scaling.sh [BINARY (default build/apollonius3d)] [SIZES (default "1000 4000 10000")]
#        [FAMILIES (default "lattice lattice-noise far-vertices sphere-tangent two-spheres circle-tangent circle")] [TIMEOUT s (default 120)]
# A family with no vertex at all (circle-mixed, whose balls all tie along one axis) shows 0 in the last column.
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-build/apollonius3d} sizes=${2:-1000 4000 10000}
families=${3:-lattice lattice-noise far-vertices sphere-tangent two-spheres circle-tangent circle} limit=${4:-120}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() {  # family n -> "seconds peak_MiB sites_with_a_vertex" or "timeout - -"
  "$binary" generate "$1" --n "$2" --seed 7 -o "$work/in.balls"
  if /usr/bin/time -f "%U %S %M" -o "$work/time" timeout "$limit" "$binary" vertices "$work/in.balls" --threads 1 -o "$work/out" > /dev/null 2>&1; then
    # The tie sets are the fields before the last four (x y z r).
    local with_vertex
    with_vertex=$(awk '{ for (i = 1; i <= NF - 4; ++i) seen[$i] = 1 } END { print length(seen) }' "$work/out")
    awk -v v="$with_vertex" '{printf "%.2f %.1f %d\n", $1 + $2, $3 / 1024, v}' "$work/time"
  else
    echo "timeout - -"
  fi
}
printf "| family | sites | sites with a vertex | CPU s (user+sys, 1 thread) | peak MiB | time/site vs uniform | memory/site vs uniform | time per site with a vertex vs uniform |\n|---|--:|--:|--:|--:|--:|--:|--:|\n"
for n in $sizes; do
  read -r base_seconds base_memory base_visible < <(run uniform "$n")
  printf "| uniform | %d | %d | %s | %s | 1 | 1 | 1 |\n" "$n" "$base_visible" "$base_seconds" "$base_memory"
  for family in $families; do
    read -r seconds memory visible < <(run "$family" "$n")
    if [ "$seconds" = timeout ]; then
      printf "| %s | %d | - | > %s | - | - | - | - |\n" "$family" "$n" "$limit"
    else
      printf "| %s | %d | %d | %s | %s | %.2f | %.2f | %.2f |\n" "$family" "$n" "$visible" "$seconds" "$memory" \
        "$(echo "$seconds / $base_seconds" | bc -l)" "$(echo "$memory / $base_memory" | bc -l)" \
        "$(if [ "$visible" -gt 0 ]; then echo "($seconds / $visible) / ($base_seconds / $base_visible)" | bc -l; else echo 0; fi)"
    fi
  done
done
