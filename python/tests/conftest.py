"""Shared by the suite: the repository, the command line to compare with, and the bundled inputs.

Run by ctest (python/pytest) with PYTHONPATH at the built module and APOLLONIUS3D_BINARY at the command
line; by hand: PYTHONPATH=build/python /usr/bin/python3 -m pytest python/tests.
"""
import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

REPOSITORY = Path(__file__).resolve().parents[2]
BINARY = Path(os.environ.get("APOLLONIUS3D_BINARY", REPOSITORY / "build" / "apollonius3d"))

# Every input file the repository bundles, bad ones included (the regression files of gemmi's bugs).
BUNDLED_INPUTS = sorted(
    [REPOSITORY / "examples" / "pept.pdb", REPOSITORY / "tests" / "data" / "pept.balls"]
    + list((REPOSITORY / "tests" / "data" / "vdrc").glob("*.txt"))
    + list((REPOSITORY / "tests" / "data" / "regression").glob("*"))
    + list((REPOSITORY / "bench" / "data" / "vdrc").glob("*.txt"))
    + list((REPOSITORY / "bench" / "data" / "pdb").glob("*.pdb"))
)


def run_cli(*arguments, timeout=600):
    """The command line's exit code, standard output and standard error."""
    assert BINARY.exists(), f"no command line at {BINARY} (set APOLLONIUS3D_BINARY)"
    result = subprocess.run([str(BINARY), *map(str, arguments)], capture_output=True, text=True, timeout=timeout)
    return result.returncode, result.stdout, result.stderr


def cli_error_message(stderr):
    """The message of a bad-input error as the command line prints it, less its 'apollonius3d: ' prefix."""
    assert stderr.startswith("apollonius3d: ") and stderr.endswith("\n") and stderr.count("\n") == 1, stderr
    return stderr[len("apollonius3d: "):-1]


def json_double(value):
    """A coordinate of the command line's JSON: a number, or "inf" / "-inf" beyond the double range."""
    return {"inf": math.inf, "-inf": -math.inf}.get(value, value) if isinstance(value, str) else float(value)


def cli_vertices_json(path, *options):
    code, out, err = run_cli("vertices", path, "--format", "json", *options)
    assert code == 0, err
    return json.loads(out)


def assert_same_doubles(actual, expected):
    """Bit for bit: the same doubles, -0.0 told from 0.0."""
    actual = np.ascontiguousarray(actual, dtype=np.float64)
    expected = np.ascontiguousarray(expected, dtype=np.float64)
    assert actual.shape == expected.shape
    assert np.array_equal(actual.view(np.uint64), expected.view(np.uint64))


def assert_equals_cli_json(result, document):
    """A Vertices result against the command line's JSON document of the same input."""
    vertices = document["vertices"]
    assert result.site_count == document["sites"]
    assert len(result) == len(vertices)
    expected_points = np.array([[json_double(v[k]) for k in "xyzr"] for v in vertices]).reshape(len(vertices), 4)
    assert_same_doubles(result.points, expected_points)
    expected_offsets = np.cumsum([0] + [len(v["sites"]) for v in vertices])
    assert np.array_equal(result.tie_sets.offsets, expected_offsets)
    assert result.tie_sets.sites.tolist() == [s for v in vertices for s in v["sites"]]
    hidden = document["hidden_sites"]
    assert result.hidden.site.tolist() == [h["site"] for h in hidden]
    assert result.hidden.hidden_by.tolist() == [h["hidden_by"] for h in hidden]
    assert result.hidden.duplicate.tolist() == [h["duplicate"] for h in hidden]
    assert result.sites_without_vertex.tolist() == document["sites_without_vertex"]


@pytest.fixture(scope="session")
def pept_pdb():
    return REPOSITORY / "examples" / "pept.pdb"


@pytest.fixture(scope="session")
def protein_1j3h():
    """1j3h.pdb, 4,924 atoms: a computation of about a second, long enough to measure threads."""
    import apollonius3d

    return apollonius3d.read_sites(REPOSITORY / "bench" / "data" / "pdb" / "1j3h.pdb")
