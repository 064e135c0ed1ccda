"""Figure of the nonlinear analysis of `geardyn train`: the peak-to-peak deflection of every mesh
(and the peak-to-peak radial displacement of every bearing with a radial clearance) against
input speed from the harmonic-balance continuation (nonlinear_up.csv, nonlinear_down.csv),
stable solid and unstable dashed, folds x, Newmark checks o, and the mesh frequency on a
secondary axis."""

import math
import pathlib

from matplotlib.lines import Line2D

from ._plot_common import _read_columns, _read_summary, plt
from ._tables import stability_runs

_SWEEP_COLOURS = {"up": "tab:blue", "down": "tab:orange"}


# The legend's name of the stability method the run used (summary results.nonlinear).
_STABILITY_METHODS = {"monodromy": "monodromy", "hill": "Hill's method"}


def _stable_flags(table):
    """The stable column as booleans (all True when the run skipped stability)."""
    values = table["stable"]
    return [v == 1.0 if not isinstance(v, str) else True for v in values]


def train_nonlinear_figure(result_dir, axes=None, max_meshes=8, title=None):
    """p2p mesh deflection [µm] against input speed [rpm], one panel per mesh (the first
    `max_meshes` by name), then one per clearance bearing (p2p radial displacement |u| [µm]):
    every sweep in its colour (the up sweep wide and pale under the down sweep),
    stable runs solid and unstable runs dashed, folds x, Newmark checks o. The legend has solid
    entries per sweep and separate entries for the two line styles. On `axes` (a flat list, one
    per mesh) if given; returns the Figure."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    results = summary["results"]["nonlinear"]
    sweeps = {name: _read_columns(folder / info["file"])
              for name, info in results["sweeps"].items() if info["points"] > 0}
    # By name, so that a planetary stage's sun-planet and ring-planet meshes each fill a row.
    meshes = sorted(results["mesh_multiples"])[:max_meshes]
    bearings = results.get("clearance_bearings", {})
    panels = [(name, "deflection") for name in meshes] + [(name, "radial") for name in bearings]
    if axes is None:
        count = len(panels)
        columns = 1 if count == 1 else (2 if count <= 4 else 3)
        rows = math.ceil(count / columns)
        figure, grid = plt.subplots(rows, columns, figsize=(4.6 * columns + 1.8, 3.0 * rows + 0.9),
                                    squeeze=False, layout="constrained")
        axes = [ax for row in grid for ax in row]
        for ax in axes[count:]:
            ax.axis("off")
    figure = axes[0].figure
    both = len(sweeps) > 1
    styles = set()
    checks = results.get("newmark_checks", [])
    for ax, (mesh, quantity) in zip(axes, panels):
        column = f"p2p_{quantity}_{mesh}_m"
        for name, table in sweeps.items():
            style = dict(color=_SWEEP_COLOURS[name], lw=2.6 if both and name == "up" else 1.2,
                         alpha=0.45 if both and name == "up" else 1.0)
            for xs, ys, stable in stability_runs(table["speed_rpm"],
                                                 [1e6 * v for v in table[column]],
                                                 _stable_flags(table)):
                ax.plot(xs, ys, ls="-" if stable else "--", **style)
                styles.add(stable)
        folds = [f for f in results.get("folds", []) if mesh in f.get(f"p2p_{quantity}_m", {})]
        ax.plot([f["speed_rpm"] for f in folds], [1e6 * f[f"p2p_{quantity}_m"][mesh] for f in folds],
                "kx", ms=6, ls="none")
        key = f"p2p_{quantity}_newmark_m"
        done = [c for c in checks if mesh in c.get(key, {})]
        ax.plot([c["speed_rpm"] for c in done], [1e6 * c[key][mesh] for c in done],
                "ko", mfc="none", ms=7, ls="none")
        ax.tick_params(labelsize=7)
        ax.grid(alpha=0.3)
        if quantity == "radial":
            clearance = 1e6 * bearings[mesh]["radial_clearance_m"]
            ax.set_title(f"bearing {mesh} (radial clearance {clearance:.3g} µm)", fontsize=9)
            ax.set_ylabel("p2p radial displacement [µm]", fontsize=8)
            continue
        ax.set_title(mesh, fontsize=9)
        ax.set_ylabel("p2p mesh deflection [µm]", fontsize=8)
        per_rpm = results["mesh_frequency_hz_per_rpm"][mesh]
        top = ax.secondary_xaxis("top", functions=(lambda n, k=per_rpm: n * k,
                                                   lambda f, k=per_rpm: f / k))
        top.set_xlabel("mesh frequency [Hz]", fontsize=7)
        top.tick_params(labelsize=6)
    shown = axes[:len(panels)]
    columns = sum(1 for ax in shown if ax.get_subplotspec().is_first_row()) or 1
    for i, ax in enumerate(shown):
        if i + columns >= len(shown):  # the lowest panel of its column
            ax.set_xlabel("input speed [rpm]", fontsize=8)
    handles = [Line2D([], [], ls="-", color=_SWEEP_COLOURS[name],
                      lw=2.6 if both and name == "up" else 1.2,
                      alpha=0.45 if both and name == "up" else 1.0, label=f"harmonic balance, sweep {name}")
               for name in sweeps]
    if False in styles:
        method = _STABILITY_METHODS.get(results.get("stability_method"), "monodromy")
        handles += [Line2D([], [], color="0.3", ls="-", label=f"stable ({method})"),
                    Line2D([], [], color="0.3", ls="--", label=f"unstable ({method})")]
    if results.get("folds"):
        handles.append(Line2D([], [], color="k", marker="x", ls="none", label="folds"))
    if any("p2p_deflection_newmark_m" in c for c in checks):
        handles.append(Line2D([], [], color="k", marker="o", mfc="none", ls="none",
                              label="Newmark started on the solution"))
    # On the last panel of the first row, outside it (constrained layout keeps it in the image).
    shown[columns - 1].legend(handles=handles, fontsize=7, loc="upper left",
                              bbox_to_anchor=(1.02, 1.0), borderaxespad=0)
    title = title or summary["config"].get("gearbox", {}).get("name") or "gear train"
    figure.suptitle(f"{title}: nonlinear steady state (harmonic balance, H = {results['harmonics']}, "
                    f"N = {results['samples']})", fontsize=9)
    return figure
