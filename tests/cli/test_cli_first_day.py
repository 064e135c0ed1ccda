"""Issue #18, "a first day with geardyn": resource limits up front, progress on long runs,
messages that name real keys in the user's units, sweeps that do not lose work, and a command
line that says what it wants. Each test fails on the main branch before the issue."""

import csv
import json
import os
import pathlib
import re
import subprocess
import sys

import pytest

from cli_support import CLI, EXAMPLES, run

sys.path.insert(0, str(pathlib.Path(__file__).parents[1] / "examples"))
from result_names import badly_cased, stdout_lines_without_units, summary_keys_badly_named  # noqa: E402

SIMULATE = EXAMPLES / "simulate_gear_pair_backlash.toml"
STATS_MC = EXAMPLES / "stats_monte_carlo_pitch_errors.toml"
HBM = EXAMPLES / "hbm_saletti2025_100Nm.toml"
ROTOR = EXAMPLES / "rotor_rao2023_table41.toml"


def run_env(*args, env=None):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True,
                          env=dict(os.environ, **(env or {})))


def sweep_file(folder, parameters, outputs='["df=/dynamic_factor"]', extra=""):
    path = folder / "study.toml"
    path.write_text(f'[study]\ncommand = "simulate"\nbase = "{SIMULATE}"\noutputs = {outputs}\n'
                    f'{extra}\n[study.parameters]\n{parameters}\n[output]\nplots = false\n')
    return path


# --- item 1: resource limits up front ---------------------------------------------------------

def test_a_billion_case_sweep_is_refused_before_it_allocates(tmp_path):
    study = sweep_file(tmp_path, '"model.damping_ratio" = {min = 0.0, max = 1.0, num = 1000000000}')
    result = run("sweep", study, "--out", tmp_path / "out")
    assert result.returncode == 2, result.stderr
    assert "study.parameters" in result.stderr and "1e+09 cases" in result.stderr
    assert "memory limit" in result.stderr and "MemAvailable" in result.stderr
    assert not (tmp_path / "out" / "sweep_journal.jsonl").exists()


def test_monte_carlo_over_the_memory_limit_is_refused_naming_the_key(tmp_path):
    result = run_env("stats", STATS_MC, "--out", tmp_path, "--set", "monte_carlo.samples=100000000",
                     env={"GEARDYN_MEMORY_LIMIT": "4e9"})
    assert result.returncode == 2, result.stderr
    assert "monte_carlo.samples = 100000000" in result.stderr
    assert "GB" in result.stderr and "GEARDYN_MEMORY_LIMIT" in result.stderr


def test_simulate_that_may_take_long_says_so_and_proceeds(tmp_path):
    # Up to 1e8 periods of 1e5 steps: an estimate of days, but the run reaches its steady state
    # in a few dozen periods.
    result = run("simulate", SIMULATE, "--out", tmp_path, "--set", "solver.steps_per_period=102400",
                 "--set", "solver.max_periods=100000000", "--set", "output.plots=false")
    assert result.returncode == 0, result.stderr
    assert "estimated to take up to" in result.stderr and "proceeding" in result.stderr
    assert "solver.steps_per_period = 102400" in result.stderr


def test_hbm_and_rotor_estimate_before_running(tmp_path):
    result = run_env("hbm", HBM, "--out", tmp_path / "h", "--set", "hbm.harmonics=512",
                     "--set", "hbm.samples=1048576", env={"GEARDYN_MEMORY_LIMIT": "1e8"})
    assert result.returncode == 2 and "hbm.harmonics = 512" in result.stderr, result.stderr
    result = run("rotor", ROTOR, "--out", tmp_path / "r", "--set", "time.samples=200000000")
    assert result.returncode == 2 or "estimated to take" in result.stderr, result.stderr
    result = run_env("rotor", ROTOR, "--out", tmp_path / "r", "--set", "time.samples=200000000",
                     env={"GEARDYN_MEMORY_LIMIT": "1e9"})
    assert result.returncode == 2 and "time.samples = 200000000" in result.stderr, result.stderr


# --- item 2: progress on long runs ------------------------------------------------------------

LONG_SIMULATE = ["--set", "solver.steps_per_period=20480", "--set", "solver.steady_tolerance=1e-300",
                 "--set", "solver.max_periods=400", "--set", "output.plots=false"]
