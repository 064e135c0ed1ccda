"""geardyn.run in-process (issue 19): every analysis from a file, a dict or keyword objects,
results as numpy views and DataFrames with units, the same files as the CLI, errors in Python
terms, no temporary folders, progress, GIL release and Ctrl-C."""

import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import textwrap
import threading
import time

import numpy as np
import pytest

import geardyn

SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXAMPLES = SOURCE / "examples"
PAIR = {"pinion": {"teeth": 25, "module": 3e-3, "face_width": 0.02},
        "gear": {"teeth": 30, "module": 3e-3, "face_width": 0.02}}

# One quick run of every in-process analysis (overrides keep the slow ones short).
CASES = {
    "geometry": ("geometry_rao2023_rig.toml", []),
    "stiffness": ("stiffness_visnadi2021_spur.toml", []),
    "simulate": ("simulate_gear_pair_backlash.toml", []),
    "hbm": ("hbm_backlash_kahraman_singh.toml", []),
    "rotor": ("rotor_rao2023_table41.toml", []),
    "rotor_fe": ("rotor_visnadi2021_modal.toml", []),
    "stats": ("stats_monte_carlo_pitch_errors.toml", []),
    "spectrum": ("spectrum_rao2023_table41_probes.toml", []),
    "identify": ("identify_rao2023_table41.toml", []),
    "ltca": ("ltca_visnadi2021_long_relief.toml", []),
    "ltca_gearbox_mesh": ("ltca_two_stage_reducer_stage1.toml", []),
    "train_stats": ("train_two_stage_reducer_stats.toml", []),
}
COMMANDS = {"rotor_fe": "rotor", "ltca_gearbox_mesh": "ltca", "train_stats": "train"}


@pytest.fixture(scope="module")
def results():
    out = {}
    for name, (file, overrides) in CASES.items():
        command = COMMANDS.get(name, name)
        out[name] = geardyn.run(command, EXAMPLES / file, overrides=overrides, progress=False)
    return out


@pytest.mark.parametrize("name", list(CASES))
def test_every_table_of_every_analysis_is_a_dataframe_with_units(results, name):
    result = results[name]
    assert result.ok and result.tables, result
    for table in result.tables:
        frame = result.to_pandas(table)
        units = frame.attrs["units"]
        assert list(units) == list(frame.columns)
        for column, unit in units.items():
            if frame[column].dtype.kind in "fiu":
                assert unit is not None and unit != "?", f"{name}/{table}: {column} has no unit"
            else:
                assert unit is None
    assert repr(result).startswith(f"<geardyn {result.command} result: status {result.status}")
    assert "<table>" in result._repr_html_()


def test_columns_are_read_only_views_of_the_result_memory():
    result = geardyn.run("geometry", PAIR)
    radius = result.table("gears")["base_radius_m"]
    assert isinstance(radius, np.ndarray) and not radius.flags["OWNDATA"]
    assert not radius.flags["WRITEABLE"] and radius.base is not None
    assert result.table("gears")["base_radius_m"].ctypes.data == radius.ctypes.data  # no copy
    history = geardyn.run("simulate", EXAMPLES / "simulate_gear_pair_backlash.toml")
    frame = history.to_pandas("time_response")  # all-real table: pandas keeps the views
    assert np.shares_memory(frame["t_s"].to_numpy(), history.table("time_response")["t_s"])
    del result  # the view keeps the result alive
    expected = 0.5 * 3e-3 * np.array([25, 30]) * np.cos(np.radians(20.0))
    np.testing.assert_allclose(radius, expected, rtol=1e-12)


def test_keyword_objects_dicts_and_files_give_the_same_result():
    from_objects = geardyn.run("geometry", pinion=geardyn.Gear(teeth=25, module=3e-3, face_width=0.02),
                               gear=geardyn.Gear(teeth=30, module=3e-3, face_width=0.02))
    from_dict = geardyn.run("geometry", PAIR)
    assert from_objects.results == from_dict.results
    assert from_dict.results["contact_ratio_transverse"] == pytest.approx(1.6325826, abs=1e-7)



