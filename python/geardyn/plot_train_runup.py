"""Figures of a gear train's run-up (`geardyn train`, analysis "runup"): the order tracks of every
channel against input speed with the Campbell resonances, and the waterfall of the first channel
with the tracked mesh-order lines."""

import math
import pathlib

from ._plot_common import _axes, _long_table, _read_columns, _read_summary, plt
from ._tables import log_floor


def _unit_label(unit):
    return {"N": "N", "m": "m", "rad": "rad"}.get(unit, unit)


def train_runup_figure(result_dir, title="gear train"):
    """runup.png: one panel per channel, the amplitude of every tracked mesh harmonic (and the
    input's 1×) against input speed on a log axis; the Campbell resonances of the mesh lines
    dotted."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    run = summary["results"]["runup"]
    tracks = _long_table(folder / "runup.csv", ["channel"])
    shown = list(tracks.items())[:4]
    figure, axes = plt.subplots(len(shown), 1, figsize=(10.5, 2.6 * len(shown) + 0.9), sharex=True,
                                squeeze=False, layout="constrained")
    for ax, ((channel,), data) in zip(axes[:, 0], shown):
        columns = [c for c in data if c.startswith("amplitude_")]
        values = [v for c in columns for v in data[c] if not math.isnan(v)]
        floor = log_floor(values) or 1e-12
        for c in columns:
            label = c[len("amplitude_"):].replace("_mesh_", " mesh ").replace("_", " ")
            style = ":" if "_mesh_" not in c else "-"
            ax.semilogy(data["speed_rpm"], [max(v, floor) if not math.isnan(v) else float("nan")
                                            for v in data[c]], style, lw=1.1, label=label)
        ax.set_ylim(floor, max(values + [floor]) * 3)
        for r in run.get("campbell_resonances", []):
            ax.axvline(r["speed_rpm"], color="0.5", ls="--", lw=0.7)
        unit = data["unit"][0] if data.get("unit") else ""
        ax.set_ylabel(f"{channel}\namplitude [{_unit_label(unit)}]", fontsize=8)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    axes[-1, 0].set_xlabel("input speed [rpm]")
    figure.suptitle(
        f"{title}: order tracking of the run-up {run['speed_start_rpm']:.0f} → "
        f"{run['speed_end_rpm']:.0f} rpm in {run['duration_s']:.3g} s "
        f"(window {1e3 * run['window_s']:.3g} ms); dashed: Campbell resonances of the mesh orders",
        fontsize=9)
    return figure


def train_waterfall_figure(result_dir, title="gear train", max_lines=8):
    """waterfall.png: the amplitude spectrum of the first channel in every window (log colour)
    over input speed and frequency, with the tracked mesh-order lines."""
    folder = pathlib.Path(result_dir)
    data = _read_columns(folder / "waterfall.csv")
    orders = _read_columns(folder / "runup_orders.csv")
    speeds = list(dict.fromkeys(data["speed_rpm"]))
    freqs = list(dict.fromkeys(data["frequency_hz"]))
    si = {s: i for i, s in enumerate(speeds)}
    fi = {f: i for i, f in enumerate(freqs)}
    positive = [a for a in data["amplitude"] if a > 0]
    top = max(positive) if positive else 1.0
    floor = top * 1e-4  # four decades of colour
    grid = [[math.log10(floor)] * len(speeds) for _ in freqs]
    for s, f, a in zip(data["speed_rpm"], data["frequency_hz"], data["amplitude"]):
        grid[fi[f]][si[s]] = math.log10(max(a, floor))
    figure, ax = _axes(None, (10.5, 5.5))
    mesh = ax.pcolormesh(speeds, freqs, grid, shading="nearest", cmap="magma")
    channel, unit = data["channel"][0], data["unit"][0]
    figure.colorbar(mesh, ax=ax, label=f"log10 amplitude of {channel} [{_unit_label(unit)}]")
    for name, slope in list(zip(orders["line"], orders["hz_per_rpm"]))[:max_lines]:
        if not name.startswith("1x_mesh") and not name.startswith("2x_mesh") and \
                not name.startswith("3x_mesh"):
            continue
        ys = [slope * s for s in (speeds[0], speeds[-1])]
        ax.plot((speeds[0], speeds[-1]), ys, color="white", lw=0.6, ls="--", alpha=0.8)
        s_label = min(speeds[-1], freqs[-1] / slope)
        ax.text(s_label, slope * s_label, " " + name.replace("_mesh_", " mesh "), color="white",
                fontsize=7, ha="right", va="bottom")
    ax.set_xlim(min(speeds), max(speeds))
    ax.set_ylim(freqs[0], freqs[-1])
    ax.set_xlabel("input speed [rpm]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(f"{title}: waterfall of the run-up ({channel}); dashed: mesh orders", fontsize=9)
    return figure
