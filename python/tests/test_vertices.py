"""vertices(): the command line's answer bit for bit, from every kind of array-like input."""
import json
from fractions import Fraction

import numpy as np
import pytest

import apollonius3d
from conftest import (BUNDLED_INPUTS, REPOSITORY, assert_equals_cli_json, assert_same_doubles,
                      cli_error_message, cli_vertices_json, run_cli)


@pytest.mark.parametrize("path", BUNDLED_INPUTS, ids=lambda p: str(p.relative_to(REPOSITORY)))
def test_every_bundled_input_gives_the_command_lines_answer(path):
    code, out, err = run_cli("vertices", path, "--format", "json")
    if code == 2:  # a bad input: the same message
        with pytest.raises(ValueError) as error:
            apollonius3d.read_sites(path)
        assert str(error.value) == cli_error_message(err)
        return
    assert code == 0, err
    assert_equals_cli_json(apollonius3d.vertices(*apollonius3d.read_sites(path)), json.loads(out))


def test_the_command_lines_text_output_bit_for_bit(pept_pdb):
    code, out, err = run_cli("vertices", pept_pdb)
    assert code == 0, err
    result = apollonius3d.vertices(*apollonius3d.read_sites(pept_pdb))
    lines = out.splitlines()
    assert len(lines) == len(result) > 500
    for i, line in enumerate(lines):
        fields = line.split()
        assert [int(s) for s in fields[:-4]] == result.tie_sets[i].tolist()
        assert_same_doubles(result.points[i], [float(x) for x in fields[-4:]])


@pytest.mark.parametrize("threads", [2, 3, 1024])
def test_every_thread_count_gives_the_same_answer(threads):
    path = REPOSITORY / "bench" / "data" / "pdb" / "1hpv.pdb"
    assert_equals_cli_json(apollonius3d.vertices(*apollonius3d.read_sites(path), threads=threads),
                           cli_vertices_json(path))


def test_box_as_the_command_lines(pept_pdb):
    box = (0.0, -15.0, 20.0, 5.0, -5.0, 30.0)
    restricted = apollonius3d.vertices(*apollonius3d.read_sites(pept_pdb), box=box)
    document = cli_vertices_json(pept_pdb, "--box", *box)
    assert 0 < len(restricted) < len(apollonius3d.vertices(*apollonius3d.read_sites(pept_pdb)))
    assert_equals_cli_json(restricted, document)


def test_stats_as_the_command_lines(pept_pdb):
    result = apollonius3d.vertices(*apollonius3d.read_sites(pept_pdb), stats=True)
    # The module registers the counters of every layer it links, the binary those of its own: the lists
    # may differ by predicates that never ran.
    ran = [p for p in result.stats["predicates"] if p["evaluations"] > 0]
    assert ran == [p for p in cli_vertices_json(pept_pdb, "--stats")["stats"]["predicates"] if p["evaluations"] > 0]
    assert {"vertices_of", "vertex_conflict"} <= {p["name"] for p in ran}
    # pept's 107 sites go to the lifted triangulation at once (at most 256 active sites); 1j3h to the octree.
    octree = result.stats["octree"]
    assert octree["lifted_fallback"] and octree["lifted_small_input"] and octree["lifted_quadruples"] > 0
    assert octree["seed_boxes"] == 0 and octree["boxes"] == 0
    assert apollonius3d.vertices(*apollonius3d.read_sites(pept_pdb)).stats is None


def test_hidden_sites_and_sites_without_vertex():
    centres = [[0, 0, 0], [0.5, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10], [10, 10, 10], [10, 0, 0], [-30, 0, 0]]
    weights = [3, 1, 1, 1, 1, 1, 1, 0.5]  # 1 inside 0; 6 duplicates 2
    result = apollonius3d.vertices(centres, weights)
    assert result.hidden.site.tolist() == [1, 6]
    assert result.hidden.hidden_by.tolist() == [0, 2]
    assert result.hidden.duplicate.tolist() == [False, True]
    assert len(result.hidden) == 2
    assert not set(result.tie_sets.sites.tolist()) & {1, 6}