PROGRESS_NOW = {"GEARDYN_PROGRESS_AFTER": "0"}  # the first line at once, not after 2 s


def test_long_runs_show_progress_with_eta_unless_quiet(tmp_path):
    result = run_env("simulate", SIMULATE, "--out", tmp_path / "a", "--progress", *LONG_SIMULATE,
                     env=PROGRESS_NOW)
    assert result.returncode == 1, result.stderr  # max_periods: never steady at 1e-300
    lines = [l for l in result.stderr.splitlines() if l.startswith("simulate: ") and "ETA" in l]
    assert lines and "periods of max_periods" in lines[0], result.stderr
    assert "simulate: finished in" in result.stderr
    quiet = run_env("simulate", SIMULATE, "--out", tmp_path / "b", "--progress", "--quiet",
                    *LONG_SIMULATE, env=PROGRESS_NOW)
    assert "ETA" not in quiet.stderr
    # Issue #33 item 1: on by default, also when stderr is not a terminal; --no-progress: off.
    piped = run_env("simulate", SIMULATE, "--out", tmp_path / "c", *LONG_SIMULATE, env=PROGRESS_NOW)
    assert "ETA" in piped.stderr
    off = run_env("simulate", SIMULATE, "--out", tmp_path / "d", "--no-progress", *LONG_SIMULATE,
                  env=PROGRESS_NOW)
    assert "ETA" not in off.stderr
    # The same reporter in the other long commands.
    for command, config, extra, label in [
            ("stats", STATS_MC, ["--set", "monte_carlo.samples=400"], "stats: Monte Carlo: "),
            ("hbm", HBM, ["--set", "sweep.start=2000.0", "--set", "sweep.stop=2100.0"], "hbm: sweep"),
            ("rotor", ROTOR, ["--set", "time.duration=4.0", "--set", "measurement.formats=[]"],
             "rotor: time response: ")]:
        result = run_env(command, config, "--out", tmp_path / command, "--progress",
                         "--set", "output.plots=false", *extra, env=PROGRESS_NOW)
        assert result.returncode in (0, 1), result.stderr  # rotor: 4 s is still transient
        assert any(l.startswith(label) and "ETA" in l for l in result.stderr.splitlines()), \
            (command, result.stderr)


def test_ltca_identify_and_train_campbell_show_progress(tmp_path):
    for command, config, extra, label in [
            ("ltca", EXAMPLES / "ltca_visnadi2021_long_relief.toml", [], "ltca: Harris map: "),
            ("ltca", EXAMPLES / "ltca_visnadi2021_long_relief.toml", [], "ltca: loaded contact: "),
            ("identify", EXAMPLES / "identify_rao2023_table41.toml", [], "identify: joint fit: "),
            ("train", EXAMPLES / "train_two_stage_reducer.toml",
             ["--set", 'analysis.run=["campbell"]'], "train: Campbell: ")]:
        result = run_env(command, config, "--out", tmp_path / command, "--progress",
                         "--set", "output.plots=false", *extra, env=PROGRESS_NOW)
        assert result.returncode == 0, (command, result.stderr)
        assert any(l.startswith(label) and "ETA" in l for l in result.stderr.splitlines()), \
            (command, result.stderr)
        quiet = run_env(command, config, "--out", tmp_path / (command + "_q"), "--progress",
                        "--quiet", "--set", "output.plots=false", *extra, env=PROGRESS_NOW)
        assert "ETA" not in quiet.stderr


# --- item 4: messages name real keys, in the user's units -------------------------------------

def test_simulate_at_zero_speed_names_the_speed_key(tmp_path):
    result = run("simulate", SIMULATE, "--out", tmp_path, "--set", "excitation.mesh_frequency=0")
    assert result.returncode == 2
    assert "excitation.mesh_frequency = 0 Hz" in result.stderr
    assert "solver.period" not in result.stderr


def test_hbm_echoes_steps_in_hz_as_typed(tmp_path):
    result = run("hbm", HBM, "--out", tmp_path, "--set", "sweep.max_step=1",
                 "--set", "sweep.min_step=2")
    assert result.returncode == 2, result.stderr
    assert "sweep.max_step = 1 Hz" in result.stderr and "2 Hz" in result.stderr
    assert "6.28" not in result.stderr


# --- item 8: sweeps ---------------------------------------------------------------------------

