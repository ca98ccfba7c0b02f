"""Bad input raises ValueError with the command line's message; internal errors raise RuntimeError."""
from fractions import Fraction

import numpy as np
import pytest

import apollonius3d
from conftest import REPOSITORY, cli_error_message, run_cli

# (name, file name, content): each makes the command line exit 2 with FILE[:LINE]: reason.
BAD_FILES = [
    ("NaN", "bad.txt", "1 2 3 4\n1 nan 3 4\n"),
    ("infinity", "bad.txt", "1 2 3 4\n1 2 inf 4\n"),
    ("out of range", "bad.txt", "1 2 3 4\n1 2 3 1e400\n"),
    ("three numbers", "bad.txt", "1 2 3 4\n1 2 3\n"),
    ("words", "bad.txt", "1 2 3 4\nhello world foo bar\n"),
    ("empty file", "bad.txt", ""),
    ("comments only", "bad.txt", "# nothing\n\n"),
    ("binary data", "bad.txt", "1 2 3 4\n\0\0\x01 junk"),
    ("vdrc count", "bad.txt", "3\n1 0 0 0 1\n2 1 0 0 1\n"),
    ("PDB without atoms", "bad.pdb", "HEADER    NOTHING HERE\nEND\n"),
    ("PDB coordinate", "bad.pdb", "ATOM      1  N   ALA A   1       1.0x0   2.000   3.000  1.00  0.00           N\n"),
    ("mmCIF without atoms", "bad.cif", "data_empty\n_cell.length_a 10\n"),
]


@pytest.mark.parametrize("name,file_name,content", BAD_FILES, ids=[b[0] for b in BAD_FILES])
def test_bad_files_raise_the_command_lines_message(tmp_path, name, file_name, content):
    path = tmp_path / file_name
    path.write_bytes(content.encode("latin-1"))
    code, _, err = run_cli("vertices", path)
    assert code == 2
    with pytest.raises(ValueError) as error:
        apollonius3d.read_sites(path)
    assert str(error.value) == cli_error_message(err)
    assert str(error.value).startswith(str(path))


def test_missing_file_and_directory(tmp_path):
    for path in [tmp_path / "missing.txt", tmp_path / "missing.pdb.gz", tmp_path]:
        code, _, err = run_cli("vertices", path)
        assert code == 2
        with pytest.raises(ValueError) as error:
            apollonius3d.read_sites(path)
        assert str(error.value) == cli_error_message(err)
        assert "cannot open" in str(error.value)


def test_bundled_bad_structure_files():
    for name in ["structure_coordinate_not_finite.pdb", "gemmi_cif_integer_overflow.cif",
                 "gemmi_line_split_at_high_byte.pdb", "gemmi_shift_of_negative_char.txt"]:
        path = REPOSITORY / "tests" / "data" / "regression" / name
        code, _, err = run_cli("vertices", path)
        assert code == 2
        with pytest.raises(ValueError, match="^" + str(path)) as error:
            apollonius3d.read_sites(path)
        assert str(error.value) == cli_error_message(err)


CENTRES = np.arange(15, dtype=float).reshape(5, 3)
WEIGHTS = np.ones(5)


def with_value(array, index, value, dtype=float):
    changed = np.array(array, dtype=dtype)
    changed[index] = value
    return changed


