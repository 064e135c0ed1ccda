"""`geardyn rotor FILE --print-gearbox` for a finite-element rotor file (issue #31): the gearbox
description it writes is read by `geardyn train`, whose modal solver gives the rotor's own modal
table — the FE rotor's modes come from the train's modal solver on that gearbox."""

import csv
import json

import pytest
import tomllib

from cli_support import EXAMPLES, run

MODAL = EXAMPLES / "rotor_visnadi2021_modal.toml"

# Both runs solve the same damped eigenproblem of the same matrices (one assembled from the
# gearbox text, whose doubles read back exactly, the other from the same text inside `rotor`):
# the frequencies agree to the eigensolver's round-off; 1e-9 relative leaves it room.
RTOL = 1e-9


def rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def print_gearbox(tmp_path, *args):
    result = run("rotor", MODAL, "--print-gearbox", *args)
    assert result.returncode == 0, result.stderr
    gearbox = tmp_path / "g.toml"
    gearbox.write_text(result.stdout)
    return gearbox


def test_the_printed_gearbox_is_a_flexible_two_shaft_train(tmp_path):
    text = print_gearbox(tmp_path).read_text()
    for line in ('dofs = "full"', "[shafts.pinion_shaft]", "[shafts.gear_shaft]", "flexible = true",
                 "stiffness_proportional_damping = 3e-05", '[meshes.mesh]',
                 'stiffness = "potential_energy"', "[mesh_stiffness.fourier]", "[operating_point]"):
        assert line in text, line
    # It does not run anything: no result folder.
    assert not (tmp_path / "summary.json").exists()


def test_the_train_modal_table_of_the_printed_gearbox_is_the_rotors(tmp_path):
    gearbox = print_gearbox(tmp_path)
    analysis = tmp_path / "modal.toml"
    analysis.write_text('[gearbox]\nfile = "g.toml"\n\n[analysis]\nrun = ["modal"]\n\n'
                        "[modal]\nmodes = 60\n\n[output]\nplots = false\n")
    train = run("train", analysis, "--out", tmp_path / "train")
    assert train.returncode == 0, train.stderr
    rotor = run("rotor", MODAL, "--out", tmp_path / "rotor", "--set", "output.plots=false")
    assert rotor.returncode == 0, rotor.stderr
    rotor_modes = json.loads((tmp_path / "rotor" / "summary.json").read_text())
    train_modes = json.loads((tmp_path / "train" / "summary.json").read_text())
    ours = rotor_modes["results"]["modal"]["modes"]
    theirs = train_modes["results"]["modal"]["modes"]
    assert len(ours) == 16
    # The train keeps the shafts' axial DOFs, which the spur rotor file leaves out (uncoupled:
    # their modes are extra entries of its list); every rotor mode is a train mode.
    train_frequencies = [m["frequency_hz"] for m in theirs]
    for mode in ours:
        f = mode["frequency_hz"]
        match = min(train_frequencies, key=lambda g: abs(g - f))
        assert match == pytest.approx(f, rel=RTOL), (f, match)
    assert train_frequencies[0] == pytest.approx(ours[0]["frequency_hz"], rel=RTOL)
    assert ours[0]["frequency_hz"] == pytest.approx(666.976, rel=1e-5)  # the example's number


def test_a_files_unbalance_is_the_gearboxs_unbalance(tmp_path):
    # The unbalance becomes [unbalances.<shaft>_unbalance<i>] at its node's position, and the
    # printed gearbox is a valid `train` file.
    result = run("rotor", MODAL, "--print-gearbox", "--set", "pinion_shaft.unbalance.nodes=[1]",
                 "--set", "pinion_shaft.unbalance.amount=[1e-5]",
                 "--set", "pinion_shaft.unbalance.phase_deg=[45.0]")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "[unbalances.pinion_shaft_unbalance0]" in result.stdout
    gearbox = tomllib.loads(result.stdout)
    unbalance = gearbox["unbalances"]["pinion_shaft_unbalance0"]
    assert unbalance["shaft"] == "pinion_shaft"
    assert unbalance["position"] == pytest.approx(0.1, rel=1e-15)  # node 1: one 100 mm element
    assert unbalance["mass_eccentricity"] == pytest.approx(1e-5, rel=1e-15)
    assert unbalance["phase_deg"] == pytest.approx(45.0, rel=1e-15)
    (tmp_path / "g.toml").write_text(result.stdout)
    analysis = tmp_path / "modal.toml"
    analysis.write_text('[gearbox]\nfile = "g.toml"\n\n[analysis]\nrun = ["modal"]\n\n'
                        "[output]\nplots = false\n")
    check = run("train", analysis, "--out", tmp_path / "train")
    assert check.returncode == 0, check.stdout + check.stderr


def test_a_helical_file_without_axial_dofs_is_refused_naming_the_key():
    result = run("rotor", MODAL, "--print-gearbox", "--set", "pinion.helix_angle_deg=5.0",
                 "--set", "gear.helix_angle_deg=-5.0")
    assert result.returncode == 2, result.stdout + result.stderr
    assert "model.axial" in result.stderr, result.stderr