def test_sweep_refuses_to_discard_the_journal_of_an_interrupted_sweep(tmp_path):
    study = sweep_file(tmp_path, '"model.damping_ratio" = [0.04, 0.06]')
    out = tmp_path / "out"
    assert run("sweep", study, "--out", out, "--quiet").returncode == 0
    # A completed sweep is replaced like any command's results (make demo, ctest reruns).
    assert run("sweep", study, "--out", out, "--quiet").returncode == 0
    # Killed before the end: the journal has finished cases, no summary written after them.
    (out / "summary.json").unlink()
    again = run("sweep", study, "--out", out, "--quiet")
    assert again.returncode == 2 and "--resume" in again.stderr and "--overwrite" in again.stderr
    assert "2 finished case(s)" in again.stderr
    assert len((out / "sweep_journal.jsonl").read_text().splitlines()) == 3  # header + 2 cases
    assert run("sweep", study, "--out", out, "--quiet", "--overwrite").returncode == 0


def test_sweep_finds_a_bad_value_before_any_case_runs(tmp_path):
    study = sweep_file(tmp_path, '"model.damping_ratio" = [0.1, -1]')
    result = run("sweep", study, "--out", tmp_path / "out")
    assert result.returncode == 2
    assert 'study.parameters.model.damping_ratio[1] = -1' in result.stderr, result.stderr
    assert "--set" not in result.stderr
    assert not (tmp_path / "out" / "sweep.csv").exists()


def test_sweep_finds_a_bad_output_pointer_after_the_first_case(tmp_path):
    study = sweep_file(tmp_path, '"model.damping_ratio" = {min = 0.02, max = 0.1, num = 40}',
                       outputs='["/dynamic_factr"]')
    result = run("sweep", study, "--out", tmp_path / "out", "--threads", 1)
    assert result.returncode == 2, result.stderr
    assert "study.outputs" in result.stderr and "did you mean /dynamic_factor?" in result.stderr
    journal = (tmp_path / "out" / "sweep_journal.jsonl").read_text().splitlines()
    assert len(journal) == 2  # the header and the one probing case


def test_sweep_set_overrides_study_parameters_and_refuses_swept_base_keys(tmp_path):
    study = sweep_file(tmp_path, '"model.damping_ratio" = [0.04, 0.06, 0.08]')
    out = tmp_path / "out"
    result = run("sweep", study, "--out", out, "--quiet", "--set",
                 'study.parameters."model.damping_ratio"=[0.05]')
    assert result.returncode == 0, result.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["results"]["cases"] == 1
    clash = run("sweep", study, "--out", tmp_path / "o2", "--set", "model.damping_ratio=0.05")
    assert clash.returncode == 2 and "study.parameters" in clash.stderr


def test_sweep_summary_std_of_a_constant_column_is_zero(tmp_path):
    # solver.harmonics only changes what is reported: the mean mesh force is the same number in
    # every case, and its standard deviation is exactly 0 (sum(x²) − n x̄² gave 2.5e-5 N here).
    study = sweep_file(tmp_path, '"solver.harmonics" = [1, 2, 3, 4, 5, 6, 7]',
                       outputs='["mean=/mesh_force/mean"]')
    out = tmp_path / "out"
    assert run("sweep", study, "--out", out, "--quiet").returncode == 0
    stats = json.loads((out / "summary.json").read_text())["results"]["outputs"]["mean"]
    assert stats["count"] == 7 and stats["min"] == stats["max"]
    assert stats["std"] == 0.0


def test_sweep_quiet_does_not_repeat_a_warning_per_case(tmp_path):
    study = sweep_file(tmp_path, '"model.damping_ratio" = {min = 0.03, max = 0.09, num = 6}',
                       extra='set = ["model.contact=\\"linear\\""]')
    result = run("sweep", study, "--out", tmp_path / "out", "--quiet")
    assert result.returncode == 0, result.stderr
    warnings = [l for l in result.stderr.splitlines() if l.startswith("warning:")]
    assert len(warnings) == len(set(warnings)) == 1, result.stderr


# --- item 9: the command line -----------------------------------------------------------------

def test_unknown_command_suggests_the_closest():
    result = run("simulat", SIMULATE)
    assert result.returncode == 2 and "did you mean simulate?" in result.stderr


