"""Figures of the finite-element geared rotor (Visnadi 2021): the comparison of mesh-stiffness
models (Figs. 1, 3-6), time response and spectra, run-up order tracking and waterfall, modes and
the Campbell diagram."""

import json
import math
import pathlib

from ._plot_common import _axes, _long_table, _read_columns, _read_summary, _save_atomically, finish, plt
from ._tables import log_floor


_WHIRL_COLOURS = {"forward": "tab:red", "backward": "tab:blue", "mixed": "tab:purple",
                  "torsional": "tab:green", "axial": "tab:brown"}


def _fe_figure_channels(channels):
    """The channels of Visnadi 2021 Figs. 3-6: gear-node u_y of each shaft (displacement) and
    the first bearing's u_y of each shaft (acceleration); what exists of them, else the first."""
    gear = [c for c in channels if c.endswith(".uy") and not c.split(".")[1] == "0"]
    bearing = [c for c in channels if c.endswith(".uy") and c.split(".")[1] == "0"]
    picked = [(c, "displacement") for c in gear[:2]] + [(c, "acceleration") for c in bearing[:2]]
    return picked or [(channels[0], "displacement")]


def _fe_compare(folder, summary, title):
    spectra = _long_table(folder / "compare_spectra.csv", ["model", "channel"])
    stiffness = _long_table(folder / "compare_stiffness.csv", ["model"])
    models = list(dict.fromkeys(k[0] for k in spectra))
    channels = list(dict.fromkeys(k[1] for k in spectra))
    picked = _fe_figure_channels(channels)
    figure, axes = plt.subplots(len(picked) + 1, 1, figsize=(10, 2.6 * (len(picked) + 1)), layout="constrained")
    ax = axes[0]
    for model in models:
        k = stiffness[(model,)]
        ax.plot(k["mesh_fraction"], [v / 1e8 for v in k["stiffness_normal_n_per_m"]], lw=1.2, label=model)
    ax.set_xlabel("mesh phase [mesh periods]")
    ax.set_ylabel("k_m [1e8 N/m]")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    ax.grid(alpha=0.3)
    ax.set_title(f"{title}\nmesh stiffness (Fig. 1) and DFT amplitudes of the steady response (Figs. 3-6)",
                 fontsize=9)
    harmonics = _long_table(folder / "compare_harmonics.csv", ["model", "channel"])
    markers = "os^vDx*+"
    for ax, (channel, quantity) in zip(axes[1:], picked):
        for i, model in enumerate(models):
            data = spectra[(model, channel)]
            scale = 1e6 if quantity == "displacement" else 1.0
            line, = ax.semilogy(data["frequency_hz"], [max(a * scale, 1e-12) for a in data[quantity]],
                                lw=0.8, label=model)
            peaks = harmonics[(model, channel)]  # the mesh-order peaks, marked
            ax.scatter(peaks["frequency_hz"], [max(a * scale, 1e-12) for a in peaks[quantity]],
                       marker=markers[i % len(markers)], s=18, color=line.get_color(), zorder=3)
        ax.set_ylabel(f"{channel}\n{'[µm]' if quantity == 'displacement' else '[m/s²]'}", fontsize=8)
        ax.grid(alpha=0.3)
        positive = [a for m in models for a in spectra[(m, channel)][quantity] if a > 0]
        if positive:
            top = max(positive) * (1e6 if quantity == "displacement" else 1.0)
            ax.set_ylim(top * 1e-6, top * 3)
    axes[-1].set_xlabel("frequency [Hz]")
    axes[1].legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    return {"compare.png": figure}


def _fe_time(folder, summary, title):
    figures = {}
    history = _read_columns(folder / "time_history.csv", short=True)
    channels = [c for c in history if c not in ("t", "speed_rpm", "mesh_stiffness", "mesh_force")
                and not c.endswith("_vel") and not c.endswith("_acc")]
    figure, axes = plt.subplots(2, 1, figsize=(10, 6), sharex=True, layout="constrained")
    for channel in channels[:4]:
        axes[0].plot(history["t"], [x * 1e6 for x in history[channel]], lw=0.8, label=channel)
    axes[0].set_ylabel("displacement [µm]")
    axes[0].legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    axes[0].grid(alpha=0.3)
    axes[0].set_title(f"{title}\ntime response from rest (Fig. 2)", fontsize=9)
    axes[1].plot(history["t"], history["mesh_force"], lw=0.8, color="black")
    axes[1].set_ylabel("mesh force [N]")
    axes[1].set_xlabel("time [s]")
    axes[1].grid(alpha=0.3)
    figures["time_history.png"] = figure
    if (folder / "spectrum.csv").exists():
        spectra = _long_table(folder / "spectrum.csv", ["channel"])
        picked = _fe_figure_channels([k[0] for k in spectra])
        figure, axes = plt.subplots(len(picked), 1, figsize=(9, 2.4 * len(picked)), squeeze=False,
                                    layout="constrained")
        for ax, (channel, quantity) in zip(axes[:, 0], picked):
            data = spectra[(channel,)]
            scale = 1e6 if quantity == "displacement" else 1.0
            values = [a * scale for a in data[quantity]]
            floor = log_floor(values) or 1e-12
            ax.semilogy(data["frequency_hz"], [max(a, floor) for a in values], lw=1.0)
            ax.set_ylim(floor, max(values + [floor]) * 3)
            ax.set_ylabel(f"{channel}\n{'[µm]' if quantity == 'displacement' else '[m/s²]'}", fontsize=8)
            ax.grid(alpha=0.3)
        axes[0, 0].set_title(f"{title}\nDFT amplitude of the steady window", fontsize=9)
        axes[-1, 0].set_xlabel("frequency [Hz]")
        figures["spectrum.png"] = figure
    if (folder / "runup.csv").exists():
        figures["runup.png"] = runup_figure(folder)
        figures["waterfall.png"] = _waterfall(folder, title)
    return figures


