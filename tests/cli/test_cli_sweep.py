"""geardyn sweep: the same results whatever the threads or MPI ranks, failing cases recorded
while the sweep goes on, resume after SIGKILL without recomputing, bad study definitions."""

import json
import os
import shutil
import signal
import subprocess
import time

import h5py
import numpy as np
import pytest

from cli_support import CLI, EXAMPLES, run

BASE = EXAMPLES / "simulate_gear_pair_backlash.toml"
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_btl="self,tcp", OMPI_MCA_btl_tcp_if_include="lo",
               OMPI_MCA_rmaps_base_oversubscribe="1")
# Under `make sanitize` the MPI ranks keep every ASan check but leak detection: OpenMPI's own
# components (dlopen'ed, unloaded at MPI_Finalize) leave allocations LeakSanitizer reports.
if "ASAN_OPTIONS" in MPI_ENV:
    MPI_ENV["ASAN_OPTIONS"] += ":detect_leaks=0"


def write_study(folder, body, name="study.toml"):
    path = folder / name
    path.write_text(f'[study]\ncommand = "simulate"\nbase = "{BASE}"\n' + body +
                    "\n[output]\nplots = false\n")
    return path


RANDOM = """design = "random"
samples = 24
seed = 2024
outputs = ["df=/dynamic_factor", "p2p=/mesh_force/peak_to_peak"]
[study.parameters]
"excitation.mesh_frequency" = { distribution = "uniform", min = 1500.0, max = 3500.0 }
"model.damping_ratio" = { distribution = "truncated_normal", mean = 0.06, std = 0.02, min = 0.03, max = 0.1 }
"model.mass" = { distribution = "normal", mean = 1.589, std = 0.02 }
"""


def h5(path):
    with h5py.File(path) as f:
        return {k: f[k][()] for k in f.keys()}, dict(f.attrs)


def assert_same(a, b):
    assert a.keys() == b.keys()
    for k in a:
        if a[k].dtype.kind == "f":
            assert np.array_equal(a[k], b[k], equal_nan=True), k
        else:
            assert np.array_equal(a[k], b[k]), k


def test_random_sweep_is_bit_identical_on_one_or_two_threads(tmp_path):
    study = write_study(tmp_path, RANDOM)
    outs = []
    for threads in (1, 2):
        out = tmp_path / f"t{threads}"
        result = run("sweep", study, "--out", out, "--threads", threads, "--quiet")
        assert result.returncode == 0, result.stderr
        outs.append(out)
    a, attrs = h5(outs[0] / "sweep.h5")
    b, _ = h5(outs[1] / "sweep.h5")
    assert_same(a, b)
    assert list(a["case"]) == list(range(24))
    assert all(s == b"ok" for s in a["status"])
    p = a["parameters"]
    assert p.shape == (24, 3) and a["outputs"].shape == (24, 2)
    assert ((1500 <= p[:, 0]) & (p[:, 0] < 3500)).all()
    assert ((0.03 <= p[:, 1]) & (p[:, 1] <= 0.1)).all()
    assert len(set(a["seed"])) == 24
    study_json = json.loads(attrs["study"])
    assert study_json["seed"] == 2024 and study_json["cases"] == 24
    assert json.loads(attrs["base_config"])["model"]["mass"] == 1.589
    summary = json.loads((outs[0] / "summary.json").read_text())
    assert summary["seed"] == 2024 and summary["geardyn_version"]
    assert summary["results"]["outputs"]["df"]["count"] == 24


@pytest.mark.skipif(shutil.which("mpirun") is None, reason="OpenMPI not installed")
def test_mpi_sweep_gives_the_same_hdf5_as_threads(tmp_path):
    study = write_study(tmp_path, RANDOM)
    assert run("sweep", study, "--out", tmp_path / "threads", "--quiet").returncode == 0
    mpi = subprocess.run(["mpirun", "-n", "2", CLI, "sweep", str(study), "--out",
                          str(tmp_path / "mpi"), "--quiet"],
                         capture_output=True, text=True, env=MPI_ENV)
    assert mpi.returncode == 0, mpi.stdout + mpi.stderr
    a, _ = h5(tmp_path / "threads" / "sweep.h5")
    b, _ = h5(tmp_path / "mpi" / "sweep.h5")
    assert_same(a, b)
    summary = json.loads((tmp_path / "mpi" / "summary.json").read_text())
    assert summary["results"]["workers"] == "2 MPI ranks"


