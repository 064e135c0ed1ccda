"""The Python module mirrors the C++ geometry API (same fields, same checks, same numbers)."""

import json
import math
import os
import pathlib

import pytest

import geardyn

SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
RAO_RIG = SOURCE / "examples" / "geometry_rao2023_rig.toml"


def standard_pair(z1, z2, module, **pair):
    pinion = geardyn.Gear(teeth=z1, module=module, face_width=10 * module)
    gear = geardyn.Gear(teeth=z2, module=module, face_width=10 * module)
    return geardyn.GearPair(pinion=pinion, gear=gear, **pair)


@pytest.mark.parametrize(
    "z1, z2, module, expected",
    [(25, 30, 3e-3, 1.6325826), (62, 62, 2e-3, 1.78977987), (55, 75, 2e-3, 1.79398836)],
)
def test_standard_contact_ratios(z1, z2, module, expected):
    assert standard_pair(z1, z2, module).contact_ratio_transverse == pytest.approx(expected, abs=1e-7)


def test_rao_rig_from_config_matches_table_5_1():
    pair = geardyn.GearPair.from_config(str(RAO_RIG))
    assert 2 * pair.pinion.base_radius == pytest.approx(30.07016e-3, abs=1e-8)
    assert 2 * pair.gear.base_radius == pytest.approx(65.77848e-3, abs=1e-8)
    assert pair.contact_ratio_transverse == pytest.approx(1.57692, abs=1e-4)
    assert pair.mesh_frequency == pytest.approx(16 * 970 / 60)
    assert pair.pinion.undercut and any("undercut" in w for w in pair.warnings)


def test_overrides_from_python():
    pair = geardyn.GearPair.from_config(str(RAO_RIG), overrides=["pair.speed_rpm=660"])
    assert pair.mesh_frequency == pytest.approx(16 * 660 / 60)


def test_to_dict_is_the_summary_results():
    pair = standard_pair(25, 30, 3e-3, speed_rpm=1200.0)
    results = pair.to_dict()
    assert results["contact_ratio_transverse"] == pair.contact_ratio_transverse
    assert results["pinion"]["base_radius"] == pair.pinion.base_radius
    assert results["mesh_frequency"] == pytest.approx(500.0)
    json.dumps(results)  # plain JSON types only


def test_named_arguments_only_and_docstrings():
    with pytest.raises(TypeError):
        geardyn.Gear(25, 3e-3, 0.02)  # positional arguments would be easy to swap
    assert "normal module" in geardyn.Gear.__init__.__doc__
    assert "contact ratio" in geardyn.GearPair.__doc__


def test_bad_input_raises_value_error_naming_the_argument():
    with pytest.raises(ValueError, match=r"^teeth = 0"):
        geardyn.Gear(teeth=0, module=3e-3, face_width=0.02)
    with pytest.raises(ValueError, match=r"^pressure_angle_deg = 45"):
        geardyn.Gear(teeth=20, module=3e-3, face_width=0.02, pressure_angle_deg=45)
    with pytest.raises(ValueError, match="module"):
        geardyn.Gear(teeth=20, module=math.nan, face_width=0.02)
    with pytest.raises(ValueError, match="centre_distance"):
        standard_pair(25, 30, 3e-3, centre_distance=0.07)
    with pytest.raises(ValueError, match="driver"):
        standard_pair(25, 30, 3e-3, driver="motor")
    with pytest.raises(FileNotFoundError, match="no such configuration file"):
        geardyn.GearPair.from_config("/nonexistent.toml")


def test_plot_geometry_writes_a_png(tmp_path):
    import subprocess
    cli = os.environ.get("GEARDYN_CLI", "build/bin/geardyn")
    subprocess.run([cli, "geometry", str(RAO_RIG), "--out", str(tmp_path), "--quiet",
                    "--set", "output.plots=false"], check=True, capture_output=True)
    import geardyn.plot
    assert not list(tmp_path.glob("*.png"))
    figures = geardyn.plot.plot_geometry(tmp_path)  # Figures only: nothing written
    assert list(figures) == ["mesh.png"] and not list(tmp_path.glob("*.png"))
    geardyn.plot.plot_geometry(tmp_path, save=True)
    assert (tmp_path / "mesh.png").read_bytes()[:4] == b"\x89PNG"
    assert not [p for p in tmp_path.iterdir() if ".tmp" in p.name]


def test_load_config_resolves_defaults_and_reference_lists_keys():
    config = geardyn.load_config("geometry", str(RAO_RIG))
    assert config["pinion"]["dedendum_coefficient"] == 1.25
    assert config["pair"]["driver"] == "pinion"
    assert "`tip_radius_modification`" in geardyn.config_reference("geometry")
    with pytest.raises(ValueError, match="command"):
        geardyn.load_config("nonsense", str(RAO_RIG))
