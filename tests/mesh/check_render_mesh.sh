#!/usr/bin/env bash
# scripts/render_mesh.py on a mesh of the binary (PLY binary, PLY ASCII, OBJ): each writes a PNG of the
# size asked for (read from its IHDR chunk). Usage: check_render_mesh.sh SOURCE_DIR BINARY
set -euo pipefail
source_dir=$1
binary=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
printf '0 0 0 1\n3 0 0 1.2\n0 3 0 0.8\n0 0 3 1\n1.5 1.5 1.5 0.5\n' > "$scratch/balls.txt"
"$binary" mesh "$scratch/balls.txt" -o "$scratch/m.ply" --lloyd 2
"$binary" mesh "$scratch/balls.txt" -o "$scratch/a.ply" --lloyd 2 --ascii --sites 4
"$binary" mesh "$scratch/balls.txt" -o "$scratch/m.obj" --lloyd 2
for mesh in m.ply a.ply m.obj; do
  /usr/bin/python3 "$source_dir/scripts/render_mesh.py" "$scratch/$mesh" -o "$scratch/$mesh.png" --size 320 240 --cells 0,4
  size=$(/usr/bin/python3 -c "
import struct, sys
data = open(sys.argv[1], 'rb').read(24)
assert data[:8] == b'\x89PNG\r\n\x1a\n' and data[12:16] == b'IHDR', 'not a PNG'
print(*struct.unpack('>II', data[16:24]))" "$scratch/$mesh.png")
  if [ "$size" != "320 240" ]; then
    echo "check_render_mesh: $mesh.png is $size, not 320 240" >&2
    exit 1
  fi
done
# A mesh file that is not one: a message and a failure.
echo "not a mesh" > "$scratch/bad.ply"
if /usr/bin/python3 "$source_dir/scripts/render_mesh.py" "$scratch/bad.ply" -o "$scratch/bad.png" 2>/dev/null; then
  echo "check_render_mesh: a bad file was rendered" >&2
  exit 1
fi
echo "check_render_mesh: ok"
