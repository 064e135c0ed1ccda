"""Figure of a gear train's mesh statistics (`geardyn train`, analysis "stats"): Gelman's mean
excitation ratio R, the dynamic factor and the mesh force and dynamic transmission error
statistics of every mesh, side by side."""

import math
import pathlib

from ._plot_common import _read_columns, _read_summary, plt


def _numbers(values):
    """Floats of a column; a blank cell (a mesh without load) is nan."""
    out = []
    for v in values:
        try:
            out.append(float(v))
        except (TypeError, ValueError):
            out.append(math.nan)
    return out


def train_stats_figure(result_dir, title="gear train"):
    """mesh_statistics.png: four panels over the meshes: R − 1 from the curves (bars) and from the
    Newmark record (dots), the dynamic factor, the static, mean, RMS and peak-to-peak mesh force
    [kN], and the peak-to-peak and RMS-about-mean dynamic transmission error [µm]."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    run = summary["results"]["stats"]
    table = _read_columns(folder / "mesh_statistics.csv")
    meshes = [str(m) for m in table["mesh"]]
    x = list(range(len(meshes)))
    figure, axes = plt.subplots(2, 2, figsize=(10.5, 6.4), layout="constrained")
    (ax_r, ax_df), (ax_f, ax_e) = axes

    ratio = _numbers(table["mean_excitation_ratio"])
    simulated = _numbers(table["simulated_mean_excitation_ratio"])
    ax_r.bar(x, [1e3 * (r - 1.0) for r in ratio], width=0.6, color="tab:blue",
             label="curves (Gelman eqs. 5–7)")
    ax_r.plot(x, [1e3 * (r - 1.0) for r in simulated], "o", color="k", ms=5,
              label="Newmark record m₁(K δ)/F")
    shown = [1e3 * (r - 1.0) for r in ratio + simulated if not math.isnan(r)] + [0.0]
    low, high = min(shown), max(shown)
    span = max(high - low, 1e-3)
    ax_r.set_ylim(low - 0.25 * span, high + 0.25 * span)
    for i, r in enumerate(ratio):
        if not math.isnan(r):  # written beside the zero line, away from the bar
            ax_r.annotate(f"R = {r:.5f}", (i, 0.0), textcoords="offset points",
                          xytext=(0, -12 if r >= 1 else 5), ha="center", fontsize=8)
    ax_r.axhline(0.0, color="0.3", lw=0.8)
    ax_r.set_ylabel("mean excitation ratio R − 1 [10⁻³]")
    ax_r.legend(fontsize=7, loc="lower right")

    factor = _numbers(table["dynamic_factor"])
    ax_df.bar(x, factor, width=0.6, color="tab:red")
    for i, f in enumerate(factor):
        if not math.isnan(f):
            ax_df.annotate(f"{f:.3f}", (i, f), textcoords="offset points", xytext=(0, 3),
                           ha="center", fontsize=8)
    ax_df.axhline(1.0, color="0.3", lw=0.8, ls="--")
    ax_df.set_ylim(0.0, max([f for f in factor if not math.isnan(f)] + [1.0]) * 1.15)
    ax_df.set_ylabel("dynamic factor max |F| / F_static [-]")

    width = 0.2
    for j, (column, label) in enumerate((("static_force_n", "static"),
                                         ("mesh_force_mean_n", "mean"),
                                         ("mesh_force_rms_n", "RMS"),
                                         ("mesh_force_p2p_n", "peak-to-peak"))):
        ax_f.bar([i + (j - 1.5) * width for i in x], [1e-3 * v for v in _numbers(table[column])],
                 width=width, label=label)
    forces = [1e-3 * v for c in ("static_force_n", "mesh_force_rms_n")
              for v in _numbers(table[c]) if not math.isnan(v)]
    ax_f.set_ylim(0.0, 1.45 * max(forces + [1e-3]))  # room for the legend above the bars
    ax_f.set_ylabel("mesh force [kN]")
    ax_f.legend(fontsize=7, loc="upper left", ncols=4)

    p2p = [1e6 * v for v in _numbers(table["dte_p2p_m"])]
    mean = _numbers(table["dte_mean_m"])
    rms = _numbers(table["dte_rms_m"])
    spread = [1e6 * math.sqrt(max(r * r - m * m, 0.0)) for r, m in zip(rms, mean)]
    ax_e.bar([i - 0.15 for i in x], p2p, width=0.3, label="peak-to-peak", color="tab:green")
    ax_e.bar([i + 0.15 for i in x], spread, width=0.3, label="RMS about the mean",
             color="tab:olive")
    ax_e.set_ylim(0.0, 1.35 * max([v for v in p2p if not math.isnan(v)] + [1e-6]))
    ax_e.set_ylabel("dynamic transmission error [µm]")
    ax_e.legend(fontsize=7, loc="upper left", ncols=2)

    for ax in (ax_r, ax_df, ax_f, ax_e):
        ax.set_xticks(x)
        ax.set_xticklabels(meshes, fontsize=8)
        ax.grid(alpha=0.3, axis="y")
    figure.suptitle(
        f"{title}: mesh statistics at {run['speed_rpm']:g} rpm over {1e3 * run['record_s']:.3g} ms "
        f"(design torque {run['design_torque_n_m']:g} N m)", fontsize=9)
    return figure
