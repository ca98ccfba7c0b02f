"""read_sites(): the sites the command line reads, with the atom labels of structures."""
import numpy as np
import pytest

import apollonius3d
from conftest import REPOSITORY, assert_same_doubles

# Residue 1 (ALA) with a hydrogen, atom CB in two alternate locations, a ligand, and a water.
SMALL_PDB = (
    "HEADER    TEST\n"
    "ATOM      1  N   ALA A   1       1.000   2.000   3.000  1.00  0.00           N\n"
    "ATOM      2  CA  ALA A   1       2.000   2.000   3.000  1.00  0.00           C\n"
    "ATOM      3  CB AALA A   1       3.000   2.000   3.000  0.50  0.00           C\n"
    "ATOM      4  CB BALA A   1       3.500   2.000   3.000  0.50  0.00           C\n"
    "ATOM      5  H   ALA A   1       0.500   2.000   3.000  1.00  0.00           H\n"
    "HETATM    6 SE   SE  A 101       5.000   5.000   5.000  1.00  0.00          SE\n"
    "HETATM    7  O   HOH A 201       9.000   9.000   9.000  1.00  0.00           O\n"
    "END\n"
)


def pdb_atoms(path):
    """An independent reading of a PDB file's first model, with the command line's rules: no hydrogens,
    no waters, the first alternate location of each atom."""
    atoms, first_altloc = [], {}
    for line in open(path, encoding="latin-1"):
        if line.startswith("ENDMDL"):
            break
        if not line.startswith(("ATOM  ", "HETATM")):
            continue
        element = line[76:78].strip()
        if not element.isalpha():  # old files hold other things there: the element from the atom name
            element = line[12:14].strip().lstrip("0123456789")
        residue = line[17:20].strip()
        if element in ("H", "D") or residue in ("HOH", "WAT", "DOD", "H2O"):
            continue
        altloc = line[16]
        key = (line[21], line[22:27], line[12:16].strip())
        if altloc != " " and first_altloc.setdefault(key, altloc) != altloc:
            continue
        atoms.append(dict(serial=int(line[6:11]), atom_name=line[12:16].strip(), altloc=altloc.strip(),
                          residue_name=residue, chain=line[21].strip(), residue_number=int(line[22:26]),
                          insertion_code=line[26].strip(), element=element.capitalize(),
                          centre=[float(line[30:38]), float(line[38:46]), float(line[46:54])]))
    return atoms


@pytest.mark.parametrize("name", ["examples/pept.pdb", "bench/data/pdb/1hpv.pdb", "bench/data/pdb/1j3h.pdb"])
def test_structure_atoms_and_labels(name):
    sites = apollonius3d.read_sites(REPOSITORY / name)
    atoms = pdb_atoms(REPOSITORY / name)
    assert sites.format == "structure"
    assert len(sites) == len(sites.labels) == len(atoms) > 100
    assert_same_doubles(sites.centres, [a["centre"] for a in atoms])
    labels = sites.labels
    assert labels.serial.tolist() == [a["serial"] for a in atoms]
    assert labels.atom_name.tolist() == [a["atom_name"] for a in atoms]
    assert labels.residue_name.tolist() == [a["residue_name"] for a in atoms]
    assert labels.residue_number.tolist() == [a["residue_number"] for a in atoms]
    assert labels.insertion_code.tolist() == [a["insertion_code"] for a in atoms]
    assert labels.chain.tolist() == [a["chain"] for a in atoms]
    assert labels.element.tolist() == [a["element"] for a in atoms]
    assert labels.alternate_location.tolist() == [a["altloc"] for a in atoms]
    radii = {"C": 1.70, "N": 1.55, "O": 1.52, "S": 1.80, "Se": 1.90, "P": 1.80}
    assert sites.weights.tolist() == [radii.get(a["element"], 1.80) for a in atoms]
    assert labels.residue_number.dtype == np.int64 and labels.serial.dtype == np.int64
    for column in (labels.chain, labels.residue_name, labels.residue_number, labels.insertion_code, labels.atom_name,
                   labels.element, labels.alternate_location, labels.serial):
        assert column.flags.owndata and column.shape == (len(sites),)
        assert column.dtype.kind in "Ui"


