"""geardyn import / export and REXS gearbox files in analyses (issue 20): the FVA two-stage
gearbox from ../shared/rexs (skipped when absent) imported, analysed directly, exported and
read back; zipped .rexsz; bad input exits 2 naming the REXS component."""

import csv
import json
import shutil
import zipfile

import pytest

from cli_support import SOURCE, run

REXS = SOURCE.parent / "shared" / "rexs"
TWO_STAGE = REXS / "FVA-Industriegetriebe_2_stufig_1-6.rexs"
needs_data = pytest.mark.skipif(
    not REXS.is_dir(),
    reason=f"the FVA/SEW REXS models are not in {REXS} (they live beside the repository, not in "
    "it); test_cli_rexs_generated.py covers the importer with a gearbox the tests write")


def rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def analysis(tmp_path, gearbox, extra=""):
    path = tmp_path / "modal.toml"
    path.write_text(f'[gearbox]\nfile = "{gearbox}"\n{extra}\n[analysis]\nrun = ["static", "modal"]\n'
                    "[output]\nplots = false\n")
    return path


@needs_data
def test_import_writes_a_commented_gearbox_file(tmp_path):
    out = tmp_path / "two_stage.toml"
    result = run("import", TWO_STAGE, "-o", out)
    assert result.returncode == 0, result.stderr
    assert "3 shafts, 4 gears, 2 meshes" in result.stdout
    assert "4 load case(s)" in result.stdout
    text = out.read_text()
    assert "# component 6 (cylindrical_gear \"Cylindrical gear [27]\")" in text
    assert "centre_distance = 0.19" in text
    assert 'dofs = "planar"' in text
    assert "without a radial stiffness" in result.stderr  # the bearings named in a warning
    # The written file is a gearbox file like any other: train reads it.
    result = run("train", analysis(tmp_path, out.name), "--out", tmp_path / "res")
    assert result.returncode == 0, result.stderr


@needs_data
def test_analysis_reads_rexs_directly_and_picks_the_load_case(tmp_path):
    shutil.copy(TWO_STAGE, tmp_path / "box.rexs")
    imported = tmp_path / "box.toml"
    assert run("import", tmp_path / "box.rexs", "-o", imported, "--load-case", "3").returncode == 0
    direct = run("train", analysis(tmp_path, "box.rexs", "load_case = 3"), "--out", tmp_path / "a")
    assert direct.returncode == 0, direct.stderr
    path = analysis(tmp_path, "box.toml")
    via_toml = run("train", path, "--out", tmp_path / "b")
    assert via_toml.returncode == 0, via_toml.stderr
    a = [float(m["frequency_hz"]) for m in rows(tmp_path / "a" / "modes.csv")]
    b = [float(m["frequency_hz"]) for m in rows(tmp_path / "b" / "modes.csv")]
    assert a == b  # the same gearTrainFromConfig path: identical
    summary = json.loads((tmp_path / "a" / "summary.json").read_text())
    assert summary["config"]["gearbox_description"]["operating_point"]["speed_rpm"] == 1234.0
    # --set reaches the load case (it belongs to the analysis file, not the gearbox).
    other = run("train", analysis(tmp_path, "box.rexs"), "--out", tmp_path / "d",
                "--set", "gearbox.load_case=2")
    assert other.returncode == 0, other.stderr
    summary = json.loads((tmp_path / "d" / "summary.json").read_text())
    assert summary["config"]["gearbox_description"]["operating_point"]["speed_rpm"] == 3456.0
    # Every load case, each into its own folder, at its own speed.
    every = run("train", analysis(tmp_path, "box.rexs", "all_load_cases = true"), "--out",
                tmp_path / "all")
    assert every.returncode == 0, every.stderr
    for case, rpm in [(1, 543.0), (2, 3456.0), (3, 1234.0), (4, 789.0)]:
        summary = json.loads((tmp_path / "all" / f"load_case_{case}" / "summary.json").read_text())
        assert summary["config"]["gearbox_description"]["operating_point"]["speed_rpm"] == rpm
        assert summary["config"]["gearbox"]["load_case"] == case
    bad = run("train", analysis(tmp_path, "box.toml", "all_load_cases = true"), "--out", tmp_path / "e")
    assert bad.returncode == 2 and "gearbox.all_load_cases" in bad.stderr
    bad = run("train", analysis(tmp_path, "box.rexs", "load_case = 9"), "--out", tmp_path / "c")
    assert bad.returncode == 2
    assert "load_case = 9" in bad.stderr and "1, 2, 3, 4" in bad.stderr


