#!/usr/bin/env bash
# Small inputs (issue 20: at most 50 sites in at most 50 ms): `apollonius3d vertices --threads 1` on every
# bundled, regression and open input of at most MAX_SITES sites, wall time (the best of REPEAT runs: startup
# included, as a user sees it) and the octree's box count, slowest first. Exits 1 if any is over LIMIT ms.
# Usage: bench/small_inputs.sh [BINARY (default build/apollonius3d)] [LIMIT ms (default 50)]
#        [MAX_SITES (default 50)] [REPEAT (default 3)] [TIMEOUT s per run (default 120)]
set -euo pipefail
cd "$(dirname "$0")/.."
binary=${1:-build/apollonius3d} limit=${2:-50} max_sites=${3:-50} repeat=${4:-3} timeout_s=${5:-120}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for input in tests/data/*.balls tests/data/regression/*.balls tests/data/open/*.balls; do
  [ -e "$input" ] || continue
  sites=$(grep -cv '^#' "$input" || true)
  [ "$sites" -le "$max_sites" ] || continue
  best=""
  for _ in $(seq "$repeat"); do
    if /usr/bin/time -f "%e" -o "$work/time" timeout "$timeout_s" "$binary" vertices "$input" --threads 1 \
        -o /dev/null > /dev/null 2>&1; then
      ms=$(awk '{printf "%d", $1 * 1000}' "$work/time")
    else
      ms=$((timeout_s * 1000))
    fi
    if [ -z "$best" ] || [ "$ms" -lt "$best" ]; then best=$ms; fi
  done
  boxes=$(timeout "$timeout_s" "$binary" vertices "$input" --threads 1 -o /dev/null --stats 2>&1 | awk '$1 == "boxes" {print $2}')
  echo "$best $sites ${boxes:--} $(basename "$input")"
done | sort -rn > "$work/table"
printf "| ms (best of %d) | sites | boxes | input |\n|--:|--:|--:|---|\n" "$repeat"
awk '{printf "| %s | %s | %s | %s |\n", $1, $2, $3, $4}' "$work/table"
over=$(awk -v limit="$limit" '$1 > limit' "$work/table" | wc -l)
echo
echo "$over of $(wc -l < "$work/table") inputs of at most $max_sites sites over $limit ms"
[ "$over" -eq 0 ]
