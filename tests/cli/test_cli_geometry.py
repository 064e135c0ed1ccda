"""The geardyn executable: help, version, result files, exit codes and error messages."""

import json
import os
import pathlib
import subprocess

import pytest

CLI = os.environ.get("GEARDYN_CLI", "build/bin/geardyn")
SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
RAO_RIG = SOURCE / "examples" / "geometry_rao2023_rig.toml"
# Plots need the Python package in the build (not in the sanitizer build).
PLOTS = os.environ.get("GEARDYN_PLOTS", "1") == "1"

VALID = """
[pinion]
teeth = 25
module = 0.003
face_width = 0.02

[gear]
teeth = 30
module = 0.003
face_width = 0.02
"""


def run(*args, cwd=None):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, cwd=cwd)


def write(tmp_path, text, name="pair.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_version_and_help():
    version = run("--version")
    assert version.returncode == 0 and version.stdout.startswith("geardyn 0.")
    help_ = run("--help")
    assert help_.returncode == 0 and "geometry" in help_.stdout and "Exit codes" in help_.stdout
    sub = run("geometry", "--help")
    assert sub.returncode == 0
    for option in ("--out", "--set", "--threads", "--quiet"):
        assert option in sub.stdout


def test_no_command_is_a_usage_error():
    assert run().returncode == 2
    assert run("frobnicate", "x.toml").returncode == 2


def test_rao_rig_end_to_end(tmp_path):
    out = tmp_path / "rig"
    result = run("geometry", RAO_RIG, "--out", out)
    assert result.returncode == 0, result.stderr
    assert "undercut" in result.stderr  # the 16-tooth pinion is (slightly) undercut
    summary = json.loads((out / "summary.json").read_text())
    assert summary["geardyn_version"].startswith("0.")
    assert summary["command"] == "geometry"
    assert summary["status"] == "ok"
    assert summary["seed"] is None
    assert 0 < summary["wall_time_s"] < 60 and summary["numerical_failure"] is False
    assert summary["files"] == ["gears.csv", "tooth_profiles.csv"] + (["mesh.png"] if PLOTS else [])
    if PLOTS:
        assert (out / "mesh.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # The resolved configuration has every default filled in.
    assert summary["config"]["gear"]["addendum_coefficient"] == 1.0
    assert summary["config"]["pair"]["centre_distance"] == 0.051125
    results = summary["results"]
    assert results["contact_ratio_transverse"] == pytest.approx(1.57692, abs=1e-4)
    assert 2e3 * results["pinion"]["base_radius"] == pytest.approx(30.07016, abs=1e-5)
    assert 2e3 * results["gear"]["base_radius"] == pytest.approx(65.77848, abs=1e-5)
    assert 2e3 * results["pinion"]["active_profile_start_radius"] == pytest.approx(30.09285, abs=1e-5)
    assert results["mesh_frequency"] == pytest.approx(16 * 970 / 60)
    lines = (out / "gears.csv").read_text().splitlines()
    assert lines[0].startswith("member,teeth,pitch_radius_m,base_radius_m")
    assert lines[1].startswith("pinion,16,") and lines[2].startswith("gear,35,")
    assert not [p for p in out.iterdir() if ".tmp" in p.name]


def test_default_output_folder_is_results_config_stem(tmp_path):
    config = write(tmp_path, VALID, "my_pair.toml")
    result = run("geometry", config, "--quiet", "--set", "output.plots=false", cwd=tmp_path)
    assert result.returncode == 0 and result.stdout == ""
    folder = tmp_path / "results" / "my_pair"
    assert (folder / "summary.json").is_file()
    assert sorted(p.name for p in folder.iterdir()) == ["gears.csv", "summary.json", "tooth_profiles.csv"]


def test_missing_plotter_is_a_warning_not_a_failure(tmp_path):
    config = write(tmp_path, VALID)
    env = dict(os.environ, GEARDYN_PYTHON="/nonexistent/python3")
    result = subprocess.run([CLI, "geometry", str(config), "--out", str(tmp_path / "o")],
                            capture_output=True, text=True, env=env)
    assert result.returncode == 0
    assert "warning: plots skipped" in result.stderr
    assert json.loads((tmp_path / "o" / "summary.json").read_text())["files"] == ["gears.csv", "tooth_profiles.csv"]


def test_set_overrides_are_recorded(tmp_path):
    config = write(tmp_path, VALID)
    result = run("geometry", config, "--out", tmp_path / "o", "--set", "pinion.teeth=20",
                 "--set", "pair.speed_rpm=600")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["config"]["pinion"]["teeth"] == 20
    assert summary["results"]["mesh_frequency"] == pytest.approx(200.0)


def edited(old, new, text=VALID):
    assert old in text
    return text.replace(old, new, 1)


BAD_INPUTS = [
    (edited("teeth = 25", "teeth = 0"), "pinion.teeth = 0"),
    (edited("teeth = 25", "teeth = 3.5"), "pinion.teeth = 3.5: expected an integer"),
    (edited("module = 0.003\nface", "module = -0.003\nface"), "pinion.module = -0.003"),
    (edited("teeth = 30", "teeth = 30\npressure_angle_deg = 0"), "gear.pressure_angle_deg = 0"),
    (edited("teeth = 30", "teeth = 30\npressure_angle_deg = 45"), "gear.pressure_angle_deg = 45"),
    (edited("teeth = 30", "teeth = 30\naddendum_coefficient = 0.5",
            edited("teeth = 25", "teeth = 25\naddendum_coefficient = 0.5")),
     "cannot mesh continuously"),
    (edited("module = 0.003\nface", "modul = 0.003\nface"), 'did you mean "pinion.module"?'),
    (edited("face_width = 0.02\n", "\n"), "pinion.face_width: missing required key"),
    (edited("face_width = 0.02\n", 'face_width = "wide"\n'), 'pinion.face_width = "wide": expected a number'),
    (edited("face_width = 0.02\n", "face_width = nan\n"), "pinion.face_width = nan: must be finite"),
    (edited("face_width = 0.02\n", "face_width = inf\n"), "pinion.face_width = inf: must be finite"),
    (VALID + "\n[pair]\ncentre_distance = 0.07\n", "pair.centre_distance = 0.07 m: must exceed"),
    (edited("teeth = 30", "teeth = = 30"), "pair.toml line 8"),
]


@pytest.mark.parametrize("text, expected", BAD_INPUTS, ids=[e for _, e in BAD_INPUTS])
def test_bad_input_exits_2_naming_the_key(tmp_path, text, expected):
    config = write(tmp_path, text)
    result = run("geometry", config, "--out", tmp_path / "o")
    assert result.returncode == 2, result.stderr
    assert expected in result.stderr
    assert "Traceback" not in result.stderr and "terminate" not in result.stderr
    assert not (tmp_path / "o" / "summary.json").exists()


def test_bad_override_exits_2(tmp_path):
    config = write(tmp_path, VALID)
    result = run("geometry", config, "--set", "pinion.modul=0.002")
    assert result.returncode == 2 and 'did you mean "pinion.module"?' in result.stderr


def test_missing_config_file_exits_3():
    result = run("geometry", "/nonexistent/pair.toml")
    assert result.returncode == 3 and "no such file" in result.stderr


def test_unwritable_output_exits_3(tmp_path):
    config = write(tmp_path, VALID)
    blocker = tmp_path / "blocker"
    blocker.write_text("a file where a folder should be")
    result = run("geometry", config, "--out", blocker / "out")
    assert result.returncode == 3 and "I/O error" in result.stderr


@pytest.mark.parametrize("command", ["geometry", "stiffness", "simulate", "stats", "hbm", "rotor", "spectrum", "identify", "ltca", "sweep", "train"])
def test_schema_reference_in_docs_is_current(command):
    result = run("schema", command)
    assert result.returncode == 0
    committed = (SOURCE / "docs" / "config" / f"{command}.md").read_text()
    assert result.stdout == committed, f"regenerate: build/bin/geardyn schema {command} > docs/config/{command}.md"


def test_a_rerun_removes_the_previous_runs_files_only(tmp_path):
    config = write(tmp_path, VALID)
    out = tmp_path / "o"
    assert run("geometry", config, "--out", out, "--set", "output.plots=false").returncode == 0
    (out / "notes.txt").write_text("mine")          # a user's file in the folder
    (out / "gears.csv").write_text("stale")         # will be rewritten
    assert run("geometry", config, "--out", out, "--set", "output.plots=false").returncode == 0
    assert (out / "notes.txt").read_text() == "mine"
    assert (out / "gears.csv").read_text().startswith("member,")


UNDERCUT_10_40 = """
[pinion]
teeth = 10
module = 0.002
face_width = 0.02
bore_diameter = 0.008

[gear]
teeth = 40
module = 0.002
face_width = 0.02
bore_diameter = 0.02
"""


def swept_form_radius(teeth, module):
    """True form radius of a standard-rack (h_f* = 1.25, ρ_fP* = 0.38, α = 20°, x = 0) spur gear,
    found without the library: sweep 4000 points of the rack's tip rounding through the rolling
    motion, take the smallest angle any reaches at a radius (each path crosses r_y at
    r φ = −p_x ± √(r_y² − p_y²)), and bisect for where that meets the involute."""
    from math import acos, atan2, cos, pi, sin, sqrt, tan
    alpha, m = pi / 9, module
    r = teeth * m / 2
    rb, rho = r * cos(alpha), 0.38 * m
    yc = r - 1.25 * m + rho
    xc = pi * m / 4 + (r - yc) * tan(alpha) + rho / cos(alpha)
    inv = lambda a: tan(a) - a
    psi = lambda ry: pi / (2 * teeth) + inv(alpha) - inv(acos(rb / ry))
    arc = [(xc + rho * cos(t), yc + rho * sin(t))
           for t in (pi + alpha + (pi / 2 - alpha) * i / 4000 for i in range(4001))]

    def swept(ry):
        best = 1e9
        for px, py in arc:
            h = sqrt(ry * ry - py * py)
            for phi in ((-px + h) / r, (-px - h) / r):
                x, y = px + r * phi, py
                best = min(best, atan2(cos(phi) * x - sin(phi) * y, sin(phi) * x + cos(phi) * y))
        return best
    lo, hi = rb * (1 + 1e-9), rb * 1.1
    for _ in range(45):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if swept(mid) < psi(mid) else (lo, mid)
    return 0.5 * (lo + hi), rb


def test_undercut_pinion_meshes_from_its_true_form_circle(tmp_path):
    # 10/40 standard teeth: the gear tip passes through the pinion's undercut. The involute
    # starts at the true form radius r_Ff above the base circle, so contact (SAP) starts there
    # and the contact ratio is that of the path from r_Ff, not from T1 (1.264 on the uncut
    # involute). Reference: the sweep above (its grid moves r_Ff by < 1e-9 r_b).
    out = tmp_path / "uc"
    result = run("geometry", write(tmp_path, UNDERCUT_10_40), "--out", out, "--set",
                 "output.plots=false")
    assert result.returncode == 0, result.stderr
    assert "below the true form diameter" in result.stderr
    results = json.loads((out / "summary.json").read_text())["results"]
    r_ff, rb = swept_form_radius(10, 0.002)
    assert results["pinion"]["form_radius"] == pytest.approx(r_ff, rel=1e-8)
    assert results["pinion"]["active_profile_start_radius"] == pytest.approx(r_ff, rel=1e-8)
    from math import cos, pi, sqrt
    p_bt = pi * 0.002 * cos(pi / 9)
    rho_a1 = sqrt(0.012 ** 2 - rb ** 2)
    eps = (rho_a1 - sqrt(r_ff ** 2 - rb ** 2)) / p_bt
    assert results["contact_ratio_transverse"] == pytest.approx(eps, rel=1e-8)
    assert rho_a1 / p_bt - eps > 0.15
    assert f"{eps:.4f}" in result.stderr and f"{rho_a1 / p_bt:.4f}" in result.stderr
    # The stiffness command's potential-energy model meshes over the same path of contact.
    stiffness = run("stiffness", write(tmp_path, UNDERCUT_10_40), "--out", tmp_path / "k",
                    "--set", "output.plots=false")
    assert stiffness.returncode == 0, stiffness.stderr
    model = json.loads((tmp_path / "k" / "summary.json").read_text())["results"]["mesh_stiffness"]
    assert model["contact_ratio"] == pytest.approx(eps, rel=1e-8)
    # The roll √(r_Ff² − r_b²) amplifies the sweep's 1e-10 on r_Ff ~90 times near the base circle.
    assert model["contact_start"] == pytest.approx(sqrt(r_ff ** 2 - rb ** 2), rel=1e-6)
