"""geardyn rotor and geardyn spectrum on the Rao (2023) Table 4.1 rotor: the time-domain steady
state against the exact frequency-domain solution, the spectrum's structure (§4.4), the round trip
through CSV/WAV/HDF5 probe records with a keyphasor, the §4.5 study, and corrupt input."""

import cmath
import csv
import json
import math
import struct

import pytest

from cli_support import EXAMPLES, run

TABLE41 = EXAMPLES / "rotor_rao2023_table41.toml"
STUDY = EXAMPLES / "rotor_rao2023_study.toml"


def peaks(path):
    with open(path, newline="") as handle:
        return {(r["shaft"], r["component"]): r for r in csv.DictReader(handle)}


def value(row):
    return complex(float(row["re_m"]), float(row["im_m"]))


@pytest.fixture(scope="module")
def table41(tmp_path_factory):
    """One run in the probe frame with probe records in every format (2 common periods)."""
    out = tmp_path_factory.mktemp("rotor")
    result = run("rotor", TABLE41, "--out", out, "--set", "output.plots=false",
                 "--set", "spectrum.frame=\"probe\"", "--set", "measurement.formats=[\"csv\",\"wav\",\"hdf5\"]",
                 "--set", "measurement.duration=6.5")
    assert result.returncode == 0, result.stderr
    return out, json.loads((out / "summary.json").read_text())


def test_time_domain_steady_state_matches_the_frequency_domain(table41):
    # The criterion: every peak within 0.5 % in amplitude and 0.01 rad in phase. Dormand-
    # Prince at rtol 1e-8 does far better (measured ~1e-9); peaks below 1e-3 of the largest have
    # no meaningful phase and are compared in absolute terms.
    out, summary = table41
    td, fd = peaks(out / "spectrum_peaks.csv"), peaks(out / "frequency_components.csv")
    assert set(td) == set(fd) and len(td) == 2 * (1 + 10 + 4)
    largest = max(abs(value(r)) for r in fd.values())
    for key, row in fd.items():
        a, b = value(td[key]), value(row)
        if abs(b) < 1e-3 * largest:
            assert abs(a - b) < 1e-6 * largest, key
            continue
        assert abs(abs(a) / abs(b) - 1) < 5e-3, key
        assert abs(cmath.phase(a / b)) < 0.01, key
    assert summary["results"]["time_domain"]["extraction"] == "exact_bins"
    assert summary["results"]["time_vs_frequency"]["max_relative_amplitude_difference"] < 1e-6
    assert summary["results"]["time_domain"]["transient_end_s"] > 0.1  # detected, not zero
    assert summary["results"]["time_domain"]["window_periods"] >= 3


def test_spectrum_structure_of_table41(table41):
    # §4.4: mesh harmonics 176 ... 880 Hz forward and backward; pinion runout at 11 Hz in one
    # whirl direction only (backward in the probe frame: the pinion turns in -z) and gear runout
    # at 5.03 Hz in the other; a static deflection from gravity and the mean TE.
    out, summary = table41
    p = peaks(out / "spectrum_peaks.csv")
    for shaft in ("pinion", "gear"):
        for i in range(1, 6):
            for d in ("fwd", "bwd"):
                row = p[(shaft, f"mesh_{i}_{d}")]
                assert float(row["frequency_hz"]) == pytest.approx((1 if d == "fwd" else -1) * 176.0 * i)
                assert float(row["amplitude_m"]) > 1e-7
        assert float(p[(shaft, "static")]["amplitude_m"]) > 1e-6
    assert float(p[("pinion", "pinion_1x_bwd")]["amplitude_m"]) == pytest.approx(200e-6, rel=1e-6)
    assert float(p[("pinion", "pinion_1x_bwd")]["frequency_hz"]) == pytest.approx(-11.0)
    assert float(p[("pinion", "pinion_1x_fwd")]["amplitude_m"]) < 1e-9
    assert float(p[("gear", "gear_1x_fwd")]["amplitude_m"]) == pytest.approx(300e-6, rel=1e-6)
    assert float(p[("gear", "gear_1x_fwd")]["frequency_hz"]) == pytest.approx(11.0 * 16 / 35)
    assert float(p[("gear", "gear_1x_bwd")]["amplitude_m"]) < 1e-9
    conventions = summary["results"]["conventions"]
    assert "1/N" in conventions["fft"] and "-z" in conventions["rotation"]["pinion"]
    assert summary["seed"] is None if "seed" in summary else True


