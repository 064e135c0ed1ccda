"""geardyn hbm on the Saletti (2025) contact-element model: complete curves, folds, stability,
Newmark checks, one-period details; bad input."""

import csv
import json
import os
import pathlib
import subprocess

import pytest

CLI = os.environ.get("GEARDYN_CLI", "build/bin/geardyn")
SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXAMPLE = SOURCE / "examples" / "hbm_saletti2025_100Nm.toml"


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)


@pytest.fixture(scope="module")
def sweep(tmp_path_factory):
    out = tmp_path_factory.mktemp("hbm")
    result = run("hbm", EXAMPLE, "--out", out, "--set", "output.plots=false")
    assert result.returncode == 0, result.stderr
    return out, json.loads((out / "summary.json").read_text())["results"]


def test_complete_curves_through_every_fold(sweep):
    out, results = sweep
    assert results["sweeps"]["up"]["completed"] and results["sweeps"]["down"]["completed"]
    assert results["failures"] == 0
    # Softening primary resonance (two folds) and the superharmonic's folds, met by both sweeps.
    up = [f["frequency"] for f in results["folds"] if f["sweep"] == "up"]
    down = [f["frequency"] for f in results["folds"] if f["sweep"] == "down"]
    assert len(up) == len(down) >= 4
    assert sorted(up) == pytest.approx(sorted(down), rel=1e-3)
    assert any(1550 < f < 1700 for f in up) and any(2150 < f < 2300 for f in up)
    with open(out / "sweep.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    x = "_transverse_m"  # along the transverse line of action, in metres
    assert list(rows[0])[:10] == ["frequency_hz", "branch", "p2p" + x, "mean" + x, "max" + x, "min" + x,
                                  "rms" + x, "stable", "newton_iterations", "contact_loss"]
    assert "h14" + x in rows[0] and "h15" + x not in rows[0]
    assert any(r["stable"] == "0" for r in rows)  # the unstable middle branch is traced


def test_newmark_agrees_with_the_stable_branches(sweep):
    _, results = sweep
    checks = results["newmark_checks"]
    assert [c["frequency"] for c in checks] == [1250.0, 1850.0, 3250.0]
    for check in checks:
        assert check["status"] == "converged"
        assert abs(check["relative_difference"]) < 0.01, check


def test_paper_observations_in_the_details(sweep):
    out, results = sweep
    details = results["details"]
    at = {}
    for d in details:
        at.setdefault(d["frequency"], []).append(d)
    # 1850 Hz: two stable solutions (low and high) and the unstable one between them.
    assert sorted(d["stable"] for d in at[1850.0]) == [False, True, True]

    def levels(detail):
        with open(out / detail["file"], newline="") as handle:
            return {round(float(r["mesh_stiffness_transverse_n_per_m"]) / 2.6e8, 6) for r in csv.DictReader(handle)}

    # 3250 Hz: the mesh stiffness alternates k_c and 2 k_c; 1250 Hz: it also drops to 0.
    assert levels(at[3250.0][0]) == {1.0, 2.0}
    assert 0.0 in levels(at[1250.0][0])


@pytest.mark.parametrize("override, expected", [
    ("hbm.samples=28", "must exceed 2H = 28"),
    ("sweep.stop=400", "sweep.stop = 400 Hz: must exceed sweep.start = 500 Hz"),
    ("sweep.min_step=0", "sweep.min_step = 0: must be a number > 0"),
    ("model.stiffness.contact_ratio=0.9", "model.stiffness.contact_ratio = 0.9"),
    ("hbm.harmonics=0", "hbm.harmonics = 0"),
])
def test_bad_input_exits_2(tmp_path, override, expected):
    result = run("hbm", EXAMPLE, "--out", tmp_path, "--set", override)
    assert result.returncode == 2, result.stderr
    assert expected in result.stderr


def test_backlash_softening_resonance_has_both_jumps(tmp_path):
    result = run("hbm", SOURCE / "examples" / "hbm_backlash_kahraman_singh.toml", "--out", tmp_path,
                 "--set", "output.plots=false")
    assert result.returncode == 0, result.stderr
    results = json.loads((tmp_path / "summary.json").read_text())["results"]
    # No step keys: derived from the problem (issue 17) and recorded.
    assert results["continuation_steps"]["derived"] is True
    assert results["continuation_steps"]["max_step"] == 0.0125  # ζ ω_n / 4 (4th superharmonic)
    for sweep in ("up", "down"):
        # Two hysteresis loops, each turning twice (confirmed folds, no zigzags of the sampled
        # contact): the 2nd superharmonic at 0.437–0.455 and the primary at 0.598–0.836, the jump
        # down (end of the high branch) below the jump up (end of the low branch) — softening.
        folds = sorted(f["frequency"] for f in results["folds"] if f["sweep"] == sweep)
        assert len(folds) == 4, folds
        assert abs(folds[0] - 0.437) < 3e-3 and abs(folds[1] - 0.455) < 3e-3, folds
        assert abs(folds[2] - 0.598) < 3e-3 and abs(folds[3] - 0.836) < 3e-3, folds
    assert {b["type"] for b in results["bifurcations"]} == {"fold"}
    assert results["wall_time_s"] > 0 and results["time_per_point_s"] < 1e-3
    assert results["peak"]["frequency"] < 1.0  # the peak bends to lower frequencies
    assert all(abs(c["relative_difference"]) < 0.01 for c in results["newmark_checks"])
