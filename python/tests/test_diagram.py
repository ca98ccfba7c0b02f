"""diagram(): the command line's 'diagram' JSON, bit for bit and id for id, on the bundled inputs."""
import json
import time

import numpy as np
import pytest

import apollonius3d
from conftest import (BUNDLED_INPUTS, REPOSITORY, assert_same_doubles, cli_error_message, json_double,
                      run_cli)

# Left out: the bundled inputs whose whole diagram takes more than a few seconds here (the proteins, of
# 1,631 and 4,924 atoms, and the random sets of 2,000 balls and more), and the regression input whose
# subnormal sites keep the command line's 'diagram' busy for about 25 s (its 'vertices' takes under a
# second). The three other inputs of sites spanning hundreds of binades take 3 to 6 s and are kept. Also
# left out: nine fuzz inputs of the sixth stop of 2026-11-28 (sites from subnormal to beyond 1e75), whose
# 'diagram' spends 1 to 9 s each ordering faces on exact numbers of a thousand bits or more (their
# 'vertices' takes under 0.1 s). And the 400 balls tangent to one circle and the 2,000 in concentric
# shells, whose 'vertices' the lifted fallback decides in seconds, while 'diagram', which needs the
# octree's regions, takes minutes (docs/design.md, "The lifted fallback").
SLOW = {"1hpv.pdb", "1j3h.pdb", "BALL_SMALL_2000.txt", "BALL_SMALL_5000.txt", "BALL_SMALL_10000.txt",
        "octree_11m_boxes_for_400_balls_tangent_to_one_circle.balls",
        "octree_tie_point_leaf_enumerates_quadruples_of_2000_balls_in_concentric_shells.balls",
        "octree_exact_in_box_slow_for_subnormal_sites.balls",
        "far_field_span_recomputed_for_alternating_patches.balls",
        "octree_stagnant_boxes_along_bisector_of_subnormal_cluster_1.balls",
        "octree_stagnant_boxes_along_bisector_of_subnormal_cluster_2.balls"} | {
        f"octree_boxes_explode_for_huge_sphere_near_cluster_{k}.balls" for k in range(1, 7)}
DIAGRAM_INPUTS = [p for p in BUNDLED_INPUTS if p.name not in SLOW]
_cli_diagrams = {}


def cli_diagram(path):
    """The command line's exit code, JSON output and standard error for `diagram path`, run once."""
    if path not in _cli_diagrams:
        _cli_diagrams[path] = run_cli("diagram", path, timeout=120)
    return _cli_diagrams[path]


def python_ends(edges, i):
    """Edge i's ends as the JSON writes them (src/io/write_topology.cpp): [] closed, [v, w], [v, None]
    with one end at infinity, [None, None] infinite both ways."""
    if edges.closed[i]:
        assert edges.start[i] == -1 and edges.end[i] == -1
        return []
    ends = [int(v) for v in (edges.start[i], edges.end[i]) if v >= 0]
    return ends + [None] * (2 - len(ends))


def assert_diagram_equals_cli_json(result, document):
    """A Diagram against the command line's JSON document of the same input: every array, every id."""
    assert result.site_count == document["sites"]
    vertices = document["vertices"]
    assert [v["id"] for v in vertices] == list(range(len(vertices)))
    assert len(result.vertices) == len(vertices)
    expected_points = np.array([[json_double(x) for x in v["point"]] for v in vertices]).reshape(len(vertices), 4)
    assert_same_doubles(result.vertices.points, expected_points)
    assert [t.tolist() for t in result.vertices.tie_sets] == [v["sites"] for v in vertices]
    hidden = document["hidden_sites"]
    assert result.vertices.hidden.site.tolist() == [h["site"] for h in hidden]
    assert result.vertices.hidden.hidden_by.tolist() == [h["hidden_by"] for h in hidden]
    assert result.vertices.hidden.duplicate.tolist() == [h["duplicate"] for h in hidden]

    edges = document["edges"]
    assert [e["id"] for e in edges] == list(range(len(edges)))
    assert len(result.edges) == len(edges)
    assert [t.tolist() for t in result.edges.tie_sets] == [e["sites"] for e in edges]
    assert [python_ends(result.edges, i) for i in range(len(edges))] == [e["ends"] for e in edges]
    assert result.edges.curve.tolist() == [e["curve"] for e in edges]
    assert result.edges.closed.tolist() == [e["ends"] == [] for e in edges]

    faces = document["faces"]
    assert [f["id"] for f in faces] == list(range(len(faces)))
    assert len(result.faces) == len(faces)
    assert result.faces.sites.tolist() == [f["sites"] for f in faces]
    assert [[c.tolist() for c in result.faces.boundary(f)] for f in range(len(faces))] == [f["boundary"] for f in faces]
    assert result.faces.bounded.tolist() == [f["bounded"] for f in faces]

    cells = document["cells"]
    assert len(result.cells) == len(cells)
    assert result.cells.site.tolist() == [c["site"] for c in cells]
    assert [result.cells[c]["faces"].tolist() for c in range(len(cells))] == [c["faces"] for c in cells]
    assert result.cells.bounded.tolist() == [c["bounded"] for c in cells]


