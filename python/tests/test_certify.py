"""certify(): the command line's verdicts, summary and report on the same claims."""
import json
import shutil
import subprocess

import numpy as np
import pytest

import apollonius3d
from conftest import REPOSITORY, run_cli


def certify_both(tmp_path, input_path, claim, *options, **keywords):
    """(Python's Certification, its report, the command line's exit code, stderr and report)."""
    cli_report, py_report = tmp_path / "cli.json", tmp_path / "py.json"
    code, _, err = run_cli("certify", input_path, claim, "--report", cli_report, *options)
    result = apollonius3d.certify(*apollonius3d.read_sites(input_path), claim, report=py_report, **keywords)
    return result, json.loads(py_report.read_text()), code, err, json.loads(cli_report.read_text())


def assert_same_as_cli(result, py_report, code, err, cli_report):
    assert result.summary == err
    assert result.passed == (code == 0) == bool(result)
    assert py_report.pop("input") == "<arrays>"
    cli_report.pop("input")
    assert py_report == cli_report
    assert result.counts == cli_report["counts"]
    assert result.verdicts.tolist() == [c["verdict"] for c in cli_report["claims"]]
    assert result.vertex.tolist() == [c["vertex"]["index"] if "vertex" in c else -1 for c in cli_report["claims"]]
    assert result.missing.tolist() == [m["index"] for m in cli_report["missing"]]


def test_our_own_output_is_confirmed(tmp_path, pept_pdb):
    claim = tmp_path / "pept.txt"
    assert run_cli("vertices", pept_pdb, "-o", claim)[0] == 0
    result, *rest = certify_both(tmp_path, pept_pdb, claim)
    assert_same_as_cli(result, *rest)
    assert result.passed and result.counts["confirmed"] == result.counts["claims"] > 500
    assert (result.verdicts == "confirmed").all()
    assert result.vertex.tolist() == list(range(len(result.vertex)))
    assert "passed" in repr(result)


def test_a_doctored_claim_gets_the_command_lines_verdicts(tmp_path, pept_pdb):
    lines = run_cli("vertices", pept_pdb)[1].splitlines()
    doctored = lines[:5] + lines[6:]  # vertex 5 missing
    fields = doctored[0].split()
    fields[-4] = repr(float(fields[-4]) + 1e-3)  # coordinates off
    doctored[0] = " ".join(fields)
    doctored.append(doctored[1])  # a duplicate
    doctored.append("0 1 2 100 1 2 3 4")  # not a vertex: site 100 is far from sites 0 1 2
    claim = tmp_path / "doctored.txt"
    claim.write_text("\n".join(doctored) + "\n")
    result, *rest = certify_both(tmp_path, pept_pdb, claim)
    assert_same_as_cli(result, *rest)
    assert not result.passed
    assert result.verdicts[0] == "coordinates_off" and result.verdicts[-2] == "duplicate"
    assert result.verdicts[-1] == "not_a_vertex" and result.vertex[-1] == -1
    assert result.missing.tolist() == [5]


def test_options_as_the_command_lines(tmp_path, pept_pdb):
    lines = run_cli("vertices", pept_pdb)[1].splitlines()
    fields = lines[0].split()
    fields[-4] = repr(float(fields[-4]) + 1e-7)
    claim = tmp_path / "claim.txt"
    claim.write_text("\n".join([" ".join(fields)] + lines[1:]) + "\n")
    result, *rest = certify_both(tmp_path, pept_pdb, claim, "--coord-tol", "1e-6", "--format", "text", "--threads",
                                 "2", coord_tol=1e-6, format="text", threads=2)
    assert_same_as_cli(result, *rest)
    assert result.passed
    assert not apollonius3d.certify(*apollonius3d.read_sites(pept_pdb), claim).passed


@pytest.mark.skipif(shutil.which("voronota") is None, reason="Debian's voronota is not installed")
def test_voronotas_output(tmp_path):
    balls = REPOSITORY / "tests" / "data" / "vdrc" / "ANO3_3CONNECT.txt"
    # Voronota reads balls text: the vdrc file less its count line and ids.
    sites = apollonius3d.read_sites(balls)
    balls_text = "".join(f"{x!r} {y!r} {z!r} {w!r}\n" for (x, y, z), w in zip(sites.centres.tolist(),
                                                                              sites.weights.tolist()))
    (tmp_path / "ano3.balls").write_text(balls_text)
    claim = tmp_path / "ano3.voronota"
    claim.write_text(subprocess.run(["voronota", "calculate-vertices"], input=balls_text, capture_output=True,
                                    text=True, check=True).stdout)
    result, *rest = certify_both(tmp_path, tmp_path / "ano3.balls", claim)
    assert_same_as_cli(result, *rest)
    assert result.counts["missing"] == 4 and result.counts["confirmed"] == 4  # README: tracing finds 4 of 8


def test_json_claims(tmp_path, pept_pdb):
    claim = tmp_path / "pept.json"
    assert run_cli("vertices", pept_pdb, "-o", claim)[0] == 0
    result, *rest = certify_both(tmp_path, pept_pdb, claim, strict=True)
    rest[-1]["strict"] = True  # the command line ran without --strict; nothing else differs here
    assert_same_as_cli(result, *rest)
    assert result.passed and isinstance(result.missing, np.ndarray)
