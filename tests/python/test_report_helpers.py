"""The pieces of the figures and the HTML report that are plain functions: stability runs,
log-axis floors, headline rows, JSON for a <script> element, finding plotly.js."""

import json
import pathlib

import pytest

from geardyn import report
from geardyn._tables import log_floor, mesh_frequency_per_rpm, stability_runs


def test_stability_runs_share_their_boundary_points():
    runs = stability_runs([0, 1, 2, 3, 4], [10, 11, 12, 13, 14], [False, False, True, True, False])
    assert runs == [([0, 1, 2], [10, 11, 12], False), ([2, 3, 4], [12, 13, 14], True), ([4], [14], False)]
    assert stability_runs([0, 1], [5, 6], [True, True]) == [([0, 1], [5, 6], True)]
    assert stability_runs([], [], []) == []


def test_log_floor_is_derived_from_the_data():
    assert log_floor([1e-20, 1e-3, 2.0]) == pytest.approx(2e-6)  # numerical zeros do not count
    assert log_floor([0.5, 2.0]) == 0.5  # small dynamic range: the smallest value
    assert log_floor([0.0, -1.0]) is None


def test_mesh_frequency_per_rpm_needs_the_pinion_teeth():
    assert mesh_frequency_per_rpm({"config": {"pinion": {"teeth": 25}}}) == pytest.approx(25 / 60)
    assert mesh_frequency_per_rpm({"config": {"model": {"torque": 100.0}}}) is None


def test_headline_rows_flatten_results_with_units_from_key_names():
    summary = {"command": "hbm", "status": "ok",
               "results": {"wall_time_s": 0.25, "peak": {"frequency_hz": 1632.5, "stable": True},
                           "folds": [{"f": 1}, {"f": 2}], "harmonics": 14, "skip": None,
                           "conventions": {"frame": "shaft: each shaft relative to its own rotation (long)"}}}
    rows = report.headline_rows(summary)
    assert ("wall_time_s", "0.25", "s") in rows
    assert ("peak.frequency_hz", "1632.5", "Hz") in rows
    assert ("peak.stable", "yes", "") in rows
    assert ("folds", "2 entries", "") in rows
    assert not [r for r in rows if r[0] in ("skip", "conventions.frame")]  # nothing, prose


def test_headline_units_come_from_lower_case_suffixes_longest_first():
    # A torque in N m is not in m, a force per rpm is not in rpm: the longest ending wins.
    summary = {"command": "train", "status": "ok",
               "results": {"kinematics": {"output_torque_n_m": -975.0, "input_speed_rpm": 1500.0},
                           "static": {"mesh_force_n": {"stage1": 3084.5}},
                           "nonlinear": {"mesh_frequency_hz_per_rpm": {"stage1": 0.38},
                                         "stiffness_n_per_m": 4e8, "tilt_deg": 1.5,
                                         "energy_j": 2.0, "stress_pa": 1e6},
                           "old": {"torque_N_m": 1.0, "frequency_Hz": 2.0}}}
    units = {name: unit for name, _, unit in report.headline_rows(summary)}
    assert units["kinematics.output_torque_n_m"] == "N m"
    assert units["kinematics.input_speed_rpm"] == "rpm"
    assert units["static.mesh_force_n.stage1"] == "N"  # a mesh's name: its parent's unit
    assert units["nonlinear.mesh_frequency_hz_per_rpm.stage1"] == "Hz/rpm"
    assert units["nonlinear.stiffness_n_per_m"] == "N/m"
    assert units["nonlinear.tilt_deg"] == "°"
    assert units["nonlinear.energy_j"] == "J"
    assert units["nonlinear.stress_pa"] == "Pa"
    # Files written before the convention still read.
    assert units["old.torque_N_m"] == "N m" and units["old.frequency_Hz"] == "Hz"


def test_script_json_cannot_close_the_script_element_and_has_no_nan():
    text = report._script_json({"a": "</script><b>", "b": float("nan"), "c": [float("inf"), 1.0]})
    assert "</" not in text
    assert json.loads(text) == {"a": "</script><b>", "b": None, "c": [None, 1.0]}


def test_missing_plotly_js_names_the_fix(tmp_path, monkeypatch):
    monkeypatch.setenv("GEARDYN_PLOTLY_JS", str(tmp_path / "none.js"))
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(report, "_NPM_PATH", tmp_path / "absent" / "plotly.min.js")
    monkeypatch.setattr(report.pathlib.Path, "is_file", lambda self: False)
    with pytest.raises(FileNotFoundError, match="scripts/setup.sh --deps"):
        report.find_plotly_js()


def test_write_report_refuses_a_folder_without_summary(tmp_path):
    with pytest.raises(FileNotFoundError, match="no summary.json"):
        report.write_report(tmp_path)


def test_python_m_geardyn_report_imports_the_module_once(tmp_path):
    # `geardyn report` runs `python -m geardyn.report`: importing the package must not import
    # geardyn.report first (runpy's RuntimeWarning "found in sys.modules"), made an error here.
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-W", "error::RuntimeWarning", "-m", "geardyn.report",
                           str(tmp_path)], capture_output=True, text=True)
    assert "RuntimeWarning" not in done.stderr, done.stderr
    assert "no summary.json" in done.stderr and done.returncode != 0


def test_the_report_header_states_the_run_s_wall_time(tmp_path):
    import geardyn

    result = geardyn.run("geometry", {"pinion": {"teeth": 25, "module": 3e-3, "face_width": 0.02},
                                      "gear": {"teeth": 30, "module": 3e-3, "face_width": 0.02}})
    folder = result.save(tmp_path / "run")
    page = pathlib.Path(report.write_report(str(folder), str(tmp_path / "r.html"))).read_text()
    assert f"wall time {result.wall_time_s:.3g} s" in page
