"""REXS through the command line in every clone (issue 34): a gearbox the tests write
themselves (rexs_generated.py: the two-stage reducer exported, with three load cases) is
imported, analysed directly at each load case, read zipped, and refused where it should be.
The FVA/SEW models of ../shared/rexs (test_cli_rexs.py) add third-party files where present."""

import csv
import json
import re
import zipfile

import pytest

from cli_support import EXAMPLES, run
from rexs_generated import LOAD_CASES, write_rexs_gearbox


@pytest.fixture(scope="module")
def rexs(tmp_path_factory):
    return write_rexs_gearbox(tmp_path_factory.mktemp("rexs"))


def static_analysis(folder, gearbox, extra=""):
    path = folder / f"static_{abs(hash((str(gearbox), extra)))}.toml"
    path.write_text(f'[gearbox]\nfile = "{gearbox}"\n{extra}\n[analysis]\nrun = ["static", "modal"]\n'
                    "[output]\nplots = false\n")
    return path


def results(folder):
    return json.loads((folder / "summary.json").read_text())


def frequencies(folder):
    with open(folder / "modes.csv", newline="") as handle:
        return [float(row["frequency_hz"]) for row in csv.DictReader(handle)]


def test_import_lists_the_written_load_cases(rexs, tmp_path):
    rexsj, _ = rexs
    out = tmp_path / "reducer.toml"
    result = run("import", rexsj, "-o", out, "--load-case", "2")
    assert result.returncode == 0, result.stderr
    assert "3 load case(s)" in result.stdout, result.stdout
    assert "2 meshes" in result.stdout
    text = out.read_text()
    assert "speed_rpm = 3000" in text
    # The motor's lumped mass and inertia (a shaft without sections) come back as a disk: the
    # export once dropped them, and the re-imported motor had no inertia at all.
    disk = text[text.index("motor lumped mass"):]
    assert "mass = 15" in disk and "polar_inertia = 0.04" in disk, disk[:400]


def test_each_load_case_scales_the_static_mesh_forces(rexs, tmp_path):
    """The static mesh forces are proportional to the input torque: load case 2 (400 N m) gives
    twice and case 7 (100 N m) half those of case 1 (the gearbox file's 200 N m, whose stage-1
    force the example train_two_stage_reducer states: 6169.1465 N). Linear statics: to 1e-9."""
    rexsj, _ = rexs
    forces = {}
    for case_id in LOAD_CASES:
        out = tmp_path / f"case{case_id}"
        done = run("train", static_analysis(tmp_path, rexsj, f"load_case = {case_id}"), "--out", out)
        assert done.returncode == 0, done.stderr
        summary = results(out)
        speed = summary["config"]["gearbox_description"]["operating_point"]["speed_rpm"]
        assert speed == LOAD_CASES[case_id][0]
        forces[case_id] = summary["results"]["static"]["mesh_force_n"]
    assert forces[1]["stage1"] == pytest.approx(6169.1465, rel=1e-7)
    for case_id, (_, torque) in LOAD_CASES.items():
        for mesh in ("stage1", "stage2"):
            assert forces[case_id][mesh] == pytest.approx(forces[1][mesh] * torque / 200.0, rel=1e-9)


def test_zipped_and_plain_give_identical_results(rexs, tmp_path):
    rexsj, rexsz = rexs
    for name, gearbox in (("plain", rexsj), ("zipped", rexsz)):
        done = run("train", static_analysis(tmp_path, gearbox, "load_case = 2"), "--out",
                   tmp_path / name)
        assert done.returncode == 0, done.stderr
    assert frequencies(tmp_path / "plain") == frequencies(tmp_path / "zipped")


def test_an_unknown_load_case_is_refused_naming_the_key_and_the_cases(rexs, tmp_path):
    rexsj, _ = rexs
    bad = run("train", static_analysis(tmp_path, rexsj, "load_case = 5"), "--out", tmp_path / "bad")
    assert bad.returncode == 2
    assert "load_case = 5" in bad.stderr and "1, 2, 7" in bad.stderr, bad.stderr