@needs_data
def test_export_and_reimport(tmp_path):
    first = tmp_path / "first.toml"
    assert run("import", TWO_STAGE, "-o", first).returncode == 0
    exported = tmp_path / "out.rexsj"
    result = run("export", first, "-o", exported)
    assert result.returncode == 0, result.stderr
    model = json.loads(exported.read_text())["model"]
    assert model["version"] == "2.0.0" and model["applicationId"] == "geardyn"
    second = tmp_path / "second.toml"
    assert run("import", exported, "-o", second).returncode == 0
    for toml in (first, second):
        assert run("train", analysis(tmp_path, toml.name), "--out", tmp_path / toml.stem).returncode == 0
    a = [float(m["frequency_hz"]) for m in rows(tmp_path / "first" / "modes.csv")]
    b = [float(m["frequency_hz"]) for m in rows(tmp_path / "second" / "modes.csv")]
    assert a == pytest.approx(b, rel=1e-10)


@needs_data
def test_zipped_rexsz(tmp_path):
    archive = tmp_path / "box.rexsz"
    with zipfile.ZipFile(archive, "w", zipfile.ZIP_DEFLATED) as z:
        z.write(TWO_STAGE, "model.rexs")
    out = tmp_path / "box.toml"
    result = run("import", archive, "-o", out)
    assert result.returncode == 0, result.stderr
    assert "3 shafts, 4 gears, 2 meshes" in result.stdout
    with zipfile.ZipFile(tmp_path / "nomodel.rexsz", "w") as z:
        z.writestr("readme.txt", "no model here")
    bad = run("import", tmp_path / "nomodel.rexsz", "-o", tmp_path / "x.toml")
    assert bad.returncode == 2 and "holds a .rexs or .rexsj" in bad.stderr
    (tmp_path / "broken.rexsz").write_bytes(archive.read_bytes()[:200])
    bad = run("import", tmp_path / "broken.rexsz", "-o", tmp_path / "x.toml")
    assert bad.returncode == 2 and "zip" in bad.stderr


BAD_GEAR = """<?xml version="1.0"?>
<model applicationId="t" applicationVersion="1" version="1.6"><relations>
<relation id="1" type="assembly"><ref id="3" role="assembly"/><ref id="4" role="part"/></relation>
</relations><components>
<component id="3" name="Shaft" type="shaft"/>
<component id="4" name="Pinion" type="cylindrical_gear">
<attribute id="normal_module" unit="mm">2.0</attribute><attribute id="face_width" unit="mm">20</attribute>
</component></components></model>
"""


def test_bad_rexs_input_exits_2_naming_the_component(tmp_path):
    path = tmp_path / "bad.rexs"
    path.write_text(BAD_GEAR)
    result = run("import", path, "-o", tmp_path / "bad.toml")
    assert result.returncode == 2
    assert "component 4 (cylindrical_gear \"Pinion\") attribute number_of_teeth" in result.stderr
    path.write_text(BAD_GEAR[: len(BAD_GEAR) // 2])
    result = run("import", path, "-o", tmp_path / "bad.toml")
    assert result.returncode == 2 and "offset" in result.stderr
    path.write_text(BAD_GEAR.replace('id="4" role="part"', 'id="7" role="part"'))
    result = run("import", path, "-o", tmp_path / "bad.toml")
    assert result.returncode == 2 and "relation 1" in result.stderr and "component 7" in result.stderr
    path.write_text(BAD_GEAR.replace('unit="mm">2.0', 'unit="inch">2.0'))
    result = run("import", path, "-o", tmp_path / "bad.toml")
    assert result.returncode == 2 and "normal_module" in result.stderr and "inch" in result.stderr
    assert not (tmp_path / "bad.toml").exists()
    assert run("import", tmp_path / "absent.rexs").returncode == 3


@needs_data
def test_capped_stiffnesses_are_one_line_per_kind(tmp_path):
    """Issue #33 item 4: the planetary file gave one warning per capped attribute (19 lines); the
    worm file's caps said "x the stiffest mesh" with no cylindrical mesh to scale them."""
    planetary = run("import", REXS / "FVA_Planetary_stage_-_Minus_gearing_1.1_vers2.rexsj",
                    "-o", tmp_path / "planetary.toml")
    assert planetary.returncode == 0, planetary.stderr
    capped = [l for l in planetary.stderr.splitlines() if "treated as rigid" in l]
    # Kinds: a planet bearing's radial, and the bearings' and couplings' radial, axial,
    # rotational and bending stiffnesses.
    assert 1 <= len(capped) <= 5, planetary.stderr
    radial = next(l for l in capped if ": radial_stiffness" in l)
    assert "the same for" in radial and "Rolling bearing [60]" in radial, radial
    worm = run("import", REXS / "FVA_worm_stage_1-4.rexs", "-o", tmp_path / "worm.toml")
    assert worm.returncode == 0, worm.stderr
    capped = [l for l in worm.stderr.splitlines() if "treated as rigid" in l]
    assert capped and all("no cylindrical gear" in l and "stiffest mesh" not in l
                          for l in capped), worm.stderr
