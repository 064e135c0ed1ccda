"""REXS rolling bearings with their inner geometry (issue 35): a gearbox the tests write
themselves (rexs_generated.write_rexs_rolling_bearings: the two-stage reducer exported, its
bearings made rolling_bearing_with_detailed_geometry with a row and a rolling element) imports
as the gearbox file's geometric bearings, and the static analysis of the REXS file gives the
bearings of the hand-written example (examples/train_two_stage_reducer_rolling_bearings.toml).
Concept bearings keep their stiffness; the default-stiffness warning names only the bearings
without data. The models of ../shared/rexs carry no inner geometry (checked where present)."""

import json
import os
import pathlib
import tomllib

import pytest

from cli_support import EXAMPLES, run
from rexs_generated import BALL_6208, write_rexs_rolling_bearings

#: Newton's relative residual in the static deflection is 1e-10 or below; the imported and the
#: hand-written bearings are the same numbers (mm -> m divides exactly), so their results agree
#: to the solver's round-off, far inside 1e-7.
SAME_SOLVE = 1e-7


def static_run(folder, gearbox, name):
    analysis = folder / f"{name}.toml"
    analysis.write_text(f'[gearbox]\nfile = "{gearbox}"\n[analysis]\nrun = ["static"]\n'
                        "[output]\nplots = false\n")
    out = folder / name
    done = run("train", analysis, "--out", out)
    assert done.returncode == 0, done.stderr
    return json.loads((out / "summary.json").read_text()), done.stderr


def test_detailed_bearings_import_as_geometric_bearings(tmp_path):
    rexsj = write_rexs_rolling_bearings(tmp_path)
    out = tmp_path / "imported.toml"
    done = run("import", rexsj, "-o", out)
    assert done.returncode == 0, done.stderr
    text = out.read_text()
    ball = text[text.index("[bearings.input_a]"):text.index("[bearings.input_b]")]
    for line in ('type = "deep_groove_ball"', "elements = 9", "element_diameter = 0.0127",
                 "pitch_diameter = 0.06", "inner_groove_radius = 0.006604",
                 "outer_groove_radius = 0.006731", "radial_clearance = 7.5e-06",
                 "dynamic_load_rating = 32500"):
        assert line in ball, ball
    assert "kyy" not in ball, ball
    tapered = text[text.index("[bearings.intermediate_b]"):text.index("[bearings.output_a]")]
    for line in ('type = "tapered_roller"', "elements = 17", "roller_length = 0.014",
                 "contact_angle_deg = 15", "reversed = true"):
        assert line in tapered, tapered
    # Every bearing has its geometry: no default stiffness, no warning about one.
    assert "without a radial stiffness" not in done.stderr, done.stderr


def test_static_results_equal_the_hand_written_example(tmp_path):
    """The REXS file analysed directly against the example's gearbox file with the importer's
    slice count (REXS has none; the example uses 10, the gearbox file's default is 20): every
    bearing's load, tangent stiffness and L10r agree to SAME_SOLVE."""
    rexsj = write_rexs_rolling_bearings(tmp_path)
    gearbox = (EXAMPLES / "gearboxes" / "two_stage_reducer_rolling_bearings.toml").read_text()
    hand = tmp_path / "hand_gearbox.toml"
    hand.write_text(gearbox.replace("slices = 10", "slices = 20"))
    imported, _ = static_run(tmp_path, rexsj, "rexs")
    written, _ = static_run(tmp_path, hand, "hand")
    a, b = imported["results"]["bearings"]["bearings"], written["results"]["bearings"]["bearings"]
    assert sorted(a) == sorted(b) and len(a) == 6
    for name in a:
        assert a[name]["type"] == b[name]["type"]
        for key in ("radial_load_n", "axial_load_n", "radial_stiffness_yy_n_per_m",
                    "rating_life_l10r_mrev", "max_contact_pressure_pa"):
            assert a[name][key] == pytest.approx(b[name][key], rel=SAME_SOLVE), (name, key)
    # The 6208's numbers are the example's (its expect lines): 3084.573 N, 1.02765e8 N/m.
    assert a["input_a"]["radial_load_n"] == pytest.approx(3084.573, rel=1e-5)
    assert a["input_a"]["radial_stiffness_yy_n_per_m"] == pytest.approx(1.02765e8, rel=1e-4)