def test_threads_zero_is_readable(tmp_path):
    result = run("simulate", SIMULATE, "--out", tmp_path, "--threads", 0)
    assert result.returncode == 2
    assert "[1, 4096]" in result.stderr and len(result.stderr) < 400, result.stderr


def test_exit_codes_are_one_list_in_help_and_docs():
    help_text = run("--help").stdout
    docs = (EXAMPLES.parent / "docs" / "cli.md").read_text()
    for code in range(5):
        assert f"\n  {code}  " in help_text
        assert f"| {code} |" in docs


def test_missing_config_is_an_io_failure(tmp_path):
    result = run("simulate", tmp_path / "nope.toml")
    assert result.returncode == 3 and "no such file" in result.stderr


def test_empty_out_stdin_and_empty_config_are_explained(tmp_path):
    assert run("simulate", SIMULATE, "--out", "").returncode == 2
    stdin = run("simulate", "-")
    assert stdin.returncode == 2 and "stdin" in stdin.stderr
    empty = tmp_path / "empty.toml"
    empty.write_text("# nothing yet\n\n")
    result = run("geometry", empty)
    assert result.returncode == 2
    assert "the configuration is empty; start from `geardyn schema geometry`" in result.stderr


def test_geometry_and_stiffness_name_the_key_the_user_set(tmp_path):
    spur = EXAMPLES / "stiffness_visnadi2021_spur.toml"
    far = run("stiffness", spur, "--out", tmp_path / "a", "--set", "pair.centre_distance=1.0")
    assert far.returncode == 2
    assert "pair.centre_distance = 1 m" in far.stderr and "too large" in far.stderr, far.stderr
    solid = run("stiffness", spur, "--out", tmp_path / "b", "--set", "pinion.bore_diameter=0",
                "--set", 'mesh_stiffness.models=["potential_energy"]')
    assert solid.returncode == 2
    assert "pinion.bore_diameter = 0 m" in solid.stderr, solid.stderr
    assert "mesh_stiffness.potential_energy.pinion_hub_radius" in solid.stderr


def test_a_module_in_millimetres_is_flagged(tmp_path):
    # 3 instead of 0.003: the error the wrong length causes says what is implausible.
    rig = EXAMPLES / "geometry_rao2023_rig.toml"
    result = run("geometry", rig, "--out", tmp_path, "--set", "pinion.module=3",
                 "--set", "gear.module=3")
    assert result.returncode == 2
    assert "pinion.module = 3 m is outside the usual 0.1 mm to 100 mm" in result.stderr
    wide = run("geometry", rig, "--out", tmp_path, "--set", "pinion.face_width=20",
               "--set", "gear.face_width=20", "--set", "output.plots=false")
    assert wide.returncode == 0, wide.stderr
    assert "warning: pinion.face_width = 20 m is outside the usual 1 mm to 2 m" in wide.stderr


def test_rotor_sampling_message_echoes_the_samples_as_given(tmp_path):
    result = run("rotor", ROTOR, "--out", tmp_path, "--set", "time.samples=16")
    assert result.returncode == 2
    assert "time.samples = 16 (over time.duration" in result.stderr, result.stderr
    assert "Hz sampling" not in result.stderr


# --- item 7: probe CSVs as people have them ---------------------------------------------------

def _spectrum(tmp_path, name, text, extra=""):
    record = tmp_path / f"{name}.csv"
    record.write_bytes(text.encode("utf-8"))
    config = tmp_path / f"{name}.toml"
    config.write_text(f'[input]\nfile = "{record}"\n{extra}[gears]\npinion_teeth = 16\n'
                      'gear_teeth = 35\n[output]\nplots = false\n')
    result = run("spectrum", config, "--out", tmp_path / name)
    return result, tmp_path / name


