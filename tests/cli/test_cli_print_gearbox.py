"""geardyn simulate|hbm|stats FILE --print-gearbox (issue #31): the gearbox a gear-pair file is,
analysed by `geardyn train`, has the gear pair's natural frequency and mean mesh force; a command
without a translation refuses the flag (exit 2)."""

import json
import math

from cli_support import EXAMPLES, run

BACKLASH = EXAMPLES / "simulate_gear_pair_backlash.toml"

# The first elastic mode of the two-inertia torsional train is sqrt(k_mean / m_e) / 2 pi
# (undamped); it comes from a dense symmetric eigensolver on a 2x2 system whose matrices are built
# from the printed doubles (inertias 2 m_e r_b^2, mean stiffness of the Fourier series), so the
# two agree to round-off; 1e-9 leaves room for the eigensolver's and the mean's quadrature
# round-off while a wrong mass, stiffness or radius (errors of percent) fails.
FREQUENCY_RTOL = 1e-9
# The static mesh force is the input torque F r_b over r_b: round-off only.
FORCE_RTOL = 1e-12


def summary(folder):
    with open(folder / "summary.json") as handle:
        return json.load(handle)


def test_printed_gearbox_is_the_simulated_gear_pair(tmp_path):
    printed = run("simulate", BACKLASH, "--print-gearbox")
    assert printed.returncode == 0, printed.stderr
    assert not (tmp_path / "results").exists()
    gearbox = tmp_path / "g.toml"
    gearbox.write_text(printed.stdout)
    text = printed.stdout
    assert "nominal spur pair" in text  # the file has no gear geometry: the comment says so
    assert "backlash = 0.0002" in text  # model.normal_backlash, the full clearance
    analysis = tmp_path / "analysis.toml"
    analysis.write_text(
        '[gearbox]\nfile = "g.toml"\n\n[analysis]\nrun = ["static", "modal"]\n\n'
        "[output]\nplots = false\n")
    train = run("train", analysis, "--out", tmp_path / "train")
    assert train.returncode == 0, train.stderr
    simulate = run("simulate", BACKLASH, "--out", tmp_path / "simulate",
                   "--set", "output.plots=false")
    assert simulate.returncode == 0, simulate.stderr

    model = summary(tmp_path / "simulate")["results"]["model"]
    results = summary(tmp_path / "train")["results"]
    first = results["modal"]["modes"][0]  # the rigid-body mode is not listed
    # The train's modes are the damped ones: f_d = f_n sqrt(1 - zeta^2).
    zeta = first["damping_ratio"]
    assert math.isclose(zeta, model["damping_ratio"], rel_tol=FREQUENCY_RTOL), (first, model)
    f_undamped = first["frequency_hz"] / math.sqrt(1.0 - zeta * zeta)
    f_n = model["natural_frequency"] / (2.0 * math.pi)
    assert math.isclose(f_undamped, f_n, rel_tol=FREQUENCY_RTOL), (f_undamped, f_n)
    force = results["static"]["mesh_force_n"]["mesh"]
    assert math.isclose(abs(force), model["mean_force"], rel_tol=FORCE_RTOL), (force, model)


def test_hbm_and_stats_print_their_gearbox(tmp_path):
    for command, example in [("hbm", "hbm_saletti2025_100Nm.toml"),
                             ("hbm", "hbm_backlash_kahraman_singh.toml"),
                             ("stats", "stats_monte_carlo_pitch_errors.toml")]:
        printed = run(command, EXAMPLES / example, "--print-gearbox")
        assert printed.returncode == 0, (example, printed.stderr)
        assert "[meshes.mesh]" in printed.stdout and 'dofs = "torsional"' in printed.stdout


def test_print_gearbox_without_a_translation_is_bad_input(tmp_path):
    # geometry and train have no gearbox translation (train reads a gearbox): the option is not
    # theirs; stats from moments holds no gear pair.
    for command, example in (("geometry", "geometry_rao2023_rig.toml"),
                             ("train", "train_two_stage_reducer.toml")):
        refused = run(command, EXAMPLES / example, "--print-gearbox")
        assert refused.returncode == 2, refused.stderr
        assert "--print-gearbox" in refused.stderr and refused.stdout == ""
        assert "--print-gearbox" not in run(command, "--help").stdout
    moments = run("stats", EXAMPLES / "stats_gelman2005_case1_a025.toml", "--print-gearbox")
    assert moments.returncode == 2, moments.stderr
    assert "stats.source" in moments.stderr
    assert moments.stdout == ""