def test_errors_in_python_terms(tmp_path):
    with pytest.raises(geardyn.ConfigError) as error:
        geardyn.run("geometry", PAIR, overrides={"pinion.teeth": 2})
    assert isinstance(error.value, ValueError)
    assert error.value.key == "pinion.teeth" and error.value.value == "2"
    assert ">= 3" in error.value.allowed or "3" in error.value.allowed
    with pytest.raises(geardyn.ConfigError, match="did you mean 'simulate'"):
        geardyn.run("simulat", {})
    with pytest.raises(geardyn.ConfigError, match="did you mean"):
        geardyn.run("geometry", {"pinion": {"teeth": 25, "modul": 3e-3, "face_width": 0.02},
                                 "gear": PAIR["gear"]})
    with pytest.raises(FileNotFoundError):
        geardyn.run("geometry", tmp_path / "missing.toml")
    with pytest.raises(FileNotFoundError) as missing:  # the C++ loaders too
        geardyn.load_config("geometry", str(tmp_path / "missing.toml"))
    assert missing.value.filename == str(tmp_path / "missing.toml")
    with pytest.raises(IsADirectoryError):
        geardyn.GearPair.from_config(str(tmp_path))
    with pytest.raises(TypeError, match=r"Gear\(\): face_width is required"):
        geardyn.Gear(teeth=21, module=3e-3)
    with pytest.raises(TypeError, match="did you mean 'module'"):
        geardyn.Gear(teeth=21, modul=3e-3, face_width=0.02)


def test_numerical_failure_raises_with_the_result_attached():
    with pytest.raises(RuntimeError) as error:
        geardyn.run("simulate", EXAMPLES / "simulate_gear_pair_backlash.toml",
                    overrides={"solver.max_periods": 3, "solver.steady_tolerance": 1e-14})
    assert error.value.result.status != "ok" and not error.value.result.ok
    result = geardyn.run("simulate", EXAMPLES / "simulate_gear_pair_backlash.toml",
                         overrides={"solver.max_periods": 3, "solver.steady_tolerance": 1e-14},
                         check=False)
    assert result.status == error.value.result.status


class _PrivateTmp:
    """A temporary folder of the test's own (TMPDIR, which Python, the C++ library and the
    sweep's executable all honour), since other tests of the suite (the notebooks' Jupyter
    kernels) create tmp* entries in /tmp meanwhile; geardyn's own prefix is watched in /tmp
    too. ``check()``: nothing was left in either."""

    def __init__(self, monkeypatch, tmp_path):
        self.private = tmp_path / "tmp"
        self.private.mkdir()
        monkeypatch.setenv("TMPDIR", str(self.private))
        monkeypatch.setattr(tempfile, "tempdir", None)  # gettempdir() reads TMPDIR again
        assert tempfile.gettempdir() == str(self.private)
        self.before = self._geardyn_in_system_tmp()

    @staticmethod
    def _geardyn_in_system_tmp():
        return {e.name for e in pathlib.Path("/tmp").iterdir() if e.name.startswith("geardyn")}

    def check(self):
        assert not list(self.private.iterdir())
        assert not self._geardyn_in_system_tmp() - self.before


def test_in_process_runs_leave_nothing_in_tmp(monkeypatch, tmp_path):
    tmp = _PrivateTmp(monkeypatch, tmp_path)
    geardyn.run("geometry", PAIR)
    geardyn.run("simulate", EXAMPLES / "simulate_gear_pair_backlash.toml")
    geardyn.sweep({"study": {"command": "simulate",
                             "base": str(EXAMPLES / "simulate_gear_pair_backlash.toml"),
                             "outputs": ["df=/dynamic_factor"],
                             "parameters": {"model.damping_ratio": [0.05, 0.1]}}})
    tmp.check()


LONG = {"solver.max_periods": 200000, "solver.steady_tolerance": 1e-16}


