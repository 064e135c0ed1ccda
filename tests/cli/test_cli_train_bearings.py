"""`geardyn train` with rolling bearings from their geometry (issue 35): the nonlinear static
deflection, the linearised modes, the results and the input checks (exit 2 naming the key)."""

import csv
import json

import pytest

from cli_support import EXAMPLES, run

EXAMPLE = EXAMPLES / "train_two_stage_reducer_rolling_bearings.toml"


@pytest.fixture(scope="module")
def reducer(tmp_path_factory):
    out = tmp_path_factory.mktemp("rolling_bearings")
    result = run("train", EXAMPLE, "--out", out)
    assert result.returncode == 0, result.stdout + result.stderr
    return out, json.loads((out / "summary.json").read_text())


def test_every_bearing_has_its_load_stiffness_and_life(reducer):
    out, summary = reducer
    bearings = summary["results"]["bearings"]
    assert "linearised at the static deflection" in bearings["linear_analyses"]
    assert bearings["static_status"] == "ok" and bearings["newton_iterations"] > 1
    assert len(bearings["bearings"]) == 6
    for name, b in bearings["bearings"].items():
        k = b["stiffness_matrix"]
        assert len(k) == 5 and all(len(row) == 5 for row in k)
        for i in range(5):
            for j in range(5):
                assert abs(k[i][j] - k[j][i]) <= 1e-9 * abs(k[0][0]), (name, i, j)
        assert 1e7 < k[0][0] < 1e10, name  # rolling bearings under a few kN
        assert b["radial_load_n"] > 100.0 and b["max_contact_pressure_pa"] > 3e8
        assert b["rating_life_l10r_mrev"] > 0.0
    with open(out / "bearings.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [r["bearing"] for r in rows] == list(bearings["bearings"])


def test_the_modes_use_the_linearised_bearings(reducer):
    _, summary = reducer
    lowest = summary["results"]["modal"]["lowest_frequency_hz"]
    assert lowest is not None and lowest > 0.0


@pytest.mark.parametrize("sets, key, words", [
    (["bearings.input_a.kyy=4e8"], "bearings.input_a.kyy", "either the geometry"),
    (["bearings.input_a.inner_groove_radius=6e-3"], "bearings.input_a.inner_groove_radius",
     "above the ball radius"),
    (["bearings.input_a.elements=20"], "bearings.input_a.elements", "at most"),
    (["bearings.intermediate_a.radial_clearance=-1e-4"],
     "bearings.intermediate_a.radial_clearance", "preload"),
    (["bearings.input_a.contact_angle_deg=15.0"], "bearings.input_a.contact_angle_deg", "0 for"),
])
def test_bad_bearing_geometry_exits_2_naming_the_key(tmp_path, sets, key, words):
    args = [a for s in sets for a in ("--set", s)]
    result = run("train", EXAMPLE, "--out", tmp_path, *args)
    assert result.returncode == 2, result.stdout + result.stderr
    assert key in result.stderr and words in result.stderr, result.stderr
