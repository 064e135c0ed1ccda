"""Issue #33, "a first day with a gearbox of your own": a two-stage helical reducer written from
docs/guide/gear_trains.md (z 19/71 + 21/59, six bearings without damping, as in the guide), run
as a new user runs it. Each test fails on main before the issue."""

import json
import os
import subprocess

import pytest

from cli_support import CLI


def reducer(folder, teeth=(19, 71, 21, 59), backlash=None, mesh_damping=0.05, bearing_damping=0.0):
    """The guide's reducer: three shafts, two helical meshes, six bearings."""
    z1, z2, z3, z4 = teeth
    gears = "".join(
        f'[gears.{name}]\nshaft = "{shaft}"\nteeth = {z}\nmodule = {m}\nface_width = {b}\n'
        f"helix_angle_deg = {beta}\nbore_diameter = {bore}\n"
        for name, shaft, z, m, b, beta, bore in [
            (f"z{z1}", "input", z1, 3e-3, 0.030, 15.0, 0.040),
            (f"z{z2}", "inter", z2, 3e-3, 0.030, -15.0, 0.050),
            (f"z{z3}x", "inter", z3, 4e-3, 0.040, -15.0, 0.050),
            (f"z{z4}x", "output", z4, 4e-3, 0.040, 15.0, 0.070)])
    extra = f"backlash = {backlash}\n" if backlash else ""
    text = f"""[gearbox]
name = "first-day reducer"
dofs = "planar"
[shafts.input]
section_lengths = [0.25]
outer_diameters = [0.04]
[shafts.inter]
section_lengths = [0.3]
outer_diameters = [0.05]
[shafts.output]
section_lengths = [0.3]
outer_diameters = [0.07]
{gears}[meshes.stage1]
gears = ["z{z1}", "z{z2}"]
stiffness = "fourier"
damping_ratio = {mesh_damping}
te_amplitudes = [3e-6, 1e-6]
{extra}[meshes.stage2]
gears = ["z{z3}x", "z{z4}x"]
position_angle_deg = 30.0
stiffness = "fourier"
damping_ratio = {mesh_damping}
te_amplitudes = [4e-6]
{extra}"""
    for name, shaft, k in [("in_a", "input", 4e8), ("in_b", "input", 4e8), ("mid_a", "inter", 6e8),
                           ("mid_b", "inter", 6e8), ("out_a", "output", 8e8),
                           ("out_b", "output", 8e8)]:
        text += f'[bearings.{name}]\nshaft = "{shaft}"\nkyy = {k}\nkzz = {k}\n'
        if bearing_damping:
            text += f"cyy = {bearing_damping}\nczz = {bearing_damping}\n"
    text += ('[operating_point]\ninput = "input"\nspeed_rpm = 1500.0\ntorque = 150.0\n'
             'output = "output"\n')
    path = folder / "reducer.toml"
    path.write_text(text)
    return path


def analysis(folder, run, extra=""):
    path = folder / "analysis.toml"
    path.write_text(f'[gearbox]\nfile = "reducer.toml"\n[analysis]\nrun = {json.dumps(run)}\n'
                    f'[output]\nplots = false\n{extra}')
    return path


def geardyn(*args, env=None):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True,
                          env=dict(os.environ, **(env or {})))


def warnings_of(stderr):
    return [l for l in stderr.splitlines() if l.startswith("warning: ")]


# --- item 2: undamped modes --------------------------------------------------------------------