def test_failing_cases_are_recorded_and_the_sweep_goes_on(tmp_path):
    # A mesh frequency of 0 passes the key's range (>= 0) but is bad input for its case only (no
    # period to integrate over); 5400 Hz with little damping has no periodic steady state
    # (max_periods) within the limit given. (A value outside a key's range is refused before any
    # case runs: test_cli_first_day.py.)
    study = write_study(tmp_path, """design = "zip"
set = ["solver.max_periods=300"]
outputs = ["df=/dynamic_factor"]
[study.parameters]
"excitation.mesh_frequency" = [2000.0, 0.0, 5400.0, 3000.0]
"model.damping_ratio" = [0.05, 0.05, 0.03, 0.05]
""")
    result = run("sweep", study, "--out", tmp_path / "out", "--quiet")
    assert result.returncode == 1, result.stderr
    a, _ = h5(tmp_path / "out" / "sweep.h5")
    assert [s.decode() for s in a["status"]] == ["ok", "bad_input", "max_periods", "ok"]
    assert "excitation.mesh_frequency = 0 Hz" in a["message"][1].decode()
    assert np.isnan(a["outputs"][1, 0]) and np.isfinite(a["outputs"][3, 0])
    assert "2 of 4 cases did not succeed" in result.stderr


SLOW = """design = "grid"
set = ["solver.min_periods=2000", "solver.max_periods=100000"]
outputs = ["df=/dynamic_factor"]
[study.parameters]
"excitation.mesh_frequency" = { min = 1500.0, max = 3500.0, num = 16 }
"model.damping_ratio" = [0.05, 0.08]
"""


def journal_cases(folder):
    lines = (folder / "sweep_journal.jsonl").read_text().splitlines()[1:]
    return [json.loads(line)["case"] for line in lines if line.endswith("}")]


def test_a_killed_sweep_resumes_without_recomputing_finished_cases(tmp_path):
    study = write_study(tmp_path, SLOW)
    out = tmp_path / "killed"
    process = subprocess.Popen([CLI, "sweep", str(study), "--out", str(out), "--threads", "2",
                                "--quiet"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.time() + 120
    while time.time() < deadline:
        time.sleep(0.05)
        if (out / "sweep_journal.jsonl").exists() and len(journal_cases(out)) >= 6:
            break
    process.send_signal(signal.SIGKILL)
    process.wait()
    before = journal_cases(out)
    assert 6 <= len(before) < 32, "the sweep finished before it could be killed"
    assert not (out / "sweep.h5").exists()
    mtime = (out / "sweep_journal.jsonl").stat().st_mtime

    result = run("sweep", study, "--out", out, "--resume", "--quiet")
    assert result.returncode == 0, result.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["results"]["resumed"] == len(set(before))
    assert summary["results"]["computed"] == 32 - len(set(before))
    after = journal_cases(out)
    assert after[:len(before)] == before          # nothing written before the kill was lost
    assert sorted(after) == list(range(32))       # and nothing finished was computed again
    assert (out / "sweep_journal.jsonl").stat().st_mtime >= mtime

    clean = tmp_path / "clean"
    assert run("sweep", study, "--out", clean, "--quiet").returncode == 0
    assert_same(h5(out / "sweep.h5")[0], h5(clean / "sweep.h5")[0])


def test_resume_refuses_another_study(tmp_path):
    study = write_study(tmp_path, RANDOM)
    assert run("sweep", study, "--out", tmp_path / "o", "--quiet").returncode == 0
    changed = write_study(tmp_path, RANDOM.replace("seed = 2024", "seed = 7"), "changed.toml")
    result = run("sweep", changed, "--out", tmp_path / "o", "--resume")
    assert result.returncode == 2 and "--resume" in result.stderr


@pytest.mark.parametrize("body, fragment", [
    ('desing = "grid"\noutputs = ["/dynamic_factor"]\n[study.parameters]\n"model.mass" = [1.0]\n',
     "did you mean 'design'"),
    ('outputs = ["/dynamic_factor"]\n[study.parameters]\n"model.damping_ration" = [0.1]\n',
     "damping_ratio"),
    ('outputs = ["dynamic_factor"]\n[study.parameters]\n"model.mass" = [1.0]\n', "study.outputs"),
    ('design = "zip"\noutputs = ["/dynamic_factor"]\n[study.parameters]\n"model.mass" = [1.0, 2.0]\n'
     '"model.damping_ratio" = [0.1]\n', "study.parameters.model.damping_ratio"),
    ('outputs = ["/dynamic_factor"]\n[study.parameters]\n'
     '"model.mass" = { distribution = "normal", mean = 1.0, std = 0.1 }\n', "random"),
])
def test_bad_study_definitions_are_rejected(tmp_path, body, fragment):
    study = write_study(tmp_path, body)
    result = run("sweep", study, "--out", tmp_path / "o")
    assert result.returncode == 2, result.stdout + result.stderr
    assert fragment in result.stderr, result.stderr
