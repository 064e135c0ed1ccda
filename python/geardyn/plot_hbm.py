"""Figures of the harmonic balance (`geardyn hbm`): the forced response with its stable and
unstable branches and folds (as Saletti et al. 2025, Fig. 5) and one period of the periodic
solutions at the detail frequencies (their Figs. 7-10)."""

import pathlib

from matplotlib.lines import Line2D

from ._plot_common import _axes, _read_columns, _read_summary, finish, plt
from ._tables import mesh_frequency_per_rpm, read_rows, stability_runs

_SWEEP_COLOURS = {"up": "tab:blue", "down": "tab:orange"}


def forced_response_figure(result_dir, ax=None):
    """Peak-to-peak relative deflection against the mesh frequency: every sweep in its colour,
    stable runs solid and unstable runs dashed, folds x, Newmark checks o. The legend has one
    solid entry per sweep and separate entries for the two line styles. With a pinion tooth
    count in the configuration a secondary axis gives the pinion speed [rpm]. Draws on `ax` if
    given; returns the Figure."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    results = summary["results"]
    si = summary["config"]["model"]["units"] == "SI"
    unit = 1e6 if si else 1.0
    rows = read_rows(folder / "sweep.csv")
    figure, ax = _axes(ax, (9.5, 5))
    handles, styles = [], set()
    both = len({r["sweep"] for r in rows}) > 1
    for sweep, colour in _SWEEP_COLOURS.items():
        points = [r for r in rows if r["sweep"] == sweep]
        if not points:
            continue
        # With both sweeps, the up sweep is drawn wide and pale under the down sweep, so both
        # stay visible where they coincide.
        style = dict(color=colour, lw=2.6 if both and sweep == "up" else 1.2,
                     alpha=0.45 if both and sweep == "up" else 1.0)
        for xs, ys, stable in stability_runs([float(p["frequency"]) for p in points],
                                             [float(p["p2p"]) * unit for p in points],
                                             [p["stable"] == "1" for p in points]):
            ax.plot(xs, ys, ls="-" if stable else "--", **style)
            styles.add(stable)
        handles.append(Line2D([], [], ls="-", label=f"HBM, sweep {sweep}", **style))
    if False in styles:  # the line styles need explaining only when both occur
        method = {"hill": "Hill's method"}.get(
            summary["config"].get("sweep", {}).get("stability_method"), "monodromy")
        handles += [Line2D([], [], color="0.3", ls="-", label=f"stable ({method})"),
                    Line2D([], [], color="0.3", ls="--", label=f"unstable ({method})")]
    folds = results.get("folds", [])
    if folds:
        handles += ax.plot([f["frequency"] for f in folds], [f["p2p"] * unit for f in folds], "kx", ms=6,
                           ls="none", label="folds")
    checks = results.get("newmark_checks", [])
    if checks:
        handles += ax.plot([c["frequency"] for c in checks], [c["p2p_newmark"] * unit for c in checks], "ko",
                           mfc="none", ls="none", label="Newmark (time integration)")
    ax.set_xlabel("mesh frequency [Hz]" if si else "Ω = ω_m / ω_n [-]")
    ax.set_ylabel("peak-to-peak y [µm]" if si else "peak-to-peak y [-]")
    ax.grid(alpha=0.3)
    ax.legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    per_rpm = mesh_frequency_per_rpm(summary) if si else None
    if per_rpm:
        top = ax.secondary_xaxis("top", functions=(lambda f: f / per_rpm, lambda n: n * per_rpm))
        top.set_xlabel("pinion speed [rpm]", fontsize=8)
        top.tick_params(labelsize=7)
    title = summary["config"].get("title") or "forced response"
    ax.set_title(f"{title}\nharmonic balance, H = {results['harmonics']}", fontsize=9)
    return figure


def details_figure(result_dir, axes=None):
    """One period of deflection, contact force and mesh stiffness F/y at each detail frequency
    (rows) — a grid of len(details) x 3 axes, or the `axes` given in that shape."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    details = summary["results"].get("details", [])
    si = summary["config"]["model"]["units"] == "SI"
    unit = 1e6 if si else 1.0
    if axes is None:
        figure, axes = plt.subplots(len(details), 3, figsize=(12, 2.2 * len(details) + 0.4), squeeze=False,
                                    layout="constrained")
    else:
        figure = axes[0][0].figure
    for row, detail in zip(axes, details):
        table = _read_columns(folder / detail["file"], short=True)
        tau = table["tau"]
        row[0].plot(tau, [v * unit for v in table["y"]])
        row[1].plot(tau, table["mesh_force"], color="tab:red")
        row[2].plot(tau, [k / 1e8 for k in table["mesh_stiffness"]], color="tab:green")
        state = "stable" if detail["stable"] else "unstable"
        row[0].set_ylabel(f"{detail['frequency']:g} Hz\n{state}", fontsize=8)
        for ax in row:
            ax.grid(alpha=0.3)
    axes[0][0].set_title(f"relative deflection y [{'µm' if si else '-'}]", fontsize=9)
    axes[0][1].set_title(f"contact force [{'N' if si else '-'}]", fontsize=9)
    axes[0][2].set_title("mesh stiffness F/y [1e8 N/m]", fontsize=9)
    for ax in axes[-1]:
        ax.set_xlabel("τ = ω t [rad]")
    return figure


def plot_hbm(result_dir, save=False):
    """{file name: Figure}: forced_response.png and, with detail frequencies, details.png;
    written into the folder (atomically) when `save`."""
    folder = pathlib.Path(result_dir)
    figures = {"forced_response.png": forced_response_figure(folder)}
    if _read_summary(folder)["results"].get("details"):
        figures["details.png"] = details_figure(folder)
    return finish(figures, folder, save)
