"""geardyn sweep over train (issue 31, item 4): a gearbox key of the gearbox file the analysis
names, gearbox sections inline in the base file, analysis keys, REXS load cases; a case gives
exactly the numbers of the same `geardyn train --set ...` run; a misspelt key is refused before
any case runs, with a did-you-mean naming it (and so is it by `geardyn train --set`)."""

import csv
import json
import shutil

import pytest

from cli_support import EXAMPLES, SOURCE, run

REDUCER = EXAMPLES / "train_two_stage_reducer.toml"
GEARBOX = EXAMPLES / "gearboxes" / "two_stage_reducer.toml"
TWO_STAGE_REXS = SOURCE.parent / "shared" / "rexs" / "FVA-Industriegetriebe_2_stufig_1-6.rexs"
STATIC = 'analysis.run=[\\"static\\"]'  # inside a TOML string of study.set


def study(folder, base, parameters, outputs, design="grid", extra=""):
    path = folder / "study.toml"
    path.write_text(f'[study]\ncommand = "train"\nbase = "{base}"\ndesign = "{design}"\n'
                    f"outputs = {outputs}\n{extra}\n[study.parameters]\n{parameters}\n"
                    "[output]\nplots = false\n")
    return path


def rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def swept(path, out, cases):
    """Runs the study into `out` and returns its sweep.csv rows, every one of the cases ok."""
    result = run("sweep", path, "--out", out, "--quiet")
    assert result.returncode == 0, result.stderr
    table = rows(out / "sweep.csv")
    assert [r["status"] for r in table] == ["ok"] * cases, table
    return table


def summary(folder):
    return json.loads((folder / "summary.json").read_text())


def test_a_gearbox_key_of_the_gearbox_file_is_swept(tmp_path):
    # Was: "operating_point.torque: unknown key (--set); the keys in [operating_point] are:
    # (none)" (the analysis file's schema alone).
    path = study(tmp_path, REDUCER, '"operating_point.torque" = [100.0, 200.0, 400.0]',
                 '["f1=/static/mesh_force_n/stage1", "f2=/static/mesh_force_n/stage2"]',
                 extra=f'set = ["{STATIC}"]')
    table = swept(path, tmp_path / "out", 3)
    f1 = [float(r["f1"]) for r in table]
    # The parameter overrides the gearbox file's torque (200 N m): the static mesh forces of a
    # linear train are proportional to it.
    assert f1[2] == pytest.approx(4 * f1[0], rel=1e-9) and f1[1] == pytest.approx(2 * f1[0], rel=1e-9)
    base = summary(tmp_path / "out")["config"]["base_config"]
    assert base["operating_point"]["torque"] == 200.0 and base["gearbox"]["file"]


def test_inline_gearbox_sections_are_swept(tmp_path):
    # Was: "unknown section [shafts]" for every gearbox section of the base file.
    inline = tmp_path / "inline.toml"
    inline.write_text('[analysis]\nrun = ["static", "modal"]\n' + GEARBOX.read_text())
    path = study(tmp_path, inline, '"meshes.stage1.damping_ratio" = [0.02, 0.08]\n'
                 '"operating_point.torque" = [150.0, 300.0]',
                 '["f1=/static/mesh_force_n/stage1", "fn=/modal/lowest_frequency_hz"]')
    table = swept(path, tmp_path / "out", 4)
    # Mesh damping leaves the static forces alone; torque scales them.
    assert float(table[0]["f1"]) == pytest.approx(float(table[2]["f1"]), rel=1e-12)
    assert float(table[1]["f1"]) == pytest.approx(2 * float(table[0]["f1"]), rel=1e-9)
    assert all(float(r["fn"]) > 1.0 for r in table)


def test_analysis_keys_are_swept(tmp_path):
    # Was: every case failed with "bad_function_call".
    path = study(tmp_path, REDUCER, '"forced.points" = [12, 20]\n"forced.mesh_harmonics" = [4, 6]',
                 '["speeds=/forced/speeds", "h=/forced/mesh_harmonics"]', design="zip",
                 extra='set = ["analysis.run=[\\"forced\\"]"]')
    table = swept(path, tmp_path / "out", 2)
    assert [(float(r["speeds"]), float(r["h"])) for r in table] == [(12.0, 4.0), (20.0, 6.0)]