@pytest.mark.parametrize("extension", ["csv", "wav", "h5"])
def test_probe_record_round_trip(table41, tmp_path, extension):
    # simulate -> 5 kS/s record with keyphasor -> read -> the same peaks within 1e-6 of the
    # largest (no noise): whole pinion cycles between pulses and a least-squares fit at the
    # keyphasor's speed, phases referred to the first pulse.
    out, _ = table41
    record = out / f"measurement.{extension}"
    config = tmp_path / "spectrum.toml"
    config.write_text(f'[input]\nfile = "{record}"\n[gears]\npinion_teeth = 16\ngear_teeth = 35\n'
                      '[output]\nplots = false\n')
    result = run("spectrum", config, "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["results"]["keyphasor"]["speed_rpm"] == pytest.approx(660.0, rel=1e-9)
    assert summary["results"]["record"]["sample_rate_hz"] == 5000.0
    reference, measured = peaks(out / "spectrum_peaks.csv"), peaks(tmp_path / "out" / "spectrum_peaks.csv")
    largest = max(abs(value(r)) for r in reference.values())
    for key, row in reference.items():
        assert abs(value(measured[key]) - value(row)) < 1e-6 * largest, key


def test_noise_is_seeded_and_recorded(table41, tmp_path):
    out, _ = table41
    config = tmp_path / "spectrum.toml"
    config.write_text(f'[input]\nfile = "{out / "measurement.wav"}"\n[gears]\npinion_teeth = 16\n'
                      'gear_teeth = 35\n[spectrum]\nnoise_level = 0.05\nseed = 42\n[output]\nplots = false\n')
    runs = []
    for name in ("a", "b"):
        assert run("spectrum", config, "--out", tmp_path / name).returncode == 0
        runs.append(peaks(tmp_path / name / "spectrum_peaks.csv"))
    assert runs[0] == runs[1]
    summary = json.loads((tmp_path / "a" / "summary.json").read_text())
    assert summary["seed"] == 42
    clean = peaks(out / "spectrum_peaks.csv")
    # 5 % noise barely moves the large peaks (thesis §4.4, Fig. 4.4).
    row = ("pinion", "mesh_1_bwd")
    assert abs(value(runs[0][row]) / value(clean[row]) - 1) < 0.01


def test_shaft_frame_puts_both_runouts_forward(tmp_path):
    result = run("rotor", TABLE41, "--out", tmp_path, "--set", "output.plots=false", "--set", "time.enabled=false",
                 "--set", "measurement.formats=[]")
    assert result.returncode == 0, result.stderr
    fd = peaks(tmp_path / "frequency_components.csv")
    assert float(fd[("pinion", "pinion_1x_fwd")]["frequency_hz"]) == pytest.approx(11.0)
    assert float(fd[("pinion", "pinion_1x_fwd")]["amplitude_m"]) == pytest.approx(200e-6)
    assert float(fd[("gear", "gear_1x_fwd")]["amplitude_m"]) == pytest.approx(300e-6)


def test_parametric_study(tmp_path):
    result = run("rotor", STUDY, "--out", tmp_path, "--set", "output.plots=false")
    assert result.returncode == 0, result.stderr
    study = json.loads((tmp_path / "summary.json").read_text())["results"]["study"]
    names = [c["case"] for c in study["cases"]]
    assert names == ["baseline", "speed_x2", "speed_x4", "stiffness_up_0.2_te_down", "stiffness_down_0.2_te_up",
                     "runout_x0.5", "runout_x2", "mesh_damping_x0.5", "mesh_damping_x2"]
    cases = {c["case"]: c for c in study["cases"]}
    # Runouts only move the 1x circles: no effect on the mesh vibration, doubling on the orbit.
    assert abs(cases["runout_x2"]["pinion"]["mesh_relative_change"]) < 1e-12
    assert cases["runout_x2"]["gear"]["dynamic_relative_change"] > 0.3
    # Higher TE (with softer mesh) raises the mesh vibration, lower TE lowers it (thesis §4.5).
    assert cases["stiffness_down_0.2_te_up"]["pinion"]["mesh_relative_change"] > 0
    assert cases["stiffness_up_0.2_te_down"]["pinion"]["mesh_relative_change"] < 0
    assert {r["group"] for r in study["ranking_mesh"]} == {"speed", "stiffness_te", "runout", "mesh_damping"}
    with open(tmp_path / "study.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 9 * 2 * 15


def write_wav_pcm16(path, channels, frames, rate=5000, truncate=0):
    data = b"".join(struct.pack("<h", frames[i][c]) for i in range(len(frames)) for c in range(channels))
    header = b"RIFF" + struct.pack("<I", 36 + len(data)) + b"WAVEfmt " + struct.pack(
        "<IHHIIHH", 16, 1, channels, rate, rate * channels * 2, channels * 2, 16) + b"data" + struct.pack("<I", len(data))
    path.write_bytes((header + data)[: len(header) + len(data) - truncate])


def spectrum_config(tmp_path, file, extra=""):
    config = tmp_path / "s.toml"
    config.write_text(f'[input]\nfile = "{file}"\n[gears]\npinion_teeth = 16\ngear_teeth = 35\n{extra}'
                      '[output]\nplots = false\n')
    return config


@pytest.mark.parametrize("case, expected", [
    ("nan", "sample"),
    ("time", "not increasing"),
    ("truncated", "truncated"),
    ("channels", "channels"),
    ("no_pulses", "no pulses"),
    ("missing_column", "x2"),
])
def test_corrupt_records_are_rejected(tmp_path, case, expected):
    if case in ("nan", "time", "no_pulses", "missing_column"):
        lines = ["time,x1,y1,x2,y2,keyphasor"]
        for i in range(2000):
            t = i / 5000
            key = 1.0 if (case != "no_pulses" and (t * 11) % 1.0 < 0.1) else 0.0
            lines.append(f"{t},{math.sin(t)},{math.cos(t)},{key}" if case == "missing_column"
                         else f"{t},{math.sin(t)},{math.cos(t)},0,0,{key}")
        if case == "nan":
            lines[500] = lines[500].replace(",0,0,", ",nan,0,")
        if case == "time":
            lines[700], lines[701] = lines[701], lines[700]
        if case == "missing_column":
            lines[0] = "time,x1,y1,keyphasor"
        file = tmp_path / "m.csv"
        file.write_text("\n".join(lines) + "\n")
    else:
        file = tmp_path / "m.wav"
        frames = [[int(1000 * math.sin(i / 10))] * 5 for i in range(2000)]
        write_wav_pcm16(file, 4 if case == "channels" else 5,
                        [f[:4] for f in frames] if case == "channels" else frames,
                        truncate=3 if case == "truncated" else 0)
    result = run("spectrum", spectrum_config(tmp_path, file), "--out", tmp_path / "out")
    assert result.returncode == 2, result.stderr
    assert expected in result.stderr, result.stderr
    assert "input.file" in result.stderr or "keyphasor" in result.stderr or "input.channels" in result.stderr


def test_pcm_wav_is_scaled(tmp_path):
    # A 16-bit PCM record: values scaled to [-1, 1) then by input.scale; runs end to end.
    file = tmp_path / "pcm.wav"
    frames = []
    for i in range(10000):
        t = i / 5000
        key = 30000 if (t * 11) % 1.0 < 0.1 else 0
        x = int(20000 * math.cos(2 * math.pi * 176 * t))
        y = int(20000 * math.sin(2 * math.pi * 176 * t))
        frames.append([x, y, x, -y, key])
    write_wav_pcm16(file, 5, frames)
    config = spectrum_config(tmp_path, file, "")
    config.write_text(config.read_text().replace("[gears]", "[gears]\nharmonics = 1", 1).replace(
        "[input]\n", "[input]\nscale = 1e-4\n", 1))
    result = run("spectrum", config, "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    p = peaks(tmp_path / "out" / "spectrum_peaks.csv")
    # x + jy = A e^{+j 2 pi 176 t} on the pinion shaft: forward, radius 20000/32768 * 1e-4.
    assert float(p[("pinion", "mesh_1_fwd")]["amplitude_m"]) == pytest.approx(20000 / 32768 * 1e-4, rel=2e-3)
    assert float(p[("gear", "mesh_1_bwd")]["amplitude_m"]) == pytest.approx(20000 / 32768 * 1e-4, rel=2e-3)


def test_rotor_bad_input_names_the_key(tmp_path):
    result = run("rotor", TABLE41, "--out", tmp_path, "--set", "mesh.te_y=[1e-6]")
    assert result.returncode == 2 and "mesh.te_y" in result.stderr
    result = run("rotor", TABLE41, "--out", tmp_path, "--set", "mesh.stifness=1e8")
    assert result.returncode == 2 and "mesh.stiffness" in result.stderr
    result = run("rotor", TABLE41, "--out", tmp_path, "--set", "time.samples=1000")
    assert result.returncode == 2 and "time.samples" in result.stderr  # aliasing of 880 Hz
    result = run("rotor", TABLE41, "--out", tmp_path, "--set", "time.duration=2.0", "--set", "output.plots=false",
                 "--set", "measurement.formats=[]")
    assert result.returncode == 1 and "common period" in result.stderr
    assert json.loads((tmp_path / "summary.json").read_text())["numerical_failure"] is True


def test_default_samples_follow_the_highest_mesh_harmonic(tmp_path):
    """A rig of one's own at default [time] settings (follow-up of issue 31): 23/61 teeth at
    1450 rpm with two TE harmonics puts the 2nd mesh harmonic at 1111.7 Hz, which the thesis's
    fixed 2^15 samples over 15 s (2184 Hz) would alias. time.samples, not given, is the smallest
    power of two with 2.2 samples per period of that harmonic: 2.2 x 1111.7 Hz x 15 s = 36 685
    -> 2^16 (the run is snapped to the common period, so the rate is within 1e-3 of 65535/15 s)."""
    config = tmp_path / "rig.toml"
    config.write_text(
        "[rotor]\npinion_teeth = 23\ngear_teeth = 61\nspeed_rpm = 1450.0\n"
        "[mesh]\nte_x = [20e-6, 8e-6]\nte_y = [15e-6, 6e-6]\n"
        "[measurement]\nformats = []\n[output]\nplots = false\n")
    result = run("rotor", config, "--out", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["config"]["time"]["samples"] is None  # not given: derived
    time = summary["results"]["time_domain"]
    assert time["sample_rate_hz"] == pytest.approx(65535 / 15.0, rel=1e-3)
    assert time["sample_rate_hz"] > 2 * 2 * 23 * 1450 / 60
    # The same rig with the samples given is read as given, and refused when they alias.
    result = run("rotor", config, "--out", tmp_path / "given", "--set", "time.samples=32768")
    assert result.returncode == 2, result.stderr
    assert "time.samples = 32768 (over time.duration = 15 s)" in result.stderr
    assert "1111.67 Hz" in result.stderr