@pytest.mark.parametrize("path", DIAGRAM_INPUTS, ids=lambda p: str(p.relative_to(REPOSITORY)))
def test_every_bundled_input_gives_the_command_lines_diagram(path):
    start = time.monotonic()
    code, out, err = cli_diagram(path)
    if code == 2:  # a bad input: read_sites refuses it (test_vertices checks the message)
        with pytest.raises(ValueError):
            apollonius3d.read_sites(path)
        return
    sites = apollonius3d.read_sites(path)
    if code == 3:  # what this version does not decide: the same internal error
        with pytest.raises(RuntimeError) as error:
            apollonius3d.diagram(*sites)
        assert str(error.value) == cli_error_message(err)
        return
    assert code == 0, err
    document = json.loads(out)
    result = apollonius3d.diagram(*sites)
    assert_diagram_equals_cli_json(result, document)
    print(f"{path.name}: {len(result.vertices)} vertices, {len(result.edges)} edges, {len(result.faces)} faces, "
          f"{time.monotonic() - start:.2f} s")


def test_the_inputs_cover_every_part_of_the_diagram():
    """The comparison above sees closed edges, edges infinite at one and at both ends, bounded and
    unbounded faces and cells, faces with several boundary components, and an internal error."""
    seen = set()
    for path in DIAGRAM_INPUTS:
        code, out, _ = cli_diagram(path)
        seen.add(f"exit {code}")
        if code != 0:
            continue
        document = json.loads(out)
        for e in document["edges"]:
            seen.add({0: "closed edge", 2: "edge"}.get(len(e["ends"])) if e["ends"] != [None, None]
                     else "edge infinite both ways")
            if len(e["ends"]) == 2 and e["ends"][0] is not None and e["ends"][1] is None:
                seen.add("edge with one end at infinity")
        for f in document["faces"]:
            seen.add("bounded face" if f["bounded"] else "unbounded face")
            if len(f["boundary"]) > 1:
                seen.add("face with several boundary components")
        for c in document["cells"]:
            seen.add("bounded cell" if c["bounded"] else "unbounded cell")
    expected = {"exit 0", "exit 2", "exit 3", "closed edge", "edge", "edge infinite both ways", "edge with one end at infinity",
                "bounded face", "unbounded face", "bounded cell", "unbounded cell"}
    assert expected <= seen, expected - seen
    print(sorted(seen))


def test_the_comparison_sees_every_kind_of_difference():
    """assert_diagram_equals_cli_json fails on a JSON document changed in any one place."""
    path = REPOSITORY / "tests" / "data" / "vdrc" / "ANO3_3CONNECT.txt"
    code, out, err = cli_diagram(path)
    assert code == 0, err
    result = apollonius3d.diagram(*apollonius3d.read_sites(path))
    assert_diagram_equals_cli_json(result, json.loads(out))
    one_end = next(i for i, e in enumerate(json.loads(out)["edges"]) if e["ends"][1] is None)
    changes = [
        lambda d: d["vertices"][0]["point"].__setitem__(0, np.nextafter(d["vertices"][0]["point"][0], np.inf)),
        lambda d: d["vertices"][1]["sites"].reverse(),
        lambda d: d["edges"][one_end]["ends"].reverse(),
        lambda d: d["edges"][0].__setitem__("curve", "circle"),
        lambda d: d["edges"].pop(),
        lambda d: d["faces"][0]["boundary"][0].reverse() if len(d["faces"][0]["boundary"][0]) > 1 else
        d["faces"][0]["boundary"].append([0]),
        lambda d: d["faces"][-1].__setitem__("bounded", not d["faces"][-1]["bounded"]),
        lambda d: d["cells"][0]["faces"].pop(),
        lambda d: d["cells"][-1].__setitem__("bounded", not d["cells"][-1]["bounded"]),
        lambda d: d["hidden_sites"].append({"site": 0, "hidden_by": 1, "duplicate": False}),
    ]
    for k, change in enumerate(changes):
        document = json.loads(out)
        change(document)
        with pytest.raises(AssertionError):
            assert_diagram_equals_cli_json(result, document)
        print(f"change {k}: seen")


