"""The Newmark time response of a gear train (`geardyn train`, run = ["time"]) over its
frequency-domain steady state. A record of a few mesh periods is drawn as lines; a longer one
(a hundred mesh periods drawn as a line is a solid band) as an envelope beside a zoom on its
last few periods of the fastest mesh, where the two solutions compare cycle by cycle."""

import numpy as np

from ._plot_common import _read_columns, plt

#: At most this many envelope bins across the record (otherwise one per fastest mesh period).
_BINS = 400
#: Periods of the fastest mesh in the zoom window; a record up to twice as long is drawn whole.
_ZOOM_PERIODS = 4


def _envelope(t, f, bins):
    """(bin centres, min, max) of f over `bins` equal bins of t: with one bin per mesh period
    the band is the per-cycle extremes (the envelope), not the waveform."""
    edges = np.linspace(t[0], t[-1], max(1, min(bins, _BINS, len(t) // 2)) + 1)
    index = np.clip(np.searchsorted(edges, t, side="right") - 1, 0, len(edges) - 2)
    lo = np.full(len(edges) - 1, np.inf)
    hi = np.full(len(edges) - 1, -np.inf)
    np.minimum.at(lo, index, f)
    np.maximum.at(hi, index, f)
    keep = np.isfinite(lo)
    return 0.5 * (edges[:-1] + edges[1:])[keep], lo[keep], hi[keep]


def _fastest_mesh_period_ms(summary):
    meshes = (summary["results"].get("kinematics") or {}).get("meshes") or []
    frequencies = [m["mesh_frequency_hz"] for m in meshes if m.get("mesh_frequency_hz", 0) > 0]
    return 1e3 / max(frequencies) if frequencies else None


#: What the figure draws per row: the mesh forces, or (a train without meshes, e.g. a rotor with
#: an unbalance) the bearing forces: (column prefix, column suffix, axis label).
_MESH = ("mesh_force_", "_normal_n", "mesh force")
_BEARING = ("bearing_force_", "_y_n", "bearing force y")
#: The figure's title per kind.
_TITLE = {_MESH: "dynamic mesh forces", _BEARING: "dynamic bearing forces (y)"}


def _names(table, kind):
    prefix, suffix, _ = kind
    return [n[len(prefix):-len(suffix)] for n in table
            if n.startswith(prefix) and n.endswith(suffix)]


def _force_unit(table, shown, kind):
    """(scale, unit) for the drawn forces: kN, or N when they all stay below 1 kN (a rotor's
    unbalance forces would read as zeros in kN)."""
    prefix, suffix, _ = kind
    largest = max(np.max(np.abs(table[prefix + name + suffix])) for name in shown)
    return (1e-3, "kN") if largest >= 1e3 else (1.0, "N")


def _forces(table, name, kind, scale):
    """Newmark's and the steady state's (or None) force of `name`, times `scale`."""
    prefix, suffix, _ = kind
    steady = table.get("steady_" + prefix + name + suffix)
    return (scale * np.asarray(table[prefix + name + suffix]),
            scale * np.asarray(steady) if steady else None)


def _whole_record(table, t_ms, shown, summary, title, kind):
    scale, unit = _force_unit(table, shown, kind)
    figure, axes = plt.subplots(len(shown), 1, figsize=(10.5, 2.2 * len(shown) + 0.6),
                                sharex=True, squeeze=False, layout="constrained")
    for ax, name in zip(axes[:, 0], shown):
        newmark, steady = _forces(table, name, kind, scale)
        ax.plot(t_ms, newmark, lw=1.4, label="Newmark")
        if steady is not None:
            ax.plot(t_ms, steady, "--", lw=1.0, color="k", label="frequency-domain steady state")
        ax.set_ylabel(f"{name}\n{kind[2]} [{unit}]", fontsize=8)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    axes[-1, 0].set_xlabel("time in the steady-state window [ms]")
    speed = summary["results"]["time"]["speed_rpm"]
    figure.suptitle(f"{title}: {_TITLE[kind]} at {speed:g} rpm", fontsize=9)
    return figure


def train_time_figure(folder, summary, title):
    table = _read_columns(folder / "time_history.csv")
    t_ms = 1e3 * (np.asarray(table["t_s"]) - table["t_s"][0])
    kind = _MESH if _names(table, _MESH) else _BEARING
    shown = _names(table, kind)[:4]
    if not shown:
        return None  # nothing with a force to draw (no mesh, no bearing)
    period = _fastest_mesh_period_ms(summary) if kind is _MESH else None
    # Without meshes the record is a few periods of the slowest excitation: drawn whole.
    window = _ZOOM_PERIODS * period if period else t_ms[-1]
    if t_ms[-1] <= 2 * window:
        return _whole_record(table, t_ms, shown, summary, title, kind)
    zoom = t_ms >= t_ms[-1] - window
    scale, unit = _force_unit(table, shown, kind)
    figure, axes = plt.subplots(len(shown), 2, figsize=(11.5, 2.3 * len(shown) + 0.8),
                                squeeze=False, layout="constrained",
                                gridspec_kw={"width_ratios": [1.6, 1.0]})
    for row, name in enumerate(shown):
        newmark, steady = _forces(table, name, kind, scale)
        whole, near = axes[row]
        bins = int(round(t_ms[-1] / period)) if period else _BINS
        tc, lo, hi = _envelope(t_ms, newmark, bins)
        whole.fill_between(tc, lo, hi, color="tab:blue", alpha=0.35, lw=0,
                           label="Newmark (envelope)")
        if steady is not None:
            tc, lo, hi = _envelope(t_ms, steady, bins)
            whole.plot(tc, lo, "--", color="k", lw=0.8, label="steady state (envelope)")
            whole.plot(tc, hi, "--", color="k", lw=0.8)
        whole.axvspan(t_ms[-1] - window, t_ms[-1], color="tab:orange", alpha=0.15, lw=0,
                      label="zoom window" if row == 0 else None)
        whole.set_ylabel(f"{name}\n{kind[2]} [{unit}]", fontsize=8)
        near.plot(t_ms[zoom], newmark[zoom], lw=1.4, color="tab:blue", label="Newmark")
        if steady is not None:
            near.plot(t_ms[zoom], steady[zoom], "--", lw=1.0, color="k",
                      label="frequency-domain steady state")
        for ax in (whole, near):
            ax.grid(alpha=0.3)
            ax.tick_params(labelsize=7)
    axes[0, 1].legend(fontsize=7, loc="lower right", bbox_to_anchor=(1.0, 1.08), ncols=2,
                      borderaxespad=0)
    axes[0, 0].set_title("the recorded window: Newmark's extremes per cycle (band), the "
                         "steady state's (dashed), the zoom (orange)", fontsize=8)
    axes[0, 1].set_title(f"its last {window:.3g} ms"
                         + (f" ({_ZOOM_PERIODS} periods of the fastest mesh)" if period else ""),
                         fontsize=8)
    axes[-1, 0].set_xlabel("time in the steady-state window [ms]")
    axes[-1, 1].set_xlabel("time in the steady-state window [ms]")
    speed = summary["results"]["time"]["speed_rpm"]
    figure.suptitle(f"{title}: {_TITLE[kind]} at {speed:g} rpm", fontsize=9)
    return figure
