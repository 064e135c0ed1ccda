"""Gelman et al. (2005), Case 1: the mean excitation ratio R for a = 0.25, 0.75 (printed 1.2
and 1.05), from the committed configurations, in a few lines."""

import pathlib

import geardyn

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]
for case, printed in (("stats_gelman2005_case1_a025", 1.2), ("stats_gelman2005_case1_a075", 1.05)):
    r = geardyn.run("stats", EXAMPLES / f"{case}.toml", plots=False).results["mean_excitation"]
    print(f"{case}: R = {r['ratio']:.4f} (printed {printed})")
    assert abs(r["ratio"] - printed) < 0.05
