"""Figures of the finite-element geared rotor (Visnadi 2021): the comparison of mesh-stiffness
models (Figs. 1, 3-6), time response and spectra, run-up order tracking and waterfall, modes and
the Campbell diagram."""

import json
import math
import pathlib

from ._plot_common import _long_table, _read_columns, _save_atomically, plt


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
    figure, axes = plt.subplots(len(picked) + 1, 1, figsize=(9, 2.6 * (len(picked) + 1)))
    ax = axes[0]
    for model in models:
        k = stiffness[(model,)]
        ax.plot(k["mesh_fraction"], [v / 1e8 for v in k["stiffness"]], lw=1.2, label=model)
    ax.set_xlabel("mesh phase [mesh periods]")
    ax.set_ylabel("k_m [1e8 N/m]")
    ax.legend(fontsize=7, ncol=len(models))
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
        ax.set_ylabel(f"{channel}\n{'[um]' if quantity == 'displacement' else '[m/s^2]'}", fontsize=8)
        ax.grid(alpha=0.3)
        positive = [a for m in models for a in spectra[(m, channel)][quantity] if a > 0]
        if positive:
            top = max(positive) * (1e6 if quantity == "displacement" else 1.0)
            ax.set_ylim(top * 1e-6, top * 3)
    axes[-1].set_xlabel("frequency [Hz]")
    axes[1].legend(fontsize=7, ncol=len(models))
    figure.tight_layout()
    return [_save_atomically(figure, folder / "compare.png")]


