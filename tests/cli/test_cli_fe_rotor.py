"""geardyn rotor with [model] type = "fe_geared_rotor" (Visnadi 2021): the result files and
summary of each analysis, the choice of schema from the file, and bad input named by its key."""

import csv
import json
import math

import pytest

from cli_support import EXAMPLES, run

TIME = EXAMPLES / "rotor_visnadi2021_time.toml"
RUNUP = EXAMPLES / "rotor_visnadi2021_runup.toml"
MODAL = EXAMPLES / "rotor_visnadi2021_modal.toml"


def rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def test_time_analysis_writes_steady_harmonics_and_the_resolved_config(tmp_path):
    result = run("rotor", TIME, "--out", tmp_path, "--set", "output.plots=false",
                 "--set", "time.duration=0.3")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["config"]["model"]["type"] == "fe_geared_rotor"
    assert summary["config"]["damping"]["stiffness_proportional"] == 3e-5
    assert summary["geardyn_version"]
    results = summary["results"]
    assert results["model"]["dofs"] == 30
    assert results["model"]["mean_mesh_stiffness_n_per_m"] == pytest.approx(3.1636e8, rel=1e-4)
    # Mesh frequency 25 × 500/60 and a periodic steady state by the end.
    assert results["model"]["mesh_frequency_hz"] == pytest.approx(208.3333, rel=1e-6)
    assert results["steady"]["last_period_change"] < 1e-8
    table = rows(tmp_path / "harmonics.csv")
    assert {r["channel"] for r in table} >= {"pinion_shaft.1.uy", "gear_shaft.0.uz"}
    assert len(table) == 8 * 10
    history = rows(tmp_path / "time_history.csv")
    assert len(history) == 3001  # 30,000 steps written every 10th, with t = 0
    assert float(history[0]["t_s"]) == 0.0 and float(history[0]["pinion_shaft.1.uy_m"]) == 0.0
    # The mesh force settles around T / r_bp (the steady mean of the dynamic force).
    tail = [float(r["mesh_force_normal_n"]) for r in history[-480:]]
    assert sum(tail) / len(tail) == pytest.approx(results["model"]["nominal_mesh_force_n"], rel=2e-2)


def test_run_up_tracks_orders_and_lists_the_campbell_crossings(tmp_path):
    result = run("rotor", RUNUP, "--out", tmp_path, "--set", "output.plots=false",
                 "--set", "time.duration=0.4", "--set", "speed.end_rpm=1800")
    assert result.returncode == 0, result.stderr
    runup = json.loads((tmp_path / "summary.json").read_text())["results"]["runup"]
    crossings = runup["campbell_mesh_crossings"]
    # Within 1000-1800 rpm the mesh line meets only the first mode (at 1601 rpm; the second
    # follows at 1818 rpm).
    assert [c["mode"] for c in crossings] == [0]
    assert crossings[0]["speed_rpm"] == pytest.approx(1600.7, rel=1e-3)
    track = rows(tmp_path / "runup.csv")
    speeds = [float(r["speed_rpm"]) for r in track if r["channel"] == "gear_shaft.1.rx"]
    assert speeds == sorted(speeds) and 1000 < speeds[0] < speeds[-1] < 1800
    assert (tmp_path / "waterfall.csv").exists()


def test_modal_analysis_lists_modes_and_shapes(tmp_path):
    result = run("rotor", MODAL, "--out", tmp_path, "--set", "output.plots=false")
    assert result.returncode == 0, result.stderr
    modes = rows(tmp_path / "modes.csv")
    assert len(modes) == 16
    freqs = [float(m["frequency_hz"]) for m in modes]
    assert freqs == sorted(freqs) and freqs[0] == pytest.approx(667.0, rel=1e-3)
    assert {m["whirl"] for m in modes} >= {"forward", "backward", "torsional"}
    for m in modes:
        total = float(m["lateral_fraction"]) + float(m["torsional_fraction"]) + float(m["axial_fraction"])
        assert total == pytest.approx(1.0, abs=1e-12)
    assert len(rows(tmp_path / "mode_shapes.csv")) == 16 * 30