def test_default_stiffness_warning_names_only_bearings_without_data(tmp_path):
    """input_a/b with geometry, output_a a catalogue bearing by designation (a row without
    geometry), output_b a concept bearing without stiffness, intermediate_a/b concept bearings
    with theirs (4e8 N/m, kept)."""
    rexsj = write_rexs_rolling_bearings(
        tmp_path, bearings={"input_a": BALL_6208, "input_b": BALL_6208},
        catalogue_only=("output_a",), no_stiffness=("output_b",))
    out = tmp_path / "imported.toml"
    done = run("import", rexsj, "-o", out)
    assert done.returncode == 0, done.stderr
    warning = [line for line in done.stderr.splitlines() if "without a radial stiffness" in line]
    assert len(warning) == 1, done.stderr
    assert "2 bearing(s)" in warning[0] and "output_a" in warning[0] and "output_b" in warning[0]
    for name in ("input_a", "input_b", "intermediate_a", "intermediate_b"):
        assert name not in warning[0], warning[0]
    text = out.read_text()
    concept = text[text.index("[bearings.intermediate_a]"):text.index("[bearings.intermediate_b]")]
    assert "kyy = 400000000" in concept or "kyy = 4e+08" in concept, concept
    assert 'type = "deep_groove_ball"' in text


def test_incomplete_rows_are_named_and_fall_back_to_stiffness(tmp_path):
    bearing_type, own, row, element = BALL_6208
    no_radii = [a for a in row if not a[0].startswith("raceway_radius")]
    rexsj = write_rexs_rolling_bearings(tmp_path,
                                        bearings={"input_a": (bearing_type, own, no_radii, element)})
    out = tmp_path / "imported.toml"
    done = run("import", rexsj, "-o", out)
    assert done.returncode == 0, done.stderr
    assert "raceway_radius_of_inner_ring, raceway_radius_of_outer_ring" in done.stderr, done.stderr
    text = out.read_text()
    section = text[text.index("[bearings.input_a]"):text.index("[bearings.input_b]")]
    assert "type =" not in section and "kyy" in section, section


SHARED = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", ".")).resolve().parent / "shared" / "rexs"


@pytest.mark.skipif(not (SHARED / "SEW_3-stage_cylindrical_gearbox_1.0.rexs").exists(),
                    reason="../shared/rexs not present")
def test_shared_catalogue_bearings_have_no_inner_geometry(tmp_path):
    """The SEW and FVA models' catalogue bearings give designation, bore, width and rows with a
    pressure angle only (no element count, diameter or pitch diameter): they keep their file's
    stiffness (SEW: radial_stiffness) or the default (FVA), none becomes a geometric bearing."""
    for name in ("SEW_3-stage_cylindrical_gearbox_1.0.rexs",
                 "FVA-Industriegetriebe_2_stufig_1-6.rexs"):
        out = tmp_path / (name + ".toml")
        done = run("import", SHARED / name, "-o", out)
        assert done.returncode == 0, done.stderr
        assert "type = \"" not in out.read_text().split("[bearings.", 1)[1].split("[couplings", 1)[0]


def test_export_writes_geometric_bearings_back(tmp_path):
    """The example's gearbox file → REXS → gearbox file: every bearing comes back with its type
    and geometry (mm ↔ m round off in the last bits: 1e-12), the slice count (not in REXS)
    warned about on export."""
    gearbox = EXAMPLES / "gearboxes" / "two_stage_reducer_rolling_bearings.toml"
    rexsj = tmp_path / "exported.rexsj"
    done = run("export", gearbox, "-o", rexsj)
    assert done.returncode == 0, done.stderr
    assert "slice count" in done.stderr, done.stderr
    back = tmp_path / "back.toml"
    done = run("import", rexsj, "-o", back)
    assert done.returncode == 0, done.stderr
    assert "without a radial stiffness" not in done.stderr, done.stderr
    original = tomllib.loads(gearbox.read_text())["bearings"]
    imported = tomllib.loads(back.read_text())["bearings"]
    for name, b in original.items():
        for key in ("type", "elements", "element_diameter", "pitch_diameter", "contact_angle_deg",
                    "inner_groove_radius", "outer_groove_radius", "roller_length",
                    "radial_clearance", "dynamic_load_rating", "reversed"):
            if key in b:
                expected, got = b[key], imported[name].get(key, False if key == "reversed" else None)
                if isinstance(expected, float):
                    assert got == pytest.approx(expected, rel=1e-12, abs=1e-18), (name, key)
                else:
                    assert got == expected, (name, key)
