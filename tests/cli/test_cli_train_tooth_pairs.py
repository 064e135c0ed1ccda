"""geardyn train, analysis "nonlinear" with contact = "tooth_pairs" (issue 17): the two-stage
example with tooth-pair contact elements at both meshes (long tip reliefs as gaps) sweeps through
contact loss, its Newmark checks agree within 1 %, and bad input exits 2 naming the key."""

import csv
import json

import pytest

from cli_support import EXAMPLES, run

TOOTH_PAIRS = EXAMPLES / "train_tooth_pairs_nonlinear.toml"
PLANETARY = EXAMPLES / "train_planetary_nonlinear.toml"


def rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def test_the_tooth_pair_example_loses_contact_and_agrees_with_newmark(tmp_path):
    result = run("train", TOOTH_PAIRS, "--out", tmp_path, "--set", "output.plots=false")
    assert result.returncode == 0, result.stderr
    info = json.loads((tmp_path / "summary.json").read_text())["results"]["nonlinear"]
    assert all(s["completed"] for s in info["sweeps"].values()), info["sweeps"]
    table = [r for sweep in info["sweeps"] for r in rows(tmp_path / f"nonlinear_{sweep}.csv")]
    # Contact loss at some speeds and not at others, at each of the two meshes.
    for mesh in ("stage1", "stage2"):
        flags = {r[f"contact_loss_{mesh}"] for r in table}
        assert "1" in flags, mesh
        assert {r[f"back_flank_{mesh}"] for r in table} == {"0"}  # no back flank: one-sided
    assert {r["contact_loss_stage1"] for r in table} == {"0", "1"}
    checks = rows(tmp_path / "newmark_checks.csv")
    stable = [c for c in checks if c["stable"] == "1"]
    assert len(stable) >= 2
    for c in stable:
        assert c["newmark_status"] == "steady_state", c
        assert float(c["max_relative_difference"]) < 0.01, c


@pytest.mark.parametrize("example, sets, key, words", [
    # A ring mesh has no tooth model (the loaded tooth contact is written for external pairs).
    (PLANETARY, ['planetary.stage.ring_planet.contact="tooth_pairs"'],
     "planetary.stage.ring_planet.contact", "ring (internal) mesh"),
    # The elements are the loaded flank's: no backlash with them.
    (PLANETARY, ['planetary.stage.sun_planet.contact="tooth_pairs"'],
     "planetary.stage.sun_planet.backlash", "tooth_pairs"),
    # Modifications without tooth pairs would be ignored: refused.
    (PLANETARY, ['planetary.stage.sun_planet.modifications.pinion_crowning=1e-6'],
     "planetary.stage.sun_planet.modifications", "only with contact = \"tooth_pairs\""),
    # A designed relief and an explicit amount on the same flank end.
    (TOOTH_PAIRS, ['meshes.stage1.modifications.relief="short"',
                   'meshes.stage1.modifications.pinion_tip_relief=1e-6'],
     "meshes.stage1.modifications.pinion_tip_relief", "conflicts"),
    (TOOTH_PAIRS, ['meshes.stage2.tooth_pair_slices=0'], "meshes.stage2.tooth_pair_slices", ""),
])
def test_bad_tooth_pair_input_exits_2_naming_the_key(tmp_path, example, sets, key, words):
    args = [a for s in sets for a in ("--set", s)]
    result = run("train", example, "--out", tmp_path, "--set", "output.plots=false", *args)
    assert result.returncode == 2, result.stdout + result.stderr
    assert key in result.stderr and words in result.stderr, result.stderr
    assert not (tmp_path / "summary.json").exists()
