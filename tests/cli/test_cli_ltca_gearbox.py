"""geardyn ltca on a mesh of a gearbox ([gearbox] file + mesh), alone and swept over the meshes:
the load is the mesh's static force of `geardyn train`, the tables of a gearbox whose mesh is the
Visnadi pair equal the standalone example's, and a bad mesh name or a pair given twice is an
input error (exit 2)."""

import csv
import json
import math

import pytest

from cli_support import EXAMPLES, run

STAGE1 = EXAMPLES / "ltca_two_stage_reducer_stage1.toml"
STANDALONE = EXAMPLES / "ltca_visnadi2021_long_relief.toml"
QUICK = ["--set", "output.plots=false"]

# The standalone example's pair and modifications as the one mesh of a torsional gearbox.
PAIR_GEARBOX = """
[gearbox]
name = "Visnadi 2021 pair"
dofs = "torsional"
[shafts.pinion_shaft]
mass = 1.0
polar_inertia = 1e-3
[shafts.gear_shaft]
mass = 1.5
polar_inertia = 2e-3
[gears.pinion]
shaft = "pinion_shaft"
teeth = 25
module = 0.003
face_width = 0.020
youngs_modulus = 200e9
poisson_ratio = 0.3
bore_diameter = 0.030
[gears.wheel]
shaft = "gear_shaft"
teeth = 30
module = 0.003
face_width = 0.020
youngs_modulus = 200e9
poisson_ratio = 0.3
bore_diameter = 0.030
[meshes.pair]
gears = ["pinion", "wheel"]
stiffness = "potential_energy"
contact = "tooth_pairs"
[meshes.pair.modifications]
relief = "long"
design_load = 3000.0
shape = "linear"
[operating_point]
input = "pinion_shaft"
speed_rpm = 1000.0
torque = {torque!r}
output = "gear_shaft"
"""

MESH_FILE = """
[gearbox]
file = "pair_gearbox.toml"
mesh = "pair"
[ltca]
positions = 200
[harris]
compare_reliefs = ["none", "short"]
"""


def _rows(path):
    with open(path, newline="") as handle:
        return list(csv.reader(handle))


def test_load_is_the_static_mesh_force_of_train(tmp_path):
    result = run("ltca", STAGE1, "--out", tmp_path / "ltca", *QUICK)
    assert result.returncode == 0, result.stderr
    ltca = json.loads((tmp_path / "ltca" / "summary.json").read_text())["results"]["ltca"]
    assert ltca["gearbox_mesh"] == "stage1"
    analysis = tmp_path / "static.toml"
    gearbox = (EXAMPLES / "gearboxes" / "two_stage_reducer_tooth_pairs.toml").as_posix()
    analysis.write_text(f'[gearbox]\nfile = "{gearbox}"\n[analysis]\nrun = ["static"]\n')
    train = run("train", analysis, "--out", tmp_path / "train", *QUICK)
    assert train.returncode == 0, train.stderr
    static = json.loads((tmp_path / "train" / "summary.json").read_text())["results"]["static"]
    assert ltca["force"] == pytest.approx(static["mesh_force_n"]["stage1"], rel=1e-12)
    assert ltca["force"] == pytest.approx(3084.5733, rel=1e-6)  # 100 N m / r_b1 (spur)
    # --set reaches the ltca file's keys on top of the translated pair.
    other = run("ltca", STAGE1, "--out", tmp_path / "other", *QUICK, "--set", "ltca.force=6169.0",
                "--set", "gearbox.mesh=stage2")
    assert other.returncode == 0, other.stderr
    o = json.loads((tmp_path / "other" / "summary.json").read_text())
    assert o["results"]["ltca"]["force"] == 6169.0 and o["config"]["pinion"]["teeth"] == 17


