"""geardyn train: a gearbox file read by an analysis file (or inline), the result files of every
analysis, the Lin & Parker table from the command line, --set into the gearbox file, and bad
input named by component and key."""

import csv
import json
import shutil

import pytest

from cli_support import EXAMPLES, run

REDUCER = EXAMPLES / "train_two_stage_reducer.toml"
PLANETARY = EXAMPLES / "train_planetary_parallel.toml"
LIN_PARKER = EXAMPLES / "train_lin_parker1999.toml"


def rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def quick(*extra):
    return ["--set", "output.plots=false", *extra]


def test_lin_parker_table_from_the_command_line(tmp_path):
    result = run("train", LIN_PARKER, "--out", tmp_path, *quick())
    assert result.returncode == 0, result.stderr
    modes = rows(tmp_path / "modes.csv")
    assert len(modes) == 18
    found = {(round(float(m["frequency_hz"]), 1), m["stage_type"]) for m in modes}
    # Lin & Parker 1999 (N = 3): rotational and translational frequencies [Hz].
    for hz, kind in [(1475.7, "rotational"), (11775.3, "rotational"), (743.2, "translational"),
                     (9647.9, "translational")]:
        assert (hz, kind) in found


def test_reducer_writes_every_analysis_and_records_both_files(tmp_path):
    result = run("train", REDUCER, "--out", tmp_path, *quick("--set", "forced.points=20",
                                                             "--set", "campbell.points=11"))
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["geardyn_version"]
    assert summary["config"]["gearbox"]["file"] == "gearboxes/two_stage_reducer.toml"
    assert summary["config"]["gearbox_description"]["meshes"]["stage1"]["gears"] == ["z1", "z2"]
    results = summary["results"]
    assert results["kinematics"]["output_torque_n_m"] == pytest.approx(-200 * 51 / 23 * 47 / 17)
    for name in ["bodies.csv", "meshes.csv", "static_forces.csv", "modes.csv", "mode_shapes.csv",
                 "campbell.csv", "critical_speeds.csv", "forced_response.csv", "time_history.csv"]:
        assert (tmp_path / name).exists(), name
    meshes = {m["mesh"]: m for m in rows(tmp_path / "meshes.csv")}
    assert float(meshes["stage1"]["mesh_frequency_hz"]) == pytest.approx(23 * 1500 / 60)
    # Newmark agrees with the frequency-domain steady state within 0.5 % of the p2p.
    for mesh, difference in results["time"]["max_difference_to_steady_state_relative_to_p2p"].items():
        assert difference < 5e-3, mesh


def test_set_reaches_the_gearbox_file(tmp_path):
    result = run("train", REDUCER, "--out", tmp_path,
                 *quick("--set", "analysis.run=[\"static\"]", "--set", "operating_point.torque=400"))
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "summary.json").read_text())
    forces = summary["results"]["static"]["mesh_force_n"]
    half = run("train", REDUCER, "--out", tmp_path / "b", *quick("--set", "analysis.run=[\"static\"]"))
    assert half.returncode == 0
    base = json.loads((tmp_path / "b" / "summary.json").read_text())["results"]["static"]["mesh_force_n"]
    assert forces["stage1"] == pytest.approx(2 * base["stage1"], rel=1e-9)


def test_inline_and_file_descriptions_give_the_same_results(tmp_path):
    inline = tmp_path / "inline.toml"
    gearbox = (EXAMPLES / "gearboxes" / "two_stage_reducer.toml").read_text()
    inline.write_text('[analysis]\nrun = ["static", "modal"]\n' + gearbox)
    a = run("train", inline, "--out", tmp_path / "a", *quick())
    b = run("train", REDUCER, "--out", tmp_path / "b", *quick("--set", 'analysis.run=["static","modal"]'))
    assert a.returncode == 0 and b.returncode == 0, a.stderr + b.stderr
    assert (tmp_path / "a" / "modes.csv").read_text() == (tmp_path / "b" / "modes.csv").read_text()


@pytest.mark.parametrize("edit, key, words", [
    (("[meshes.stage1]\n", "[meshes.stage1]\nposition_angel_deg = 3\n"),
     "meshes.stage1.position_angel_deg", "did you mean"),
    (('gears = ["z1", "z2"]', 'gears = ["z1", "z9"]'), "meshes.stage1.gears", "z9"),
    (('shaft = "intermediate"\nteeth = 51', 'shaft = "input"\nteeth = 51'), "meshes.stage1.gears",
     "both sit on shaft"),
    (("teeth = 51\nmodule = 3e-3", "teeth = 51\nmodule = 3.5e-3"), "gears.z2", "module"),
    (('input = "motor"', 'input = "motr"'), "operating_point.input", "did you mean \"motor\""),
    (("k_torsion = 2.5e4", "k_torsion = -2.5e4"), "couplings.motor_coupling.k_torsion", "> 0"),
    # Nonlinear meshes (issue 17): a backlash law needs its backlash, and only it takes one.
    (("[meshes.stage1]\n", "[meshes.stage1]\ncontact = \"backlash\"\n"), "meshes.stage1.backlash",
     "contact = \"backlash\""),
    (("[meshes.stage1]\n", "[meshes.stage1]\ncontact = \"linear\"\nbacklash = 2e-5\n"),
     "meshes.stage1.backlash", "only with contact"),
    (("[meshes.stage1]\n", "[meshes.stage1]\nbacklash = -2e-5\n"), "meshes.stage1.backlash", "> 0"),
])
def test_bad_gearbox_input_exits_2_naming_the_key(tmp_path, edit, key, words):
    folder = tmp_path / "case"
    shutil.copytree(EXAMPLES, folder, ignore=shutil.ignore_patterns("data", "python"))
    gearbox = folder / "gearboxes" / "two_stage_reducer.toml"
    text = gearbox.read_text()
    assert edit[0] in text
    gearbox.write_text(text.replace(edit[0], edit[1], 1))
    result = run("train", folder / REDUCER.name, "--out", tmp_path / "out", *quick())
    assert result.returncode == 2, result.stdout + result.stderr
    assert key in result.stderr and words in result.stderr, result.stderr
    assert not (tmp_path / "out" / "summary.json").exists()


