"""geardyn train `time` on a train without meshes: a flexible Jeffcott rotor driven only by an
unbalance steps by the excitation's period, writes its bearing forces (Newmark and the
frequency-domain steady state) and agrees with the steady state; a train that nothing drives is
refused naming the key (exit 2)."""

import json

from cli_support import run

JEFFCOTT = """
[gearbox]
name = "Jeffcott rotor"
dofs = "full"

[shafts.rotor]
section_lengths = [0.3, 0.3]
outer_diameters = [0.02]
flexible = true
stiffness_proportional_damping = 2e-5

[disks.wheel]
shaft = "rotor"
position = 0.3
mass = 10.0
polar_inertia = 0.05
diametral_inertia = 0.025

[bearings.left]
shaft = "rotor"
position = 0.0
kyy = 1e8
kzz = 1e8
cyy = 200.0
czz = 200.0

[bearings.right]
shaft = "rotor"
position = 0.6
kyy = 1e8
kzz = 1e8
cyy = 200.0
czz = 200.0

[operating_point]
input = "rotor"
speed_rpm = 3000.0
torque = 0.0
output = "rotor"

[analysis]
run = ["time"]
"""

UNBALANCE = """
[unbalances.wheel]
shaft = "rotor"
position = 0.3
mass_eccentricity = 1e-4
phase_deg = 0.0
"""


def test_unbalanced_rotor_time_run_agrees_with_its_steady_state(tmp_path):
    path = tmp_path / "jeffcott.toml"
    path.write_text(JEFFCOTT + UNBALANCE)
    result = run("train", path, "--out", tmp_path / "out", "--quiet")
    assert result.returncode == 0, result.stderr
    time = json.loads((tmp_path / "out" / "summary.json").read_text())["results"]["time"]
    assert time["status"] == "completed"
    # 128 steps per period of the unbalance (1x, 50 Hz): the default step of a train without
    # meshes.
    assert abs(time["time_step_s"] - 1.0 / (50.0 * 128)) < 1e-12
    # Newmark (average acceleration) against the steady state: the period error (ωΔt)²/12 =
    # 2.0e-4 at 128 steps per period is the expected difference (measured 3.0e-4); 2e-3 leaves
    # room for the phase it accumulates over the recorded periods, and fails on a missing or
    # wrong force.
    differences = time["bearing_force_difference_to_steady_state_relative_to_p2p"]
    assert set(differences) == {"left", "right"}
    assert all(0.0 < d < 2e-3 for d in differences.values()), differences
    header = (tmp_path / "out" / "time_history.csv").read_text().splitlines()[0].split(",")
    assert header == ["t_s"] + [f"{p}bearing_force_{b}_{a}_n" for p in ("", "steady_")
                                for b in ("left", "right") for a in ("y", "z")]
    # The unbalance force m e Ω² = 1e-4 × (100π)² = 9.87 N: the run speed (50 Hz) lies above the
    # rotor's first bending critical (29.4 Hz), where its response is mass-controlled, so each
    # bearing of this symmetric rotor transmits less than that (measured 2.74 N).
    rows = (tmp_path / "out" / "time_history.csv").read_text().splitlines()[1:]
    peak = max(abs(float(r.split(",")[1])) for r in rows)
    assert 0.0 < peak < 1e-4 * (100.0 * 3.141592653589793) ** 2


def test_history_stride_keeps_every_nth_row_and_the_comparisons(tmp_path):
    path = tmp_path / "jeffcott.toml"
    path.write_text(JEFFCOTT + UNBALANCE)
    full = run("train", path, "--out", tmp_path / "full", "--quiet")
    strided = run("train", path, "--out", tmp_path / "strided", "--quiet",
                  "--set", "time.history_stride=5")
    assert full.returncode == 0 and strided.returncode == 0, strided.stderr
    rows = (tmp_path / "full" / "time_history.csv").read_text().splitlines()
    kept = (tmp_path / "strided" / "time_history.csv").read_text().splitlines()
    assert kept[0] == rows[0] and kept[1:] == rows[1::5]
    # The comparison with the steady state still reads every step.
    results = [json.loads((tmp_path / d / "summary.json").read_text())["results"]["time"]
               for d in ("full", "strided")]
    key = "bearing_force_difference_to_steady_state_relative_to_p2p"
    assert results[0][key] == results[1][key]
    bad = run("train", path, "--out", tmp_path / "bad", "--quiet", "--set", "time.history_stride=0")
    assert bad.returncode == 2 and "time.history_stride" in bad.stderr