def test_progress_is_reported_and_the_gil_is_released():
    calls = []
    ticks = [0]
    done = threading.Event()

    def work():  # about 1 s of Newmark (20000 periods measured at 1.9 s on the 2-core machine)
        geardyn._geardyn.analyze("simulate", path=str(EXAMPLES / "simulate_gear_pair_backlash.toml"),
                                 overrides=["solver.max_periods=10000",
                                            "solver.steady_tolerance=1e-16"],
                                 progress=lambda *a: calls.append(a))
        done.set()

    thread = threading.Thread(target=work)
    thread.start()
    while not done.is_set():
        ticks[0] += 1  # runs only while the analysis has released the GIL
        time.sleep(0.001)
    thread.join()
    assert ticks[0] > 50, "the main thread did not run during the analysis"
    # At most one call per 0.1 s, and the last one when the run ends.
    assert 2 <= len(calls) <= 200
    assert calls[-1][0] == "simulate" and calls[-1][1] == "periods of max_periods"
    assert all(c[2] <= c[3] for c in calls)


def test_ctrl_c_interrupts_a_long_run():
    script = textwrap.dedent(f"""
        import os, signal, threading, time, geardyn
        threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        start = time.monotonic()
        try:
            geardyn.run("simulate", {str(EXAMPLES / 'simulate_gear_pair_backlash.toml')!r},
                        overrides={LONG!r}, progress=False)
        except KeyboardInterrupt:
            print("interrupted after", round(time.monotonic() - start, 2))
    """)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          env=os.environ)
    assert "interrupted after" in done.stdout, done.stderr
    assert float(done.stdout.split()[-1]) < 10.0


def test_saved_tables_are_byte_for_byte_the_cli_files(tmp_path):
    cli = geardyn._cli.cli_path()
    for command, file, sets in [
            ("stiffness", "stiffness_visnadi2021_spur.toml", []),
            ("hbm", "hbm_backlash_kahraman_singh.toml", []),
            ("train", "train_two_stage_reducer.toml", ["analysis.run=[\"static\", \"modal\"]"])]:
        overrides = ["output.plots=false"] + sets
        subprocess.run([cli, command, str(EXAMPLES / file), "--out", str(tmp_path / "cli"),
                        "--quiet"] + [a for s in overrides for a in ("--set", s)], check=True)
        result = geardyn.run(command, EXAMPLES / file, overrides=overrides)
        result.save(tmp_path / "py")
        assert result.tables
        for table in result.tables:
            assert (tmp_path / "py" / f"{table}.csv").read_bytes() == \
                (tmp_path / "cli" / f"{table}.csv").read_bytes(), table
        shutil.rmtree(tmp_path / "py"), shutil.rmtree(tmp_path / "cli")


def test_train_and_sweep_results_are_dataframes_with_units_too():
    train = geardyn.run("train", EXAMPLES / "train_two_stage_reducer.toml",
                        overrides={"analysis.run": ["static", "modal", "campbell", "forced"]})
    assert isinstance(train, geardyn.Result)  # in-process from a file
    for table in train.tables:
        units = train.to_pandas(table).attrs["units"]
        assert "?" not in units.values(), f"train/{table}: {units}"
    assert train.to_pandas("meshes").attrs["units"]["mean_stiffness_normal_n_per_m"] == "N/m"
    # Issue #33 item 7: a train result's headline was {}.
    headline = train.headline
    assert headline["input speed [rpm]"] > 0 and headline["output torque [N m]"] != 0
    assert headline["lowest natural frequency [Hz]"] > 0, headline
    sweep = geardyn.sweep({"study": {"command": "simulate",
                                     "base": str(EXAMPLES / "simulate_gear_pair_backlash.toml"),
                                     "outputs": ["df=/dynamic_factor",
                                                 "f=/mesh_force/peak_to_peak"],
                                     "parameters": {"excitation.mesh_frequency": [900.0, 1000.0]}}})
    units = sweep.to_pandas("sweep").attrs["units"]
    assert units == {"case": "", "status": None, "seed": "", "excitation.mesh_frequency": "Hz",
                     "df": "", "f": "N", "message": None}
    # ... and the seed stays an integer (it was read as a float).
    assert sweep.to_pandas("sweep")["seed"].dtype.kind in "iu"


