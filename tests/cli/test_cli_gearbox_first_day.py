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


# --- item 3: defaults that work, errors that name the gearbox's keys ---------------------------

def test_a_gear_without_a_bore_takes_its_shafts_diameter(tmp_path):
    """On main: "gear.bore_diameter = 0 m ... set gear.bore_diameter" (no such key)."""
    path = reducer(tmp_path)
    path.write_text(path.read_text().replace("bore_diameter = 0.05\n", ""))  # z71 and z21x
    result = geardyn("train", analysis(tmp_path, ["static", "modal"]), "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    # The bores now default to the 50 mm shaft they sit on: the same model as the given 0.05.
    (tmp_path / "given").mkdir()
    reducer(tmp_path / "given")
    same = geardyn("train", analysis(tmp_path / "given", ["static", "modal"]),
                   "--out", tmp_path / "given" / "out")
    assert same.returncode == 0, same.stderr
    a = json.loads((tmp_path / "out" / "summary.json").read_text())["results"]["modal"]
    b = json.loads((tmp_path / "given" / "out" / "summary.json").read_text())["results"]["modal"]
    assert [m["frequency_hz"] for m in a["modes"]] == [m["frequency_hz"] for m in b["modes"]]


def test_a_bore_the_tooth_model_needs_is_asked_for_under_the_gears_own_key(tmp_path):
    path = reducer(tmp_path)
    # A pinion cut into its shaft (the shaft is as wide as the gear): no bore to derive.
    path.write_text(path.read_text().replace("bore_diameter = 0.04\n", "")
                    .replace("outer_diameters = [0.04]", "outer_diameters = [0.07]"))
    result = geardyn("train", analysis(tmp_path, ["static"]), "--out", tmp_path / "out")
    assert result.returncode == 2, result.stderr
    assert "gears.z19.bore_diameter = 0 m" in result.stderr, result.stderr
    assert "set gears.z19.bore_diameter" in result.stderr
    assert "pinion" not in result.stderr.replace("pinion_hub_radius", "")


def test_mismatched_gears_are_named_by_their_keys(tmp_path):
    path = reducer(tmp_path)
    path.write_text(path.read_text().replace("module = 0.004\n", "module = 0.003\n", 1))
    result = geardyn("train", analysis(tmp_path, ["static"]), "--out", tmp_path / "out")
    assert result.returncode == 2, result.stderr
    assert "gears.z59x.module = 0.004: must equal gears.z21x.module = 0.003" in result.stderr, \
        result.stderr


PLANETARY = """[gearbox]
name = "first-day planetary"
dofs = "planar"
[shafts.sun]
mass = 0.4
polar_inertia = 3e-4
[shafts.ring]
mass = 2.4
polar_inertia = 2e-2
[shafts.carrier]
mass = 5.4
polar_inertia = 2.3e-2
[gears.sun_gear]
shaft = "sun"
teeth = 30
module = 2e-3
face_width = 0.02
bore_diameter = 0.02
[gears.ring_gear]
shaft = "ring"
teeth = 90
module = 2e-3
face_width = 0.02
internal = true
[planetary.stage]
sun = "sun_gear"
ring = "ring_gear"
carrier = "carrier"
planets = 3
pin_radial_stiffness = 1e8
pin_tangential_stiffness = 1e8
[planetary.stage.planet]
teeth = 30
module = 2e-3
face_width = 0.02
bore_diameter = 0.02
[bearings.sun_bearing]
shaft = "sun"
kyy = 1e8
kzz = 1e8
[bearings.ring_support]
shaft = "ring"
kyy = 1e8
kzz = 1e8
k_torsion = 6.7e6
[bearings.carrier_bearing]
shaft = "carrier"
kyy = 1e8
kzz = 1e8
[operating_point]
input = "sun"
speed_rpm = 1000.0
torque = 100.0
output = "carrier"
"""


def test_a_planetary_stage_with_default_mesh_models_runs(tmp_path):
    """On main the ring mesh's default, potential_energy, was refused for ring meshes. Ring meshes
    now default to ISO 6336-1 method B with the ring tooth as a rack tooth (z_n2 -> inf)."""
    (tmp_path / "reducer.toml").write_text(PLANETARY)
    result = geardyn("train", analysis(tmp_path, ["static", "modal"]), "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    meshes = {m["mesh"]: m for m in summary["results"]["kinematics"]["meshes"]}
    ring = [m for name, m in meshes.items() if m["kind"] == "ring_planet"]
    assert len(ring) == 3
    # ISO 6336-1 method B by hand for z_p = 30, x = 0, alpha_n = 20 deg, h_fP* = 1.25, spur,
    # steel: q' = C1 + C2/30 (C3/z_n2 -> 0) = 0.04723 + 0.15551/30 mm um/N, c'_th = 1/q',
    # C_M = 0.8, C_R = 1, C_B = 1 + 0.5 (1.2 - 1.25) = 0.975, c' = c'_th C_M C_B,
    # c_gamma_alpha = c' (0.75 eps_alpha + 0.25) per mm of face width.
    c_prime = 0.8 * 0.975 / (0.04723 + 0.15551 / 30)
    kinematics = {m["mesh"]: m for m in
                  __import__("csv").DictReader(open(tmp_path / "out" / "meshes.csv"))}
    for m in ring:
        eps = float(kinematics[m["mesh"]]["contact_ratio"])
        expected = c_prime * (0.75 * eps + 0.25) * 20.0 * 1e6  # N/(mm um) x 20 mm = N/um -> N/m
        assert m["mean_stiffness_n_per_m"] == pytest.approx(expected, rel=1e-9)
    # The tooth models stay refused on ring meshes, with the choices that work there.
    (tmp_path / "reducer.toml").write_text(
        PLANETARY + '[planetary.stage.ring_planet]\nstiffness = "potential_energy"\n')
    refused = geardyn("train", analysis(tmp_path, ["static"]), "--out", tmp_path / "bad")
    assert refused.returncode == 2
    assert 'planetary.stage.ring_planet.stiffness = "potential_energy"' in refused.stderr
    assert '"iso6336"' in refused.stderr


def test_a_planet_without_a_bore_is_asked_for_under_its_key(tmp_path):
    (tmp_path / "reducer.toml").write_text(
        PLANETARY.replace("face_width = 0.02\nbore_diameter = 0.02\n[bearings", "face_width = 0.02\n[bearings"))
    result = geardyn("train", analysis(tmp_path, ["static"]), "--out", tmp_path / "out")
    assert result.returncode == 2, result.stderr
    assert "set planetary.stage.planet.bore_diameter" in result.stderr, result.stderr


def test_te_phases_default_to_zero_in_every_command(tmp_path):
    """One rule: no phases means every phase 0; a wrong count names both keys."""
    from cli_support import EXAMPLES
    example = EXAMPLES / "simulate_gear_pair_backlash.toml"
    ok = geardyn("simulate", example, "--out", tmp_path / "a", "--set",
                 "model.transmission_error.amplitudes=[1e-6, 5e-7]", "--set",
                 "model.transmission_error.phases_deg=[]")
    assert ok.returncode == 0, ok.stderr
    bad = geardyn("simulate", example, "--out", tmp_path / "b", "--set",
                  "model.transmission_error.phases_deg=[0, 10, 20]")
    assert bad.returncode == 2
    assert ("model.transmission_error.phases_deg = 3 values: one phase per amplitude of "
            "model.transmission_error.amplitudes (1 values), or none (all 0)") in bad.stderr


# --- item 4: one line per kind of warning; --quiet silences notes -------------------------------

def test_a_warning_shared_by_meshes_is_one_line_and_quiet_silences_notes(tmp_path):
    path = reducer(tmp_path)
    # Bores that put both pinions below Sainsot's data (r_f / r_int < 1.7).
    path.write_text(path.read_text().replace("bore_diameter = 0.04\n", "bore_diameter = 0.032\n")
                    .replace("bore_diameter = 0.05\n", "bore_diameter = 0.05\n"))
    text = path.read_text()
    text = text.replace("[gears.z21x]\nshaft = \"inter\"\nteeth = 21\nmodule = 0.004\n"
                        "face_width = 0.04\nhelix_angle_deg = -15.0\nbore_diameter = 0.05\n",
                        "[gears.z21x]\nshaft = \"inter\"\nteeth = 21\nmodule = 0.004\n"
                        "face_width = 0.04\nhelix_angle_deg = -15.0\nbore_diameter = 0.056\n")
    path.write_text(text)
    config = analysis(tmp_path, ["static"])
    result = geardyn("train", config, "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    lines = [l for l in result.stderr.splitlines() if "fillet-foundation fit" in l]
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith("note: Sainsot's (2004) fillet-foundation fit is extrapolated "
                               "for 2 meshes (meshes.stage1 (fourier model): pinion"), lines[0]
    assert "; meshes.stage2 (fourier model): pinion" in lines[0], lines[0]
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert sum("fillet-foundation fit" in w for w in summary["warnings"]) == 2
    # Issue #34: the list of affected meshes in summary.json, the line quotes the largest change.
    fits = summary["foundation_fit_extrapolated"]
    assert [f["mesh"] for f in fits] == ["meshes.stage1 (fourier model)",
                                         "meshes.stage2 (fourier model)"], fits
    assert all("pinion" in f["members"] and f["coefficients"] for f in fits), fits
    largest = max(fits, key=lambda f: abs(f["mean_stiffness_change"]))
    assert (f"changes by up to {100 * largest['mean_stiffness_change']:+.2f} % "
            f"({largest['mesh']})") in lines[0], lines[0]
    quiet = geardyn("train", config, "--out", tmp_path / "quiet", "--quiet")
    assert quiet.returncode == 0 and "fillet-foundation" not in quiet.stderr, quiet.stderr


# --- item 5: outputs with the right units --------------------------------------------------------

def test_static_forces_split_force_and_moment_with_their_units(tmp_path):
    from cli_support import EXAMPLES
    import csv
    result = geardyn("train", EXAMPLES / "train_two_stage_flexible.toml", "--out", tmp_path,
                     "--set", 'analysis.run=["static"]', "--set", "output.plots=false")
    assert result.returncode == 0, result.stderr
    rows = list(csv.DictReader(open(tmp_path / "static_forces.csv")))
    for row in rows:
        assert (row["kind"].endswith("_n_m")) == (row["unit"] == "N m"), row
        assert row["kind"].endswith("_n") or row["kind"].endswith("_n_m"), row
    axial = [r for r in rows if r["component"].endswith(".axial")]
    assert axial and all(r["unit"] == "N" for r in axial)
    beams = [r for r in rows if r["component"].startswith("input.beam")]
    assert beams and {r["unit"] for r in beams} == {"N", "N m"}
    # The 200 N m input torque passes through the input shaft's beams between the coupling and
    # the pinion: their largest moment resultant (torque and bending) is at least that, and it
    # is a moment in N m (on main the beams' resultant mixed N and N m under "N").
    moments = {r["component"]: float(r["force"]) for r in beams if r["unit"] == "N m"}
    assert max(moments.values()) >= 200.0 * (1 - 1e-9)
    summary = json.loads((tmp_path / "summary.json").read_text())["results"]["static"]
    assert "element_force" not in summary
    for name, moment in moments.items():
        assert summary["element_moment_n_m"][name] == pytest.approx(moment, rel=1e-12)


def test_the_steady_state_says_how_far_it_is_from_converged(tmp_path):
    """Item 5: with the potential-energy stiffness (jumps where pairs enter and leave) the
    frequency-domain steady state the Newmark run is compared with converges slowly in its
    harmonics; the result says by how much it changes at twice the harmonics. With the
    one-order Fourier stiffness (the default fit) the response's harmonics fall geometrically,
    by about k_1/k_0 ~ 0.1 an order through the parametric coupling: beyond 20 harmonics that is
    far below 1e-6 of the p2p."""
    changes = {}
    for stiffness in ("potential_energy", "fourier"):
        folder = tmp_path / stiffness
        folder.mkdir()
        path = reducer(folder, teeth=(20, 60, 20, 60), bearing_damping=2e3)
        path.write_text(path.read_text().replace('stiffness = "fourier"',
                                                 f'stiffness = "{stiffness}"'))
        result = geardyn("train", analysis(folder, ["time"], "[time]\nmesh_harmonics = 20\n"),
                         "--out", folder / "out")
        assert result.returncode == 0, result.stderr
        time = json.loads((folder / "out" / "summary.json").read_text())["results"]["time"]
        changes[stiffness] = time["steady_state_truncation_relative_to_p2p"]
        assert set(changes[stiffness]) == {"stage1", "stage2"}
    for mesh in ("stage1", "stage2"):
        assert 1e-4 < changes["potential_energy"][mesh] < 0.5, changes
        assert changes["fourier"][mesh] < 1e-6, changes
