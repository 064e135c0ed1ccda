"""geardyn.GearTrain (issue 39): a gear train built once from a dict, a TOML or a REXS file and
analysed many times in-process. Its modes, static forces and forced response are those of the
CLI (`geardyn train`, the CSV files written with 17 significant digits) to 1e-12, and a changed
parameter gives the result of a train built afresh with that value."""

import csv
import os
import pathlib
import subprocess
import tomllib

import numpy as np
import pytest

import geardyn

SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXAMPLES = SOURCE / "examples"
CLI = os.environ.get("GEARDYN_CLI", str(SOURCE / "build" / "bin" / "geardyn"))
LIN_PARKER = EXAMPLES / "train_lin_parker1999.toml"
REDUCER = EXAMPLES / "gearboxes" / "two_stage_reducer.toml"
# The same library calls on the same inputs: the numbers agree to the CSV's 17 digits; 1e-12
# relative leaves room for nothing but the decimal round trip.
EXACT = 1e-12
# A parameter changed in place (rank-one updates of Σ k̄ v vᵀ and C) against a train built with
# the value: equal matrices to round-off (tests/system/train_model_updates_test.cpp), natural
# frequencies to 1e-12 of the highest.
UPDATED = 1e-12


def cli(tmp_path, config, *sets):
    args = [CLI, "train", str(config), "--out", str(tmp_path), "--quiet"]
    for s in sets:
        args += ["--set", s]
    done = subprocess.run(args, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return tmp_path


def column(path, name):
    with open(path, newline="") as handle:
        return np.array([float(row[name]) for row in csv.DictReader(handle)])


def reducer_analysis(tmp_path, run='["static", "modal"]'):
    path = tmp_path / "reducer.toml"
    path.write_text(f'[gearbox]\nfile = "{REDUCER}"\n[analysis]\nrun = {run}\n'
                    "[forced]\npoints = 5\nspeed_min_rpm = 300.0\nspeed_max_rpm = 2100.0\n"
                    "mesh_harmonics = 4\n[output]\nplots = false\n")
    return path


def test_modal_equals_the_cli_from_a_file_and_from_a_dict(tmp_path):
    out = cli(tmp_path / "cli", LIN_PARKER)
    expected = column(out / "modes.csv", "frequency_hz")
    train = geardyn.GearTrain(LIN_PARKER)
    np.testing.assert_allclose(train.frequencies(), expected, rtol=EXACT, atol=0)
    frame = train.modal()
    np.testing.assert_allclose(frame["frequency_hz"], expected, rtol=EXACT, atol=0)
    for name in ("damping_ratio", "translational_fraction", "strain_stage.sun_planet1",
                 "strain_sun_bearing"):
        np.testing.assert_allclose(frame[name], column(out / "modes.csv", name), rtol=EXACT,
                                   atol=1e-15)
    assert frame.attrs["shapes"].shape == (len(train.dof_names), len(expected))
    with open(LIN_PARKER, "rb") as handle:
        document = tomllib.load(handle)
    from_dict = geardyn.GearTrain(document)
    np.testing.assert_allclose(from_dict.frequencies(), expected, rtol=EXACT, atol=0)
    # Lin & Parker (1999): the first translational pair and rotational mode (as the example).
    assert abs(expected[1] / 743.2 - 1) < 5e-4 and abs(expected[5] / 1475.7 - 1) < 5e-4


def test_static_and_forced_equal_the_cli(tmp_path):
    config = reducer_analysis(tmp_path, '["static", "modal", "forced"]')
    out = cli(tmp_path / "cli", config)
    train = geardyn.GearTrain(config)
    static = train.static()
    np.testing.assert_allclose(static["force"], column(out / "static_forces.csv", "force"),
                               rtol=EXACT)
    speeds = column(out / "forced_response.csv", "speed_rpm")
    forced = train.forced(speeds)
    for name in ("dynamic_factor_stage1", "p2p_stage2_normal_n", "h1_stage1_normal_n"):
        np.testing.assert_allclose(forced[name], column(out / "forced_response.csv", name),
                                   rtol=EXACT)
    # The whole `train` on the built model: the CLI's summary numbers.
    result = geardyn.run("train", train)
    np.testing.assert_allclose(result.table("modes")["frequency_hz"],
                               column(out / "modes.csv", "frequency_hz"), rtol=EXACT)


@pytest.mark.parametrize("key, value", [
    ("planetary.stage.sun_planet.stiffness_value", 6.5e8),
    ("planetary.stage.ring_planet.stiffness_value", 3.0e8),
    ("operating_point.speed_rpm", 2000.0),
    ("operating_point.torque", 80.0),          # zero to loaded: every mesh's flank decided anew
])
def test_a_changed_parameter_gives_a_fresh_train(key, value):
    train = geardyn.GearTrain(LIN_PARKER)
    before = train.frequencies()
    assert train.set(key, value) == "parameters"
    fresh = geardyn.GearTrain(LIN_PARKER, overrides={key: value})
    np.testing.assert_allclose(train.frequencies(), fresh.frequencies(), rtol=0,
                               atol=UPDATED * fresh.frequencies()[-1])
    np.testing.assert_allclose(train.stiffness, fresh.stiffness, rtol=0,
                               atol=1e-13 * np.abs(fresh.stiffness).max())
    if key.endswith("stiffness_value"):  # the change is seen
        assert np.abs(train.frequencies() - before).max() > 1.0


def test_reducer_parameters_keys_and_rebuilds(tmp_path):
    config = reducer_analysis(tmp_path)
    train = geardyn.GearTrain(config, overrides={"meshes.stage1.stiffness": "constant",
                                                 "meshes.stage1.stiffness_value": 4e8})
    assert train.set("meshes.stage1.stiffness_value", 5.5e8) == "parameters"
    assert train.set("operating_point.torque", -150.0) == "parameters"  # other flank: rebuilt
    assert train.set("modal.modes", 6) == "nothing"
    assert train.set("bearings.input_a.kyy", 3e8) == "model"
    fresh = geardyn.GearTrain(config, overrides={
        "meshes.stage1.stiffness": "constant", "meshes.stage1.stiffness_value": 5.5e8,
        "operating_point.torque": -150.0, "modal.modes": 6, "bearings.input_a.kyy": 3e8})
    np.testing.assert_allclose(train.frequencies(), fresh.frequencies(), rtol=UPDATED)
    assert len(train.frequencies()) == 6
    np.testing.assert_allclose(train.static()["force"], fresh.static()["force"], rtol=1e-10)
    # The train's summary records every key set.
    config_seen = train.run(["static"]).summary["config"]["gearbox_description"]
    assert config_seen["meshes"]["stage1"]["stiffness_value"] == 5.5e8
    assert config_seen["operating_point"]["torque"] == -150.0


def test_bad_values_name_the_key_and_leave_the_train_as_it_was():
    train = geardyn.GearTrain(LIN_PARKER)
    before = train.frequencies()
    with pytest.raises(geardyn.ConfigError) as error:
        train.set("planetary.stage.sun_planet.stiffness_value", -1.0)
    assert error.value.key == "planetary.stage.sun_planet.stiffness_value"
    with pytest.raises(geardyn.ConfigError) as error:
        train.set("bearings.sun_bearing.kyy", -5.0)
    assert "kyy" in error.value.key
    with pytest.raises(geardyn.ConfigError):
        train.set("planetary.stage.sun_plnet.stiffness_value", 1e8)
    np.testing.assert_array_equal(train.frequencies(), before)
    with pytest.raises(FileNotFoundError):
        geardyn.GearTrain("no_such_gearbox.toml")


def test_rexs_file_equals_the_cli_on_it(tmp_path):
    exported = tmp_path / "reducer.rexsj"
    done = subprocess.run([CLI, "export", str(REDUCER), "-o", str(exported)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    analysis = tmp_path / "modal.toml"
    analysis.write_text('[gearbox]\nfile = "reducer.rexsj"\n[analysis]\nrun = ["modal"]\n'
                        "[output]\nplots = false\n")
    out = cli(tmp_path / "cli", analysis)
    train = geardyn.GearTrain(exported)
    np.testing.assert_allclose(train.frequencies(), column(out / "modes.csv", "frequency_hz"),
                               rtol=EXACT)