def test_train_on_a_dict_runs_in_process_like_its_file(monkeypatch, tmp_path):
    import tomllib

    run = {"analysis.run": ["static", "modal"]}
    from_file = geardyn.run("train", EXAMPLES / "train_two_stage_reducer.toml", overrides=run)
    gearbox = tomllib.loads((EXAMPLES / "gearboxes" / "two_stage_reducer.toml").read_text())
    with monkeypatch.context() as patch:
        tmp = _PrivateTmp(patch, tmp_path)
        inline = geardyn.run("train", {**gearbox, "analysis": {"run": ["static", "modal"]}})
        assert isinstance(inline, geardyn.Result)  # in-process: no executable, no folder
        tmp.check()
    monkeypatch.chdir(EXAMPLES)  # a dict's relative gearbox.file: from the working directory
    named = geardyn.run("train", {"gearbox": {"file": "gearboxes/two_stage_reducer.toml"}},
                        analysis={"run": ["static", "modal"]})
    for result in (inline, named):
        for table in ("modes", "meshes"):
            a, b = result.to_pandas(table), from_file.to_pandas(table)
            assert list(a.columns) == list(b.columns)
            numeric = a.select_dtypes("number").columns
            assert np.array_equal(a[numeric].to_numpy(), b[numeric].to_numpy()), table
    with pytest.raises(geardyn.ConfigError) as error:
        geardyn.run("train", {"gearbox": {"file": "gearboxes/two_stage_reducer.toml"}},
                    overrides={"gears.z1.teth": 20})
    assert "did you mean" in str(error.value) and "teeth" in str(error.value)


def test_report_writes_the_result_folder_for_geardyn_report(monkeypatch, tmp_path):
    import types

    seen = {}

    def write_report(results_dir, out=None):
        folder = pathlib.Path(results_dir)
        seen["files"] = sorted(p.name for p in folder.iterdir())
        seen["folder"] = folder
        pathlib.Path(out).write_text("<html></html>")
        return out

    monkeypatch.setitem(sys.modules, "geardyn.report", types.SimpleNamespace(write_report=write_report))
    result = geardyn.run("geometry", PAIR)
    out = tmp_path / "report.html"
    assert result.report(out) == out and out.exists()
    assert seen["files"] == ["gears.csv", "summary.json", "tooth_profiles.csv"]
    assert not seen["folder"].exists()  # the temporary result folder is removed
    result.report(tmp_path / "r2.html", folder=tmp_path / "kept")
    assert (tmp_path / "kept" / "summary.json").exists()


def test_a_run_that_would_not_fit_is_refused_before_it_allocates(monkeypatch):
    monkeypatch.setenv("GEARDYN_MEMORY_LIMIT", "1e6")  # 1 MB
    with pytest.raises(geardyn.ConfigError, match="too large for this machine") as error:
        geardyn.run("simulate", EXAMPLES / "simulate_gear_pair_backlash.toml",
                    overrides={"solver.max_periods": 1000000, "solver.output_periods": 100000})
    assert error.value.key.startswith("solver.")


def test_warnings_are_raised_once_each_and_one_per_kind(tmp_path):
    """Issue #33 item 4: Python raised every warning twice (the loading callback and the result),
    and once per mesh where the command line prints one line per kind. A renamed key (a note
    raised while loading, also in the result) and the two meshes' foundation-fit notes of the
    two-stage reducer."""
    example = EXAMPLES / "train_two_stage_reducer.toml"
    text = example.read_text().replace('run = ["static", "modal", "campbell", "forced", "time"]',
                                       'run = ["static"]')
    config = tmp_path / "reducer.toml"
    config.write_text(text.replace('file = "gearboxes/', f'file = "{EXAMPLES}/gearboxes/'))
    with warnings_recorded() as caught:
        result = geardyn.run("train", config, progress=False)
    texts = [str(w.message) for w in caught]
    assert len(texts) == len(set(texts)), texts
    fits = [t for t in texts if "fillet-foundation fit" in t]
    in_result = [w for w in result.warnings if "fillet-foundation fit" in w]
    assert len(in_result) >= 2, result.warnings  # both meshes' notes stay in the result
    assert len(fits) == 1 and f"extrapolated for {len(in_result)} meshes" in fits[0], texts


