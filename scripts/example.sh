#!/usr/bin/env bash
# Installs, builds, and computes the exact Apollonius vertices of the bundled peptide (examples/pept.pdb);
# then installs the Python module from that build for Debian's python3 (python/README.md).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh > /dev/null
build/apollonius3d vertices examples/pept.pdb -o pept.vertices.txt --stats
echo "wrote $(wc -l < pept.vertices.txt) vertices of examples/pept.pdb to pept.vertices.txt" \
     "(one line each: tie-set site indices, then x y z r)"
# pip asks no index (--no-index: numpy is Debian's) and builds nothing new (the module is in build/).
# Debian 12's pip installs outside apt, into /usr/local, only with --break-system-packages.
APOLLONIUS3D_CMAKE_BUILD_DIR=build /usr/bin/python3 -m pip install --quiet --no-build-isolation --no-index \
  --break-system-packages --root-user-action=ignore . > /dev/null
/usr/bin/python3 -c 'import apollonius3d; print("python3: import apollonius3d", apollonius3d.__version__, "from", apollonius3d.__file__)'
