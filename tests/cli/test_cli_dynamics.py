"""geardyn simulate and geardyn stats end to end: results, exit codes, bad input."""

import csv
import json
import os
import pathlib
import subprocess

import pytest

CLI = os.environ.get("GEARDYN_CLI", "build/bin/geardyn")
SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXAMPLES = SOURCE / "examples"


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)


def test_simulate_backlash_example(tmp_path):
    result = run("simulate", EXAMPLES / "simulate_gear_pair_backlash.toml", "--out", tmp_path,
                 "--set", "output.plots=false")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["status"] == "converged"
    r = summary["results"]
    assert r["steady_state"] is True
    assert r["model"]["mass"] == 1.589
    # Linear contact throughout: the mean mesh force is the transmitted load (the time average of
    # m x'' and c (x' - e') vanishes over a period).
    assert r["mesh_force"]["mean"] == pytest.approx(1418.4, rel=1e-6)
    assert r["contact_loss_fraction"] == 0.0
    assert len(r["mesh_force"]["harmonic_amplitudes"]) == 10
    with open(tmp_path / "time_response.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert list(rows[0]) == ["t_s", "x_transverse_m", "v_transverse_m_per_s", "y_transverse_m",
                             "mesh_force_transverse_n", "k_transverse_n_per_m"]
    assert len(rows) == 4 * 128
    row = rows[77]
    # Backlash law above the clearance: force = k (y - b).
    assert float(row["mesh_force_transverse_n"]) == pytest.approx(
        float(row["k_transverse_n_per_m"]) * (float(row["y_transverse_m"]) - 1e-4), rel=1e-9)


def test_simulate_contact_loss_and_newton(tmp_path):
    result = run("simulate", EXAMPLES / "simulate_gear_pair_backlash.toml", "--out", tmp_path,
                 "--set", "output.plots=false", "--set", "model.transmission_error.amplitudes=[6e-6]",
                 "--set", "excitation.mesh_frequency=2700", "--set", "solver.max_periods=3000")
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["results"]["newton_failures"] == 0
    assert summary["results"]["contact_loss_fraction"] > 0.0
    assert result.returncode in (0, 1)  # steady or not (impacting regimes may be non-periodic)
    assert (result.returncode == 0) == (summary["status"] == "converged")


def test_simulate_unstable_exits_1_with_status(tmp_path):
    config = tmp_path / "mathieu.toml"
    config.write_text("""
[model]
units = "nondimensional"
damping_ratio = 0.01
mean_force = 1.0
[model.stiffness]
cos = [0.3]
[excitation]
mesh_frequency = 2.0
[solver]
max_periods = 3000
[output]
plots = false
""")
    result = run("simulate", config, "--out", tmp_path / "o")
    assert result.returncode == 1
    assert "diverged" in result.stderr
    assert json.loads((tmp_path / "o" / "summary.json").read_text())["status"] == "diverged"


@pytest.mark.parametrize("override, expected", [
    ("model.mass=-1", "model.mass = -1: must be a number > 0 [kg]"),
    ("model.damping=10", "model.damping_ratio: give damping_ratio or damping, not both"),
    ("model.transmission_error.phases_deg=[0.0, 57.3]", "model.transmission_error.phases_deg = 2 values: one phase per amplitude of model.transmission_error.amplitudes"),
    ("model.stiffness.type=potential_energy", "computes the stiffness from the gears"),
    ("model.stiffness.mean=nan", "model.stiffness.mean = nan: must be finite"),
    ("solver.output_points_per_period=100", "must be a multiple of solver.output_points_per_period"),
    ("model.contact=backlahs", 'did you mean "backlash"?'),
])
def test_simulate_bad_input_exits_2(tmp_path, override, expected):
    result = run("simulate", EXAMPLES / "simulate_gear_pair_backlash.toml", "--out", tmp_path, "--set", override)
    assert result.returncode == 2, result.stderr
    assert expected in result.stderr


def test_simulate_warns_about_coarse_steps(tmp_path):
    result = run("simulate", EXAMPLES / "simulate_gear_pair_backlash.toml", "--out", tmp_path,
                 "--set", "output.plots=false", "--set", "solver.steps_per_period=8",
                 "--set", "solver.output_points_per_period=4")
    assert "larger than a tenth of the natural period" in result.stderr


@pytest.mark.parametrize("name, expected", [
    ("stats_gelman2005_case1_a025", 1.215), ("stats_gelman2005_case1_a075", 1.0475),
    ("stats_gelman2005_case2_a150", 0.896)])
def test_stats_paper_cases(tmp_path, name, expected):
    result = run("stats", EXAMPLES / f"{name}.toml", "--out", tmp_path)
    assert result.returncode == 0, result.stderr
    stats = json.loads((tmp_path / "summary.json").read_text())["results"]["mean_excitation"]
    assert stats["ratio"] == pytest.approx(expected, abs=1e-12)
    assert ("greater" in stats["classification"]) == (expected > 1)


