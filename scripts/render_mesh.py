#!/usr/bin/python3
"""Renders an apollonius3d mesh (PLY, binary or ASCII, or OBJ) to a PNG, one colour per cell.

Each face triangle is drawn in the colour of one of its two cells (the first one listed by --cells, else
site_a); box walls are left out unless --walls. Lambert shading along the view direction shows the shape.
Run with Debian's python3 (python3-matplotlib): /usr/bin/python3 scripts/render_mesh.py MESH -o OUT.png
"""
import argparse
import re
import struct
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402


def read_ply(path):
    with open(path, "rb") as f:
        if f.readline().strip() != b"ply":
            raise ValueError(f"{path}: not a PLY file")
        binary, vertices, faces = False, 0, 0
        while True:
            line = f.readline()
            if not line:
                raise ValueError(f"{path}: no end_header")
            words = line.split()
            if words[:1] == [b"format"]:
                binary = words[1] == b"binary_little_endian"
            elif words[:2] == [b"element", b"vertex"]:
                vertices = int(words[2])
            elif words[:2] == [b"element", b"face"]:
                faces = int(words[2])
            elif words[:1] == [b"end_header"]:
                break
        if binary:
            points = np.frombuffer(f.read(24 * vertices), dtype="<f8").reshape(vertices, 3)
            record = np.dtype([("n", "u1"), ("v", "<i4", 3), ("a", "<i4"), ("b", "<i4"), ("id", "<i4")])
            rows = np.frombuffer(f.read(record.itemsize * faces), dtype=record)
            return points, rows["v"], rows["a"], rows["b"]
        text = f.read().split()
        numbers = np.array(text[: 3 * vertices], dtype=float).reshape(vertices, 3)
        rows = np.array(text[3 * vertices: 3 * vertices + 7 * faces], dtype=np.int64).reshape(faces, 7)
        return numbers, rows[:, 1:4], rows[:, 4], rows[:, 5]