def test_nonlinear_keys_are_swept(tmp_path):
    fixed = ['analysis.run=[\\"nonlinear\\"]', "nonlinear.speed_min_rpm=1400.0",
             "nonlinear.speed_max_rpm=1600.0", "nonlinear.stability=false"]
    path = study(tmp_path, REDUCER, '"nonlinear.harmonics" = [4, 6]\n"nonlinear.samples" = [48, 64]',
                 '["h=/nonlinear/harmonics", "n=/nonlinear/samples", '
                 '"p2p=/nonlinear/peaks/stage1/p2p_force_n"]', design="zip",
                 extra="set = [" + ", ".join(f'"{s}"' for s in fixed) + "]")
    table = swept(path, tmp_path / "out", 2)
    assert [(float(r["h"]), float(r["n"])) for r in table] == [(4.0, 48.0), (6.0, 64.0)]
    assert all(float(r["p2p"]) > 0 for r in table)


def test_a_case_gives_the_numbers_of_the_same_train_run(tmp_path):
    sets = ["operating_point.torque=350.0", "meshes.stage1.damping_ratio=0.03",
            'analysis.run=["static", "modal", "forced"]', "forced.points=15"]
    direct = run("train", REDUCER, "--out", tmp_path / "direct", "--quiet",
                 *sum((["--set", s] for s in sets + ["output.plots=false"]), []))
    assert direct.returncode == 0, direct.stderr
    outputs = ('["f1=/static/mesh_force_n/stage1", "fn=/modal/lowest_frequency_hz", '
               '"df=/forced/meshes/stage1/max_dynamic_factor", '
               '"p2p=/forced/meshes/stage1/max_p2p_force_n"]')
    path = study(tmp_path, REDUCER, '"operating_point.torque" = [100.0, 350.0]\n'
                 '"meshes.stage1.damping_ratio" = [0.03]', outputs,
                 extra='keep_case_results = true\nset = ["analysis.run=[\\"static\\", '
                       '\\"modal\\", \\"forced\\"]", "forced.points=15"]')
    case = swept(path, tmp_path / "sweep", 2)[1]
    results = summary(tmp_path / "direct")["results"]
    expected = {"f1": results["static"]["mesh_force_n"]["stage1"],
                "fn": results["modal"]["lowest_frequency_hz"],
                "df": results["forced"]["meshes"]["stage1"]["max_dynamic_factor"],
                "p2p": results["forced"]["meshes"]["stage1"]["max_p2p_force_n"]}
    # sweep.csv writes 17 significant digits: the same doubles.
    assert {k: float(case[k]) for k in expected} == expected
    kept = tmp_path / "sweep" / "cases" / "000001"
    for table in ("static_forces.csv", "modes.csv", "forced_response.csv"):
        assert (kept / table).read_text() == (tmp_path / "direct" / table).read_text(), table


@pytest.mark.parametrize("key, suggestion", [
    ("operating_point.torqe", "operating_point.torque"),  # a key of the gearbox file
    ("operating_pont.torque", "operating_point.torque"),  # its section misspelt
    ("forced.pionts", "forced.points"),                    # a key of the analysis file
    ("meshes.stage3.damping_ratio", "meshes.stage1.damping_ratio"),  # no such mesh
])
def test_a_misspelt_key_is_refused_before_any_case_runs(tmp_path, key, suggestion):
    path = study(tmp_path, REDUCER, f'"{key}" = [1.0, 2.0]', '["/static/status"]')
    result = run("sweep", path, "--out", tmp_path / "out")
    assert result.returncode == 2, result.stdout + result.stderr
    assert key in result.stderr and "did you mean" in result.stderr, result.stderr
    assert suggestion in result.stderr, result.stderr
    assert not (tmp_path / "out" / "sweep_journal.jsonl").exists()


@pytest.mark.parametrize("key, suggestion", [
    ("operating_point.torqe", "operating_point.torque"),
    ("operating_pont.torque", "operating_point.torque"),
    ("forced.pionts", "forced.points"),
])
def test_train_set_names_a_misspelt_key_of_either_file(tmp_path, key, suggestion):
    result = run("train", REDUCER, "--out", tmp_path / "out", "--set", f"{key}=1")
    assert result.returncode == 2, result.stdout + result.stderr
    assert key in result.stderr and f'did you mean "{suggestion}"' in result.stderr, result.stderr


