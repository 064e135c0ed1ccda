"""The plot functions return matplotlib Figures (drawn on the caller's axes when given, saved
only when asked), and what a first-day user saw in the PNGs of `make demo` stays fixed: solid
legend handles, µm, no repeated titles, units on every axis, log axes clipped below the peak,
legends clear of the data, mode shapes along the shafts, orbits with keyphasor and precession,
an rpm axis on forced responses."""

import math
import os
import pathlib
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

import geardyn.plot as gplot  # noqa: E402

CLI = os.environ.get("GEARDYN_CLI", "build/bin/geardyn")
SOURCE = pathlib.Path(os.environ.get("GEARDYN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXAMPLES = ["hbm_backlash_kahraman_singh", "hbm_ltca_visnadi2021_long_relief", "rotor_rao2023_study",
            "spectrum_rao2023_table41_probes", "rotor_visnadi2021_modal", "rotor_visnadi2021_campbell",
            "rotor_visnadi2021_runup", "sweep_gear_pair_speed_damping", "simulate_gear_pair_backlash",
            "train_two_stage_reducer_runup", "train_two_stage_reducer_stats"]
PLOTTER = {"hbm": "hbm", "rotor": None, "spectrum": "spectrum", "sweep": "sweep", "simulate": "simulate"}


@pytest.fixture(scope="module")
def folders(tmp_path_factory):
    root = tmp_path_factory.mktemp("plots")
    out = {}
    for stem in EXAMPLES:
        command = stem.split("_", 1)[0]
        folder = root / stem
        done = subprocess.run([CLI, command, str(SOURCE / "examples" / f"{stem}.toml"), "--out", str(folder),
                               "--quiet", "--set", "output.plots=false"], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        out[stem] = folder
    return out


def _plotter(stem):
    command = stem.split("_", 1)[0]
    if command == "rotor":
        return gplot.plot_rotor_fe if "visnadi" in stem else gplot.plot_rotor
    return gplot.PLOTTERS[command]


@pytest.fixture(scope="module")
def figures(folders):
    """{(stem, png name): Figure} of every example, drawn (so that extents are known)."""
    out = {}
    for stem, folder in folders.items():
        for name, figure in _plotter(stem)(folder).items():
            figure.canvas.draw()
            out[(stem, name)] = figure
    yield out
    plt.close("all")


def _texts(figure):
    texts = [figure._suptitle.get_text()] if figure._suptitle else []
    for ax in figure.axes:
        texts += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()]
    return [t for t in texts if t]


def test_plot_functions_return_figures_and_write_nothing_unless_asked(folders):
    folder = folders["hbm_backlash_kahraman_singh"]
    figures = gplot.plot_hbm(folder)
    assert set(figures) == {"forced_response.png"}  # no detail frequencies in this example
    assert all(isinstance(f, matplotlib.figure.Figure) for f in figures.values())
    assert not list(folder.glob("*.png"))
    saved = gplot.plot_hbm(folder, save=True)
    assert sorted(p.name for p in folder.glob("*.png")) == sorted(saved)
    assert not [p for p in folder.iterdir() if ".tmp" in p.name]


def test_the_command_line_pngs_come_from_the_same_functions(folders, capsys):
    folder = folders["rotor_rao2023_study"]
    assert gplot.main(["rotor", str(folder)]) == 0
    assert capsys.readouterr().out.split() == list(gplot.plot_rotor(folder))


def test_figures_draw_on_the_callers_axes(folders):
    figure, (left, right) = plt.subplots(1, 2)
    assert gplot.forced_response_figure(folders["hbm_backlash_kahraman_singh"], ax=left) is figure
    assert left.lines and not right.lines
    assert gplot.campbell_figure(folders["rotor_visnadi2021_campbell"], ax=right) is figure
    assert right.get_xlabel() == "pinion speed [rpm]"
    figure, axes = plt.subplots(1, 2)
    assert gplot.orbits_figure(folders["spectrum_rao2023_table41_probes"], axes=axes, only_steady=False) is figure


def test_forced_response_legend_handles_are_solid_and_styles_explained(figures):
    # The first run of the down sweep is unstable: its legend entry must still be solid.
    ax = figures[("hbm_backlash_kahraman_singh", "forced_response.png")].axes[0]
    legend = ax.get_legend()
    handles = {h.get_label(): h for h in getattr(legend, "legend_handles", None) or legend.legendHandles}
    for sweep in ("up", "down"):
        assert handles[f"HBM, sweep {sweep}"].get_linestyle() == "-"
    assert handles["stable (monodromy)"].get_linestyle() == "-"  # the example's (the default)
    assert handles["unstable (monodromy)"].get_linestyle() == "--"
    assert any(line.get_linestyle() == "--" for line in ax.lines)  # unstable runs are drawn dashed


def _legend_labels(axes):
    return {t.get_text() for ax in axes for legend in [ax.get_legend()] if legend for t in legend.get_texts()}


def test_stability_legends_name_the_method_the_run_used(tmp_path):
    # Both nonlinear response plots once named a fixed method; with Hill's method they say so.
    runs = {"hbm": ("hbm_backlash_kahraman_singh", ["sweep.stability_method=\"hill\""]),
            "train": ("train_planetary_nonlinear",
                      ["nonlinear.stability_method=\"hill\"", "nonlinear.speed_min_rpm=15000.0",
                       "nonlinear.speed_max_rpm=15700.0", "nonlinear.direction=\"up\"",
                       "nonlinear.newmark_speeds_rpm=[]"])}
    for command, (stem, settings) in runs.items():
        folder = tmp_path / command
        arguments = [CLI, command, str(SOURCE / "examples" / f"{stem}.toml"), "--out", str(folder),
                     "--quiet", "--set", "output.plots=false"]
        for setting in settings:
            arguments += ["--set", setting]
        done = subprocess.run(arguments, capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        figure = (gplot.forced_response_figure(folder) if command == "hbm"
                  else gplot.train_nonlinear_figure(folder))
        labels = _legend_labels(figure.axes) | {t.get_text() for legend in figure.legends for t in legend.get_texts()}
        assert {"stable (Hill's method)", "unstable (Hill's method)"} <= labels, (command, labels)
        plt.close(figure)


def test_forced_response_has_an_rpm_axis_when_the_teeth_are_known(figures):
    figure = figures[("hbm_ltca_visnadi2021_long_relief", "forced_response.png")]
    secondary = [a for a in figure.axes[0].child_axes if "rpm" in a.get_xlabel()]
    assert secondary, "no pinion-speed axis"
    # 25 teeth: 1000 Hz mesh frequency is 2400 rpm.
    forward = secondary[0]._functions[0]  # matplotlib 3.6 keeps (forward, inverse) there
    assert forward(1000.0) == pytest.approx(2400.0)


def test_micro_sign_units_and_no_issue_numbers(figures):
    for key, figure in figures.items():
        for text in _texts(figure):
            assert "[um]" not in text and "issue #" not in text, (key, text)


def test_no_title_line_repeats(figures):
    for key, figure in figures.items():
        lines = [line.strip() for t in _texts(figure) for line in t.split("\n")]
        titles = [l for l in lines if l]
        words = [l.lower() for l in titles]
        for phrase in ("campbell diagram", "modes at"):
            assert sum(phrase in w for w in words) <= 1, (key, titles)


CATEGORICAL = {"whirl component"}  # axes of names, not quantities


def test_every_data_axis_has_a_unit(figures):
    for key, figure in figures.items():
        for ax in figure.axes:
            if not ax.has_data() or ax.get_label() == "<colorbar>":
                continue
            for label in (ax.get_xlabel(), ax.get_ylabel()):
                if label and "\n" not in label and label not in CATEGORICAL:
                    assert "[" in label and "]" in label, (key, label)


def test_sweep_axes_carry_units(figures):
    figure = figures[("sweep_gear_pair_speed_damping", "sweep.png")]
    assert figure.axes[-1].get_xlabel() == "excitation.mesh_frequency [Hz]"
    assert [ax.get_ylabel() for ax in figure.axes] == ["dynamic_factor [-]", "force_p2p [N]", "contact_loss [-]"]


def test_log_axes_span_at_most_seven_decades(figures):
    checked = 0
    for key, figure in figures.items():
        for ax in figure.axes:
            if ax.get_yscale() == "log":
                low, high = ax.get_ylim()
                assert math.log10(high / low) < 7.0, (key, low, high)
                checked += 1
    assert checked >= 5  # study (2), full spectrum (2), run-up


def _points_under(legend, ax):
    """How many drawn data points lie under the legend box (display coordinates)."""
    box = legend.get_window_extent()
    count = 0
    for line in ax.lines:
        for x, y in line.get_transform().transform(line.get_xydata()):
            count += box.contains(x, y)
    for collection in ax.collections:
        for x, y in collection.get_offset_transform().transform(collection.get_offsets()):
            count += box.contains(x, y)
    for patch in ax.patches:
        count += box.overlaps(patch.get_window_extent()) and patch.get_height() > 0 if hasattr(patch, "get_height") else 0
    return count


def test_legends_are_clear_of_the_data(figures):
    for stem, name in [("rotor_visnadi2021_runup", "runup.png"), ("rotor_visnadi2021_campbell", "campbell.png"),
                       ("rotor_rao2023_study", "study.png"), ("hbm_backlash_kahraman_singh", "forced_response.png"),
                       ("spectrum_rao2023_table41_probes", "full_spectrum.png"),
                       ("train_two_stage_reducer_stats", "mesh_statistics.png")]:
        figure = figures[(stem, name)]
        for ax in figure.axes:
            legend = ax.get_legend()
            if legend is not None:
                assert _points_under(legend, ax) == 0, (stem, name)


def test_fe_mode_shapes_are_drawn_along_the_shafts(figures):
    figure = figures[("rotor_visnadi2021_modal", "modes.png")]
    drawn = [ax for ax in figure.axes if ax.lines]
    assert len(drawn) == 8 and not any(ax.patches for ax in drawn)  # no bar chart
    for ax in drawn:
        xs = [x for line in ax.lines for x in line.get_xdata()]
        assert min(xs) == 0.0 and max(xs) == pytest.approx(200.0)  # two 100 mm elements [mm]
        assert "Hz" in ax.get_title() and ax.get_xlabel() == "axial position x [mm]"


def test_orbits_have_keyphasor_marks_and_precession(figures):
    figure = figures[("spectrum_rao2023_table41_probes", "orbits.png")]
    # 0.91 s of record from the first keyphasor pulse: 10 revolutions of the pinion (11 Hz), 4 of
    # the gear (5.03 Hz).
    for ax, revolutions in zip(figure.axes, (10, 4)):
        marks = [l for l in ax.lines if l.get_label().startswith("keyphasor")]
        assert marks and abs(len(marks[0].get_xdata()) - revolutions) <= 1
        assert "precession" in ax.get_title()
        assert any(getattr(child, "arrow_patch", None) is not None for child in ax.texts)


def test_a_long_train_record_is_an_envelope_beside_a_zoom(tmp_path):
    """Issue #33 item 5: 142 mesh periods drawn as lines were a solid band. A long record is
    drawn as the extremes per cycle of the fastest mesh (a few points per cycle, not the
    waveform) beside its last four cycles; a short one as lines."""
    shapes = {}
    for periods in (1, 14):
        folder = tmp_path / f"p{periods}"
        done = subprocess.run([CLI, "train", str(SOURCE / "examples" / "train_two_stage_reducer.toml"),
                               "--out", str(folder), "--quiet", "--set", 'analysis.run=["time"]',
                               "--set", f"time.record_periods={periods}", "--set", "output.plots=false"],
                              capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        figure = gplot.PLOTTERS["train"](folder)["time_history.png"]
        figure.canvas.draw()
        shapes[periods] = figure
    assert len(shapes[1].axes) == 2  # two meshes, whole record as lines
    long = shapes[14]
    assert len(long.axes) == 4
    whole, zoom = long.axes[0], long.axes[1]
    band = [c for c in whole.collections if len(c.get_paths())]
    assert band, "the envelope is a filled band"
    # 14 common periods of 3 stage-1 mesh periods: ~42 cycles; the dashed envelope has a point
    # per cycle, not the ~10^5 samples of the record.
    dashed = [line for line in whole.get_lines() if line.get_linestyle() == "--"]
    assert dashed and all(len(line.get_xdata()) < 100 for line in dashed)
    assert zoom.get_xlim()[1] - zoom.get_xlim()[0] < 0.2 * (whole.get_xlim()[1] - whole.get_xlim()[0])
    legend = zoom.get_legend()
    assert legend is not None and _points_under(legend, zoom) == 0
    plt.close("all")