# (name, centres, weights, message): the whole ValueError message.
BAD_ARRAYS = [
    ("NaN x", with_value(CENTRES, (3, 0), np.nan), WEIGHTS, "centres: site 3, x: not a finite number: nan"),
    ("inf z", with_value(CENTRES, (0, 2), np.inf), WEIGHTS, "centres: site 0, z: not a finite number: inf"),
    ("NaN weight", CENTRES, with_value(WEIGHTS, 4, np.nan), "weights: site 4: not a finite number: nan"),
    ("-inf weight", CENTRES, with_value(WEIGHTS, 1, -np.inf), "weights: site 1: not a finite number: -inf"),
    ("NaN in a list", [[0, 0, 0], [1, 1, float("nan")]], [1, 1], "centres: site 1, z: not a finite number: nan"),
    ("no site", np.zeros((0, 3)), np.zeros(0), "centres: empty input: no sites"),
    ("two columns", np.zeros((5, 2)), WEIGHTS, "centres: expected shape (n, 3), found (5, 2)"),
    ("flat centres", np.zeros(15), WEIGHTS, "centres: expected shape (n, 3), found (15,)"),
    ("3-d centres", np.zeros((5, 3, 1)), WEIGHTS, "centres: expected shape (n, 3), found (5, 3, 1)"),
    ("scalar centres", 1.0, WEIGHTS, "centres: expected shape (n, 3), found ()"),
    ("empty list", [], [], "centres: expected shape (n, 3), found (0,)"),
    ("short weights", CENTRES, np.ones(4), "weights: expected shape (5,), one per centre, found (4,)"),
    ("2-d weights", CENTRES, np.ones((5, 1)), "weights: expected shape (5,), one per centre, found (5, 1)"),
    ("scalar weight", CENTRES, 1.4, "weights: expected shape (5,), one per centre, found ()"),
    ("strings", [["a", "b", "c"]] * 5, WEIGHTS, "centres: expected numbers, found an array of dtype <U1"),
    ("complex", CENTRES + 1j, WEIGHTS, "centres: expected numbers, found an array of dtype complex128"),
    ("bool", CENTRES, np.ones(5, dtype=bool), "weights: expected numbers, found an array of dtype bool"),
    ("None", [[0, 0, None]] * 5, WEIGHTS, "centres: site 0, z: not a finite number: nan"),  # numpy's None is NaN
    ("object", [[0, 0, {}]] * 5, WEIGHTS,
     "centres: cannot convert to float64: float() argument must be a string or a real number, not 'dict'"),
    ("ragged", [[0, 0, 0], [1, 1]], [1, 1], "centres: not an array of numbers: setting an array element with a "
     "sequence. The requested array has an inhomogeneous shape after 1 dimensions. The detected shape was (2,) + "
     "inhomogeneous part."),
    ("int64 beyond 2^53", with_value(CENTRES, (2, 1), 2**53 + 1, np.int64), WEIGHTS,
     "centres: site 2, y: 9007199254740993 (int64) is not exactly a double; round it first if that is meant"),
    ("uint64 at 2^64 - 1", CENTRES, with_value(WEIGHTS, 0, 2**64 - 1, np.uint64),
     "weights: site 0: 18446744073709551615 (uint64) is not exactly a double; round it first if that is meant"),
    ("a third", CENTRES, [1, 1, Fraction(1, 3), 1, 1],
     "weights: site 2: 1/3 (object) is not exactly a double; round it first if that is meant"),
    ("long double", with_value(CENTRES, (1, 0), np.longdouble(1) / 3, np.longdouble), WEIGHTS,
     "centres: site 1, x: " + str(np.longdouble(1) / 3) + " (float128) is not exactly a double; round it first if "
     "that is meant"),
]


@pytest.mark.parametrize("name,centres,weights,message", BAD_ARRAYS, ids=[b[0] for b in BAD_ARRAYS])
def test_bad_arrays_raise_value_error(name, centres, weights, message):
    with pytest.raises(ValueError) as error:
        apollonius3d.vertices(centres, weights)
    assert str(error.value) == message


def test_bad_arrays_for_certify_too(tmp_path):
    claim = tmp_path / "claim.txt"
    claim.write_text("")
    with pytest.raises(ValueError, match=r"^centres: site 3, x: not a finite number: nan$"):
        apollonius3d.certify(with_value(CENTRES, (3, 0), np.nan), WEIGHTS, claim)