def test_train_that_nothing_drives_is_refused_naming_the_key(tmp_path):
    path = tmp_path / "still.toml"
    path.write_text(JEFFCOTT)
    result = run("train", path, "--out", tmp_path / "out", "--quiet")
    assert result.returncode == 2
    assert "meshes" in result.stderr and "unbalance" in result.stderr, result.stderr


def test_unbalance_response_peaks_at_the_first_critical_speed(tmp_path):
    """forced on the rotor: the bearings' dynamic force against speed (the rotor's Bode plot,
    forced_response.png) peaks where the 1x line meets the first bending mode."""
    path = tmp_path / "jeffcott.toml"
    path.write_text(JEFFCOTT.replace('run = ["time"]', 'run = ["modal", "forced"]') + UNBALANCE)
    result = run("train", path, "--out", tmp_path / "out", "--quiet",
                 "--set", "forced.speed_min_rpm=300", "--set", "forced.speed_max_rpm=6000",
                 "--set", "forced.points=400")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    first = min(m["frequency_hz"] for m in summary["results"]["modal"]["modes"]
                if m["frequency_hz"] > 1.0)
    rows = [r.split(",") for r in (tmp_path / "out" / "forced_response.csv").read_text().splitlines()]
    column = rows[0].index("dynamic_left_n")
    peak = max(rows[1:], key=lambda r: float(r[column]))
    # The mode at the operating speed stands for the critical: the disk sits mid-span, so the
    # gyroscopic shift of this bending mode is small; 2 % holds it and the 14 rpm grid.
    assert abs(float(peak[0]) / 60.0 - first) < 0.02 * first, (peak[0], first)


def test_dormand_prince_time_run_meets_the_steady_state_where_newmark_has_its_period_error(
        tmp_path):
    """time.method = "dormand_prince" on the same rotor: the same record (times, tables), sampled
    from an error-controlled integration. Newmark's 2e-4 period error is gone: against the
    steady state within 1e-5 of p2p (rtol 1e-8 over the derived duration; measured below 1e-6),
    and the summary says which integrator ran and how many adaptive steps it took."""
    path = tmp_path / "jeffcott.toml"
    path.write_text(JEFFCOTT + UNBALANCE + '\n[time]\nmethod = "dormand_prince"\n')
    result = run("train", path, "--out", tmp_path / "out", "--quiet")
    assert result.returncode == 0, result.stderr
    time = json.loads((tmp_path / "out" / "summary.json").read_text())["results"]["time"]
    assert time["status"] == "completed"
    assert time["method"] == "dormand_prince" and time["integrator_steps"] > 0
    differences = time["bearing_force_difference_to_steady_state_relative_to_p2p"]
    assert set(differences) == {"left", "right"}
    assert all(0.0 < d < 1e-5 for d in differences.values()), differences


def test_dormand_prince_refuses_a_nonlinear_train_naming_the_key(tmp_path):
    path = tmp_path / "clearance.toml"
    text = (JEFFCOTT + UNBALANCE + '\n[time]\nmethod = "dormand_prince"\n').replace(
        "position = 0.6\n", "position = 0.6\nradial_clearance = 10e-6\n")
    path.write_text(text)
    result = run("train", path, "--out", tmp_path / "out", "--quiet")
    assert result.returncode == 2, result.stderr
    assert "time.method" in result.stderr and "newmark" in result.stderr, result.stderr