def test_every_load_case_in_one_case_is_refused(tmp_path):
    path = study(tmp_path, REDUCER, '"operating_point.torque" = [100.0]', '["/static/status"]',
                 extra='set = ["gearbox.all_load_cases=true"]')
    result = run("sweep", path, "--out", tmp_path / "out")
    assert result.returncode == 2 and "gearbox.all_load_cases" in result.stderr, result.stderr
    assert "gearbox.load_case" in result.stderr


@pytest.mark.skipif(not TWO_STAGE_REXS.is_file(), reason=f"{TWO_STAGE_REXS} not found")
def test_rexs_load_cases_and_gearbox_keys_are_swept(tmp_path):
    shutil.copy(TWO_STAGE_REXS, tmp_path / "box.rexs")
    analysis = tmp_path / "modal.toml"
    analysis.write_text('[gearbox]\nfile = "box.rexs"\n[analysis]\nrun = ["static", "modal"]\n')
    path = study(tmp_path, analysis, '"gearbox.load_case" = [1, 2, 3, 4]\n'
                 '"operating_point.torque" = [500.0, 1000.0]',
                 '["rpm=/kinematics/input_speed_rpm", "f1=/static/mesh_force_n/cylindrical_stage_41"]')
    table = swept(path, tmp_path / "out", 8)
    # The load cases' speeds (test_cli_rexs.py); the torque parameter overrides each one's.
    assert [float(r["rpm"]) for r in table[::2]] == [543.0, 3456.0, 1234.0, 789.0]
    for low, high in zip(table[::2], table[1::2]):
        assert float(high["f1"]) == pytest.approx(2 * float(low["f1"]), rel=1e-9)
    bad = study(tmp_path, analysis, '"gearbox.load_case" = [1, 9]', '["/static/status"]')
    result = run("sweep", bad, "--out", tmp_path / "bad")
    assert result.returncode == 2 and "study.parameters.gearbox.load_case[1] = 9" in result.stderr


def test_an_edited_gearbox_file_is_not_resumed(tmp_path):
    # The journal's fingerprint holds the gearbox the analysis file names, not only the base.
    shutil.copy(REDUCER, tmp_path / "analysis.toml")
    (tmp_path / "gearboxes").mkdir()
    gearbox = tmp_path / "gearboxes" / GEARBOX.name
    shutil.copy(GEARBOX, gearbox)
    path = study(tmp_path, tmp_path / "analysis.toml", '"operating_point.torque" = [100.0, 200.0]',
                 '["f1=/static/mesh_force_n/stage1"]', extra=f'set = ["{STATIC}"]')
    swept(path, tmp_path / "out", 2)
    assert run("sweep", path, "--out", tmp_path / "out", "--quiet", "--resume").returncode == 0
    gearbox.write_text(gearbox.read_text().replace("damping_ratio = 0.05", "damping_ratio = 0.06", 1))
    again = run("sweep", path, "--out", tmp_path / "out", "--quiet", "--resume")
    assert again.returncode == 2 and "changed since" in again.stderr, again.stderr


def test_gearbox_files_are_swept(tmp_path):
    # A --set of gearbox.file chooses the gearbox read (it named the file but read the original).
    heavy = tmp_path / "heavy.toml"
    heavy.write_text(GEARBOX.read_text().replace("torque = 200.0", "torque = 400.0", 1))
    path = study(tmp_path, REDUCER, f'"gearbox.file" = ["{GEARBOX}", "{heavy}"]',
                 '["f1=/static/mesh_force_n/stage1"]', extra=f'set = ["{STATIC}"]')
    f1 = [float(r["f1"]) for r in swept(path, tmp_path / "out", 2)]
    assert f1[1] == pytest.approx(2 * f1[0], rel=1e-9)
    direct = run("train", REDUCER, "--out", tmp_path / "direct", "--quiet", "--set",
                 'analysis.run=["static"]', "--set", f"gearbox.file={heavy}")
    assert direct.returncode == 0, direct.stderr
    assert summary(tmp_path / "direct")["results"]["static"]["mesh_force_n"]["stage1"] == f1[1]