def test_tables_equal_the_standalone_pairs(tmp_path):
    rb1 = 0.5 * 0.003 * 25 * math.cos(math.radians(20.0))
    (tmp_path / "pair_gearbox.toml").write_text(PAIR_GEARBOX.format(torque=3000.0 * rb1))
    (tmp_path / "mesh.toml").write_text(MESH_FILE)
    on_mesh = run("ltca", tmp_path / "mesh.toml", "--out", tmp_path / "mesh", *QUICK)
    assert on_mesh.returncode == 0, on_mesh.stderr
    alone = run("ltca", STANDALONE, "--out", tmp_path / "alone", *QUICK)
    assert alone.returncode == 0, alone.stderr
    names = sorted(p.name for p in (tmp_path / "alone").glob("*.csv"))
    assert names == sorted(p.name for p in (tmp_path / "mesh").glob("*.csv"))
    assert {"ltca.csv", "harris.csv", "harris_designs.csv", "load_statistics.csv"} <= set(names)
    for name in names:
        a, b = _rows(tmp_path / "alone" / name), _rows(tmp_path / "mesh" / name)
        assert a[0] == b[0] and len(a) == len(b), name
        for j in range(len(a[0])):
            try:
                x = [float(r[j]) for r in a[1:]]
                y = [float(r[j]) for r in b[1:]]
            except ValueError:
                assert [r[j] for r in a] == [r[j] for r in b], (name, a[0][j])
                continue
            scale = max([abs(v) for v in x] + [1e-300])
            # 1e-9 of the column's range: the force is 3000 N to round-off of T/r_b (9e-15).
            assert max(abs(u - v) for u, v in zip(x, y)) <= 1e-9 * scale, (name, a[0][j])


@pytest.mark.parametrize("override, text", [
    ("gearbox.mesh=stage3", "did you mean 'stage1'"),
    ("gearbox.mesh=sun", "stage1 stage2"),
])
def test_unknown_mesh_is_an_input_error(tmp_path, override, text):
    result = run("ltca", STAGE1, "--out", tmp_path, *QUICK, "--set", override)
    assert result.returncode == 2, result.stderr
    assert "gearbox.mesh" in result.stderr and text in result.stderr, result.stderr


def test_a_pair_beside_the_gearbox_is_an_input_error(tmp_path):
    config = tmp_path / "both.toml"
    gearbox = (EXAMPLES / "gearboxes" / "two_stage_reducer_tooth_pairs.toml").as_posix()
    config.write_text(f'[gearbox]\nfile = "{gearbox}"\nmesh = "stage1"\n[pinion]\nteeth = 20\n')
    result = run("ltca", config, "--out", tmp_path / "out", *QUICK)
    assert result.returncode == 2, result.stderr
    assert "pinion" in result.stderr and "gearbox mesh's gears" in result.stderr, result.stderr


def test_sweep_over_the_meshes_of_a_gearbox(tmp_path):
    study = tmp_path / "sweep.toml"
    study.write_text(f"""
[study]
command = "ltca"
base = "{STAGE1.as_posix()}"
design = "grid"
set = ["output.plots=false"]
outputs = ["force_n=/ltca/force"]
[study.parameters]
"gearbox.mesh" = ["stage1", "stage2"]
""")
    result = run("sweep", study, "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    with open(tmp_path / "out" / "sweep.csv", newline="") as handle:
        rows = {r["gearbox.mesh"]: float(r["force_n"]) for r in csv.DictReader(handle)}
    # The intermediate shaft's torque balance: F₂ = F₁ r_b(z2)/r_b(z3) = F₁ × 51 × 3 / (17 × 4.5).
    assert rows["stage2"] == pytest.approx(rows["stage1"] * 51 * 3.0 / (17 * 4.5), rel=1e-9)


def test_the_centre_distance_comes_from_the_mesh(tmp_path):
    config = tmp_path / "distance.toml"
    gearbox = (EXAMPLES / "gearboxes" / "two_stage_reducer_tooth_pairs.toml").as_posix()
    config.write_text(f'[gearbox]\nfile = "{gearbox}"\nmesh = "stage1"\n[pair]\ncentre_distance = 0.1\n')
    result = run("ltca", config, "--out", tmp_path / "out", *QUICK)
    assert result.returncode == 2, result.stderr
    assert "pair.centre_distance" in result.stderr, result.stderr
    driver = run("ltca", STAGE1, "--out", tmp_path / "driver", *QUICK, "--set", "pair.driver=gear")
    assert driver.returncode == 0, driver.stderr
    resolved = json.loads((tmp_path / "driver" / "summary.json").read_text())["config"]
    assert resolved["pair"]["driver"] == "gear" and resolved["pinion"]["teeth"] == 23
