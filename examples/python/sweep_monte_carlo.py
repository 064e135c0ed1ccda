"""A Monte Carlo study from Python: the dynamic factor of the SDOF gear pair with backlash when
its damping ratio, mass and mesh frequency scatter (64 cases on all cores, reproducible from the
seed), with the histogram of geardyn.plot."""

import math
import pathlib
import tempfile

import geardyn
import geardyn.plot

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]
study = {"study": {
    "command": "simulate",
    "base": str(EXAMPLES / "simulate_gear_pair_backlash.toml"),
    "design": "random", "samples": 64, "seed": 7,
    "outputs": ["dynamic_factor=/dynamic_factor"],
    "parameters": {
        "model.damping_ratio": {"distribution": "truncated_normal", "mean": 0.05, "std": 0.01,
                                "min": 0.02, "max": 0.08},
        "model.mass": {"distribution": "normal", "mean": 1.589, "std": 0.03},
        "excitation.mesh_frequency": {"distribution": "uniform", "min": 900.0, "max": 1100.0},
    }}}
result = geardyn.sweep(study, plots=False)
table = result.table("sweep")
factors = [x for x, s in zip(table["dynamic_factor"], table["status"]) if s == "ok"]
mean = sum(factors) / len(factors)
print(f"{len(factors)} cases: dynamic factor {mean:.4f} ± "
      f"{math.sqrt(sum((x - mean) ** 2 for x in factors) / (len(factors) - 1)):.4f}")
assert len(factors) == 64 and 1.0 < mean < 2.0
again = geardyn.sweep(study, plots=False).table("sweep")["dynamic_factor"]
assert list(again) == list(table["dynamic_factor"])  # same seed, same numbers
with tempfile.TemporaryDirectory(prefix="geardyn-example-") as folder:
    png = pathlib.Path(folder) / "dynamic_factor.png"
    geardyn.plot.plot_histograms([factors], ["dynamic factor"], "Monte Carlo: gear pair", png)
    assert png.exists()
