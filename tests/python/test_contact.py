"""The Python loaded-contact API: unmodified teeth give the potential-energy stiffness, a long
relief flattens the STE at its design load and the Harris map bottoms out there."""

import numpy as np
import pytest

import geardyn


def visnadi_pair():
    def gear(teeth):
        return geardyn.Gear(teeth=teeth, module=3e-3, face_width=0.02, youngs_modulus=200e9,
                            poisson_ratio=0.3, bore_diameter=0.03)
    return geardyn.GearPair(pinion=gear(25), gear=gear(30))


def test_unmodified_contact_is_the_potential_energy_stiffness():
    pair = visnadi_pair()
    c = geardyn.loaded_contact(pair, 2000.0, positions=50)
    k = geardyn.mesh_stiffness(pair)
    assert np.allclose(c["secant_stiffness"], k(c["phase"]), rtol=1e-9)
    assert np.allclose(c["pair_loads"].sum(axis=1), 2000.0, rtol=1e-12)


def test_long_relief_and_harris_map():
    pair = visnadi_pair()
    plain = geardyn.loaded_contact(pair, 3000.0)
    relieved = geardyn.loaded_contact(pair, 3000.0, relief="long", design_load=3000.0)
    assert np.ptp(relieved["ste"]) < 0.25 * np.ptp(plain["ste"])
    forces = np.arange(1, 21) * 300.0
    ptp = geardyn.harris_map(pair, forces, relief="long", design_load=3000.0)
    assert forces[np.argmin(ptp)] == pytest.approx(3000.0, abs=300.0)
    with pytest.raises(ValueError, match="design_load"):
        geardyn.loaded_contact(pair, 3000.0, relief="long")