def test_same_as_command_line_with_hidden_sites(tmp_path):
    centres = np.array([[0, 0, 0], [0.5, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10], [10, 10, 10], [10, 0, 0],
                        [-30, 0, 0], [5, 5, -40]], dtype=float)
    weights = np.array([3, 1, 1, 1, 1, 1, 1, 0.5, 2])
    balls = tmp_path / "hidden.balls"
    balls.write_text("".join(f"{x!r} {y!r} {z!r} {w!r}\n" for (x, y, z), w in zip(centres.tolist(), weights.tolist())))
    document = cli_vertices_json(balls)
    assert document["hidden_sites"] and len(document["vertices"]) > 0
    assert_equals_cli_json(apollonius3d.vertices(centres, weights), document)


def test_result_arrays_own_their_memory(pept_pdb):
    result = apollonius3d.vertices(*apollonius3d.read_sites(pept_pdb))
    arrays = [result.points, result.tie_sets.offsets, result.tie_sets.sites, result.hidden.site,
              result.hidden.hidden_by, result.hidden.duplicate, result.sites_without_vertex]
    for array in arrays:
        assert array.flags.owndata and array.base is None and array.flags.c_contiguous
    assert result.points.dtype == np.float64 and result.points.shape == (len(result), 4)
    assert result.tie_sets.offsets.dtype == np.int64 and result.tie_sets.sites.dtype == np.int64
    assert result.hidden.duplicate.dtype == np.bool_
    # The result outlives its inputs, and its arrays outlive the result.
    points = result.points
    del result
    assert np.isfinite(points).all()


def test_tie_sets_index_like_a_sequence():
    result = apollonius3d.vertices(*apollonius3d.read_sites(REPOSITORY / "tests" / "data" / "vdrc" / "ANO3_3CONNECT.txt"))
    assert len(result.tie_sets) == len(result) == 8
    assert result.tie_sets[0].tolist() == [0, 1, 2, 4]
    assert result.tie_sets[-1].tolist() == [0, 1, 7, 8]
    assert [t.tolist() for t in result.tie_sets] == [result.tie_sets[i].tolist() for i in range(8)]
    with pytest.raises(IndexError):
        result.tie_sets[8]
    assert "8 vertices of 9 sites" in repr(result)


def test_array_likes_convert_exactly(pept_pdb):
    sites = apollonius3d.read_sites(pept_pdb)
    expected = apollonius3d.vertices(sites.centres, sites.weights)
    centres, weights = sites.centres, sites.weights
    big_endian = centres.astype(">f8")
    fortran = np.asfortranarray(centres)
    strided = np.repeat(centres, 2, axis=0)[::2]
    assert not strided.flags.c_contiguous and not fortran.flags.c_contiguous
    for c, w in [(centres.tolist(), weights.tolist()), (tuple(map(tuple, centres.tolist())), tuple(weights.tolist())),
                 (big_endian, weights.astype(">f8")), (fortran, weights), (strided, np.repeat(weights, 2)[::2]),
                 (centres.astype(object), weights.astype(object)), (centres.astype(np.longdouble), weights)]:
        result = apollonius3d.vertices(c, w)
        assert_same_doubles(result.points, expected.points)
        assert np.array_equal(result.tie_sets.sites, expected.tie_sets.sites)


def test_integer_float32_and_fraction_inputs_give_the_float64_answer():
    rng = np.random.default_rng(5)
    centres = rng.integers(-50, 50, (40, 3))
    weights = rng.integers(1, 4, 40)
    expected = apollonius3d.vertices(centres.astype(float), weights.astype(float))
    assert len(expected) > 0
    for c, w in [(centres, weights), (centres.astype(np.int32), weights.astype(np.uint8)),
                 (centres.astype(np.float32), weights.astype(np.float16)),
                 (np.vectorize(Fraction)(centres).astype(object), [Fraction(int(x), 1) for x in weights]),
                 ((centres / 4).astype(np.float32), (weights / 8).astype(np.float32))]:
        result = apollonius3d.vertices(c, w)
        reference = apollonius3d.vertices(np.asarray(c, dtype=float), np.asarray(w, dtype=float))
        assert_same_doubles(result.points, reference.points)
    assert_same_doubles(apollonius3d.vertices(centres, weights).points, expected.points)


