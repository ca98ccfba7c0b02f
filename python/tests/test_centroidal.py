"""centroidal(): the command line's answer bit for bit on the bundled 6-site example, every bad parameter
with the command line's reason, the same answer for every thread count. Ctrl-C: test_interrupt.py."""
import numpy as np
import pytest

import apollonius3d
from conftest import REPOSITORY, assert_same_doubles, run_cli

EXAMPLE = REPOSITORY / "examples" / "centroidal6"
UNIT = (0, 0, 0, 1, 1, 1)
# The history CSV's columns, in its order; all but seconds are the same doubles on every run.
COLUMNS = ["iteration", "E4", "max_relative_mass_error", "largest_site_move", "seconds", "median_residual",
           "E4_before_weight_step", "E4_error_estimate", "weight_retries"]


def numbers_of(path):
    """The numbers of a text file, one row per line that is not blank or a comment (Python's float is
    correctly rounded, as the command line's reader)."""
    lines = [line.split("#")[0].split() for line in path.read_text().splitlines()]
    return [[float(field) for field in line] for line in lines if line]


@pytest.fixture(scope="module")
def example():
    sites = apollonius3d.read_sites(EXAMPLE / "sites.txt")
    masses = np.array(numbers_of(EXAMPLE / "masses.txt")).ravel()
    return sites.centres, sites.weights, masses


@pytest.fixture(scope="module")
def command_line(tmp_path_factory):
    """The command line's output on the example: the final sites (n, 4), the history rows, its comment."""
    directory = tmp_path_factory.mktemp("centroidal6")
    out, history = directory / "out.txt", directory / "history.csv"
    code, _, err = run_cli("centroidal", EXAMPLE / "sites.txt", "--domain", *UNIT, "--masses", EXAMPLE / "masses.txt",
                           "-o", out, "--history", history)
    assert code == 0, err
    header, *rows = history.read_text().splitlines()
    assert header.split(",") == COLUMNS
    return np.array(numbers_of(out)), [row.split(",") for row in rows], out.read_text().splitlines()[0]


def test_the_example_equals_the_command_line_bit_for_bit(example, command_line):
    sites, rows, comment = command_line
    result = apollonius3d.centroidal(*example[:2], UNIT, masses=example[2])
    assert_same_doubles(result.centres, sites[:, :3])
    assert_same_doubles(result.weights, sites[:, 3])
    assert result.converged and comment.startswith("# apollonius3d centroidal: converged after")
    assert result.iterations == len(rows) == len(result.history)
    assert f"after {result.iterations} iterations" in comment
    assert result.history.dtype.names == tuple(COLUMNS)
    for k, name in enumerate(COLUMNS):
        if name == "seconds":
            assert np.all(np.diff(result.history[name]) >= 0) and np.all(result.history[name] > 0)
        elif name in ("iteration", "weight_retries"):
            assert result.history[name].tolist() == [int(row[k]) for row in rows]
        else:
            assert_same_doubles(result.history[name], [float(row[k]) for row in rows])
    assert result.mass_error == result.history["max_relative_mass_error"][-1] <= 1e-6
    assert result.median_residual == result.history["median_residual"][-1] <= 1e-6
    assert result.energy == result.history["E4"][-1]
    assert float(comment.split("max relative mass error ")[1].split(",")[0]) == result.mass_error
    # The volumes hold the masses within the tolerance and the estimates the mass error includes.
    assert np.all(np.abs(result.volumes - example[2]) <= 1e-6 * example[2])
    assert result.reports == []
    assert repr(result) == f"<CentroidalResult: 6 sites, converged after {result.iterations} iterations>"
    assert result.centres.flags.owndata or result.centres.base is not None  # numpy's memory either way


def test_equal_masses_by_default_as_the_command_line(example, tmp_path):
    out = tmp_path / "out.txt"
    code, _, err = run_cli("centroidal", EXAMPLE / "sites.txt", "--domain", *UNIT, "--max-iterations", "3", "-o", out)
    assert code == 1, err  # not converged in 3 iterations
    result = apollonius3d.centroidal(*example[:2], UNIT, max_iterations=3)
    expected = np.array(numbers_of(out))
    assert_same_doubles(result.centres, expected[:, :3])
    assert_same_doubles(result.weights, expected[:, 3])