def test_probe_csv_with_t_bom_semicolons_or_a_named_time_column(tmp_path):
    rotor = tmp_path / "rotor"
    made = run("rotor", ROTOR, "--out", rotor, "--set", "output.plots=false",
               "--set", 'measurement.formats=["csv"]', "--set", "measurement.duration=6.5")
    assert made.returncode == 0, made.stderr
    original = (rotor / "measurement.csv").read_text()
    header, body = original.split("\n", 1)
    # The result-name convention: time and displacement channels name their units.
    assert header == "t_s,x1_m,y1_m,x2_m,y2_m,keyphasor", header
    rest = header[len("t_s"):]
    reference, _ = _spectrum(tmp_path, "reference", original)
    assert reference.returncode == 0, reference.stderr
    expected = (tmp_path / "reference" / "spectrum_peaks.csv").read_text()
    variants = {
        # Records written before the convention (time, x1, ...) still read.
        "unsuffixed": ("time" + rest.replace("_m", "") + "\n" + body, ""),
        "t": ("t" + rest + "\n" + body, ""),
        "time_s_bom": ("\ufefftime_s" + rest + "\n" + body, ""),
        "semicolon": ((header + "\n" + body).replace(",", ";").replace(".", ","), ""),
        "named": ("seconds" + rest + "\n" + body, 'time_column = "seconds"\n'),
    }
    for name, (text, extra) in variants.items():
        result, out = _spectrum(tmp_path, name, text, extra)
        assert result.returncode == 0, (name, result.stderr)
        assert (out / "spectrum_peaks.csv").read_text() == expected, name


# --- item 3: one name per quantity, one file for every command ---------------------------------

ONE_FILE = """title = "21/37 helical pair, 3000 rpm, 200 N m"
[pinion]
teeth = 21
module = 0.003
helix_angle_deg = 15.0
face_width = 0.03
bore_diameter = 0.03
[gear]
teeth = 37
module = 0.003
helix_angle_deg = -15.0
face_width = 0.03
bore_diameter = 0.05
[pair]
speed_rpm = 3000.0
[mesh_stiffness]
models = ["potential_energy"]
positions = 200
[model]
damping_ratio = 0.05
torque = 200.0
[model.stiffness]
type = "potential_energy"
[hbm]
harmonics = 6
[sweep]
start = 800.0
stop = 1200.0
max_step = 50.0
direction = "up"
stability = false
[stats]
simulate = false
[output]
plots = false
"""


def test_one_file_drives_every_gear_pair_command(tmp_path):
    config = tmp_path / "pair.toml"
    config.write_text(ONE_FILE)
    for command in ("geometry", "stiffness", "simulate", "hbm", "stats"):
        result = run(command, config, "--out", tmp_path / command)
        assert result.returncode == 0, (command, result.stderr)
    notes = run("geometry", config, "--out", tmp_path / "g2").stderr
    assert "[hbm] is for `geardyn hbm`; `geardyn geometry` ignores it" in notes, notes
    simulate = json.loads((tmp_path / "simulate" / "summary.json").read_text())
    assert simulate["config"]["pair"]["speed_rpm"] == 3000.0  # used, not ignored:
    # Through the gearbox's kinematics (rpm → rad/s → Hz): equal to round-off.
    assert simulate["results"]["model"]["mesh_frequency"] == pytest.approx(21 * 3000.0 / 60.0,
                                                                          rel=1e-12)


def test_other_commands_sections_are_still_spell_checked(tmp_path):
    config = tmp_path / "pair.toml"
    config.write_text(ONE_FILE.replace("harmonics = 6", "harmonix = 6"))
    result = run("geometry", config, "--out", tmp_path / "g")
    assert result.returncode == 2 and 'did you mean "hbm.harmonics"?' in result.stderr, result.stderr


def test_old_spellings_work_with_a_warning_naming_the_new_key(tmp_path):
    new = run("hbm", HBM, "--out", tmp_path / "new", "--set", "model.torque=200",
              "--set", "sweep.start=2000.0", "--set", "sweep.stop=2200.0")
    old = run("hbm", HBM, "--out", tmp_path / "old", "--set", "model.pinion_torque=200",
              "--set", "sweep.start=2000.0", "--set", "sweep.stop=2200.0")
    assert new.returncode == old.returncode == 0, old.stderr
    assert "model.pinion_torque is deprecated" in old.stderr and "model.torque" in old.stderr
    assert ((tmp_path / "new" / "sweep.csv").read_text() ==
            (tmp_path / "old" / "sweep.csv").read_text())
    file = tmp_path / "both.toml"
    file.write_text(HBM.read_text().replace("torque = 100.0", "torque = 100.0\npinion_torque = 100.0"))
    both = run("hbm", file, "--out", tmp_path / "both")
    assert both.returncode == 2 and "keep only model.torque" in both.stderr, both.stderr