def runup_figure(result_dir, ax=None):
    """Mesh-order acceleration of each channel against speed (order tracking of a run-up), the
    Campbell crossings of the mesh line dashed, legend beside the axes; on `ax` if given."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    title = summary.get("config", {}).get("title") or "finite-element geared rotor"
    track = _long_table(folder / "runup.csv", ["channel"])
    crossings = summary["results"]["runup"]["campbell_mesh_crossings"]
    figure, ax = _axes(ax, (10, 4.8))
    values = [v for d in track.values() for v in d["mesh_order_acceleration"]]
    floor = log_floor(values) or 1e-12
    for (channel,), data in track.items():
        ax.semilogy(data["speed_rpm"], [max(v, floor) for v in data["mesh_order_acceleration"]], lw=1.0,
                    label=channel)
    ax.set_ylim(floor, max(values + [floor]) * 3)
    for c in crossings:
        ax.axvline(c["speed_rpm"], color="grey", ls="--", lw=0.8)
        ax.text(c["speed_rpm"], ax.get_ylim()[1], f" mode {c['mode'] + 1}", fontsize=7,
                rotation=90, va="top")
    ax.set_xlabel("pinion speed [rpm]")
    ax.set_ylabel("mesh-order acceleration [m/s²]")
    ax.set_title(f"{title}\norder tracking of the run-up; dashed: Campbell crossings of the mesh line",
                 fontsize=9)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    ax.grid(alpha=0.3)
    return figure


def _waterfall(folder, title):
    """waterfall.png: the cascade of a run-up, amplitude (log colour) over speed and frequency."""
    data = _read_columns(folder / "waterfall.csv")
    speeds = list(dict.fromkeys(data["speed_rpm"]))
    freqs = list(dict.fromkeys(data["frequency_hz"]))
    grid = [[0.0] * len(speeds) for _ in freqs]
    si = {s: i for i, s in enumerate(speeds)}
    fi = {f: i for i, f in enumerate(freqs)}
    for s, f, a in zip(data["speed_rpm"], data["frequency_hz"], data["amplitude"]):
        grid[fi[f]][si[s]] = math.log10(max(a, 1e-12))
    figure, ax = plt.subplots(figsize=(9, 5), layout="constrained")
    mesh = ax.pcolormesh(speeds, freqs, grid, shading="nearest", cmap="viridis")
    figure.colorbar(mesh, ax=ax, label="log10 amplitude [m/s²]")
    ax.set_xlabel("pinion speed [rpm]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(f"{title}\nwaterfall of the run-up (first output channel, acceleration)", fontsize=9)
    return figure


def plot_campbell(speeds_rpm, modes, lines=(), critical=(), title="Campbell diagram", path=None, ax=None):
    """A Campbell diagram: `modes` is a list of tracks, each a list of (frequency_hz, whirl) per
    speed; `lines` (name, order) are drawn as order lines; `critical` are dicts with speed_rpm
    and frequency_hz (the crossings, x). Legend beside the axes. Draws on `ax` if given; writes
    a PNG to `path` only if given; returns the Figure."""
    figure, ax = _axes(ax, (10.5, 5.5))
    top = 0.0
    seen = set()
    for track in modes:
        freqs = [f for f, _ in track]
        top = max(top, max(freqs))
        ax.plot(speeds_rpm, freqs, color="0.6", lw=0.8)
        for whirl, colour in _WHIRL_COLOURS.items():
            pts = [(s, f) for s, (f, w) in zip(speeds_rpm, track) if w == whirl]
            if pts:
                ax.scatter(*zip(*pts), s=8, color=colour, label=f"{whirl} whirl" if whirl not in seen else None)
                seen.add(whirl)
    for name, order in lines:
        ax.plot(speeds_rpm, [order * s / 60.0 for s in speeds_rpm], ls="--", lw=1.0, label=f"{name} order line")
    if critical:
        ax.plot([c["speed_rpm"] for c in critical], [c["frequency_hz"] for c in critical], "kx", ms=7, ls="none",
                label="critical speeds (crossings)")
    ax.set_ylim(0, top * 1.1)
    ax.set_xlabel("pinion speed [rpm]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    ax.grid(alpha=0.3)
    if path:
        _save_atomically(figure, path)
    return figure


def _shaft_nodes_mm(config, shaft):
    """Axial position [mm] of every node of a shaft: the running sum of its element lengths."""
    xs = [0.0]
    for length in config.get(shaft, {}).get("element_lengths", []):
        xs.append(xs[-1] + 1e3 * length)
    return xs


def fe_modes_figure(result_dir, count=8):
    """The mode shapes along the shafts: for each of the first `count` modes, the lateral
    displacements u_y (solid) and u_z (dashed) of every node of each shaft (real part), drawn
    against the axial position, one band per shaft, normalised by the mode's largest
    translation; the title gives frequency, damping ratio and whirl."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    config = summary["config"]
    modes = _read_columns(folder / "modes.csv")
    shapes = _long_table(folder / "mode_shapes.csv", ["mode"])
    count = min(count, len(modes["mode"]))
    columns = 4 if count > 4 else count
    rows = -(-count // columns)
    figure, axes = plt.subplots(rows, columns, figsize=(3.5 * columns, 2.9 * rows + 0.5), squeeze=False,
                                layout="constrained")
    shafts = ("pinion_shaft", "gear_shaft")
    for j in range(rows * columns):
        ax = axes[j // columns][j % columns]
        if j >= count:
            ax.axis("off")
            continue
        mode = int(modes["mode"][j])
        values = dict(zip(shapes[(str(mode),)]["dof"], shapes[(str(mode),)]["re"]))
        largest = max([abs(v) for d, v in values.items() if d.endswith((".ux", ".uy", ".uz"))] + [1e-300])
        for k, shaft in enumerate(shafts):
            xs = _shaft_nodes_mm(config, shaft)
            base = -1.2 * k
            ax.plot(xs, [base] * len(xs), color="0.75", lw=3, solid_capstyle="butt")
            for dof, style in (("uy", "-"), ("uz", "--")):
                ax.plot(xs, [base + 0.5 * values.get(f"{shaft}.{n}.{dof}", 0.0) / largest for n in range(len(xs))],
                        color=f"C{k}", ls=style, lw=1.3, marker="o", ms=2.5)
        ax.set_yticks([0.0, -1.2], ["pinion\nshaft", "gear\nshaft"], fontsize=7)
        ax.set_ylim(-1.9, 0.7)
        ax.tick_params(labelsize=7)
        ax.set_xlabel("axial position x [mm]", fontsize=7)
        whirl = modes["whirl"][j]
        ax.set_title(f"mode {mode}: {modes['frequency_hz'][j]:.0f} Hz, ζ {modes['damping_ratio'][j]:.3f}\n{whirl}",
                     fontsize=8, color=_WHIRL_COLOURS.get(whirl, "0.2"))
        ax.grid(alpha=0.3)
    title = config.get("title") or "finite-element geared rotor"
    speed = summary["results"]["modal"]["speed_rpm"]
    title = title if f"{speed:g} rpm" in title else f"{title} at {speed:g} rpm"
    figure.suptitle(f"{title}\nmode shapes along the shafts: u_y solid, u_z dashed (real part, normalised to "
                    "the largest translation); title colour: whirl", fontsize=9)
    return figure


def campbell_figure(result_dir, ax=None):
    """campbell.png of a finite-element rotor run (analysis.type = "campbell")."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    title = summary.get("config", {}).get("title") or "finite-element geared rotor"
    table = _long_table(folder / "campbell.csv", ["mode"])
    speeds = list(table[("1",)]["speed_rpm"])
    tracks = [list(zip(d["frequency_hz"], d["whirl"])) for _, d in sorted(table.items(), key=lambda kv: int(kv[0][0]))]
    lines = _read_columns(folder / "campbell_lines.csv")
    critical = summary["results"]["campbell"]["critical_speeds"]
    if "campbell" not in title.lower():
        title += ": Campbell diagram"
    return plot_campbell(speeds, tracks, list(zip(lines["line"], lines["order"])), critical,
                         f"{title}\nmarker colour: whirl; x: critical speeds", ax=ax)


def plot_rotor_fe(result_dir, save=False):
    """{file name: Figure} of a finite-element geared rotor run (Visnadi 2021): compare.png
    (mesh stiffness and DFT amplitudes per model, Figs. 1, 3-6), time_history.png, spectrum.png,
    runup.png and waterfall.png, modes.png, campbell.png; written into the folder when `save`."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    title = summary.get("config", {}).get("title") or "finite-element geared rotor"
    analysis = summary["config"]["analysis"]["type"]
    figures = {}
    if analysis == "compare_stiffness":
        figures = _fe_compare(folder, summary, title)
    elif analysis == "time":
        figures = _fe_time(folder, summary, title)
    elif analysis == "modal":
        figures = {"modes.png": fe_modes_figure(folder)}
    elif analysis == "campbell":
        figures = {"campbell.png": campbell_figure(folder)}
    return finish(figures, folder, save)