@pytest.mark.parametrize("override, key, fragment", [
    ("pinion_shaft.gear_nod=1", "pinion_shaft.gear_nod", "gear_node"),  # unknown key: did-you-mean
    ("time.outputs=[\"pinion_shaft.7.uy\"]", "time.outputs", "pinion_shaft.7.uy"),
    ("time.outputs=[\"gear_shaft.1.ux\"]", "time.outputs", "model.axial"),
    ("pinion_shaft.bearings.nodes=[0, 5]", "pinion_shaft.bearings.nodes", "[0, 2]"),
    ("gear_shaft.bearings.kyy=[7e7, 7e7, 7e7]", "gear_shaft.bearings.kyy", "one value or 2"),
    ("gear_shaft.bearings.czz=[-150.0]", "gear_shaft.bearings.czz", ">= 0"),
    ("pinion_shaft.element_lengths=[0.1, nan]", "pinion_shaft.element_lengths", "finite"),
    ("pinion_shaft.element_lengths=[0.1, -0.1]", "pinion_shaft.element_lengths", "> 0"),
    ("model.axial=true", "pinion_shaft.bearings.k_axial", "axial"),
    ("speed.end_speed_rpm=800.0", "speed.end_speed_rpm", "constant speed"),
    ("speed.speed_rpm=0.0", "speed.speed_rpm", "speed > 0"),
])
def test_bad_input_is_rejected_naming_the_key(tmp_path, override, key, fragment):
    config = EXAMPLES / "rotor_visnadi2021_compare_spur.toml"
    result = run("rotor", config, "--out", tmp_path, "--set", override)
    assert result.returncode == 2, result.stdout + result.stderr
    assert key in result.stderr and fragment in result.stderr, result.stderr
    assert not (tmp_path / "summary.json").exists()


def test_schema_depends_on_the_model_type(tmp_path):
    # The FE keys are unknown to Rao's rotor schema and the other way round.
    rao = EXAMPLES / "rotor_rao2023_table41.toml"
    result = run("rotor", rao, "--out", tmp_path, "--set", "damping.stiffness_proportional=1e-5")
    assert result.returncode == 2 and "damping" in result.stderr
    reference = run("schema", "rotor").stdout
    assert "`pinion_mass`" in reference and "one of \"fe_geared_rotor\"" in reference


def test_time_analysis_at_rest_has_no_harmonics(tmp_path):
    result = run("rotor", TIME, "--out", tmp_path, "--set", "output.plots=false",
                 "--set", "speed.rpm=0.0", "--set", "time.duration=0.01")
    assert result.returncode == 0, result.stderr
    assert json.loads((tmp_path / "summary.json").read_text())["results"]["steady"] is None


def test_a_record_too_short_for_the_steady_window_is_refused_before_it_runs(tmp_path):
    # 100 rpm, 25 pinion teeth: mesh period 24 ms; the example's window is 40 mesh periods,
    # so 2 ms is refused (exit 2) before anything is integrated or written.
    out = tmp_path / "new" / "out"
    result = run("rotor", TIME, "--out", out, "--set", "speed.rpm=100.0",
                 "--set", "time.duration=0.002")
    assert result.returncode == 2, result.stdout + result.stderr
    assert "time.duration = 0.002 s" in result.stderr, result.stderr
    assert "at least 0.96 s" in result.stderr and "mesh periods of 24 ms" in result.stderr
    assert "time.window_mesh_periods = 40" in result.stderr
    assert not (tmp_path / "new").exists()  # nothing written, not even the folder


def test_a_failed_run_leaves_the_previous_results_of_the_folder_whole(tmp_path):
    ok = run("rotor", TIME, "--out", tmp_path, "--set", "output.plots=false",
             "--set", "speed.rpm=0.0", "--set", "time.duration=0.002")
    assert ok.returncode == 0, ok.stderr
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    assert "summary.json" in before and "time_history.csv" in before
    failed = run("rotor", TIME, "--out", tmp_path, "--set", "output.plots=false",
                 "--set", "speed.rpm=100.0", "--set", "time.duration=0.002")
    assert failed.returncode == 2, failed.stderr
    # Same files, same bytes, no staging folder left behind.
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before


def test_a_run_up_shorter_than_one_tracking_window_is_refused(tmp_path):
    result = run("rotor", RUNUP, "--out", tmp_path / "out", "--set", "time.duration=0.01",
                 "--set", "time.runup_window=0.02")
    assert result.returncode == 2, result.stderr
    assert "time.duration = 0.01 s" in result.stderr and "time.runup_window = 0.02 s" in result.stderr
    assert not (tmp_path / "out").exists()
