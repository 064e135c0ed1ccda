"""The Python rotor, spectrum and identification API against the library's own checks: the
frequency-domain solution vs Dormand-Prince, whirl peaks from numpy records, identification."""

import cmath

import numpy as np
import pytest

import geardyn


def test_table41_defaults_and_damping_mapping():
    rotor = geardyn.LateralRotor()
    assert rotor.mesh_stiffness == 6e8
    assert rotor.mesh_damping == pytest.approx(2 * 0.01 * (6e8 * 0.31 * 1.27 / 1.58) ** 0.5)
    assert rotor.common_period == pytest.approx(35 / 11)
    assert len(rotor.te_x) == 5 and rotor.te_x[0] == pytest.approx((40e-6, 0.785))
    with pytest.raises(ValueError, match="te_y_phase"):
        geardyn.LateralRotor(te_y_phase=[0.1, 0.2])


def test_time_response_matches_the_frequency_domain_peaks():
    rotor = geardyn.LateralRotor()
    r = rotor.time_response()
    assert r["status"] == "steady_state" and r["eta"].shape == (len(r["t"]), 4)
    begin, end = r["window"]
    eta, t = r["eta"][begin:end], r["t"][begin:end]
    peaks = geardyn.gear_whirl_peaks(eta[:, 0], eta[:, 1], eta[:, 2], eta[:, 3], r["sample_rate"],
                                     pinion_speed_rpm=660.0, pinion_teeth=16, gear_teeth=35,
                                     first_sample_time=t[0], reference_time=0.0)
    exact = rotor.frequency_response()
    largest = max(abs(v[1]) for shaft in exact.values() for v in shaft.values())
    for shaft, components in exact.items():
        for name, (frequency, value) in components.items():
            measured_frequency, measured = peaks["peaks"][shaft][name]
            assert measured_frequency == pytest.approx(frequency)
            assert abs(measured - value) < 1e-6 * largest, (shaft, name)
    # The pinion runout circle: -e_p e^{-j phi_p} at -11 Hz (backward in the probe frame).
    f, v = exact["pinion"]["pinion_1x_bwd"]
    assert f == pytest.approx(-11.0) and v == pytest.approx(-200e-6 * cmath.exp(-1j * 1.047))


def test_full_spectrum_of_a_forward_circle():
    fs, n = 1000.0, 1000
    t = np.arange(n) / fs
    f, c = geardyn.full_spectrum(2e-6 * np.cos(2 * np.pi * 50 * t), 2e-6 * np.sin(2 * np.pi * 50 * t), fs)
    assert f[np.argmax(abs(c))] == pytest.approx(50.0)
    assert abs(c).max() == pytest.approx(2e-6)
    assert abs(c[f == -50.0][0]) < 1e-18


def test_identify_from_exact_peaks_both_methods():
    truth = geardyn.LateralRotor()
    peaks = {"pinion_speed": 11.0, "peaks": truth.frequency_response()}
    for method in ("joint", "three_step"):
        r = geardyn.identify_dte(truth, [peaks], method=method)
        assert r["mesh_stiffness"]["value"] == pytest.approx(6e8, rel=1e-6)
        assert r["mean_te"]["value"] == pytest.approx(50e-6, rel=1e-6)
        assert r["te_x"][0]["amplitude"]["value"] == pytest.approx(40e-6, rel=1e-6)
        assert r["te_y"][4]["phase"]["value"] == pytest.approx(1.570, abs=1e-6)
        assert r["pinion_runout"]["phase"]["value"] == pytest.approx(1.047, abs=1e-6)
        assert isinstance(r["rotor"], geardyn.LateralRotor)
