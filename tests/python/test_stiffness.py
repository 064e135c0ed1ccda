"""The Python mesh-stiffness API mirrors the C++ models and the CLI's numbers."""

import math

import numpy as np
import pytest

import geardyn


def visnadi_pair(helix_deg=0.0):
    def gear(teeth, helix):
        return geardyn.Gear(teeth=teeth, module=3e-3, face_width=0.02, youngs_modulus=200e9,
                            poisson_ratio=0.3, bore_diameter=0.03, helix_angle_deg=helix)
    return geardyn.GearPair(pinion=gear(25, helix_deg), gear=gear(30, -helix_deg))


def test_potential_energy_matches_the_independent_reference():
    k = geardyn.mesh_stiffness(visnadi_pair())
    s = k.summary(3)
    assert s["mean"] == pytest.approx(3.164e8, rel=5e-4)
    assert s["min"] == pytest.approx(2.151e8, rel=5e-4)
    assert s["max"] == pytest.approx(3.787e8, rel=5e-4)
    assert k.contact_ratio == pytest.approx(1.6325826, abs=1e-7)


def test_call_accepts_numbers_and_arrays_and_is_periodic():
    k = geardyn.mesh_stiffness(visnadi_pair())
    phases = np.linspace(0.0, 1.0, 101)
    values = k(phases)
    assert values.shape == (101,)
    assert np.all(values > 0)
    assert k(0.3) == pytest.approx(k(1.3), rel=1e-12)
    assert np.allclose(k(phases.reshape(1, -1)), values.reshape(1, -1), rtol=0, atol=0)
    total = k.pair_stiffness(phases, 0) + k.pair_stiffness(phases, 1)
    assert np.allclose(total, values, rtol=1e-14)
    with pytest.raises(ValueError, match="phase"):
        k("not a phase")


def test_roll_angle_and_time():
    pair = visnadi_pair()
    k = geardyn.mesh_stiffness(pair)
    theta = geardyn.roll_angle_from_mesh_phase(0.4, 25)
    assert theta == pytest.approx(0.4 * 2 * math.pi / 25)
    assert geardyn.mesh_phase_from_roll_angle(theta, 25) == pytest.approx(0.4)
    assert k(geardyn.mesh_phase_from_roll_angle(theta + 2 * math.pi / 25, 25)) == pytest.approx(k(0.4), rel=1e-12)


def test_every_model_by_name():
    pair = visnadi_pair()
    means = {m: geardyn.mesh_stiffness(pair, m).summary(1)["mean"] for m in geardyn.MESH_STIFFNESS_MODELS}
    assert means["api"] == pytest.approx(2.41140e8, rel=1e-12)
    assert means["step"] == pytest.approx(means["potential_energy"], rel=1e-12)  # mean-preserving
    assert means["fourier"] == pytest.approx(means["potential_energy"], rel=1e-12)
    assert means["iso6336"] == pytest.approx(3.707e8 * 200 / 206, rel=5e-4)
    step = geardyn.mesh_stiffness(pair, "step", levels="api")
    assert step.k_max / step.k_min == pytest.approx(2.0)
    sine = geardyn.mesh_stiffness(pair, "fourier", mean="api")
    assert sine.summary(1)["mean"] == pytest.approx(2.41140e8, rel=1e-12)
    with pytest.raises(ValueError, match="model"):
        geardyn.mesh_stiffness(pair, "sinus")
    with pytest.raises(ValueError, match="no option"):
        geardyn.mesh_stiffness(pair, "api", slices=3)


def test_api_matrix_and_iso_factors():
    k = geardyn.api_directional_stiffness(2.41140e8, 20.0, "down", "clockwise")
    assert k[0, 0] == pytest.approx(2.820802e7, rel=1e-6)
    assert k[0, 1] == pytest.approx(-7.750090e7, rel=1e-6)
    assert k[1, 1] == pytest.approx(2.129320e8, rel=1e-6)
    iso = geardyn.iso6336_stiffness(visnadi_pair(), material_factor=False)
    assert iso["mesh_stiffness"] == pytest.approx(3.707e8, rel=5e-4)
    with pytest.raises(ValueError, match="loading"):
        geardyn.api_directional_stiffness(1e8, 20.0, "sideways")


def test_helical_and_options():
    spur = geardyn.mesh_stiffness(visnadi_pair(0.0)).summary(1)
    helical = geardyn.mesh_stiffness(visnadi_pair(5.0))
    assert helical.summary(1)["mean"] > geardyn.api_mesh_stiffness(0.02, 5.0)
    assert helical.summary(1)["std"] < spur["std"]  # overlap smooths the curve
    sliced = geardyn.mesh_stiffness(visnadi_pair(5.0), slices=40)
    assert sliced(0.4) == pytest.approx(helical(0.4), rel=0.02)
    with pytest.raises(ValueError, match="root"):
        geardyn.mesh_stiffness(visnadi_pair(), root="curved")
    with pytest.raises(ValueError, match="slices"):
        geardyn.mesh_stiffness(visnadi_pair(), slices=-1)


def test_step_and_fourier_constructors_validate():
    with pytest.raises(ValueError, match="contact_ratio"):
        geardyn.StepMeshStiffness(k_min=1e8, k_max=2e8, contact_ratio=0.8)
    with pytest.raises(ValueError, match="amplitudes"):
        geardyn.FourierMeshStiffness(mean=1e8, amplitudes=[0.6, 0.5], phases_deg=[0, 0], contact_ratio=1.5)
    k = geardyn.FourierMeshStiffness(mean=1e8, amplitudes=[0.2], phases_deg=[90.0], contact_ratio=1.5)
    assert k(0.25) == pytest.approx(1e8 * (1 + 0.2 * math.cos(math.pi / 2 - math.pi / 2)))
