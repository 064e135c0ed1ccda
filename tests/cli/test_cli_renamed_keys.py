"""Issue #31: one vocabulary for the input files. Each renamed key, written the old way, gives the
numbers of the new key and one warning naming the new key; both spellings in one file are an
error (exit 2) naming both. Converting renames: the gear pair's old half clearance b reads as the
full clearance 2b, radian phases read as degrees."""

import json
import math

import pytest

from cli_support import EXAMPLES, run

BACKLASH = EXAMPLES / "simulate_gear_pair_backlash.toml"
HBM = EXAMPLES / "hbm_backlash_kahraman_singh.toml"
RAO = EXAMPLES / "rotor_rao2023_table41.toml"
CAMPBELL = EXAMPLES / "rotor_visnadi2021_campbell.toml"

# Degrees ↔ radians round trips change the last bits of a phase: the responses agree to far
# better than any printed digit, not to the bit.
RTOL = 1e-9


def numbers(node, prefix=""):
    """Every number of a JSON tree by its path (run times left out: they differ run to run)."""
    out = {}
    if isinstance(node, dict):
        for key, value in node.items():
            if any(word in key for word in ("elapsed", "wall", "seconds", "cpu", "time_s", "time_per")):
                continue
            out.update(numbers(value, f"{prefix}/{key}"))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            out.update(numbers(value, f"{prefix}/{i}"))
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        out[prefix] = node
    return out


def assert_same_results(a, b, rtol=RTOL):
    na, nb = numbers(a["results"]), numbers(b["results"])
    assert na.keys() == nb.keys()
    assert na, "no numbers compared"
    for key in na:
        x, y = na[key], nb[key]
        if isinstance(x, float) and math.isnan(x):
            assert math.isnan(y), key
        else:
            assert x == pytest.approx(y, rel=rtol, abs=1e-300), key


def edited(tmp_path, name, source, replacements):
    text = source.read_text()
    for old, new in replacements:
        assert old in text, old
        text = text.replace(old, new)
    path = tmp_path / name
    path.write_text(text)
    return path


def solve(tmp_path, name, command, file, *sets):
    out = tmp_path / name
    args = [command, file, "--out", out, "--set", "output.plots=false"]
    for s in sets:
        args += ["--set", s]
    result = run(*args)
    assert result.returncode == 0, result.stderr
    return json.loads((out / "summary.json").read_text()), result.stderr


NEW_BACKLASH = "normal_backlash = 2e-4       # full clearance j [m] (half clearance b = 1e-4 m)"
# A 30 µm error and a 4 µm clearance: the teeth separate (21 % contact loss; the example itself
# stays in contact), so the clearance changes the numbers and the test can fail.
IMPACTS = "model.transmission_error.amplitudes=[3e-5]"


def test_backlash_old_half_clearance_reads_as_twice_the_full_clearance(tmp_path):
    old = edited(tmp_path, "old.toml", BACKLASH, [(NEW_BACKLASH, "backlash = 2e-6")])
    new = edited(tmp_path, "new.toml", BACKLASH, [(NEW_BACKLASH, "normal_backlash = 4e-6")])
    a, _ = solve(tmp_path, "new", "simulate", new, IMPACTS)
    b, stderr = solve(tmp_path, "old", "simulate", old, IMPACTS)
    assert "model.backlash is deprecated: write model.normal_backlash" in stderr
    assert "× 2" in stderr
    assert stderr.count("model.backlash is deprecated") == 1
    assert b["config"]["model"]["normal_backlash"] == 4e-6
    assert_same_results(a, b, rtol=0.0)
    assert a["results"]["contact_loss_fraction"] > 0.0
    other, _ = solve(tmp_path, "other", "simulate", new, IMPACTS, "model.normal_backlash=3e-6")
    assert other["results"]["dynamic_factor"] != pytest.approx(a["results"]["dynamic_factor"])


def test_backlash_both_spellings_are_an_error(tmp_path):
    both = edited(tmp_path, "both.toml", BACKLASH,
                  [("normal_backlash = 2e-4", "backlash = 1e-4\nnormal_backlash = 2e-4")])
    result = run("simulate", both, "--out", tmp_path / "out")
    assert result.returncode == 2, result.stderr
    assert "model.backlash" in result.stderr and "model.normal_backlash" in result.stderr


def test_backlash_old_key_on_the_command_line(tmp_path):
    new, _ = solve(tmp_path, "new", "simulate", BACKLASH, "model.normal_backlash=3e-4")
    old, stderr = solve(tmp_path, "old", "simulate", BACKLASH, "model.backlash=1.5e-4")
    assert "model.backlash is deprecated: it now reads model.normal_backlash" in stderr
    assert_same_results(new, old, rtol=0.0)


def test_transmission_error_phases_in_radians_read_as_degrees(tmp_path):
    new = edited(tmp_path, "new.toml", BACKLASH,
                 [("phases_deg = [0.0]", "phases_deg = [45.83662361046586]")])
    old = edited(tmp_path, "old.toml", BACKLASH, [("phases_deg = [0.0]", "phases = [0.8]")])
    a, _ = solve(tmp_path, "new", "simulate", new)
    b, stderr = solve(tmp_path, "old", "simulate", old)
    assert "write model.transmission_error.phases_deg" in stderr
    assert "180/π" in stderr
    assert_same_results(a, b)
    zero, _ = solve(tmp_path, "zero", "simulate", BACKLASH)
    assert numbers(zero["results"]) != numbers(a["results"])  # the phase matters
    both = edited(tmp_path, "both.toml", BACKLASH,
                  [("phases_deg = [0.0]", "phases_deg = [0.0]\nphases = [0.0]")])
    result = run("simulate", both, "--out", tmp_path / "both")
    assert result.returncode == 2
    assert "model.transmission_error.phases" in result.stderr
    assert "model.transmission_error.phases_deg" in result.stderr


