#!/usr/bin/env bash
# `apollonius3d contacts` against `voronota calculate-contacts` on the same balls (Voronota's radii, from
# get-balls-from-atoms-file): time and peak memory of each (median of R runs, interleaved), the Pearson r
# of the contact areas and of the SAS over the union of both sides' pairs (a pair one side lacks counts
# as 0 there), and every pair that one side has and the other lacks, with its area.
# Usage: bench/contacts_vs_voronota.sh [INPUTS (default "pept 1hpv 1j3h")] [R (default 3)] [THREADS (default 1)]
set -euo pipefail
cd "$(dirname "$0")/.."
inputs=${1:-pept 1hpv 1j3h} repeat=${2:-3} threads=${3:-1}
binary=${APOLLONIUS3D:-build/apollonius3d}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pdb() { case $1 in pept) echo examples/pept.pdb ;; *) echo "bench/data/pdb/$1.pdb" ;; esac; }
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
printf "| input | balls | apollonius3d s | Voronota s | ratio | apollonius3d MiB | Voronota MiB | contacts r | SAS r | only ours | only Voronota |\n"
printf "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n"
for input in $inputs; do
  voronota get-balls-from-atoms-file < "$(pdb "$input")" > "$work/$input.annotated"
  cut -d'#' -f1 "$work/$input.annotated" > "$work/$input.balls"
  : > "$work/ours.times"; : > "$work/theirs.times"
  for _ in $(seq "$repeat"); do
    /usr/bin/time -f "%e %M" -a -o "$work/ours.times" "$binary" contacts "$work/$input.balls" --threads "$threads" -o "$work/ours.txt"
    /usr/bin/time -f "%e %M" -a -o "$work/theirs.times" voronota calculate-contacts < "$work/$input.balls" > "$work/theirs.txt"
  done
  ours_s=$(cut -d' ' -f1 "$work/ours.times" | median) theirs_s=$(cut -d' ' -f1 "$work/theirs.times" | median)
  ours_m=$(cut -d' ' -f2 "$work/ours.times" | median) theirs_m=$(cut -d' ' -f2 "$work/theirs.times" | median)
  read -r r_contacts r_sas only_ours only_theirs < <(/usr/bin/python3 - "$work/ours.txt" "$work/theirs.txt" "$work/$input.diff" <<'PY'
import sys
import numpy as np
def read(path):
    pairs = {}
    for line in open(path):
        a, b, area = line.split()[:3]
        if not b.startswith("c"):
            pairs[int(a), int(b)] = float(area)
    return pairs
ours, theirs = read(sys.argv[1]), read(sys.argv[2])
keys = sorted(set(ours) | set(theirs))
r = []
for same in (False, True):
    chosen = [k for k in keys if (k[0] == k[1]) == same]
    x = np.array([ours.get(k, 0.0) for k in chosen]); y = np.array([theirs.get(k, 0.0) for k in chosen])
    r.append(np.corrcoef(x, y)[0, 1])
with open(sys.argv[3], "w") as out:
    for k in keys:
        if (k in ours) != (k in theirs):
            out.write(f"{'ours' if k in ours else 'voronota'} {k[0]} {k[1]} {ours.get(k, theirs.get(k))!r}\n")
print(f"{r[0]:.7f} {r[1]:.7f} {sum(k not in theirs for k in ours)} {sum(k not in ours for k in theirs)}")
PY
)
  printf "| %s | %d | %s | %s | %.2f | %.1f | %.1f | %s | %s | %s | %s |\n" "$input" "$(wc -l < "$work/$input.balls")" \
    "$ours_s" "$theirs_s" "$(echo "$ours_s / $theirs_s" | bc -l)" "$(echo "$ours_m / 1024" | bc -l)" \
    "$(echo "$theirs_m / 1024" | bc -l)" "$r_contacts" "$r_sas" "$only_ours" "$only_theirs"
  sed "s/^/    $input: /" "$work/$input.diff" >&2
done
