"""geardyn stiffness: the Visnadi examples end to end, output files, bad input."""

import csv
import json
import os
import pathlib
import subprocess

import pytest

CLI = os.environ.get("GEARDYN_CLI", "build/bin/geardyn")
SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
SPUR = SOURCE / "examples" / "stiffness_visnadi2021_spur.toml"
HELICAL = SOURCE / "examples" / "stiffness_visnadi2021_helical.toml"
T = "_transverse_n_per_m"  # k along the transverse line of action, in N/m
K = "k_total" + T
PLOTS = os.environ.get("GEARDYN_PLOTS", "1") == "1"


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)


def test_visnadi_spur_end_to_end(tmp_path):
    result = run("stiffness", SPUR, "--out", tmp_path, "--set", "mesh_stiffness.transmitted_force=2000")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "summary.json").read_text())
    k = summary["results"]["mesh_stiffness"]
    assert k["model"] == "potential_energy"
    assert k["mean"] == pytest.approx(3.164e8, rel=5e-4)
    assert k["min"] == pytest.approx(2.151e8, rel=5e-4)
    assert k["max"] == pytest.approx(3.787e8, rel=5e-4)
    assert k["contact_ratio"] == pytest.approx(1.6325826, abs=1e-7)
    assert len(k["fourier"]["amplitude"]) == 10
    models = summary["results"]["models"]
    assert list(models) == ["potential_energy", "api", "step", "fourier", "iso6336"]
    assert models["api"]["mean"] == pytest.approx(2.41140e8, rel=1e-12)
    assert models["api"]["directional_matrix"][0][1] == pytest.approx(-7.750090e7, rel=1e-6)
    assert models["step"]["mean"] == pytest.approx(2.41140e8, rel=1e-12)  # levels = "api"
    assert models["fourier"]["mean"] == pytest.approx(2.41140e8, rel=1e-12)
    assert k["mean"] > models["api"]["mean"]  # the paper's finding
    ste = summary["results"]["static_transmission_error"]
    assert ste["mean"] == pytest.approx(2000 / 3.0e8, rel=0.2)
    with open(tmp_path / "mesh_stiffness.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 1000
    assert list(rows[0])[:6] == ["roll_angle_rad", "mesh_fraction", "t_s", K, "k_pair_1" + T, "k_pair_2" + T]
    assert "k_iso6336" + T in rows[0] and "ste_transverse_m" in rows[0]
    row = rows[317]
    assert float(row[K]) == pytest.approx(float(row["k_pair_1" + T]) + float(row["k_pair_2" + T]), rel=1e-14)
    assert float(row["ste_transverse_m"]) == pytest.approx(2000 / float(row[K]), rel=1e-14)
    fourier = (tmp_path / "fourier.csv").read_text().splitlines()
    assert fourier[0].startswith("model,order,cosine_n_per_m")
    assert len(fourier) == 1 + 5 * 11
    expected = ["mesh_stiffness.csv", "fourier.csv"] + (["mesh_stiffness.png"] if PLOTS else [])
    assert summary["files"] == expected


def test_visnadi_helical_mean_above_api(tmp_path):
    result = run("stiffness", HELICAL, "--out", tmp_path, "--set", "output.plots=false")
    assert result.returncode == 0, result.stderr
    models = json.loads((tmp_path / "summary.json").read_text())["results"]["models"]
    assert models["potential_energy"]["mean"] > models["api"]["mean"]
    assert models["api"]["mean"] == pytest.approx(12.057 * 20 * 1e6 * 0.9961946981 ** 2, rel=1e-6)
    assert models["potential_energy"]["contact_ratio"] > 1.8  # transverse + overlap


@pytest.mark.parametrize("override, expected", [
    ("mesh_stiffness.models=[\"potential_energy\", \"apii\"]", 'did you mean "api"?'),
    ("mesh_stiffness.step.levels=given", "mesh_stiffness.step.k_min: required when"),
    ("mesh_stiffness.positions=3", "mesh_stiffness.positions = 3: must be an integer in [8, 1e+06]"),
    ("mesh_stiffness.potential_energy.root=curved", 'must be one of "straight", "trochoid"'),
    ("mesh_stiffness.fourier.amplitudes=[0.5, -0.1]", "must be a list of numbers each >= 0"),
    ("pinion.bore_diameter=0", "fillet-foundation model (Sainsot 2004) needs the radius"),
    ("mesh_stiffness.transmitted_force=-5", "mesh_stiffness.transmitted_force = -5"),
    ("mesh_stiffness.error_phases_deg=[0.0, 10.0]", "mesh_stiffness.error_phases_deg = 2 values: one phase per amplitude of mesh_stiffness.error_amplitudes (0 values), or none"),
])
def test_bad_input_exits_2(tmp_path, override, expected):
    models = "mesh_stiffness.models=[\"potential_energy\", \"step\"]"
    extra = [] if override.startswith("mesh_stiffness.models") else ["--set", models]
    result = run("stiffness", SPUR, "--out", tmp_path, "--set", override, *extra)
    assert result.returncode == 2, result.stderr
    assert expected in result.stderr


def test_transmission_error_with_a_geometric_error_table(tmp_path):
    # Step stiffness 1e8 / 2e8 N/m, F = 1000 N, e(φ) a triangle 0 → 2 µm → 0 over the period:
    # δ = F/k + e, checked at a few phases by hand.
    result = run("stiffness", SPUR, "--out", tmp_path, "--set", "output.plots=false",
                 "--set", "mesh_stiffness.models=[\"step\"]", "--set", "mesh_stiffness.step.levels=given",
                 "--set", "mesh_stiffness.step.k_min=1e8", "--set", "mesh_stiffness.step.k_max=2e8",
                 "--set", "mesh_stiffness.transmitted_force=1000",
                 "--set", "mesh_stiffness.error_table_phases=[0.0, 0.5]",
                 "--set", "mesh_stiffness.error_table_values=[0.0, 2e-6]")
    assert result.returncode == 0, result.stderr
    with open(tmp_path / "mesh_stiffness.csv", newline="") as handle:
        rows = {round(float(r["mesh_fraction"]), 3): float(r["ste_transverse_m"]) for r in csv.DictReader(handle)}
    assert rows[0.25] == pytest.approx(5e-6 + 1e-6, rel=1e-12)   # k_max (double contact)
    assert rows[0.75] == pytest.approx(1e-5 + 1e-6, rel=1e-12)   # k_min, e back down to 1 µm
    assert rows[0.63] == pytest.approx(5e-6 + 2e-6 * (1 - 0.13 / 0.5), rel=1e-12)
    bad = run("stiffness", SPUR, "--out", tmp_path / "bad", "--set", "mesh_stiffness.error_table_phases=[0.5, 0.2]",
              "--set", "mesh_stiffness.error_table_values=[0.0, 1e-6]", "--set", "mesh_stiffness.transmitted_force=1")
    assert bad.returncode == 2 and "mesh_stiffness.error.table_phases[1] = 0.2: the phases must increase strictly" in bad.stderr