def read_obj(path):
    points, triangles, site_a, site_b = [], [], [], []
    a = b = -1
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                points.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("o "):
                face = re.match(r"o face_(-?\d+)_(\d+)_(\d+)", line)
                wall = re.match(r"o wall_(\d+)_(\d+)", line)
                if face:
                    a, b = int(face.group(2)), int(face.group(3))
                elif wall:
                    a, b = -1 - int(wall.group(1)), int(wall.group(2))
            elif line.startswith("f "):
                triangles.append([int(x.split("/")[0]) - 1 for x in line.split()[1:4]])
                site_a.append(a)
                site_b.append(b)
    return np.array(points), np.array(triangles), np.array(site_a), np.array(site_b)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", help="PLY or OBJ written by apollonius3d mesh")
    parser.add_argument("-o", "--output", required=True, help="the PNG to write")
    parser.add_argument("--size", type=int, nargs=2, default=[800, 800], metavar=("W", "H"), help="pixels")
    parser.add_argument("--cells", type=lambda s: [int(x) for x in s.split(",")], default=None,
                        help="only the faces of these cells, coloured by them (e.g. 3,7,12)")
    parser.add_argument("--walls", action="store_true", help="draw the box walls too")
    parser.add_argument("--elev", type=float, default=25, help="view elevation, degrees")
    parser.add_argument("--azim", type=float, default=-60, help="view azimuth, degrees")
    parser.add_argument("--explode", type=float, default=0,
                        help="draws each cell apart, moved away from the centre by this fraction of its offset")
    parser.add_argument("--edges", action="store_true",
                        help="draws the diagram's edges: where two triangles of different faces meet")
    parser.add_argument("--colour", choices=["cell", "face"], default="cell",
                        help="one colour per cell (default), or per face (pair of sites)")
    parser.add_argument("--title", default=None)
    args = parser.parse_args(argv)

    reader = read_obj if args.mesh.endswith(".obj") else read_ply
    points, triangles, site_a, site_b = reader(args.mesh)
    keep = np.ones(len(triangles), dtype=bool) if args.walls else site_a >= 0
    owner = np.where(site_a >= 0, site_a, site_b)
    if args.cells is not None:
        chosen = np.array(args.cells)
        in_a, in_b = np.isin(site_a, chosen), np.isin(site_b, chosen)
        keep &= in_a | in_b
        owner = np.where(in_a, site_a, site_b)
    lines = []
    if args.edges:
        pair = {}
        for t, a, b in zip(triangles[keep], site_a[keep], site_b[keep]):
            for k in range(3):
                edge = (min(t[k], t[(k + 1) % 3]), max(t[k], t[(k + 1) % 3]))
                pair.setdefault(edge, set()).add((a, b))
        lines = [points[list(e)] for e, pairs in pair.items() if len(pairs) > 1]
    if args.explode > 0:
        # Every cell on its own (a face shared by two cells drawn for each), moved apart.
        cells = args.cells if args.cells is not None else sorted(set(site_a[site_a >= 0]) | set(site_b))
        pieces, owners = [], []
        for c in cells:
            mine = keep & ((site_a == c) | (site_b == c))
            pieces.append(points[triangles[mine]])
            owners.append(np.full(int(mine.sum()), c))
        centres = [p.reshape(-1, 3).mean(axis=0) for p in pieces if len(p)]
        middle = np.mean(centres, axis=0) if centres else np.zeros(3)
        for k, p in enumerate(pieces):
            if len(p):
                pieces[k] = p + args.explode * (p.reshape(-1, 3).mean(axis=0) - middle)
        corners, owner = np.concatenate(pieces), np.concatenate(owners)
    else:
        corners, owner = points[triangles[keep]], owner[keep]
    if len(corners) == 0:
        raise SystemExit("render_mesh: no triangle to draw")

    cells = np.unique(owner)
    palette = plt.get_cmap("tab20")
    if args.colour == "face":
        # Faces are told apart by their pair; owner then carries the pair's index.
        kept = keep if args.explode == 0 else None
        if kept is None:
            raise SystemExit("render_mesh: --colour face draws the faces once: not with --explode")
        pairs = site_a[kept].astype(np.int64) * (1 << 32) + site_b[kept].astype(np.int64)
        owner = np.unique(pairs, return_inverse=True)[1]
    colour_of = {c: np.array(palette(k % 20)[:3]) for k, c in enumerate(np.unique(owner))}
    colours = np.array([colour_of[c] for c in owner])
    elev, azim = np.radians(args.elev), np.radians(args.azim)
    view = np.array([np.cos(elev) * np.cos(azim), np.cos(elev) * np.sin(azim), np.sin(elev)])
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    lengths[lengths == 0] = 1
    shade = 0.35 + 0.65 * np.abs(normals @ view) / lengths
    colours = colours * shade[:, None]

    width, height = args.size
    figure = plt.figure(figsize=(width / 100, height / 100), dpi=100)
    axes = figure.add_subplot(projection="3d")
    axes.add_collection3d(Poly3DCollection(corners, facecolors=colours, edgecolors=(0, 0, 0, 0.25), linewidths=0.1))
    if lines and args.explode == 0:
        axes.add_collection3d(Line3DCollection(lines, colors="black", linewidths=1.2))
    low, high = corners.reshape(-1, 3).min(axis=0), corners.reshape(-1, 3).max(axis=0)
    middle, half = (low + high) / 2, (high - low).max() / 2
    for setter, m in zip((axes.set_xlim, axes.set_ylim, axes.set_zlim), middle):
        setter(m - half, m + half)
    axes.set_box_aspect((1, 1, 1), zoom=1.15)
    axes.view_init(elev=args.elev, azim=args.azim)
    axes.set_axis_off()
    if args.title:
        axes.set_title(args.title)
    figure.subplots_adjust(left=0, right=1, bottom=0, top=1)
    figure.savefig(args.output, dpi=100)
    print(f"render_mesh: {len(corners)} triangles of {len(cells)} cells -> {args.output}")


if __name__ == "__main__":
    main(sys.argv[1:])
