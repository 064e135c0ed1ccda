"""geardyn train, analysis "runup": the run-up example's headline numbers (stated in its header
comment) from summary.json, the run-up's peak against the forced response's, the result files,
and bad [runup] input named by key (exit 2)."""

import csv
import json
import re

import pytest

from cli_support import EXAMPLES, run

RUNUP = EXAMPLES / "train_two_stage_reducer_runup.toml"
HEADLINE = re.compile(r"^#\s+runup\.mesh_order_peaks\.(\w+)\.(\w+): ([\d.]+) N at ([\d.]+) rpm",
                      re.MULTILINE)


def quick(*extra):
    return ["--set", "output.plots=false", *extra]


@pytest.fixture(scope="module")
def example(tmp_path_factory):
    out = tmp_path_factory.mktemp("runup")
    result = run("train", RUNUP, "--out", out, *quick())
    assert result.returncode == 0, result.stderr
    return out, result


def test_headline_numbers_of_the_example(example):
    out, result = example
    peaks = json.loads((out / "summary.json").read_text())["results"]["runup"]["mesh_order_peaks"]
    stated = HEADLINE.findall(RUNUP.read_text())
    assert len(stated) == 2
    for channel, order, amplitude, speed in stated:
        peak = peaks[channel][order]
        assert peak["unit"] == "N"
        # Tolerances of the header: the numbers are deterministic up to the compiler's floating
        # point; a change of the solver or of the derived defaults shows up here.
        assert peak["speed_rpm"] == pytest.approx(float(speed), rel=0.02), (channel, order)
        assert peak["amplitude"] == pytest.approx(float(amplitude), rel=0.03), (channel, order)
    assert "run-up 150 -> 2250 rpm" in result.stdout


def test_runup_peak_is_the_forced_response_peak(example):
    out, _ = example
    summary = json.loads((out / "summary.json").read_text())["results"]["runup"]
    peak = summary["mesh_order_peaks"]["stage2"]["1x_mesh_stage2"]
    with open(out / "forced_response.csv", newline="") as handle:
        forced = list(csv.DictReader(handle))
    best = max(forced, key=lambda r: float(r["h1_stage2_normal_n"]))
    # Within one window's speed change (sweep rate × window, about 21 rpm there) plus the
    # forced response's 10 rpm grid, and 1 % in amplitude (measured 0.0 %).
    window_rpm = summary["sweep_rate_rpm_per_s"] * summary["window_s"]
    assert abs(peak["speed_rpm"] - float(best["speed_rpm"])) < window_rpm + 10.0
    assert peak["amplitude"] == pytest.approx(float(best["h1_stage2_normal_n"]), rel=0.01)
    assert summary["start"] == "steady_state"
    assert summary["duration_derived"] is True
    assert summary["ramp_inertia_torque_fraction"] < 0.05


def test_result_files(example):
    out, _ = example
    with open(out / "runup.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert {r["channel"] for r in rows} == {"stage1", "stage2"}
    assert {"t_s", "speed_rpm", "unit", "amplitude_1x_motor", "amplitude_1x_mesh_stage1",
            "amplitude_2x_mesh_stage2"} <= set(rows[0])
    speeds = [float(r["speed_rpm"]) for r in rows if r["channel"] == "stage1"]
    assert speeds == sorted(speeds) and 150 < speeds[0] < speeds[-1] < 2250
    with open(out / "waterfall.csv", newline="") as handle:
        header = next(csv.reader(handle))
    assert header == ["channel", "unit", "t_s", "speed_rpm", "frequency_hz", "amplitude"]


@pytest.mark.parametrize("setting, key, words", [
    (["runup.speed_min_rpm=2000", "runup.speed_max_rpm=1000"], "runup.speed_max_rpm",
     "at least runup.speed_min_rpm"),
    (["runup.channels=[\"nowhere\"]"], "runup.channels", "a mesh name (stage1, stage2)"),
    (["runup.speed_tolerance=2"], "runup.speed_tolerance", "0.5"),
    (["runup.window=1e-5"], "runup.window", "time steps"),
])
def test_bad_runup_input_exits_2_naming_the_key(tmp_path, setting, key, words):
    args = [a for s in setting for a in ("--set", s)]
    result = run("train", RUNUP, "--out", tmp_path, *quick("--set", "analysis.run=[\"runup\"]",
                                                          *args))
    assert result.returncode == 2, result.stderr
    assert key in result.stderr and words in result.stderr, result.stderr


def test_a_runup_too_large_for_memory_is_refused(tmp_path):
    result = run("train", RUNUP, "--out", tmp_path,
                 *quick("--set", "analysis.run=[\"runup\"]", "--set", "runup.duration=1e5"))
    assert result.returncode == 2, result.stderr
    assert "runup.duration" in result.stderr and "memory" in result.stderr, result.stderr


def test_an_undamped_train_needs_a_duration_and_a_planetary_stage_is_refactorised(tmp_path):
    # Lin & Parker's planetary stage has no damping: no sweep passes its resonances
    # quasi-statically, so the derived duration is refused naming the key; given one, the
    # carrier-frame terms (Ω G₁, Ω² K_Ω) are refactorised along the ramp (1e-3 tolerance).
    lin_parker = EXAMPLES / "train_lin_parker1999.toml"
    common = quick("--set", "analysis.run=[\"runup\"]", "--set", "runup.speed_min_rpm=500",
                   "--set", "runup.speed_max_rpm=1500")
    result = run("train", lin_parker, "--out", tmp_path, *common)
    assert result.returncode == 2, result.stderr
    assert "runup.duration" in result.stderr and "undamped" in result.stderr, result.stderr
    result = run("train", lin_parker, "--out", tmp_path, *common, "--set", "runup.duration=0.2")
    assert result.returncode == 0, result.stderr
    runup = json.loads((tmp_path / "summary.json").read_text())["results"]["runup"]
    assert runup["factorisations"] > 100  # 1000 rpm of 1500 in steps of 1.5 rpm: about 660
