"""geardyn train, analysis "stats": Gelman's mean excitation ratio R per mesh of the two-stage
reducer example against its independent forms (R from the Newmark record, R − 1 linear in the
gear error, R independent of the baseload), the mesh force and DTE statistics against the static
forces, the result files, and bad [stats] input named by key (exit 2)."""

import csv
import json

import pytest

from cli_support import EXAMPLES, run

STATS = EXAMPLES / "train_two_stage_reducer_stats.toml"


def quick(*extra):
    return ["--set", "output.plots=false", "--set", "time.steps_per_mesh_period=128", *extra]


def stats_of(out):
    return json.loads((out / "summary.json").read_text())["results"]["stats"]["meshes"]


@pytest.fixture(scope="module")
def example(tmp_path_factory):
    out = tmp_path_factory.mktemp("stats")
    result = run("train", STATS, "--out", out, *quick())
    assert result.returncode == 0, result.stderr
    return out, result


def test_ratio_from_the_record_and_the_static_forces(example):
    out, result = example
    meshes = stats_of(out)
    assert set(meshes) == {"stage1", "stage2"}
    for name, m in meshes.items():
        # m₁(K δ)/F of the Newmark record is R when the mean mesh force is the static one
        # (torque balance of each shaft over whole periods): measured 8e-14 at 256 steps.
        assert m["simulated_mean_excitation_ratio"] == pytest.approx(m["mean_excitation_ratio"],
                                                                     abs=1e-8), name
        assert m["mesh_force_n"]["mean"] == pytest.approx(m["static_force_n"], rel=1e-8), name
        assert m["dynamic_factor"] == pytest.approx(
            max(m["mesh_force_n"]["max"], -m["mesh_force_n"]["min"]) / m["static_force_n"])
        assert m["mesh_force_n"]["rms"] >= m["mesh_force_n"]["mean"]
        assert m["mean_excitation"]["a"] == pytest.approx(1.0)  # design torque = operating
    assert meshes["stage1"]["mean_excitation_ratio"] == pytest.approx(0.9856622, abs=1e-6)
    assert meshes["stage2"]["mean_excitation_ratio"] == pytest.approx(1.0, abs=1e-12)
    assert "R 0.985662 [-]" in result.stdout


def test_ratio_is_linear_in_the_error_and_independent_of_the_baseload(example, tmp_path):
    out, _ = example
    base = stats_of(out)["stage1"]
    # R − 1 = m₁(K E)/F: doubling the gear error doubles it.
    doubled = run("train", STATS, "--out", tmp_path / "doubled",
                  *quick("--set", "meshes.stage1.te_amplitudes=[6e-6, 2e-6]"))
    assert doubled.returncode == 0, doubled.stderr
    r2 = stats_of(tmp_path / "doubled")["stage1"]["mean_excitation_ratio"]
    assert r2 - 1.0 == pytest.approx(2.0 * (base["mean_excitation_ratio"] - 1.0), rel=1e-9)
    # The baseload changes the normalised moments (a = F/F₀), not R (eq. 7 with m₁(ė) = 0).
    design = run("train", STATS, "--out", tmp_path / "design",
                 *quick("--set", "stats.design_torque=400.0"))
    assert design.returncode == 0, design.stderr
    d = stats_of(tmp_path / "design")["stage1"]
    assert d["baseload_n"] == pytest.approx(2.0 * base["static_force_n"], rel=1e-12)
    assert d["mean_excitation"]["a"] == pytest.approx(0.5, rel=1e-12)
    assert d["mean_excitation_ratio"] == pytest.approx(base["mean_excitation_ratio"], abs=1e-12)
    assert d["mean_excitation"]["d_e"] == pytest.approx(0.5 * base["mean_excitation"]["d_e"],
                                                        rel=1e-9)


def test_result_table(example):
    out, _ = example
    with open(out / "mesh_statistics.csv", newline="") as handle:
        rows = {r["mesh"]: r for r in csv.DictReader(handle)}
    meshes = stats_of(out)
    for name, m in meshes.items():
        row = rows[name]
        assert float(row["mean_excitation_ratio"]) == pytest.approx(m["mean_excitation_ratio"])
        assert float(row["mesh_force_rms_n"]) == pytest.approx(m["mesh_force_n"]["rms"])
        assert float(row["mesh_force_p2p_n"]) == pytest.approx(m["mesh_force_n"]["peak_to_peak"])
        assert float(row["dte_p2p_m"]) == pytest.approx(
            m["dynamic_transmission_error_m"]["peak_to_peak"])


@pytest.mark.parametrize("override, key, text", [
    ("stats.design_torque=-200.0", "stats.design_torque", "sense of the operating torque"),
    ("stats.design_torqe=300.0", "stats.design_torqe", "did you mean"),
])
def test_bad_stats_input_is_named(tmp_path, override, key, text):
    result = run("train", STATS, "--out", tmp_path, *quick("--set", override))
    assert result.returncode == 2, result.stderr
    assert key in result.stderr and text in result.stderr, result.stderr


def test_stats_after_time_reuses_its_newmark_record(example, tmp_path):
    out, _ = example
    both = run("train", STATS, "--out", tmp_path / "both",
               *quick("--set", 'analysis.run=["time", "stats"]'))
    assert both.returncode == 0, both.stderr
    run_both = json.loads((tmp_path / "both" / "summary.json").read_text())["results"]
    assert run_both["stats"]["record_from_time_analysis"] is True
    assert run_both["stats"]["steps"] == run_both["time"]["steps"]
    alone = json.loads((out / "summary.json").read_text())["results"]["stats"]
    assert alone["record_from_time_analysis"] is False
    for name, m in alone["meshes"].items():  # the same run: the same numbers, bit for bit
        assert run_both["stats"]["meshes"][name]["mesh_force_n"] == m["mesh_force_n"]
        assert run_both["stats"]["meshes"][name]["simulated_mean_excitation_ratio"] == \
            m["simulated_mean_excitation_ratio"]


def test_nonlinear_meshes_run_linear_with_a_warning(tmp_path):
    analysis = tmp_path / "tooth_pairs.toml"
    gearbox = (EXAMPLES / "gearboxes" / "two_stage_reducer_tooth_pairs.toml").as_posix()
    analysis.write_text(f'[gearbox]\nfile = "{gearbox}"\n[analysis]\nrun = ["stats"]\n')
    result = run("train", analysis, "--out", tmp_path / "out", *quick())
    assert result.returncode == 0, result.stderr
    assert "stats: the mean excitation statistics assume linear meshes" in result.stderr
    meshes = stats_of(tmp_path / "out")
    # No transmission error is given (the reliefs are tooth-pair gaps): R = 1 at both meshes.
    for m in meshes.values():
        assert m["mean_excitation_ratio"] == pytest.approx(1.0, abs=1e-12)
