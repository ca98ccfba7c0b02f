#!/usr/bin/env bash
# Installs, builds, and computes the exact Apollonius vertices of the bundled peptide (examples/pept.pdb).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh > /dev/null
build/apollonius3d vertices examples/pept.pdb -o pept.vertices.txt --stats
echo "wrote $(wc -l < pept.vertices.txt) vertices of examples/pept.pdb to pept.vertices.txt" \
     "(one line each: tie-set site indices, then x y z r)"
