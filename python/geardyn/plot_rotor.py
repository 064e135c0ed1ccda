"""Figures of the lumped lateral geared rotor (`geardyn rotor`, Rao 2023) and of analysed probe
records (`geardyn spectrum`): orbits with keyphasor marks and the precession direction, full
spectra, and the parametric study."""

import pathlib

from ._plot_common import _axes, _read_columns, _read_summary, finish, plt
from ._tables import keyphasor_points as _keyphasor_points, log_floor

_SHAFTS = (("pinion", "x1", "y1", "pinion_hz"), ("gear", "x2", "y2", "gear_hz"))


def _rotation_sense(summary, shaft):
    """+1 if the shaft turns counter-clockwise (+z) in the probes' x-y plane, -1 clockwise,
    None if the result does not say."""
    text = summary["results"].get("conventions", {}).get("rotation", {}).get(shaft, "")
    return -1 if text.startswith("-z") else (1 if text.startswith("+z") else None)


def orbits_figure(result_dir, axes=None, only_steady=True):
    """y against x of each shaft [µm] (as Rao 2023, Fig. 4.1) with a keyphasor mark (filled dot)
    at every revolution of that shaft and an arrow giving the direction of precession, named
    forward or backward against the shaft's rotation. `axes`: two axes, or None."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    table = _read_columns(folder / "time_history.csv", short=True)
    if axes is None:
        figure, axes = plt.subplots(1, 2, figsize=(10.5, 5), layout="constrained")
    else:
        figure = axes[0].figure
    steady = table.get("steady")
    keep = list(range(len(table["t"])))
    if only_steady and steady is not None:
        keep = [i for i in keep if steady[i] == 1.0]
    frequencies = summary["results"].get("frequencies", {})
    t0 = summary["results"].get("keyphasor", {}).get("first_pulse_s", 0.0)
    for ax, (shaft, xs_name, ys_name, f_name) in zip(axes, _SHAFTS):
        t = [table["t"][i] for i in keep]
        xs = [1e6 * table[xs_name][i] for i in keep]
        ys = [1e6 * table[ys_name][i] for i in keep]
        ax.plot(xs, ys, lw=0.5, color="tab:blue", label="orbit")
        frequency = frequencies.get(f_name)
        sense = None
        if frequency and len(t) > 2:
            marks = _keyphasor_points(t, xs, ys, frequency, t0)
            if marks:
                ax.plot(*zip(*marks), "o", color="black", ms=3.5, ls="none", label="keyphasor (once per rev)")
            # Precession: the sign of the area swept over the last revolution.
            last = [i for i in range(len(t)) if t[i] >= t[-1] - 1.0 / frequency]
            area = sum(xs[i] * ys[j] - xs[j] * ys[i] for i, j in zip(last[:-1], last[1:]))
            sense = 1 if area > 0 else -1
            # The sense as a curved arrow in the corner (a chord of a dense orbit would mislead).
            start, end = ((0.93, 0.80), (0.80, 0.93)) if sense > 0 else ((0.80, 0.93), (0.93, 0.80))
            ax.annotate("", xy=end, xytext=start, xycoords="axes fraction",
                        arrowprops=dict(arrowstyle="-|>", color="tab:red", lw=1.8, mutation_scale=16,
                                        connectionstyle=f"arc3,rad={0.6 if sense > 0 else -0.6}"))
        rotation = _rotation_sense(summary, shaft)
        kind = ""
        if sense and rotation:
            kind = ", forward precession" if sense == rotation else ", backward precession"
        elif sense:
            kind = ", counter-clockwise" if sense > 0 else ", clockwise"
        ax.set_xlabel("x [µm]")
        ax.set_ylabel("y [µm]")
        ax.set_title(f"{shaft} shaft{kind} (red arrow: sense of the orbit)", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.12), ncol=2, borderaxespad=0)
    figure.suptitle(summary["config"].get("title") or "orbits", fontsize=9)
    return figure


def full_spectrum_figure(result_dir, axes=None, dynamic_range=1e-6):
    """Amplitude against signed frequency of each shaft, forward right and backward left, whirl
    peaks marked (as Rao 2023, Fig. 4.2). The log axis spans at most 1/dynamic_range below the
    peak (numerical zeros are not drawn down to 1e-20)."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    spectrum = _read_columns(folder / "full_spectrum.csv")
    peaks = _read_columns(folder / "spectrum_peaks.csv")
    frame = summary["config"]["spectrum"]["frame"]
    if axes is None:
        figure, axes = plt.subplots(2, 1, figsize=(10, 7), layout="constrained")
    else:
        figure = axes[0].figure
    for ax, shaft in zip(axes, ("pinion", "gear")):
        f = [spectrum["frequency_hz"][i] for i, s in enumerate(spectrum["shaft"]) if s == shaft]
        a = [spectrum["amplitude_m"][i] * 1e6 for i, s in enumerate(spectrum["shaft"]) if s == shaft]
        pf = [peaks["frequency_hz"][i] for i, s in enumerate(peaks["shaft"]) if s == shaft]
        pa = [peaks["amplitude_m"][i] * 1e6 for i, s in enumerate(peaks["shaft"]) if s == shaft]
        floor = log_floor(a + pa, dynamic_range) or 1e-12
        ax.plot(f, [max(v, floor) for v in a], lw=0.6, color="0.4", label="FFT (display window)")
        ax.plot(pf, pa, "o", color="tab:red", ms=3, mfc="none", label="whirl peaks (exact bins or fit)")
        ax.set_yscale("log")
        ax.set_ylim(floor, max(a + pa + [floor]) * 3)
        ax.set_ylabel("0-peak whirl radius [µm]")
        ax.set_xlabel("frequency [Hz]")
        ax.set_title(f"{shaft} shaft ({frame} frame): forward f > 0, backward f < 0", fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    figure.suptitle(summary["config"].get("title") or "full spectrum", fontsize=9)
    return figure


def study_figure(result_dir, axes=None, dynamic_range=1e-6):
    """Dynamic whirl amplitude of every component per case and shaft (thesis §4.5), log axis
    clipped to dynamic_range below the largest amplitude, legend beside the axes."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    study = _read_columns(folder / "study.csv")
    cases = list(dict.fromkeys(study["case"]))
    components = [c for c in dict.fromkeys(study["component"]) if c != "static"]
    if axes is None:
        figure, axes = plt.subplots(2, 1, figsize=(13, 7.5), sharex=True, layout="constrained")
    else:
        figure = axes[0].figure
    floor = log_floor([1e6 * a for a in study["amplitude_m"]], dynamic_range) or 1e-12
    width = 0.8 / len(cases)
    for ax, shaft in zip(axes, ("pinion", "gear")):
        for k, case in enumerate(cases):
            values = {study["component"][i]: study["amplitude_m"][i] * 1e6 for i in range(len(study["case"]))
                      if study["case"][i] == case and study["shaft"][i] == shaft}
            ax.bar([j + k * width for j in range(len(components))], [values[c] for c in components],
                   width=width, label=case)
        ax.set_ylabel(f"{shaft} shaft [µm]")
        ax.set_yscale("log")
        ax.set_ylim(floor, None)
        ax.grid(alpha=0.3, axis="y")
    axes[0].legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0, title="case",
                   title_fontsize=8)
    axes[-1].set_xticks([j + 0.4 - width / 2 for j in range(len(components))])
    axes[-1].set_xticklabels(components, rotation=60, fontsize=7)
    axes[-1].set_xlabel("whirl component")
    ranking = ", ".join(f"{r['group']} {100 * r['max_relative_change']:.0f} %"
                        for r in summary["results"]["study"]["ranking_mesh"])
    title = summary["config"].get("title") or "lateral geared rotor"
    figure.suptitle(f"{title}\nwhirl amplitudes per case (bars below {dynamic_range:g} of the largest are "
                    f"numerical zeros); largest change of the mesh-harmonic RMS: {ranking}", fontsize=9)
    return figure


def plot_rotor(result_dir, save=False):
    """{file name: Figure}: orbits.png (steady window), full_spectrum.png and, with a study,
    study.png; written into the folder when `save`."""
    folder = pathlib.Path(result_dir)
    figures = {}
    if (folder / "time_history.csv").exists():
        figures["orbits.png"] = orbits_figure(folder)
    if (folder / "full_spectrum.csv").exists():
        figures["full_spectrum.png"] = full_spectrum_figure(folder)
    if (folder / "study.csv").exists():
        figures["study.png"] = study_figure(folder)
    return finish(figures, folder, save)


def plot_spectrum(result_dir, save=False):
    """{file name: Figure}: orbits.png and full_spectrum.png of an analysed probe record."""
    folder = pathlib.Path(result_dir)
    return finish({"orbits.png": orbits_figure(folder, only_steady=False),
                   "full_spectrum.png": full_spectrum_figure(folder)}, folder, save)