def _fe_time(folder, summary, title):
    written = []
    history = _read_columns(folder / "time_history.csv")
    channels = [c for c in history if c not in ("t", "speed_rpm", "mesh_stiffness", "mesh_force")
                and not c.endswith("_vel") and not c.endswith("_acc")]
    figure, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for channel in channels[:4]:
        axes[0].plot(history["t"], [x * 1e6 for x in history[channel]], lw=0.8, label=channel)
    axes[0].set_ylabel("displacement [um]")
    axes[0].legend(fontsize=7)
    axes[0].grid(alpha=0.3)
    axes[0].set_title(f"{title}\ntime response from rest (Fig. 2)", fontsize=9)
    axes[1].plot(history["t"], history["mesh_force"], lw=0.8, color="black")
    axes[1].set_ylabel("mesh force [N]")
    axes[1].set_xlabel("time [s]")
    axes[1].grid(alpha=0.3)
    figure.tight_layout()
    written.append(_save_atomically(figure, folder / "time_history.png"))
    if (folder / "spectrum.csv").exists():
        spectra = _long_table(folder / "spectrum.csv", ["channel"])
        picked = _fe_figure_channels([k[0] for k in spectra])
        figure, axes = plt.subplots(len(picked), 1, figsize=(9, 2.4 * len(picked)), squeeze=False)
        for ax, (channel, quantity) in zip(axes[:, 0], picked):
            data = spectra[(channel,)]
            scale = 1e6 if quantity == "displacement" else 1.0
            ax.semilogy(data["frequency_hz"], [max(a * scale, 1e-12) for a in data[quantity]], lw=1.0)
            ax.set_ylabel(f"{channel}\n{'[um]' if quantity == 'displacement' else '[m/s^2]'}", fontsize=8)
            ax.grid(alpha=0.3)
        axes[0, 0].set_title(f"{title}\nDFT amplitude of the steady window", fontsize=9)
        axes[-1, 0].set_xlabel("frequency [Hz]")
        figure.tight_layout()
        written.append(_save_atomically(figure, folder / "spectrum.png"))
    if (folder / "runup.csv").exists():
        track = _long_table(folder / "runup.csv", ["channel"])
        crossings = summary["results"]["runup"]["campbell_mesh_crossings"]
        figure, ax = plt.subplots(figsize=(9, 4.5))
        for (channel,), data in track.items():
            ax.semilogy(data["speed_rpm"], data["mesh_order_acceleration"], lw=1.0, label=channel)
        for c in crossings:
            ax.axvline(c["speed_rpm"], color="grey", ls="--", lw=0.8)
            ax.text(c["speed_rpm"], ax.get_ylim()[1], f" mode {c['mode'] + 1}", fontsize=7,
                    rotation=90, va="top")
        ax.set_xlabel("pinion speed [rpm]")
        ax.set_ylabel("mesh-order acceleration [m/s^2]")
        ax.set_title(f"{title}\norder tracking of the run-up; dashed: Campbell crossings of the mesh line",
                     fontsize=9)
        ax.legend(fontsize=7, ncol=2)
        ax.grid(alpha=0.3)
        figure.tight_layout()
        written.append(_save_atomically(figure, folder / "runup.png"))
        written.append(_waterfall(folder, title))
    return written


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
    figure, ax = plt.subplots(figsize=(9, 5))
    mesh = ax.pcolormesh(speeds, freqs, grid, shading="nearest", cmap="viridis")
    figure.colorbar(mesh, ax=ax, label="log10 amplitude [m/s^2]")
    ax.set_xlabel("pinion speed [rpm]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(f"{title}\nwaterfall of the run-up (first output channel, acceleration)", fontsize=9)
    figure.tight_layout()
    return _save_atomically(figure, folder / "waterfall.png")


def plot_campbell(speeds_rpm, modes, lines=(), critical=(), title="Campbell diagram", path=None):
    """A Campbell diagram: `modes` is a list of tracks, each a list of (frequency_hz, whirl) per
    speed; `lines` (name, order) are drawn as order lines; `critical` are dicts with speed_rpm
    and frequency_hz. Returns the figure, or writes it to `path` and returns the path."""
    figure, ax = plt.subplots(figsize=(9, 5.5))
    top = 0.0
    for j, track in enumerate(modes):
        freqs = [f for f, _ in track]
        top = max(top, max(freqs))
        ax.plot(speeds_rpm, freqs, color="0.6", lw=0.8)
        for whirl in _WHIRL_COLOURS:
            pts = [(s, f) for s, (f, w) in zip(speeds_rpm, track) if w == whirl]
            if pts:
                ax.scatter(*zip(*pts), s=8, color=_WHIRL_COLOURS[whirl],
                           label=whirl if j == 0 or whirl not in [t.get_label() for t in ax.collections] else None)
    for name, order in lines:
        ax.plot(speeds_rpm, [order * s / 60.0 for s in speeds_rpm], ls="--", lw=1.0, label=name)
    for c in critical:
        ax.plot(c["speed_rpm"], c["frequency_hz"], "kx", ms=7)
    ax.set_ylim(0, top * 1.1)
    ax.set_xlabel("pinion speed [rpm]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(title, fontsize=9)
    handles, labels = ax.get_legend_handles_labels()
    unique = dict(zip(labels, handles))
    ax.legend(unique.values(), unique.keys(), fontsize=7, ncol=3)
    ax.grid(alpha=0.3)
    figure.tight_layout()
    return _save_atomically(figure, path) if path else figure


def plot_rotor_fe(result_dir):
    """The finite-element geared rotor (Visnadi 2021): compare.png (mesh stiffness and DFT
    amplitudes per model, Figs. 1, 3-6), time_history.png and spectrum.png, runup.png and
    waterfall.png, modes.png, campbell.png."""
    folder = pathlib.Path(result_dir)
    summary = json.loads((folder / "summary.json").read_text())
    title = summary.get("config", {}).get("title") or "finite-element geared rotor"
    analysis = summary["config"]["analysis"]["type"]
    if analysis == "compare_stiffness":
        return _fe_compare(folder, summary, title)
    if analysis == "time":
        return _fe_time(folder, summary, title)
    if analysis == "modal":
        modes = _read_columns(folder / "modes.csv")
        figure, ax = plt.subplots(figsize=(9, 4))
        colours = [_WHIRL_COLOURS.get(w, "grey") for w in modes["whirl"]]
        ax.bar(range(1, len(colours) + 1), modes["frequency_hz"], color=colours)
        for i, (f, z) in enumerate(zip(modes["frequency_hz"], modes["damping_ratio"])):
            ax.text(i + 1, f, f"{f:.0f} Hz\nζ {z:.3f}", ha="center", va="bottom", fontsize=6)
        ax.set_xlabel("mode")
        ax.set_ylabel("damped natural frequency [Hz]")
        speed = summary["results"]["modal"]["speed_rpm"]
        ax.set_title(f"{title}\nmodes at {speed:g} rpm (colour: whirl; "
                     + ", ".join(f"{k} {v[4:]}" for k, v in _WHIRL_COLOURS.items()) + ")", fontsize=9)
        ax.grid(alpha=0.3, axis="y")
        figure.tight_layout()
        return [_save_atomically(figure, folder / "modes.png")]
    if analysis == "campbell":
        table = _long_table(folder / "campbell.csv", ["mode"])
        speeds = list(table[("1",)]["speed_rpm"])
        tracks = [list(zip(d["frequency_hz"], d["whirl"])) for _, d in sorted(table.items(), key=lambda kv: int(kv[0][0]))]
        lines = _read_columns(folder / "campbell_lines.csv")
        critical = summary["results"]["campbell"]["critical_speeds"]
        return [plot_campbell(speeds, tracks, list(zip(lines["line"], lines["order"])), critical,
                              f"{title}\nCampbell diagram (x: critical speeds)", folder / "campbell.png")]
    return []