def test_sites_unpack_into_vertices(pept_pdb):
    sites = apollonius3d.read_sites(pept_pdb)
    centres, weights = sites
    assert centres is sites.centres and weights is sites.weights
    assert len(apollonius3d.vertices(*sites)) == len(apollonius3d.vertices(centres, weights))


def test_far_vertices_beyond_the_double_range_are_infinite():
    path = REPOSITORY / "tests" / "data" / "regression" / "far_field_spread_overflow_at_5e289.balls"
    document = cli_vertices_json(path)
    result = apollonius3d.vertices(*apollonius3d.read_sites(path))
    assert_equals_cli_json(result, document)
    expected_infinite = any(isinstance(v[k], str) for v in document["vertices"] for k in "xyzr")
    assert np.isinf(result.points).any() == expected_infinite


def test_every_function_has_a_docstring():
    for name in ["read_sites", "vertices", "certify"]:
        doc = getattr(apollonius3d, name).__doc__
        assert doc and len(doc.splitlines()) >= 8, name
    for cls in [apollonius3d.Vertices, apollonius3d.TieSets, apollonius3d.HiddenSites, apollonius3d.Sites,
                apollonius3d.AtomLabels, apollonius3d.Certification]:
        assert cls.__doc__, cls
        for attribute, value in vars(cls).items():
            if not attribute.startswith("_") or attribute in ("__len__", "__getitem__", "__iter__"):
                assert getattr(value, "__doc__", None), f"{cls.__name__}.{attribute}"
    assert apollonius3d.__doc__ and apollonius3d.__version__


def test_fewer_than_four_active_sites(tmp_path):
    for centres, weights in [([[0, 0, 0]], [1]), ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [1, 1, 1]),
                             ([[0, 0, 0], [0, 0, 0], [1, 0, 0], [0, 1, 0], [0.1, 0, 0]], [1, 1, 1, 1, 0.5])]:
        balls = tmp_path / "few.balls"
        balls.write_text("".join(f"{x} {y} {z} {w}\n" for (x, y, z), w in zip(centres, weights)))
        result = apollonius3d.vertices(centres, weights)
        assert len(result) == 0 and result.points.shape == (0, 4)
        assert result.tie_sets.offsets.tolist() == [0]
        assert_equals_cli_json(result, cli_vertices_json(balls))


def test_stats_of_the_octree(protein_1j3h):
    octree = apollonius3d.vertices(*protein_1j3h, stats=True).stats["octree"]
    assert octree["seed_boxes"] > 0 and octree["leaves"] > 0 and octree["refinement_seconds"] >= 0
    assert not octree["lifted_fallback"] and not octree["lifted_small_input"]


@pytest.mark.parametrize("algorithm", ["auto", "octree", "lifted"])
def test_every_algorithm_gives_the_command_lines_answer(pept_pdb, algorithm):
    # pept's 107 sites: auto takes the lifted triangulation, octree the octree, lifted the triangulation.
    result = apollonius3d.vertices(*apollonius3d.read_sites(pept_pdb), algorithm=algorithm, stats=True)
    assert_equals_cli_json(result, cli_vertices_json(pept_pdb, "--algorithm", algorithm))
    octree = result.stats["octree"]
    assert octree["lifted_fallback"] == (algorithm != "octree")
    assert octree["lifted_small_input"] == (algorithm == "auto")
    assert (octree["seed_boxes"] > 0) == (algorithm == "octree")