# --- item 5: units on everything printed -------------------------------------------------------

# The checks live in tests/examples/result_names.py: run_example.py applies them to every
# example's own run (each example runs once in the suite, issue 34); here they must be able to
# fail.
def test_result_name_checks_reject_capital_units_and_other_spellings():
    # The checks run_example.py applies to every example must be able to fail.
    assert badly_cased("mesh_frequency_Hz") and badly_cased("output_torque_N_m")
    assert badly_cased("p2p_N_stage1") and badly_cased("stiffness_N_per_m")
    assert not badly_cased("mesh_frequency_hz") and not badly_cased("output_torque_n_m")
    assert not badly_cased("stage1.sun_planet1") and not badly_cased("dynamic_factor")
    assert summary_keys_badly_named({"static": {"mesh_force_N": {"s1": 1.0}}}) == [
        "static.mesh_force_N"]
    assert summary_keys_badly_named({"peak": {"freq_hz": 1.0, "time": 2.0}}) == [
        "peak.freq_hz", "peak.time"]
    assert summary_keys_badly_named({"time": {"steps": 3}}) == []  # an analysis, not a time
    assert stdout_lines_without_units("  peak p2p 2.8477e-05 at 1632.47 Hz\n") == [
        "  peak p2p 2.8477e-05 at 1632.47 Hz"]
    assert stdout_lines_without_units("  peak p2p 2.8477e-05 m at 1632.47 Hz\n"
                                      "model [N/m]   mean\n  iso 1.2e9\n") == []


def test_run_example_fails_an_example_whose_results_break_the_names(tmp_path):
    """run_example.py's naming check on a result folder, as it sees an example's run."""
    from result_names import naming_failures

    (tmp_path / "summary.json").write_text('{"results": {"peak_Hz": 1.0}}')
    (tmp_path / "table.csv").write_text("speed_rpm,force_N\n1,2\n")
    failures = naming_failures("train", tmp_path, "speed 1500.0\n")
    assert len(failures) == 3, failures
    assert "force_N" in failures[1] and "peak_Hz" in failures[2] and "1500" in failures[0]


def test_implausible_lengths_and_speeds_warn_in_pair_commands_and_gearboxes(tmp_path):
    ltca = run("ltca", EXAMPLES / "ltca_visnadi2021_long_relief.toml", "--out", tmp_path / "l",
               "--set", "output.plots=false", "--set", "pinion.face_width=20",
               "--set", "gear.face_width=20")
    assert ltca.returncode == 0, ltca.stderr
    assert "warning: pinion.face_width = 20 m is outside the usual 1 mm to 2 m" in ltca.stderr
    config = tmp_path / "pair.toml"
    config.write_text(ONE_FILE)
    fast = run("simulate", config, "--out", tmp_path / "s", "--set", "pair.speed_rpm=300000")
    assert "pair.speed_rpm = 300000 rpm is above 200000 rpm" in fast.stderr, fast.stderr
    reducer = EXAMPLES / "train_two_stage_reducer.toml"
    only_static = ["--set", 'analysis.run=["static"]', "--set", "output.plots=false"]
    wide = run("train", reducer, "--out", tmp_path / "t1", *only_static,
               "--set", "gears.z1.face_width=20", "--set", "operating_point.speed_rpm=300000")
    assert wide.returncode == 0, wide.stderr
    assert "warning: gears.z1.face_width = 20 m is outside the usual 1 mm to 2 m" in wide.stderr
    assert "operating_point.speed_rpm = 300000 rpm is above 200000 rpm" in wide.stderr
    assert "pinion.face_width" not in wide.stderr  # the gearbox's key, once
    millimetres = run("train", reducer, "--out", tmp_path / "t2", *only_static,
                      "--set", "gears.z1.module=3", "--set", "gears.z2.module=3")
    assert "gears.z1.module = 3 m is outside the usual 0.1 mm to 100 mm" in millimetres.stderr, \
        millimetres.stderr


# --- item 6: the plane of k, F and the TE of a helical pair -----------------------------------

