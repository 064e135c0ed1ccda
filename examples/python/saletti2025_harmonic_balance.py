"""Saletti et al. (2025), Table 1 at 100 N·m: the harmonic-balance forced response of the spur
pair with contact elements (H = 14), continued up and down through its folds; the peak and the
forced-response plot (stable and unstable branches). In-process: nothing is written except the
plots, into a temporary folder removed at the end."""

import pathlib
import tempfile

import geardyn

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]
result = geardyn.run("hbm", EXAMPLES / "hbm_saletti2025_100Nm.toml")
print(result)
peak = result.results["peak"]
print(f"peak {peak['p2p'] * 1e6:.2f} um p2p at {peak['frequency']:.1f} Hz, "
      f"{len(result.results['folds'])} folds, {result.results['failures']} failures")
assert result.results["failures"] == 0 and len(result.results["folds"]) >= 2
assert 1500 < peak["frequency"] < 1800
sweep = result.to_pandas("sweep")  # one row per continuation point, units in .attrs
assert sweep.attrs["units"]["frequency_hz"] == "Hz" and len(sweep) == result.results["points"]
with tempfile.TemporaryDirectory(prefix="geardyn-example-") as out:
    result.plot(out)
    assert (pathlib.Path(out) / "forced_response.png").exists()
