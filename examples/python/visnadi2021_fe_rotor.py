"""Visnadi & de Castro (2021): the finite-element two-shaft geared rotor. Modes and the first
mesh-line critical speed from Python, then the paper's comparison of mesh-stiffness models
through the command (API has no mesh peaks; the beam model's mean exceeds API)."""

import pathlib

import geardyn

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]
rotor = geardyn.FeGearedRotor(str(EXAMPLES / "rotor_visnadi2021_time.toml"))
modes = rotor.modal(500.0, modes=4)
print("modes at 500 rpm [Hz]:", [round(m["frequency_hz"], 1) for m in modes])
campbell = rotor.campbell([1000.0 + 50 * i for i in range(21)], modes=4)
first = min(c["speed_rpm"] for c in campbell["critical_speeds"] if c["line"] == "mesh")
print(f"first mesh-order critical speed {first:.0f} rpm")
assert abs(first - 1600.7) < 5

compare = geardyn.run("rotor", EXAMPLES / "rotor_visnadi2021_compare_spur.toml", plots=False)
models = compare.results["compare"]["models"]
api_peak = max(max(h["acceleration"]) for h in models["api"]["harmonics"].values())
beam_peak = max(max(h["acceleration"]) for h in models["potential_energy"]["harmonics"].values())
print(f"API mesh peaks {api_peak:.1e} m/s^2 vs beam model {beam_peak:.3g} m/s^2")
assert api_peak < 1e-8 * beam_peak
assert models["potential_energy"]["mean_stiffness_n_per_m"] > models["api"]["mean_stiffness_n_per_m"]