def test_helical_force_plane_is_stated_in_schema_output_and_headers(tmp_path):
    import csv
    import math
    config = tmp_path / "pair.toml"
    config.write_text(ONE_FILE.replace("positions = 200", "positions = 200\ntransmitted_force = 6000.0"))
    result = run("stiffness", config, "--out", tmp_path / "k")
    assert result.returncode == 0, result.stderr
    assert "k, F and STE along the transverse line of action (F = T1/r_b1)" in result.stdout
    # β_b by hand: tan α_t = tan 20° / cos 15°, tan β_b = tan 15° cos α_t.
    alpha_t = math.atan(math.tan(math.radians(20.0)) / math.cos(math.radians(15.0)))
    beta_b = math.atan(math.tan(math.radians(15.0)) * math.cos(alpha_t))
    assert f"normal plane (beta_b = {math.degrees(beta_b):.4f} deg)" in result.stdout, result.stdout
    assert f"F_n = F / cos beta_b = {6000.0 / math.cos(beta_b):g} N" in result.stdout
    plane = json.loads((tmp_path / "k" / "summary.json").read_text())["results"]["plane"]
    assert plane["plane"] == "transverse"
    assert plane["normal"]["force"] == pytest.approx(6000.0 / math.cos(beta_b), rel=1e-12)
    with open(tmp_path / "k" / "mesh_stiffness.csv", newline="") as handle:
        header = next(csv.reader(handle))
    assert "k_total_transverse_n_per_m" in header and "ste_transverse_m" in header
    simulate = run("simulate", config, "--out", tmp_path / "s")
    assert simulate.returncode == 0, simulate.stderr
    header = (tmp_path / "s" / "time_response.csv").read_text().splitlines()[0].split(",")
    assert "mesh_force_transverse_n" in header and "x_transverse_m" in header
    schema = run("schema", "stiffness").stdout
    assert "transmitted force F = T₁/r_b1 along the transverse line of action" in schema
    assert "taken as the normal-plane stiffness k_n and projected" in schema
    assert "along the transverse line of action" in run("schema", "simulate").stdout
    assert "along the transverse line of action" in run("schema", "ltca").stdout
    assert "along the contact normal" in run("schema", "train").stdout


# --- item 10: correctness loose ends ----------------------------------------------------------

def test_readme_links_stay_inside_the_repository():
    import re
    root = EXAMPLES.parent
    readme = (root / "README.md").read_text()
    targets = re.findall(r"\]\(([^)#]+)\)", readme) + re.findall(r"`(\.\./[^`]+)`", readme)
    assert targets
    for target in targets:
        if "://" in target:
            continue
        path = (root / target).resolve()
        assert path.exists() and root.resolve() in path.parents, target


def test_fe_modal_table_has_no_negative_zero_damping(tmp_path):
    # Without any damping every ζ is round-off (|ζ| ~ 1e-16, of either sign): it prints 0.0000.
    undamped = ["--set", "damping.stiffness_proportional=0"]
    for shaft in ("pinion_shaft", "gear_shaft"):
        for c in ("cyy", "czz"):
            undamped += ["--set", f"{shaft}.bearings.{c}=[0.0]"]
    result = run("rotor", EXAMPLES / "rotor_visnadi2021_modal.toml", "--out", tmp_path,
                 "--set", "output.plots=false", *undamped)
    assert result.returncode == 0, result.stderr
    assert "zeta 0.0000" in result.stdout and "-0.0000" not in result.stdout, result.stdout


def test_help_shows_each_commands_options_and_an_example():
    # Issue #33 item 7: `train --help` listed sweep's --resume/--overwrite and had no example.
    train = run("train", "--help")
    assert train.returncode == 0
    assert "--resume" not in train.stdout and "--overwrite" not in train.stdout, train.stdout
    assert "Example:\n  geardyn train examples/" in train.stdout, train.stdout
    sweep = run("sweep", "--help")
    assert "--resume" in sweep.stdout and "--overwrite" in sweep.stdout
    for command in ("geometry", "stiffness", "simulate", "stats", "hbm", "rotor", "spectrum",
                    "identify", "ltca", "sweep"):
        shown = run(command, "--help").stdout
        example = re.search(r"Example:\n  geardyn (\S+) (examples/\S+\.toml)", shown)
        assert example and example.group(1) == command, shown
        assert (EXAMPLES.parent / example.group(2)).is_file(), example.group(2)


def test_schema_of_a_misspelt_command_suggests_the_command():
    result = run("schema", "trian")
    assert result.returncode == 2
    assert "did you mean 'train'?" in result.stderr, result.stderr