def test_time_of_the_guides_undamped_reducer_runs_and_names_the_keys_once(tmp_path):
    """The output shaft's lateral modes have no damping but no mesh strain: the meshes do not
    excite them, so the derived duration does not wait for them (it was 2e13 s, exit 2)."""
    reducer(tmp_path)
    # 512 steps per mesh period: at the default 128 Newmark's phase error leaves 5 % of the
    # p2p at stage 1 (the status then says so; test_newmark_that_disagrees...).
    result = geardyn("train", analysis(tmp_path, ["modal", "time"],
                                       "[time]\nsteps_per_mesh_period = 512\n"),
                     "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    undamped = [w for w in warnings_of(result.stderr) if "have no damping" in w]
    assert len(undamped) == 1, result.stderr  # modal and time find them: one line
    assert "bearings.out_a.cyy/czz" in undamped[0] and "do not excite them" in undamped[0]
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    time = summary["results"]["time"]
    assert time["status"] == "completed"
    # The duration is the decay of the slowest mode the meshes drive (1413 Hz, ζ = 2.2e-4 from
    # the mesh damping on its 0.9 % mesh strain: σ = 1.94 1/s, ln(1e6) / σ = 7.1 s) plus the
    # recorded common periods (2 × 71 / 475 Hz = 0.30 s), rounded up to whole periods.
    transient = time["transient"]
    assert transient["slowest_mode_frequency_hz"] == pytest.approx(1413.2, abs=0.1)
    assert transient["decay_time_s"] == pytest.approx(7.1, rel=0.01)
    assert [round(f, 1) for f in transient["undamped_modes_hz"]] == [1339.8, 2683.4]
    period = 71 / 475.0
    assert 0 <= time["duration_s"] - (transient["decay_time_s"] + 2 * period) < period
    assert summary["warnings"].count(undamped[0][len("warning: "):]) == 1


def test_an_undamped_mode_the_meshes_drive_is_refused_naming_what_to_damp(tmp_path):
    reducer(tmp_path, mesh_damping=0.0)
    result = geardyn("train", analysis(tmp_path, ["static", "modal", "time"]),
                     "--out", tmp_path / "out")
    assert result.returncode == 2, result.stderr
    assert "time.duration = 0 (derived)" in result.stderr
    assert "has no damping and the meshes excite it" in result.stderr
    # Item 1: what finished before the error was printed as it finished.
    assert "static: ok" in result.stdout and "modal at 1500.0 rpm" in result.stdout


def test_newmark_that_disagrees_with_the_steady_state_says_so(tmp_path):
    """A duration far shorter than the transient: the comparison's status, never "completed"."""
    reducer(tmp_path, teeth=(20, 60, 20, 60), bearing_damping=2e3)
    result = geardyn("train", analysis(tmp_path, ["time"], "[time]\nduration = 0.002\n"),
                     "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["results"]["time"]["status"] == "differs_from_steady_state"
    assert any("differ by more than 5 %" in w for w in summary["warnings"]), summary["warnings"]


def test_neutral_multipliers_of_undamped_modes_are_not_bifurcations(tmp_path):
    """On main: dozens of "neimark_sacker" lines with |μ| = 1.000000001."""
    reducer(tmp_path, teeth=(20, 60, 20, 60), backlash=1e-4)
    result = geardyn("train", analysis(tmp_path, ["nonlinear"],
                                       '[nonlinear]\ndirection = "up"\nharmonics = 9\n'
                                       "speed_min_rpm = 1700\nspeed_max_rpm = 2000\n"),
                     "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    assert "neimark_sacker" not in result.stdout, result.stdout
    assert any("unit circle" in w for w in warnings_of(result.stderr)), result.stderr


# --- item 1: progress, estimates, results as they finish ---------------------------------------

def test_a_train_time_run_shows_progress_by_default_and_is_sized_before_it_allocates(tmp_path):
    reducer(tmp_path, bearing_damping=2e3)
    config = analysis(tmp_path, ["static", "time"])
    result = geardyn("train", config, "--out", tmp_path / "a", env={"GEARDYN_PROGRESS_AFTER": "0"})
    assert result.returncode == 0, result.stderr
    assert any(l.startswith("train: time: ") and "ETA" in l for l in result.stderr.splitlines()), \
        result.stderr  # stderr is a pipe here, and no --progress was given
    quiet = geardyn("train", config, "--out", tmp_path / "b", "--no-progress",
                    env={"GEARDYN_PROGRESS_AFTER": "0"})
    assert "ETA" not in quiet.stderr
    # 100 recorded common periods of 9088 steps of 9 DOFs: about 100 MB, over a 20 MB limit.
    big = geardyn("train", config, "--out", tmp_path / "c", "--set", "time.record_periods=100",
                  env={"GEARDYN_MEMORY_LIMIT": "2e7"})
    assert big.returncode == 2, big.stderr
    assert "time.record_periods = 100" in big.stderr and "memory limit" in big.stderr
    assert "static: ok" in big.stdout  # printed when it finished, before the refusal