def test_small_diagrams_by_hand():
    """Three equal balls at a triangle's corners: no vertex, one edge, a line infinite both ways. Four equal
    balls at a regular tetrahedron's corners: one vertex, four edges leaving it to infinity."""
    triangle = apollonius3d.diagram([[0, 0, 0], [4, 0, 0], [0, 3, 0]], [1, 1, 1])
    assert len(triangle.vertices) == 0 and len(triangle.edges) == 1
    assert triangle.edges[0]["sites"].tolist() == [0, 1, 2]
    assert (triangle.edges[0]["start"], triangle.edges[0]["end"], triangle.edges[0]["closed"]) == (None, None, False)
    assert triangle.edges[0]["curve"] == "line"
    assert triangle.faces.sites.tolist() == [[0, 1], [0, 2], [1, 2]] and not triangle.faces.bounded.any()
    assert [[c.tolist() for c in triangle.faces.boundary(f)] for f in range(3)] == [[[0]]] * 3
    assert triangle.cells.site.tolist() == [0, 1, 2]
    corners = [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]]
    tetrahedron = apollonius3d.diagram(corners, [1, 1, 1, 1])
    assert len(tetrahedron.vertices) == 1 and tetrahedron.vertices.tie_sets[0].tolist() == [0, 1, 2, 3]
    assert len(tetrahedron.edges) == 4
    for i in range(4):
        edge = tetrahedron.edges[i]
        assert edge["closed"] is False and edge["curve"] == "line"
        assert [edge["start"], edge["end"]].count(0) == 1 and [edge["start"], edge["end"]].count(None) == 1
    assert len(tetrahedron.faces) == 6 and not tetrahedron.faces.bounded.any()
    assert len(tetrahedron.cells) == 4 and not tetrahedron.cells.bounded.any()
    assert "1 vertices, 4 edges, 6 faces, 4 cells of 4 sites" in repr(tetrahedron)


def test_every_thread_count_gives_the_same_diagram():
    path = REPOSITORY / "bench" / "data" / "vdrc" / "BALL_SMALL_1000.txt"
    code, out, err = cli_diagram(path)
    assert code == 0, err
    document = json.loads(out)
    for threads in [2, 3]:
        assert_diagram_equals_cli_json(apollonius3d.diagram(*apollonius3d.read_sites(path), threads=threads), document)


def test_result_arrays_own_their_memory():
    result = apollonius3d.diagram(*apollonius3d.read_sites(REPOSITORY / "tests" / "data" / "pept.balls"))
    arrays = [result.edges.tie_sets.offsets, result.edges.tie_sets.sites, result.edges.start, result.edges.end,
              result.edges.closed, result.edges.curve, result.faces.sites, result.faces.component_offsets,
              result.faces.edge_offsets, result.faces.edges, result.faces.bounded, result.cells.site,
              result.cells.face_offsets, result.cells.faces, result.cells.bounded, result.vertices.points]
    for array in arrays:
        assert array.flags.owndata and array.base is None and array.flags.c_contiguous
    assert result.faces.sites.shape == (len(result.faces), 2)
    assert result.edges.start.dtype == np.int64 and result.edges.closed.dtype == np.bool_
    assert result.edges.curve.dtype.kind == "U"


def as_lists(item):
    """An edge, face or cell dict with its arrays as lists, to compare with ==."""
    def plain(value):
        if isinstance(value, np.ndarray):
            return value.tolist()
        if isinstance(value, list):
            return [plain(v) for v in value]
        return value
    return {key: plain(value) for key, value in item.items()}


def test_indexing_like_sequences():
    result = apollonius3d.diagram(*apollonius3d.read_sites(REPOSITORY / "tests" / "data" / "vdrc" / "Vis_I_10.txt"))
    for sequence in [result.edges, result.faces, result.cells]:
        n = len(sequence)
        assert n > 0
        assert as_lists(sequence[-1]) == as_lists(sequence[n - 1])
        assert as_lists(sequence[0]) != as_lists(sequence[n - 1])
        for outside in [n, -n - 1]:
            with pytest.raises(IndexError):
                sequence[outside]
    face = result.faces[0]
    assert face["sites"] == tuple(result.faces.sites[0].tolist())
    assert [c.tolist() for c in face["boundary"]] == [c.tolist() for c in result.faces.boundary(0)]
    cell = result.cells[1]
    offsets = result.cells.face_offsets
    assert cell["faces"].tolist() == result.cells.faces[offsets[1]:offsets[2]].tolist()


def test_bad_input_raises_value_error():
    with pytest.raises(ValueError, match=r"centres: .*shape \(n, 3\)"):
        apollonius3d.diagram([[0, 0], [1, 1]], [1, 1])
    with pytest.raises(ValueError, match="nan"):
        apollonius3d.diagram([[0, 0, 0], [1, 0, float("nan")]], [1, 1])
    with pytest.raises(ValueError, match="threads"):
        apollonius3d.diagram([[0, 0, 0]], [1], threads=0)
    with pytest.raises(ValueError):
        apollonius3d.diagram(np.zeros((0, 3)), np.zeros(0))


def test_docstrings():
    assert apollonius3d.diagram.__doc__.startswith("diagram(centres, weights, *, threads=1) -> Diagram")
    for cls in [apollonius3d.Diagram, apollonius3d.Edges, apollonius3d.Faces, apollonius3d.Cells]:
        assert cls.__doc__, cls
        for attribute, value in vars(cls).items():
            if not attribute.startswith("_") or attribute in ("__len__", "__getitem__"):
                assert getattr(value, "__doc__", None), f"{cls.__name__}.{attribute}"