def test_pept_labels_as_voronota_annotates_them():
    # tests/data/pept.balls is Voronota's reading of pept.pdb: "x y z r # serial chain resnum resname atom . ."
    sites = apollonius3d.read_sites(REPOSITORY / "examples" / "pept.pdb")
    balls = apollonius3d.read_sites(REPOSITORY / "tests" / "data" / "pept.balls")
    assert balls.format == "balls" and balls.labels is None
    assert_same_doubles(sites.centres, balls.centres)
    assert_same_doubles(sites.weights, balls.weights)
    annotations = [line.split("#")[1].split() for line in open(REPOSITORY / "tests" / "data" / "pept.balls")]
    labels = sites.labels
    assert [[str(labels.serial[i]), labels.chain[i], str(labels.residue_number[i]), labels.residue_name[i],
             labels.atom_name[i]] for i in range(len(sites))] == [a[:5] for a in annotations]


def test_hydrogens_waters_and_alternate_locations(tmp_path):
    path = tmp_path / "small.pdb"
    path.write_text(SMALL_PDB)
    sites = apollonius3d.read_sites(path)
    assert sites.labels.atom_name.tolist() == ["N", "CA", "CB", "SE"]
    assert sites.labels.alternate_location.tolist() == ["", "", "A", ""]
    assert sites.weights.tolist() == [1.55, 1.70, 1.70, 1.90]
    assert sites.labels.element.tolist() == ["N", "C", "C", "Se"]
    kept = apollonius3d.read_sites(path, keep_hydrogens=True, keep_waters=True)
    assert kept.labels.atom_name.tolist() == ["N", "CA", "CB", "H", "SE", "O"]
    assert kept.labels.residue_name.tolist() == ["ALA"] * 4 + ["SE", "HOH"]
    assert kept.labels.residue_number.tolist() == [1, 1, 1, 1, 101, 201]
    assert_same_doubles(kept.centres[3], [0.5, 2, 3])
    assert apollonius3d.read_sites(str(path), keep_waters=True).labels.residue_name.tolist()[-1] == "HOH"


def test_mmcif_labels(tmp_path):
    path = tmp_path / "small.cif"
    path.write_text(
        "data_small\n#\nloop_\n_atom_site.group_PDB\n_atom_site.id\n_atom_site.type_symbol\n"
        "_atom_site.label_atom_id\n_atom_site.label_alt_id\n_atom_site.label_comp_id\n_atom_site.label_asym_id\n"
        "_atom_site.label_entity_id\n_atom_site.label_seq_id\n_atom_site.pdbx_PDB_ins_code\n_atom_site.Cartn_x\n"
        "_atom_site.Cartn_y\n_atom_site.Cartn_z\n_atom_site.occupancy\n_atom_site.B_iso_or_equiv\n"
        "_atom_site.auth_seq_id\n_atom_site.auth_asym_id\n_atom_site.pdbx_PDB_model_num\n"
        "ATOM 1 N N  . ASP A 1 1 ? 4.868 -17.809 25.188 1.00 34.37 1 E 1\n"
        "ATOM 2 C CA . ASP A 1 1 ? 3.984 -16.723 25.698 1.00 33.85 1 E 1\n"
        "ATOM 7 SE SE . MSE A 1 2 B 1.0 2.0 3.0 1.00 33.85 12 E 1\n#\n")
    sites = apollonius3d.read_sites(path)
    assert sites.format == "structure"
    assert_same_doubles(sites.centres, [[4.868, -17.809, 25.188], [3.984, -16.723, 25.698], [1, 2, 3]])
    assert sites.labels.atom_name.tolist() == ["N", "CA", "SE"]
    assert sites.labels.chain.tolist() == ["E"] * 3
    assert sites.labels.residue_number.tolist() == [1, 1, 12]
    assert sites.labels.insertion_code.tolist() == ["", "", "B"]
    assert sites.labels.serial.tolist() == [1, 2, 7]
    assert sites.labels.element.tolist() == ["N", "C", "Se"]


def test_balls_and_vdrc_have_no_labels():
    vdrc = apollonius3d.read_sites(REPOSITORY / "tests" / "data" / "vdrc" / "ANO3_3CONNECT.txt")
    assert vdrc.format == "vdrc" and vdrc.labels is None and len(vdrc) == 9
    assert vdrc.centres.shape == (9, 3) and vdrc.weights.shape == (9,)
    for array in (vdrc.centres, vdrc.weights):
        assert array.dtype == np.float64 and array.flags.owndata and array.flags.c_contiguous
    assert "9 sites from vdrc input" in repr(vdrc)
