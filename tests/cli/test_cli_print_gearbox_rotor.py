"""`geardyn rotor FILE --print-gearbox` for a lateral [rotor] file (issue #31; Rao 2023): the gearbox
it is — the thesis's mesh an isotropic bearing between the shafts, its transmission error and the
runouts prescribed displacements across the bearings, the runouts' inertia unbalances — is read
by `geardyn train`, whose modal solver gives the 4-DOF rotor's damped modes (each twice: y and z)."""

import csv
import json

import numpy as np

from cli_support import EXAMPLES, run

TABLE41 = EXAMPLES / "rotor_rao2023_table41.toml"

# The train's damped eigenproblem holds the 4-DOF one (the rotations are uncoupled): the same
# matrices from doubles that read back exactly, so the frequencies agree to the eigensolvers'
# round-off; 1e-8 relative leaves room for the 12-state against the 8-state solve.
RTOL = 1e-8


def four_dof_frequencies():
    """Damped natural frequencies [Hz] of Table 4.1 (masses, k_s, k_m; ζ_s = ζ_m = 0.01 with the
    eq. 4.9 mesh mass), from the 4 x 4 (x and y identical: the 2 x 2 of z = x + iy)."""
    m1, m2, ks, km, z = 0.310, 1.270, 1e6, 6e8, 0.01
    cs1, cs2 = 2 * z * np.sqrt(ks * m1), 2 * z * np.sqrt(ks * m2)
    cm = 2 * z * np.sqrt(km * m1 * m2 / (m1 + m2))
    M = np.diag([m1, m2])
    K = np.array([[ks + km, -km], [-km, ks + km]])
    C = np.array([[cs1 + cm, -cm], [-cm, cs2 + cm]])
    A = np.block([[np.zeros((2, 2)), np.eye(2)],
                  [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    lam = np.linalg.eigvals(A)
    return sorted({round(abs(l.imag) / (2 * np.pi), 9) for l in lam if l.imag > 0})


def test_the_lateral_rotor_is_a_gearbox_whose_modes_are_the_four_dof_modes(tmp_path):
    printed = run("rotor", TABLE41, "--print-gearbox")
    assert printed.returncode == 0, printed.stderr
    for section in ("[bearings.mesh]", "[bearing_excitations.transmission_error]",
                    "[unbalances.pinion_runout]", "[couplings.gear_ratio]"):
        assert section in printed.stdout, section
    (tmp_path / "gearbox.toml").write_text(printed.stdout)
    (tmp_path / "modal.toml").write_text(
        '[gearbox]\nfile = "gearbox.toml"\n\n[analysis]\nrun = ["static", "modal"]\n')
    result = run("train", tmp_path / "modal.toml", "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["results"]["static"]["status"] == "ok"
    with open(tmp_path / "out" / "modes.csv", newline="") as handle:
        train = [float(row["frequency_hz"]) for row in csv.DictReader(handle)]
    for f in four_dof_frequencies():
        matches = [g for g in train if abs(g - f) <= RTOL * f]
        assert len(matches) == 2, (f, train)  # y and z


def test_the_identifications_rig_is_a_gearbox_too(tmp_path):
    """`geardyn identify FILE --print-gearbox`: the known rig (masses, shaft springs, teeth,
    speed) as the gearbox the identification reduces to its 4-DOF rotor
    (system/lateral_rotor_reduction.h). Its TE is unknown, so the TE table states only the
    pinion's teeth: order t_p at zero amplitude (a 20/40 rig would otherwise read as 1/2)."""
    identify = EXAMPLES / "identify_rao2023_table41.toml"
    printed = run("identify", identify, "--print-gearbox", "--set", "rotor.pinion_teeth=20",
                  "--set", "rotor.gear_teeth=40")
    assert printed.returncode == 0, printed.stderr
    text = printed.stdout
    assert "[bearings.mesh]" in text and "[couplings.gear_ratio]" in text
    te = text[text.index("[bearing_excitations.transmission_error]"):]
    te = te[:te.index("\n\n")]
    assert "orders = [20" in te and "amplitude_y = [0" in te, te
    # `train` reads it: the rig's lateral modes (static + modal run, no TE needed).
    (tmp_path / "gearbox.toml").write_text(text)
    (tmp_path / "modal.toml").write_text(
        '[gearbox]\nfile = "gearbox.toml"\n\n[analysis]\nrun = ["static", "modal"]\n')
    result = run("train", tmp_path / "modal.toml", "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
