#!/usr/bin/env bash
# Compares the outputs of two apollonius3d binaries (OLD NEW) on every bundled input and on generated inputs
# of every family: vertices as text (bytes), as JSON (content, read back as numbers), certify's exit code and
# summary, crosscheck's output. For refactorings that must not change any answer. Exits 1 on a difference.
# Usage: scripts/compare_outputs.sh OLD_BINARY NEW_BINARY [SITES_PER_GENERATED_INPUT (default 40)]
set -euo pipefail
cd "$(dirname "$0")/.."
old=$1 new=$2 n=${3:-40}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# COMPARE_INPUTS (a glob list) replaces the bundled inputs, e.g. the ones an old binary already had.
read -r -a inputs <<< "${COMPARE_INPUTS:-examples/*.pdb tests/data/*.balls tests/data/vdrc/*.txt tests/data/regression/*.balls}"
inputs=($(eval echo "${inputs[*]}"))
# The families both binaries know: a newer one may add families an old one cannot read.
for family in $(comm -12 <("$old" generate --list | awk '{print $1}' | sort) <("$new" generate --list | awk '{print $1}' | sort)); do
  for seed in 1 2 3; do
    "$new" generate "$family" --n "$n" --seed "$seed" -o "$work/$family-$seed.balls"
    inputs+=("$work/$family-$seed.balls")
  done
done
same_json() {  # the same JSON content, numbers compared as the doubles they denote
  /usr/bin/python3 -c 'import json, sys; sys.exit(json.load(open(sys.argv[1])) != json.load(open(sys.argv[2])))' "$1" "$2"
}
differences=0 compared=0
for input in "${inputs[@]}"; do
  for binary in old new; do
    b=${!binary}
    timeout 120 "$b" vertices "$input" > "$work/$binary.txt" 2> /dev/null || echo "exit $?" >> "$work/$binary.txt"
    timeout 120 "$b" vertices "$input" --format json > "$work/$binary.json" 2> /dev/null || true
    timeout 120 "$b" crosscheck "$input" > "$work/$binary.cross" 2> "$work/$binary.cross.err" || echo "exit $?" >> "$work/$binary.cross"
    timeout 120 "$b" certify "$input" "$work/old.txt" > /dev/null 2> "$work/$binary.certify" || echo "exit $?" >> "$work/$binary.certify"
  done
  for what in txt cross cross.err certify; do
    cmp -s "$work/old.$what" "$work/new.$what" || { echo "differs: $what of $input"; differences=$((differences + 1)); }
  done
  same_json "$work/old.json" "$work/new.json" || { echo "differs: json of $input"; differences=$((differences + 1)); }
  compared=$((compared + 1))
done
echo "compare_outputs: $compared inputs, $differences differences"
[ "$differences" -eq 0 ]