def warnings_recorded():
    import warnings
    recorder = warnings.catch_warnings(record=True)

    class _Context:
        def __enter__(self):
            self.caught = recorder.__enter__()
            warnings.simplefilter("always")
            return self.caught

        def __exit__(self, *exc):
            return recorder.__exit__(*exc)
    return _Context()


@pytest.mark.parametrize("name", ["hbm", "rotor", "train_stats"])
def test_a_saved_result_loads_back_with_the_same_tables_units_and_headline(results, name,
                                                                          tmp_path):
    """geardyn.load (issue 34: the notebooks read `make demo`'s folders): every table, column
    unit and headline number of the in-process result comes back from its saved folder. The
    CSV files hold 17 significant digits, so numbers agree to the last bit of a double's
    decimal round trip (rtol 1e-15)."""
    result = results[name]
    folder = result.save(tmp_path / name)
    loaded = geardyn.load(folder)
    assert loaded.ok and loaded.command == result.command and loaded.tables == result.tables
    assert loaded.headline == pytest.approx(result.headline, rel=1e-15)
    assert loaded.summary["geardyn_version"] == geardyn.__version__
    assert loaded.summary["wall_time_s"] == pytest.approx(result.wall_time_s, rel=1e-12)
    assert repr(loaded).startswith(f"<geardyn {result.command} result: status {result.status}")
    assert all(label in repr(loaded) for label in result.headline)
    for table in result.tables:
        frame, back = result.to_pandas(table), loaded.to_pandas(table)
        assert list(back.columns) == list(frame.columns), table
        assert back.attrs["units"] == frame.attrs["units"], table
        for column in frame.columns:
            if frame[column].dtype.kind in "fiu":
                np.testing.assert_allclose(back[column], frame[column], rtol=1e-15, atol=0,
                                           err_msg=f"{table}.{column}")
            else:
                assert list(back[column]) == list(frame[column]), f"{table}.{column}"


def test_load_names_the_folder_that_is_not_a_result(tmp_path):
    with pytest.raises(FileNotFoundError, match="no summary.json"):
        geardyn.load(tmp_path)
    (tmp_path / "summary.json").write_text("{not json")
    with pytest.raises(ValueError, match="not JSON"):
        geardyn.load(tmp_path)
    (tmp_path / "summary.json").write_text('{"results": {}}')
    with pytest.raises(ValueError, match="not a geardyn summary"):
        geardyn.load(tmp_path)


def test_a_loaded_train_folder_draws_the_same_3d_view_and_card(tmp_path):
    """geardyn.load of a train's folder: its 3-D view is the in-process result's page, byte for
    byte, and Jupyter's card shows it with the headline numbers."""
    result = geardyn.run("train", EXAMPLES / "train_two_stage_reducer.toml",
                         overrides={"analysis.run": ["static", "modal"]}, progress=False)
    loaded = geardyn.load(result.save(tmp_path / "train"))
    page = result.view3d()
    assert page is not None and loaded.view3d() == page
    card = loaded._repr_html_()
    assert "<iframe" in card and all(label in card for label in result.headline)
    assert geardyn.load(result.save(tmp_path / "other")).view3d() == page
    stiffness = geardyn.load(geardyn.run("stiffness", EXAMPLES / "stiffness_visnadi2021_spur.toml",
                                         progress=False).save(tmp_path / "k"))
    assert stiffness.view3d() is None and "<iframe" not in stiffness._repr_html_()