def test_not_converged_returns_the_state_reached_as_the_command_line(example, tmp_path):
    out = tmp_path / "out.txt"
    code, _, _ = run_cli("centroidal", EXAMPLE / "sites.txt", "--domain", *UNIT, "--masses", EXAMPLE / "masses.txt",
                         "--max-iterations", "2", "-o", out)
    assert code == 1
    result = apollonius3d.centroidal(*example[:2], UNIT, masses=example[2], max_iterations=2)
    assert not result.converged and result.iterations == 2
    expected = np.array(numbers_of(out))
    assert_same_doubles(result.centres, expected[:, :3])
    assert_same_doubles(result.weights, expected[:, 3])


def test_every_thread_count_gives_the_same_result(example):
    # The 6-site example (the brute-force diagram), and 10 iterations on 30 random sites (the octree's).
    random = np.random.default_rng(19)
    centres = random.uniform(0.05, 0.95, (30, 3))
    for arguments, options in [((*example[:2], UNIT), {"masses": example[2]}),
                               ((centres, np.zeros(30), UNIT), {"tolerance": 1e-4, "max_iterations": 10})]:
        one = apollonius3d.centroidal(*arguments, **options, threads=1)
        two = apollonius3d.centroidal(*arguments, **options, threads=2)
        assert one.iterations == two.iterations > 1
        assert_same_doubles(two.centres, one.centres)
        assert_same_doubles(two.weights, one.weights)
        for name in COLUMNS:
            if name != "seconds":
                assert_same_doubles(two.history[name], one.history[name])


def cli_message(tmp_path, domain, options=(), masses=None):
    """The command line's message for the example's sites with these parameters (masses: a list written one
    per line), less its 'apollonius3d: ' or 'apollonius3d centroidal: ' prefix; and its masses file."""
    masses_file = tmp_path / "masses.txt"
    masses_file.write_text("".join(f"{m!r}\n" for m in masses))
    out = tmp_path / "out.txt"
    code, _, err = run_cli("centroidal", EXAMPLE / "sites.txt", "--domain", *domain, *options, "--masses", masses_file,
                           "-o", out)
    assert code == 2, err
    assert not out.exists()
    first = err.splitlines()[0]
    for prefix in ("apollonius3d centroidal: ", "apollonius3d: "):
        if first.startswith(prefix):
            return first[len(prefix):], str(masses_file)
    raise AssertionError(err)


MASSES = [0.25 / 3, 0.25 / 3, 0.5 / 3, 0.5 / 3, 0.25, 0.25]  # sum to 1 within 1e-9
SITES_FILE = str(EXAMPLE / "sites.txt")

# (name, Python's keyword arguments, the command line's options, the command line's prefix (MASSES for its
# masses file), Python's prefix, a part of the reason): the same reason from both, where the command line
# names its option, or its file and line, and Python the argument, and the 0-based site or mass.
BAD_PARAMETERS = [
    ("masses not summing to 1", {"masses": MASSES[:5] + [0.3]}, [], "MASSES: ", "masses: ", "the masses sum to 1.05"),
    ("a negative mass", {"masses": MASSES[:3] + [-MASSES[3]] + MASSES[4:]}, [], "MASSES:4: ", "masses: site 3: ",
     "a mass must be positive, not -0.16666"),
    ("a zero mass", {"masses": [0.0] + MASSES[1:]}, [], "MASSES:1: ", "masses: site 0: ",
     "a mass must be positive, not 0"),
    ("too few masses", {"masses": MASSES[:4]}, [], "MASSES: ", "masses: ", "4 masses for 6 sites"),
    ("too many masses", {"masses": MASSES + [0.1]}, [], "MASSES:7: ", "masses: site 6: ",
     "more masses than the 6 sites"),
    ("a domain that does not contain the sites", {"domain": (0, 0, 0, 0.7, 1, 1)}, [], SITES_FILE + ":4: site 1: ",
     "centres: site 1: ", "the site (0.77000000000000002, 0.25, 0.31) lies outside the domain"),
    ("a flat domain", {"domain": (0, 0, 0, 1, 0, 1)}, [], "--domain: ", "domain: ",
     "needs X0 < X1, Y0 < Y1 and Z0 < Z1 (a box with a volume)"),
    ("a tolerance too tight", {"tolerance": 1e-11}, ["--tolerance", "1e-11"], "--tolerance: ", "tolerance: ",
     "must lie in [1e-10, 0.5], not 9.9999999999999994e-12"),
    ("a tolerance too loose", {"tolerance": 0.7}, ["--tolerance", "0.7"], "--tolerance: ", "tolerance: ",
     "must lie in [1e-10, 0.5], not 0.69999999999999996"),
    ("a median tolerance too loose", {"median_tolerance": 0.7}, ["--median-tolerance", "0.7"], "--median-tolerance: ",
     "median_tolerance: ", "must lie in [1e-10, 0.5], not 0.69999999999999996"),
    ("no iteration", {"max_iterations": 0}, ["--max-iterations", "0"], "--max-iterations: ", "max_iterations: ",
     "needs an integer from 1 to 100000, not 0"),
    ("too many iterations", {"max_iterations": 100001}, ["--max-iterations", "100001"], "--max-iterations: ",
     "max_iterations: ", "needs an integer from 1 to 100000, not 100001"),
]


