"""geardyn train forced on the torus of the mesh phases (issue #32): the operating deflection
shapes (forced_ods.csv) of the torus method against the common-period method where both hold
the same tones."""

import csv
import json

from cli_support import EXAMPLES, run

REDUCER = EXAMPLES / "train_two_stage_reducer.toml"


def rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def forced(tmp_path, method):
    out = tmp_path / method
    result = run("train", REDUCER, "--out", out, "--set", "output.plots=false",
                 "--set", 'analysis.run=["forced"]', "--set", "forced.points=12",
                 "--set", f'forced.method="{method}"', "--set", 'forced.torus_truncation="box"')
    assert result.returncode == 0, result.stderr
    return out


def test_torus_ods_equals_the_common_period_ods(tmp_path):
    """The two-stage reducer's meshes are 3:1 (common period 3 stage-2 mesh periods): the torus
    has one generator and the common-period balance's tones, so the two solve the same equations
    (TrainTorus.OneGeneratorIsTheCommonPeriodBalance: 1.5e-14) and their shapes agree to 1e-8 of
    the largest amplitude (round-off of two different linear solvers: GMRES to 1e-13 against LU;
    measured 9e-16)."""
    common, torus = forced(tmp_path, "common_period"), forced(tmp_path, "torus")
    summary = json.loads((torus / "summary.json").read_text())["results"]["forced"]
    assert summary["method"] == "torus"
    assert len(summary["torus"]["generators"]) == 1
    a, b = rows(common / "forced_ods.csv"), rows(torus / "forced_ods.csv")
    assert len(a) == len(b) > 0
    largest = max(abs(complex(float(r["real"]), float(r["imag"]))) for r in a)
    worst = 0.0
    for x, y in zip(a, b):
        assert (x["speed_rpm"], x["mesh"], x["order"], x["dof"], x["unit"]) == \
            (y["speed_rpm"], y["mesh"], y["order"], y["dof"], y["unit"])
        assert abs(float(x["frequency_hz"]) - float(y["frequency_hz"])) <= 1e-9 * float(x["frequency_hz"])
        qa = complex(float(x["real"]), float(x["imag"]))
        qb = complex(float(y["real"]), float(y["imag"]))
        worst = max(worst, abs(qa - qb) / largest)
    assert worst < 1e-8, worst
    assert {r["order"] for r in b} == {"1", "2", "3"}


def test_nonlinear_torus_tables_are_plotted(tmp_path):
    """The hunting-tooth reducer (z 19/71 + 21/59) with 20 µm of backlash at both meshes,
    100 N m, through stage 1's contact loss (10 000-15 000 rpm, 4 harmonics per mesh on the
    torus): nonlinear_tones.png draws the mesh orders of nonlinear_mesh_orders.csv and the
    combination tones of nonlinear_tones.csv along the continuation, one panel per mesh; the
    Newmark check at 12 500 rpm carries the Lyapunov estimate's verdict."""
    hunting = EXAMPLES / "train_hunting_tooth_reducer.toml"
    sets = ['analysis.run=["nonlinear"]', 'nonlinear.method="torus"', "nonlinear.torus_mesh_harmonics=4",
            'nonlinear.direction="up"', "nonlinear.speed_min_rpm=10000", "nonlinear.speed_max_rpm=15000",
            "operating_point.torque=100", "nonlinear.newmark_speeds_rpm=[12500.0]"]
    for mesh in ("stage1", "stage2"):
        sets += [f'meshes.{mesh}.contact="backlash"', f"meshes.{mesh}.backlash=20e-6"]
    result = run("train", hunting, "--out", tmp_path, *[a for s in sets for a in ("--set", s)])
    assert result.returncode == 0, result.stderr
    points = rows(tmp_path / "nonlinear_torus.csv")
    assert max(float(r["contact_loss_stage1"]) for r in points) > 0.1  # through contact loss
    orders = rows(tmp_path / "nonlinear_mesh_orders.csv")
    assert {(r["mesh"], r["order"]) for r in orders} >= {(m, str(o)) for m in ("stage1", "stage2") for o in (1, 2, 3)}
    png = tmp_path / "nonlinear_tones.png"
    assert png.exists() and png.stat().st_size > 20_000
    # The stability check at 12 500 rpm: Newmark and the Lyapunov estimate (its λ₁ decides).
    checks = json.loads((tmp_path / "summary.json").read_text())["results"]["nonlinear"]["newmark_checks"]
    assert len(checks) == 1 and checks[0]["status"] == "completed"
    lyapunov = checks[0]["lyapunov"]
    assert lyapunov["status"] == "completed"
    assert lyapunov["stable"] == (lyapunov["max_exponent_per_s"] < 0.0)