def test_stats_simulated_check(tmp_path):
    result = run("stats", EXAMPLES / "stats_gear_pair_simulated.toml", "--out", tmp_path)
    assert result.returncode == 0, result.stderr
    results = json.loads((tmp_path / "summary.json").read_text())["results"]
    assert results["mean_excitation"]["dynamic_mean_excitation"] == pytest.approx(0.83, rel=1e-12)
    assert abs(results["simulation"]["relative_difference"]) < 1e-3


def test_stats_moments_need_their_keys(tmp_path):
    result = run("stats", EXAMPLES / "stats_gelman2005_case1_a025.toml", "--out", tmp_path,
                 "--set", "stats.r_ke=1.5")
    assert result.returncode == 2 and "stats.r_ke = 1.5" in result.stderr


def test_stats_from_a_csv_record(tmp_path):
    # The loaded STE of errorless gears is F/K: e = 0, so R = 1 exactly (Gelman: errorless,
    # unmodified gears). The record comes from geardyn stiffness.
    result = run("stiffness", EXAMPLES / "stiffness_visnadi2021_spur.toml", "--out", tmp_path / "k",
                 "--set", "output.plots=false", "--set", "mesh_stiffness.transmitted_force=2000",
                 "--set", "mesh_stiffness.models=[\"potential_energy\"]")
    assert result.returncode == 0, result.stderr
    config = tmp_path / "stats.toml"
    config.write_text(f'[stats]\nsource = "csv"\ncsv_file = "{tmp_path / "k" / "mesh_stiffness.csv"}"\n'
                      'baseload = 2000.0\na = 1.0\nzeta = 0.05\n')
    result = run("stats", config, "--out", tmp_path / "s")
    assert result.returncode == 0, result.stderr
    stats = json.loads((tmp_path / "s" / "summary.json").read_text())["results"]["mean_excitation"]
    assert stats["ratio"] == pytest.approx(1.0, abs=1e-12)
    assert stats["r_ke"] < -0.99  # the deflection F/K is out of phase with K


def test_stats_csv_with_nan_is_rejected(tmp_path):
    record = tmp_path / "record.csv"
    record.write_text("k_total,ste_m\n3e8,6e-6\nnan,6e-6\n3.2e8,5.9e-6\n")
    config = tmp_path / "stats.toml"
    config.write_text('[stats]\nsource = "csv"\ncsv_file = "record.csv"\nbaseload = 2000.0\na = 1.0\n')
    result = run("stats", config, "--out", tmp_path / "s")
    assert result.returncode == 2
    assert "row 3, column k_total" in result.stderr and "must be finite" in result.stderr
    record.write_text("k_total,ste_m\n3e8,6e-6\n3.2e8,5.9e-6\n")
    config.write_text('[stats]\nsource = "csv"\ncsv_file = "record.csv"\nbaseload = 2000.0\na = 1.0\n'
                      'csv_error_column = "ste"\n')
    result = run("stats", config, "--out", tmp_path / "s")
    assert result.returncode == 2 and 'did you mean "ste_m"?' in result.stderr


def test_simulate_extra_harmonic_force_matches_the_linear_response(tmp_path):
    # Constant stiffness, linear contact, no error, a force 100 cos(2π 300 t): the steady mesh
    # force amplitude at the mesh order where 300 Hz falls is k |H| 100 with H the FRF of m, c, k.
    import math
    config = tmp_path / "forced.toml"
    config.write_text("""
[model]
mass = 1.589
damping_ratio = 0.05
mean_force = 1000.0
extra_force_amplitudes = [100.0]
extra_force_frequencies = [300.0]
extra_force_phases_deg = [0.0]
[model.stiffness]
mean = 4.55e8
[excitation]
mesh_frequency = 300.0
[solver]
steps_per_period = 4096
output_points_per_period = 512
steady_tolerance = 1e-9
harmonics = 2
[output]
plots = false
""")
    result = run("simulate", config, "--out", tmp_path / "o")
    assert result.returncode == 0, result.stderr
    r = json.loads((tmp_path / "o" / "summary.json").read_text())["results"]
    m, k, zeta, w = 1.589, 4.55e8, 0.05, 2 * math.pi * 300.0
    c = 2 * zeta * math.sqrt(k * m)
    expected = k * 100.0 / abs(complex(k - m * w * w, w * c))
    assert r["mesh_force"]["harmonic_amplitudes"][0] == pytest.approx(expected, rel=1e-5)
    assert r["mesh_force"]["mean"] == pytest.approx(1000.0, rel=1e-9)