def test_hostile_files_are_refused_before_they_are_read_whole(tmp_path):
    """A zip bomb (300 MiB of spaces in a few hundred kB), a deeply nested JSON model and a
    planetary stage of 10^6 planets exit 2 naming the limit, in well under a second's worth of
    memory: nothing is inflated past the limit."""
    bomb = tmp_path / "bomb.rexsz"
    with zipfile.ZipFile(bomb, "w", zipfile.ZIP_DEFLATED) as archive:
        with archive.open("model.rexsj", "w") as entry:
            block = b" " * (1 << 20)
            for _ in range(300):
                entry.write(block)
    assert bomb.stat().st_size < 2e6
    refused = run("import", bomb, "-o", tmp_path / "bomb.toml")
    assert refused.returncode == 2 and "at most 256 MiB" in refused.stderr, refused.stderr
    assert "300.0 MiB uncompressed (its declared size)" in refused.stderr, refused.stderr
    # A zip64 entry's local header holds the placeholder 0xFFFFFFFF: the real size is reported.
    bomb64 = tmp_path / "bomb64.rexsz"
    with zipfile.ZipFile(bomb64, "w", zipfile.ZIP_DEFLATED) as archive:
        with archive.open("model.rexsj", "w", force_zip64=True) as entry:
            for _ in range(300):
                entry.write(block)
    refused = run("import", bomb64, "-o", tmp_path / "bomb64.toml")
    assert refused.returncode == 2 and "at most 256 MiB" in refused.stderr, refused.stderr
    assert "4294967295" not in refused.stderr and "4096.0 MiB" not in refused.stderr
    assert re.search(r"(300\.0|25[67]\.\d) MiB uncompressed", refused.stderr), refused.stderr

    deep = tmp_path / "deep.rexsj"
    deep.write_text('{"model": {"version": "1.6", "relations": ' + "[" * 100000 + "]" * 100000 +
                    ', "components": []}}')
    refused = run("import", deep, "-o", tmp_path / "deep.toml")
    assert refused.returncode == 2 and "at most 64 levels of nesting" in refused.stderr, refused.stderr

    gearbox = (EXAMPLES / "gearboxes" / "planetary_parallel.toml").read_text()
    many = tmp_path / "many.toml"
    many.write_text(re.sub(r"(?m)^planets = .*$", "planets = 1000000", gearbox))
    refused = run("train", static_analysis(tmp_path, many), "--out", tmp_path / "many")
    assert refused.returncode == 2
    assert "planets = 1000000" in refused.stderr and "[1, 32]" in refused.stderr, refused.stderr


NOT_A_GEAR = """<?xml version="1.0"?>
<model applicationId="t" applicationVersion="1" version="1.6"><relations>
<relation id="1" type="assembly"><ref id="1" role="assembly"/><ref id="3" role="part"/></relation>
<relation id="2" type="assembly"><ref id="2" role="assembly"/><ref id="4" role="part"/></relation>
<relation id="3" type="stage"><ref id="5" role="stage"/><ref id="3" role="gear_1"/><ref id="4" role="gear_2"/></relation>
</relations><components>
<component id="1" name="Input" type="shaft"/><component id="2" name="Output" type="shaft"/>
<component id="3" name="Pinion" type="cylindrical_gear"><attribute id="number_of_teeth" unit="none">20</attribute>
<attribute id="normal_module" unit="mm">3</attribute><attribute id="face_width" unit="mm">30</attribute></component>
<component id="4" name="Wheel" type="cylunitindrical_gear"/>
<component id="5" name="Stage" type="cylindrical_stage"><attribute id="center_distance" unit="mm">92</attribute></component>
</components></model>
"""


def test_a_stage_whose_gear_is_not_a_gear_names_the_relation(tmp_path):
    """Found by the REXS fuzzer (fuzz/rexs_fuzzer.cpp): a stage relation whose gear_2 is a
    component of another type ended in std::out_of_range (exit 1), not an input error."""
    path = tmp_path / "not_a_gear.rexs"
    path.write_text(NOT_A_GEAR)
    refused = run("import", path, "-o", tmp_path / "x.toml")
    assert refused.returncode == 2, refused.stderr
    assert 'gear_2 = component 4 (cylunitindrical_gear "Wheel")' in refused.stderr, refused.stderr