def test_bad_options():
    with pytest.raises(ValueError, match=r"^threads: needs an integer from 1 to 1024, not 0$"):
        apollonius3d.vertices(CENTRES, WEIGHTS, threads=0)
    with pytest.raises(ValueError, match=r"^threads: needs an integer from 1 to 1024, not 1025$"):
        apollonius3d.vertices(CENTRES, WEIGHTS, threads=1025)
    with pytest.raises(ValueError, match=r"^box: needs X0 <= X1, Y0 <= Y1, Z0 <= Z1$"):
        apollonius3d.vertices(CENTRES, WEIGHTS, box=(0, 0, 0, 1, -1, 1))
    with pytest.raises(ValueError, match=r"^box: expected 6 numbers X0 Y0 Z0 X1 Y1 Z1$"):
        apollonius3d.vertices(CENTRES, WEIGHTS, box=(0, 0, 0, 1, 1))
    with pytest.raises(ValueError, match=r"^box: needs finite numbers$"):
        apollonius3d.vertices(CENTRES, WEIGHTS, box=(0, 0, 0, 1, 1, np.nan))
    with pytest.raises(TypeError):
        apollonius3d.vertices(CENTRES, WEIGHTS, 2)  # options are keywords
    with pytest.raises(TypeError):
        apollonius3d.read_sites(42)


# (name, claim content, CLI option): bad claim files for certify, for the sites of pept.pdb (107).
BAD_CLAIMS = [
    ("short line", "0 1 2 3 1 2 3\n"),
    ("index out of range", "0 1 2 500 1 2 3 4\n"),
    ("repeated index", "0 1 1 3 1 2 3 4\n"),
    ("NaN", "0 1 2 3 1 2 nan 4\n"),
    ("bad JSON", "{\"vertices\": [\n"),
    ("JSON for other sites", "{\"format\": \"apollonius3d-vertices\", \"sites\": 9, \"vertices\": []}\n"),
]


@pytest.mark.parametrize("name,content", BAD_CLAIMS, ids=[b[0] for b in BAD_CLAIMS])
def test_bad_claims_raise_the_command_lines_message(tmp_path, pept_pdb, name, content):
    claim = tmp_path / "claim.txt"
    claim.write_text(content)
    code, _, err = run_cli("certify", pept_pdb, claim)
    assert code == 2
    with pytest.raises(ValueError) as error:
        apollonius3d.certify(*apollonius3d.read_sites(pept_pdb), claim)
    assert str(error.value) == cli_error_message(err)


def test_missing_claim_and_unwritable_report(tmp_path, pept_pdb):
    missing = tmp_path / "missing.txt"
    code, _, err = run_cli("certify", pept_pdb, missing)
    assert code == 2
    with pytest.raises(ValueError) as error:
        apollonius3d.certify(*apollonius3d.read_sites(pept_pdb), missing)
    assert str(error.value) == cli_error_message(err)

    claim = tmp_path / "claim.txt"
    claim.write_text("")
    report = tmp_path / "no" / "such" / "directory" / "report.json"
    code, _, err = run_cli("certify", pept_pdb, claim, "--report", report)
    assert code == 2
    with pytest.raises(OSError) as error:
        apollonius3d.certify(*apollonius3d.read_sites(pept_pdb), claim, report=report)
    assert str(error.value) == cli_error_message(err)
    assert not report.parent.exists()


def test_certify_options(tmp_path, pept_pdb):
    claim = tmp_path / "claim.txt"
    claim.write_text("")
    sites = apollonius3d.read_sites(pept_pdb)
    with pytest.raises(ValueError, match=r"^format: needs text, json or voronota, not 'xml'$"):
        apollonius3d.certify(*sites, claim, format="xml")
    with pytest.raises(ValueError, match=r"^coord_tol: needs a finite number >= 0"):
        apollonius3d.certify(*sites, claim, coord_tol=-1)
    with pytest.raises(ValueError, match=r"^threads: needs an integer from 1 to 1024, not 0$"):
        apollonius3d.certify(*sites, claim, threads=0)


def test_internal_errors_raise_runtime_error():
    # The translation of C++ exceptions (python/src/errors.cpp), as the command line's exit codes 2 and 3.
    with pytest.raises(ValueError, match=r"^file.txt:3: reason$"):
        apollonius3d._raise_for_testing("input")
    with pytest.raises(OSError, match=r"^cannot write out.txt: reason$"):
        apollonius3d._raise_for_testing("output")
    with pytest.raises(RuntimeError, match=r"^internal error: broken invariant$"):
        apollonius3d._raise_for_testing("internal")
    with pytest.raises(MemoryError):
        apollonius3d._raise_for_testing("memory")
