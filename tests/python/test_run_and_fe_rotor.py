"""geardyn.run (every command from Python, config dicts with the file's key names, errors mapped
to exceptions) and the FE rotor bindings (numpy views without copies, modal, Campbell)."""

import os
import pathlib

import numpy as np
import pytest

import geardyn

SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXAMPLES = SOURCE / "examples"


def test_run_accepts_a_dict_with_the_config_key_names(tmp_path):
    config = {"pinion": {"teeth": 25, "module": 3e-3, "face_width": 0.02},
              "gear": {"teeth": 30, "module": 3e-3, "face_width": 0.02},
              "mesh_stiffness": {"models": ["api"]}}
    result = geardyn.run("stiffness", config, out=tmp_path, plots=False)
    assert result.status == "ok"
    assert result.results["mesh_stiffness"]["mean"] == pytest.approx(2.4114e8, rel=1e-4)
    table = result.table("mesh_stiffness")
    assert isinstance(table["k_total_transverse_n_per_m"], np.ndarray) and table["k_total_transverse_n_per_m"].size > 100


def test_run_maps_errors_to_exceptions(tmp_path):
    with pytest.raises(ValueError, match="pinion.teeth"):
        geardyn.run("geometry", EXAMPLES / "geometry_rao2023_rig.toml",
                    overrides={"pinion.teeth": 2}, out=tmp_path, plots=False)
    with pytest.raises(ValueError, match="did you mean"):
        geardyn.run("geometry", EXAMPLES / "geometry_rao2023_rig.toml",
                    overrides=["pinion.teth=20"], out=tmp_path, plots=False)


def test_to_toml_round_trips_through_the_loader(tmp_path):
    text = geardyn.to_toml({"study": {"command": "simulate", "outputs": ["/x"],
                                      "parameters": {"model.mass": {"min": 1.0, "max": 2.0, "num": 3}}}})
    assert '"model.mass" = { "min" = 1.0, "max" = 2.0, "num" = 3 }' in text
    assert text.startswith("[study]\n")


def test_fe_rotor_from_python():
    rotor = geardyn.FeGearedRotor(str(EXAMPLES / "rotor_visnadi2021_time.toml"),
                                  overrides=["load.torque=20.0"])
    assert rotor.dof_count == 30 and rotor.dof_names[1] == "pinion_shaft.0.uz"
    mass = rotor.mass
    assert mass.shape == (30, 30) and np.allclose(mass, mass.T)
    response = rotor.time_response(duration=0.02, channels=["gear_shaft.1.rx", "pinion_shaft.1.uy"])
    d = response.displacement
    assert d.shape == (2001, 2) and not d.flags["OWNDATA"]  # a view of the C++ result
    assert response.status == "completed"
    modes = rotor.modal(500.0, modes=6)
    assert [m["whirl"] for m in modes][:4] == ["mixed"] * 4
    assert modes[0]["shape"].dtype == np.complex128
    campbell = rotor.campbell([0.0, 1000.0, 2000.0], modes=3)
    assert campbell["frequency_hz"].shape == (3, 3)
    with pytest.raises(ValueError, match="time.outputs|pinion_shaft.gear_node"):
        geardyn.FeGearedRotor(str(EXAMPLES / "rotor_visnadi2021_time.toml"),
                              overrides=["pinion_shaft.gear_node=9"])


def test_sweep_from_a_dict_with_a_relative_base(tmp_path, monkeypatch):
    monkeypatch.chdir(EXAMPLES)
    result = geardyn.sweep({"study": {"command": "simulate", "base": "simulate_gear_pair_backlash.toml",
                                      "outputs": ["df=/dynamic_factor"],
                                      "parameters": {"model.damping_ratio": [0.05, 0.1]}}},
                           out=tmp_path / "s", plots=False)
    assert list(result.table("sweep")["status"]) == ["ok", "ok"]
    assert result.results["cases"] == 2
