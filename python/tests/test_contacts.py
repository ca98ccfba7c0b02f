"""contacts(): the command line's answer bit for bit, closed forms for two balls, parameters refused."""
import json
import math

import numpy as np
import pytest

import apollonius3d
from conftest import REPOSITORY, assert_same_doubles, cli_error_message, run_cli


def test_the_command_lines_json_bit_for_bit(pept_pdb):
    code, out, err = run_cli("contacts", pept_pdb, "--format", "json", "--probe", "1.2")
    assert code == 0, err
    document = json.loads(out)
    result = apollonius3d.contacts(*apollonius3d.read_sites(pept_pdb), probe=1.2)
    assert len(result) == len(document["contacts"]) > 300
    assert result.pairs.tolist() == [c["sites"] for c in document["contacts"]]
    assert_same_doubles(result.area, [c["area"] for c in document["contacts"]])
    assert_same_doubles(result.error, [c["error"] for c in document["contacts"]])
    for key in ("sas", "sas_error", "volume", "volume_error"):
        assert_same_doubles(getattr(result, key), [c[key] for c in document["cells"]])
    assert result.hidden.site.tolist() == [h["site"] for h in document["hidden_sites"]]


def test_the_command_lines_text_bit_for_bit(pept_pdb):
    code, out, err = run_cli("contacts", pept_pdb)
    assert code == 0, err
    result = apollonius3d.contacts(*apollonius3d.read_sites(pept_pdb))
    expected = {(a, b): area for (a, b), area in zip(result.pairs.tolist(), result.area.tolist())}
    expected.update({(i, i): sas for i, sas in enumerate(result.sas.tolist()) if sas > 0})
    lines = [line.split() for line in out.splitlines()]
    assert [(int(a), int(b)) for a, b, _ in lines] == sorted(expected)
    assert_same_doubles([float(x) for _, _, x in lines], [expected[int(a), int(b)] for a, b, _ in lines])


@pytest.mark.parametrize("w0,w1,distance", [(1, 1, 2), (1, 1.8, 2.5), (0.5, 2, 1.6)])
def test_two_balls_against_closed_forms(w0, w1, distance):
    probe = 1.4
    result = apollonius3d.contacts([[0, 0, 0], [distance, 0, 0]], [w0, w1], probe=probe, tolerance=1e-8)
    r0, r1 = w0 + probe, w1 + probe
    # The cells tile the union of the two balls; the spheres' accessible parts make its boundary.
    lens = math.pi * (r0 + r1 - distance) ** 2 * (distance ** 2 + 2 * distance * (r0 + r1) - 3 * (r0 - r1) ** 2) / (12 * distance)
    union_volume = 4 * math.pi * (r0 ** 3 + r1 ** 3) / 3 - lens
    d0 = (distance ** 2 + r0 ** 2 - r1 ** 2) / (2 * distance)
    union_area = 4 * math.pi * (r0 ** 2 + r1 ** 2) - 2 * math.pi * r0 * (r0 - d0) - 2 * math.pi * r1 * (r1 - (distance - d0))
    assert abs(result.volume.sum() - union_volume) <= result.volume_error.sum() + 1e-12 * union_volume
    assert abs(result.sas.sum() - union_area) <= result.sas_error.sum() + 1e-12 * union_area
    assert result.pairs.tolist() == [[0, 1]]
    if w0 == w1:  # the disc in the bisector plane
        disc = math.pi * (r0 ** 2 - distance ** 2 / 4)
        assert abs(result.area[0] - disc) <= result.error[0] + 1e-12 * disc


def test_hidden_balls_have_nothing():
    result = apollonius3d.contacts([[0, 0, 0], [0.5, 0, 0], [3, 0, 0]], [2, 1, 1])
    assert result.hidden.site.tolist() == [1]
    assert result.sas[1] == 0 and result.volume[1] == 0
    assert result.pairs.tolist() == [[0, 2]]


def test_every_thread_count_gives_the_same_answer():
    sites = apollonius3d.read_sites(REPOSITORY / "bench" / "data" / "pdb" / "1hpv.pdb")
    centres, weights = sites.centres[:300], sites.weights[:300]
    one, two = apollonius3d.contacts(centres, weights), apollonius3d.contacts(centres, weights, threads=2)
    assert np.array_equal(one.pairs, two.pairs)
    assert_same_doubles(one.area, two.area)
    assert_same_doubles(one.sas, two.sas)


@pytest.mark.parametrize("arguments,message", [
    ({"probe": -1.0}, "probe: needs a finite number >= 0, not -1"),
    ({"probe": math.nan}, "probe: needs a finite number >= 0, not nan"),
    ({"tolerance": 0.0}, "tolerance: needs a number in [1e-10, 0.5], not 0"),
    ({"threads": 0}, "threads: needs an integer from 1 to 1024, not 0"),
])
def test_bad_parameters_raise_value_error(arguments, message):
    with pytest.raises(ValueError) as error:
        apollonius3d.contacts([[0, 0, 0], [2, 0, 0]], [1, 1], **arguments)
    assert str(error.value) == message


def test_bad_input_raises_the_command_lines_message(tmp_path):
    with pytest.raises(ValueError) as error:
        apollonius3d.contacts([[0, 0, 0], [1, 2, math.nan]], [1, 1])
    assert str(error.value) == "centres: site 1, z: not a finite number: nan"
    bad = tmp_path / "bad.balls"
    bad.write_text("0 0 0 1\n1 2 x 1\n")
    code, _, err = run_cli("contacts", bad)
    assert code == 2
    with pytest.raises(ValueError) as error:
        apollonius3d.read_sites(bad)
    assert str(error.value) == cli_error_message(err)


def test_balls_too_close_to_measure_raise_value_error():
    """Two balls 1e-12 apart (neither hiding the other): beyond the measures' doubles, as the command line's
    exit 2 (tests/data/regression/contacts_hang_for_balls_2e-16_apart.balls)."""
    with pytest.raises(ValueError) as error:
        apollonius3d.contacts([[0, 0, 0], [1e-12, 0, 0]], [1, 1])
    assert "balls 0 and 1 lie within 1e-4 of their probe-grown radius of each other" in str(error.value)