def test_balls_of_one_radius_take_the_delaunay_triangulation(tmp_path):
    # 600 balls of radius 1.5 on a coarse grid (cospherical groups, repeats): auto goes straight to the
    # lifted triangulation, here the Delaunay triangulation of the centres, with the octree's answer.
    centres = np.random.default_rng(3).integers(0, 12, size=(600, 3)).astype(float)
    weights = np.full(600, 1.5)
    path = tmp_path / "one_radius.balls"
    path.write_text("".join(f"{x:.17g} {y:.17g} {z:.17g} 1.5\n" for x, y, z in centres))
    automatic = apollonius3d.vertices(centres, weights, stats=True)
    octree = apollonius3d.vertices(centres, weights, algorithm="octree", stats=True)
    assert_equals_cli_json(automatic, cli_vertices_json(path, "--algorithm", "octree"))
    assert_equals_cli_json(octree, cli_vertices_json(path))
    assert automatic.stats["octree"]["lifted_one_weight"] and automatic.stats["octree"]["boxes"] == 0
    assert not octree.stats["octree"]["lifted_fallback"] and octree.stats["octree"]["boxes"] > 0
    assert max(len(automatic.tie_sets[i]) for i in range(len(automatic))) > 4 and len(automatic.hidden) > 0


def test_a_cluster_beside_a_far_ball_takes_the_lifted_triangulation(tmp_path):
    # 600 balls 1/8 apart or more and one ball 1e13 away: the octree would refine through 40 binades more
    # than the cluster's spacing needs, so auto goes straight to the lifted triangulation, with the same answer.
    # "octree" takes no such shortcut, and refines: each box's nearest sites keep its seed candidates few.
    rng = np.random.default_rng(5)
    centres = np.vstack([rng.integers(0, 80, size=(600, 3)) / 8.0, [[1e13, -2e13, 3e12]]])
    weights = np.concatenate([rng.integers(2, 8, size=600) / 8.0, [4.0]])
    path = tmp_path / "far_ball.balls"
    path.write_text("".join(f"{x:.17g} {y:.17g} {z:.17g} {w:.17g}\n" for (x, y, z), w in zip(centres, weights)))
    automatic = apollonius3d.vertices(centres, weights, stats=True)
    octree = apollonius3d.vertices(centres, weights, algorithm="octree", stats=True)
    assert_equals_cli_json(automatic, cli_vertices_json(path, "--algorithm", "octree"))
    assert_equals_cli_json(octree, cli_vertices_json(path))
    assert automatic.stats["octree"]["lifted_deep_input"] and automatic.stats["octree"]["boxes"] == 0
    assert not octree.stats["octree"]["lifted_fallback"] and octree.stats["octree"]["boxes"] > 0


def test_a_cluster_beside_a_ball_1e6_away_stays_in_the_octree(tmp_path):
    # 1,000 balls and one ball 1e6 away: the seed boxes between them are far larger than the cluster's
    # spacing. Each box's nearest sites keep its candidates few (it once took hundreds per site, and the
    # lifted triangulation), and the octree gives the answer of --algorithm lifted.
    rng = np.random.default_rng(7)
    centres = np.vstack([rng.integers(0, 21, size=(1000, 3)) - 10.0, [[1e6, 0, 0]]])
    weights = np.concatenate([rng.integers(2, 8, size=1000) / 4.0, [1.0]])
    path = tmp_path / "ball_1e6_away.balls"
    path.write_text("".join(f"{x:.17g} {y:.17g} {z:.17g} {w:.17g}\n" for (x, y, z), w in zip(centres, weights)))
    automatic = apollonius3d.vertices(centres, weights, stats=True)
    assert_equals_cli_json(automatic, cli_vertices_json(path, "--algorithm", "lifted"))
    octree = automatic.stats["octree"]
    assert not octree["lifted_fallback"] and octree["boxes"] > 0
    assert octree["seed_candidates"] <= 16 * 1001 and len(automatic) > 1000


def test_an_unknown_algorithm_is_a_value_error():
    with pytest.raises(ValueError, match="algorithm: 'brute' is not one of auto, octree, lifted"):
        apollonius3d.vertices([[0, 0, 0]], [1], algorithm="brute")