def test_planets_that_cannot_be_assembled_exit_2(tmp_path):
    result = run("train", PLANETARY, "--out", tmp_path, *quick("--set", "planetary.stage1.planets=5"))
    assert result.returncode == 2
    assert "planetary.stage1.planets" in result.stderr and "96" in result.stderr


def test_a_missing_gearbox_file_is_named(tmp_path):
    analysis = tmp_path / "a.toml"
    analysis.write_text('[gearbox]\nfile = "nowhere.toml"\n')
    result = run("train", analysis, "--out", tmp_path / "o")
    assert result.returncode == 2 and "nowhere.toml" in result.stderr


def test_a_train_too_fine_for_memory_is_refused_before_it_allocates(tmp_path):
    # 1 µm elements on a 0.25 m shaft: 250 000 nodes, 1.5e6 DOFs, 1.8e14 B of dense matrices.
    flexible = EXAMPLES / "train_two_stage_flexible.toml"
    result = run("train", flexible, "--out", tmp_path, *quick(
        "--set", "shafts.input.max_element_length=1e-6"))
    assert result.returncode == 2, result.stderr
    assert "shafts.input.max_element_length = 1e-06 m" in result.stderr, result.stderr
    assert "DOFs need" in result.stderr and "GEARDYN_MEMORY_LIMIT" in result.stderr
    assert not (tmp_path / "summary.json").exists()


def test_a_divergent_mode_is_reported_not_dropped(tmp_path):
    # Planets on soft radial pins in a carrier turning at 7500 rpm: the anisotropic support in
    # the turning frame diverges (docs/theory/gear_trains.md). Before, the negative stiffness was
    # clipped to a rigid-body mode and the modal table silently had one mode less.
    result = run("train", LIN_PARKER, "--out", tmp_path, *quick(
        "--set", "planetary.stage.pin_radial_stiffness=1e5",
        "--set", "planetary.stage.sun_planet.stiffness_value=1e7",
        "--set", "planetary.stage.ring_planet.stiffness_value=1e7",
        "--set", "operating_point.speed_rpm=30000",
        "--set", 'analysis.run=["modal", "campbell"]',
        "--set", "campbell.speed_min_rpm=20000", "--set", "campbell.speed_max_rpm=40000",
        "--set", "campbell.points=6"))
    assert result.returncode == 0, result.stderr
    assert "1 divergent mode(s), growth rate up to 144.7 1/s" in result.stderr
    assert "divergent modes (statically unstable train) between 28000.0 and 40000.0 rpm" in \
        result.stderr
    first = rows(tmp_path / "modes.csv")[0]
    assert first["divergent"] == "1"
    assert float(first["frequency_hz"]) == 0.0 and float(first["damping_ratio"]) == -1.0
    assert abs(float(first["growth_rate_1_per_s"]) - 144.69) < 0.01
    rates = [float(r["divergence_rate_1_per_s"]) for r in rows(tmp_path / "campbell.csv")]
    assert rates[:2] == [0.0, 0.0] and all(r > 0 for r in rates[2:])
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["results"]["campbell"]["divergence"]["from_rpm"] == 28000.0
    assert summary["results"]["modal"]["modes"][0]["divergent"] is True
    assert any("divergent" in w for w in summary["warnings"])


def test_a_planetary_stage_with_six_dofs_per_member(tmp_path):
    full = ("--set", 'gearbox.dofs="full"')
    refused = run("train", LIN_PARKER, "--out", tmp_path / "refused", *quick(*full))
    assert refused.returncode == 2
    assert "shafts.sun.diametral_inertia" in refused.stderr
    inertias = []
    for shaft in ("sun", "ring", "carrier"):
        inertias += ["--set", f"shafts.{shaft}.diametral_inertia=1e-3"]
    for bearing in ("sun_bearing", "ring_support", "carrier_bearing"):
        inertias += ["--set", f"bearings.{bearing}.k_axial=2e8", "--set",
                     f"bearings.{bearing}.k_tilt=3e5"]
    result = run("train", LIN_PARKER, "--out", tmp_path / "ok", *quick(*full, *inertias))
    assert result.returncode == 0, result.stderr
    assert "fixed-frame lumped model" in result.stderr  # carrier_frame_terms noted, not applied
    modes = rows(tmp_path / "ok" / "modes.csv")
    assert len(modes) == 36
    types = [m["stage_type"] for m in modes]
    assert types.count("out_of_plane") == 18
    # The in-plane modes are the planar ones: Lin & Parker's table.
    found = {round(float(m["frequency_hz"]), 1) for m in modes}
    for hz in (1475.7, 11775.3, 743.2, 9647.9):
        assert hz in found