@pytest.mark.parametrize("name,options,cli_options,cli_prefix,python_prefix,reason", BAD_PARAMETERS,
                         ids=[b[0] for b in BAD_PARAMETERS])
def test_bad_parameters_raise_the_command_lines_reason(example, tmp_path, name, options, cli_options, cli_prefix,
                                                       python_prefix, reason):
    options = {"domain": UNIT, "masses": MASSES, **options}
    with pytest.raises(ValueError) as error:
        apollonius3d.centroidal(*example[:2], **options)
    python_message = str(error.value)
    cli, masses_file = cli_message(tmp_path, options["domain"], cli_options, options["masses"])
    cli_prefix = cli_prefix.replace("MASSES", masses_file)
    assert cli.startswith(cli_prefix), cli
    assert python_message.startswith(python_prefix), python_message
    # The command line quotes an option's text where its parser checks it (--max-iterations, as --threads).
    cli_reason = cli[len(cli_prefix):]
    if "--max-iterations" in cli_options:
        cli_reason = cli_reason.replace("'", "")
    assert python_message[len(python_prefix):] == cli_reason
    assert reason in cli_reason


def test_bad_parameters_of_python_only(example):
    centres, weights, masses = example
    cases = [
        ({"domain": (0, 0, 0, 1, 1)}, "domain: expected 6 numbers X0 Y0 Z0 X1 Y1 Z1"),
        ({"domain": (0, 0, 0, 1, 1, np.inf)}, "domain: needs a finite number, not inf"),
        ({"domain": (0, 0, 0, 1, 1, np.nan)}, "domain: needs a finite number, not nan"),
        ({"masses": masses.reshape(2, 3)}, "masses: expected shape (n,), one per site, found (2, 3)"),
        ({"masses": np.where(np.arange(6) == 2, np.nan, masses)}, "masses: site 2: not a finite number: nan"),
        ({"masses": [1, 1, 1, 1, 1, 1]}, "masses: the masses sum to 6, not 1 (within 1e-9)"),
        ({"threads": 0}, "threads: needs an integer from 1 to 1024, not 0"),
        ({"tolerance": np.nan}, "tolerance: must lie in [1e-10, 0.5], not nan"),
    ]
    for options, message in cases:
        arguments = {"domain": UNIT, "masses": masses, **options}
        with pytest.raises(ValueError) as error:
            apollonius3d.centroidal(centres, weights, **arguments)
        assert str(error.value) == message, options
    same_centre = centres.copy()
    same_centre[4] = same_centre[1]
    with pytest.raises(ValueError, match=r"^centres: site 4: the site has the centre of site 1 \(0-based\): one would "
                                         r"hide the other for any weights$"):
        apollonius3d.centroidal(same_centre, weights, UNIT, masses=masses)
    with pytest.raises(ValueError, match=r"^centres: site 0, x: not a finite number: nan$"):
        apollonius3d.centroidal(np.where(np.arange(18).reshape(6, 3) == 0, np.nan, centres), weights, UNIT)
    with pytest.raises(TypeError):
        apollonius3d.centroidal(centres, weights, UNIT, masses)  # options are keywords