def test_hbm_samples_per_period_is_samples(tmp_path):
    old = edited(tmp_path, "old.toml", HBM, [("\nsamples = 256", "\nsamples_per_period = 64")])
    new = edited(tmp_path, "new.toml", HBM, [("\nsamples = 256", "\nsamples = 64")])
    a, _ = solve(tmp_path, "new", "hbm", new)
    b, stderr = solve(tmp_path, "old", "hbm", old)
    assert "hbm.samples_per_period is deprecated: write hbm.samples" in stderr
    assert_same_results(a, b, rtol=0.0)
    both = edited(tmp_path, "both.toml", HBM,
                  [("\nsamples = 256", "\nsamples = 64\nsamples_per_period = 64")])
    result = run("hbm", both, "--out", tmp_path / "both")
    assert result.returncode == 2
    assert "hbm.samples_per_period" in result.stderr and "hbm.samples" in result.stderr


def test_rao_rotor_phases_in_radians_read_as_degrees(tmp_path):
    old = edited(tmp_path, "old.toml", RAO, [
        ("te_x_phase_deg = [44.977187]", "te_x_phase = [0.785]"),
        ("te_y_phase_deg = [89.954374]", "te_y_phase = [1.570]"),
        ("pinion_phase_deg = 59.988681", "pinion_phase = 1.047"),
        ("gear_phase_deg = 119.977362", "gear_phase = 2.094"),
    ])
    new = edited(tmp_path, "new.toml", RAO, [
        ("te_x_phase_deg = [44.977187]", f"te_x_phase_deg = [{math.degrees(0.785)!r}]"),
        ("te_y_phase_deg = [89.954374]", f"te_y_phase_deg = [{math.degrees(1.570)!r}]"),
        ("pinion_phase_deg = 59.988681", f"pinion_phase_deg = {math.degrees(1.047)!r}"),
        ("gear_phase_deg = 119.977362", f"gear_phase_deg = {math.degrees(2.094)!r}"),
    ])
    a, _ = solve(tmp_path, "new", "rotor", new)
    b, stderr = solve(tmp_path, "old", "rotor", old)
    for key in ("mesh.te_x_phase_deg", "mesh.te_y_phase_deg", "runout.pinion_phase_deg",
                "runout.gear_phase_deg"):
        assert f"write {key}" in stderr, key
    assert_same_results(a, b, rtol=1e-7)


def test_fe_rotor_campbell_range_and_axial_bearing_keys(tmp_path):
    short = ("campbell.points=3", "campbell.modes=2")
    old = edited(tmp_path, "old.toml", CAMPBELL, [
        ("speed_min_rpm = 0.0", "start_speed_rpm = 0.0"),
        ("speed_max_rpm = 3000.0", "end_rpm = 3000.0"),
    ])
    a, _ = solve(tmp_path, "new", "rotor", CAMPBELL, *short)
    b, stderr = solve(tmp_path, "old", "rotor", old, *short)
    assert "campbell.start_speed_rpm is deprecated: write campbell.speed_min_rpm" in stderr
    assert "campbell.end_rpm is deprecated: write campbell.speed_max_rpm" in stderr
    assert_same_results(a, b, rtol=0.0)
    c, stderr = solve(tmp_path, "kxx", "rotor", CAMPBELL, *short,
                      "pinion_shaft.bearings.kxx=[0.0]")
    assert "pinion_shaft.bearings.kxx is deprecated: it now reads pinion_shaft.bearings.k_axial" \
        in stderr
    assert c["config"]["pinion_shaft"]["bearings"]["k_axial"] == [0.0]


def test_a_sweep_warns_once_for_an_old_key(tmp_path):
    edited(tmp_path, "base.toml", BACKLASH, [(NEW_BACKLASH, "backlash = 1e-4")])
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('[study]\ncommand = "simulate"\nbase = "base.toml"\ndesign = "grid"\n'
                     'outputs = ["loss=/contact_loss_fraction"]\n'
                     '[study.parameters]\n"model.damping_ratio" = [0.03, 0.05, 0.1]\n')
    result = run("sweep", sweep, "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    assert result.stderr.count("model.backlash is deprecated") == 1, result.stderr


def test_a_swept_old_converting_key_is_converted_in_every_case(tmp_path):
    base = edited(tmp_path, "base.toml", BACKLASH,
                  [("amplitudes = [1e-6]", "amplitudes = [3e-5]")])
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('[study]\ncommand = "simulate"\nbase = "base.toml"\ndesign = "grid"\n'
                     'outputs = ["kv=/dynamic_factor"]\n'
                     '[study.parameters]\n"model.backlash" = [2e-6, 1.5e-6]\n')
    result = run("sweep", sweep, "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    assert result.stderr.count("model.backlash is deprecated") == 1, result.stderr
    assert "model.normal_backlash" in result.stderr
    rows = (tmp_path / "out" / "sweep.csv").read_text().splitlines()
    header = rows[0].split(",")
    values = [float(row.split(",")[header.index("kv")]) for row in rows[1:]]
    for j, value in zip((4e-6, 3e-6), values):
        new, _ = solve(tmp_path, f"new{j}", "simulate", base, f"model.normal_backlash={j}")
        assert value == pytest.approx(new["results"]["dynamic_factor"], rel=1e-12)
