"""Figures of a gear train (`geardyn train`): the layout with its mode shapes, the Campbell
diagram with shaft and mesh orders, the forced response against speed, the Newmark time
response over the frequency-domain steady state, the run-up's order tracks and waterfall
(plot_train_runup.py), the mesh statistics (plot_train_stats.py) and the nonlinear steady state
(plot_train_nonlinear.py)."""

import math
import pathlib

from ._plot_common import _axes, _long_table, _read_columns, _read_summary, finish, plt
from ._tables import log_floor
from .plot_train_contact import mesh_contact_figure, mesh_misalignment_figure, whine_orders_figure
from .plot_train_housing import train_housing_figure
from .plot_train_nonlinear import train_nonlinear_figure
from .plot_train_runup import train_runup_figure, train_waterfall_figure
from .plot_train_stats import train_stats_figure
from .plot_train_time import train_time_figure
from .plot_train_tones import train_tones_figure
from .plot_train_nonlinear_tones import train_nonlinear_tones_figure

_TYPE_COLOURS = {"rotational": "tab:red", "translational": "tab:blue", "planet": "tab:green",
                 "mixed": "tab:purple", "outside": "0.3", "": "0.3"}


def _bodies(folder):
    table = _read_columns(folder / "bodies.csv")
    return [dict(name=n, kind=k, y=y, z=z) for n, k, y, z in
            zip(table["body"], table["kind"], table["centre_y_m"], table["centre_z_m"])]


def _draw_layout(ax, bodies, meshes, scale_mm):
    """Bodies as circles at their centres (mm), meshes as lines between them."""
    where = {b["name"]: (1e3 * b["y"], 1e3 * b["z"]) for b in bodies}
    for a, b in zip(meshes["body_a"], meshes["body_b"]):
        (ya, za), (yb, zb) = where[a], where[b]
        ax.plot([ya, yb], [za, zb], color="0.8", lw=1.0, zorder=0)
    for body in bodies:
        y, z = where[body["name"]]
        r = 0.06 * scale_mm * (0.6 if body["kind"] == "planet" else 1.0)
        ax.add_patch(plt.Circle((y, z), r, fill=False, color="0.55", lw=0.8))
    return where


def _mode_shapes_along_shafts(folder, summary, title, modes, shapes, count):
    """Six DOFs per node: each shaft's lateral displacement u_y (solid) and u_z (dashed) along
    x, one band per shaft, normalised per mode by its largest translation."""
    table = _read_columns(folder / "bodies.csv")
    shafts = {}
    for name, shaft, x in zip(table["body"], table["shaft"], table["axial_x_m"]):
        if isinstance(shaft, str) and shaft:
            shafts.setdefault(shaft, []).append((1e3 * x, name))
    order = list(shafts)
    columns = 4 if count > 4 else count
    rows = math.ceil(count / columns)
    figure, axes = plt.subplots(rows, columns, figsize=(3.6 * columns, 3.2 * rows + 0.6),
                                squeeze=False, layout="constrained")
    for j in range(rows * columns):
        ax = axes[j // columns][j % columns]
        if j >= count:
            ax.axis("off")
            continue
        shape = shapes[(str(int(modes["mode"][j])),)]
        values = dict(zip(shape["dof"], shape["real"]))
        translations = [abs(v) for d, v in values.items() if d.endswith((".y", ".z", ".x"))]
        largest = max(translations + [1e-300])
        for k, shaft in enumerate(order):
            nodes = sorted(shafts[shaft])
            xs = [x for x, _ in nodes]
            base = -k
            ax.plot(xs, [base] * len(xs), color="0.8", lw=0.8)
            uy = [base + 0.4 * values.get(n + ".y", 0.0) / largest for _, n in nodes]
            uz = [base + 0.4 * values.get(n + ".z", 0.0) / largest for _, n in nodes]
            ax.plot(xs, uy, color=f"C{k}", lw=1.4, marker="o" if len(xs) == 1 else None, ms=3)
            ax.plot(xs, uz, color=f"C{k}", lw=1.1, ls="--", marker="s" if len(xs) == 1 else None,
                    ms=3)
        ax.set_yticks([-k for k in range(len(order))], order, fontsize=6)
        divergent = "divergent" in modes and int(modes["divergent"][j])
        label = (f"divergent, {modes['growth_rate_1_per_s'][j]:.3g} 1/s" if divergent
                 else f"{modes['frequency_hz'][j]:.1f} Hz")
        ax.set_title(f"mode {j + 1}: {label}", fontsize=8)
        ax.tick_params(labelsize=6)
        ax.set_xlabel("x along the shafts [mm]", fontsize=7)
    speed = summary["results"]["modal"]["speed_rpm"]
    figure.suptitle(f"{title}: mode shapes at {speed:g} rpm (lateral displacement along each "
                    "shaft, normalised: u_y solid, u_z dashed)", fontsize=9)
    return figure


def _mode_shapes(folder, summary, title):
    modes = _read_columns(folder / "modes.csv")
    shapes = _long_table(folder / "mode_shapes.csv", ["mode"])
    if any(str(d).endswith(".theta_y") for d in next(iter(shapes.values()))["dof"]):
        return _mode_shapes_along_shafts(folder, summary, title, modes, shapes,
                                         min(8, len(modes["mode"])))
    bodies = _bodies(folder)
    meshes = _read_columns(folder / "meshes.csv")
    count = min(8, len(modes["mode"]))
    ys = [1e3 * b["y"] for b in bodies]
    zs = [1e3 * b["z"] for b in bodies]
    span = max(max(ys) - min(ys), max(zs) - min(zs), 50.0)
    columns = 4 if count > 4 else count
    rows = math.ceil(count / columns)
    figure, axes = plt.subplots(rows, columns, figsize=(3.3 * columns, 3.3 * rows + 0.6),
                                squeeze=False, layout="constrained")
    for j in range(rows * columns):
        ax = axes[j // columns][j % columns]
        if j >= count:
            ax.axis("off")
            continue
        where = _draw_layout(ax, bodies, meshes, span)
        shape = shapes[(str(int(modes["mode"][j])),)]
        values = dict(zip(shape["dof"], shape["real"]))
        largest = max(abs(v) for v in values.values()) or 1.0
        for body in bodies:
            y0, z0 = where[body["name"]]
            uy = values.get(body["name"] + ".y", 0.0) / largest
            uz = values.get(body["name"] + ".z", 0.0) / largest
            th = values.get(body["name"] + ".theta", 0.0) / largest
            if abs(uy) + abs(uz) > 1e-3:
                ax.annotate("", xy=(y0 + 0.25 * span * uy, z0 + 0.25 * span * uz), xytext=(y0, z0),
                            arrowprops=dict(arrowstyle="->", color="tab:blue", lw=1.4))
            if abs(th) > 1e-3:
                ax.scatter([y0], [z0], s=300 * abs(th), color="tab:red" if th > 0 else "tab:orange",
                           alpha=0.6, zorder=3)
        kind = modes["stage_type"][j] if "stage_type" in modes else ""
        kind = kind if isinstance(kind, str) else ""
        divergent = "divergent" in modes and int(modes["divergent"][j])
        label = (f"divergent, {modes['growth_rate_1_per_s'][j]:.3g} 1/s" if divergent
                 else f"{modes['frequency_hz'][j]:.1f} Hz")
        ax.set_title(f"mode {j + 1}: {label}"
                     + (f"\n{kind}" if kind else ""), fontsize=8,
                     color=_TYPE_COLOURS.get(kind.split('/')[0], "0.2"))
        ax.set_aspect("equal")
        ax.set_xlim(min(ys) - 0.45 * span, max(ys) + 0.45 * span)
        ax.set_ylim(min(zs) - 0.45 * span, max(zs) + 0.45 * span)
        ax.tick_params(labelsize=6)
        ax.set_xlabel("y [mm]", fontsize=7)
        ax.set_ylabel("z [mm]", fontsize=7)
    speed = summary["results"]["modal"]["speed_rpm"]
    figure.suptitle(f"{title}: mode shapes at {speed:g} rpm (blue arrows: translation of the "
                    "body centre; red/orange discs: rotation +/-, area ~ amplitude)", fontsize=9)
    return figure


def train_campbell_figure(result_dir, ax=None):
    """The train's Campbell diagram: modes against input speed with shaft (dashed) and mesh
    (dash-dot) order lines, crossings x, the operating speed dotted; on `ax` if given."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    return _campbell(folder, summary, _train_title(summary), ax)


def _campbell(folder, summary, title, ax=None):
    table = _read_columns(folder / "campbell.csv")
    lines = _read_columns(folder / "order_lines.csv")
    critical = _read_columns(folder / "critical_speeds.csv") if (folder / "critical_speeds.csv").stat().st_size else {}
    speeds = table["speed_rpm"]
    figure, ax = _axes(ax, (10.5, 6))
    top = 0.0
    for name, values in table.items():
        if name.startswith("mode_"):
            ax.plot(speeds, values, color="0.25", lw=1.0)
            top = max(top, max(values))
    top *= 1.1
    for name, slope in zip(lines["line"], lines["hz_per_rpm"]):
        y = [slope * s for s in speeds]
        style = "--" if name.startswith("1x ") else "-."
        (line,) = ax.plot(speeds, y, style, lw=0.9)
        # Label each order line where it leaves the plotted frequency range or at its end.
        s_end = min(speeds[-1], top / slope if slope > 0 else speeds[-1])
        ax.text(s_end, slope * s_end, " " + name, fontsize=6, color=line.get_color(),
                va="bottom", ha="right" if s_end < speeds[-1] else "left")
    if critical:
        ax.plot(critical["speed_rpm"], critical["frequency_hz"], "kx", ms=5,
                label="critical speeds (order line crosses a mode)")
    rates = table.get("divergence_rate_1_per_s", [])
    unstable = [s for s, r in zip(speeds, rates) if r > 0]
    if unstable:
        ax.axvspan(min(unstable), max(unstable), color="tab:red", alpha=0.12,
                   label=f"divergent mode (growth up to {max(rates):.3g} 1/s)")
    operating = summary["results"]["kinematics"]["input_speed_rpm"]
    if operating:
        ax.axvline(abs(operating), color="tab:red", lw=0.8, ls=":", label="operating speed")
    ax.set_xlim(speeds[0], speeds[-1] * 1.12)
    ax.set_ylim(0, top)
    ax.set_xlabel("input speed [rpm]")
    ax.set_ylabel("natural frequency [Hz]")
    ax.set_title(f"{title}: Campbell diagram (dashed: 1× shaft orders, dash-dot: mesh orders)",
                 fontsize=9)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    ax.grid(alpha=0.3)
    return figure


def train_forced_response_figure(result_dir, axes=None):
    """Dynamic factor and mesh force at the mesh frequency of every mesh against input speed,
    the operating speed dotted; on two `axes` if given."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    return _forced(folder, summary, _train_title(summary), axes)


def _forced(folder, summary, title, axes=None):
    table = _read_columns(folder / "forced_response.csv")
    speeds = table["speed_rpm"]
    if axes is None:
        figure, (top_ax, bottom_ax) = plt.subplots(2, 1, figsize=(10.5, 7), sharex=True, layout="constrained")
    else:
        (top_ax, bottom_ax), figure = axes, axes[0].figure
    for name, values in table.items():
        if name.startswith("dynamic_factor_"):
            top_ax.plot(speeds, values, lw=1.1, label=name[len("dynamic_factor_"):])
        if name.startswith("h1_") and name.endswith("_normal_n"):
            floor = log_floor([v for n, vs in table.items() if n.startswith("h1_") for v in vs]) or 1e-12
            bottom_ax.semilogy(speeds, [max(v, floor) for v in values], lw=1.1,
                               label=name[len("h1_"):-len("_normal_n")])
    operating = abs(summary["results"]["kinematics"]["input_speed_rpm"])
    for ax in (top_ax, bottom_ax):
        if operating:
            ax.axvline(operating, color="tab:red", lw=0.8, ls=":", label="operating speed")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    top_ax.set_ylabel("dynamic factor max F / mean F [-]")
    bottom_ax.set_ylabel("mesh force at the mesh frequency [N]")
    bottom_ax.set_xlabel("input speed [rpm]")
    top_ax.set_title(f"{title}: forced response to transmission error and mesh-stiffness "
                     "variation (frequency domain)", fontsize=9)
    return figure


def _bearing_forced(folder, summary, title):
    """A train without meshes (a rotor driven by an unbalance, a runout or a bearing excitation):
    the dynamic force every bearing transmits against speed (forced_response.csv's
    dynamic_<bearing>_n, the amplitude of its spring force), the rotor's Bode plot."""
    table = _read_columns(folder / "forced_response.csv")
    speeds = table["speed_rpm"]
    gearbox = summary["config"].get("gearbox_description") or summary["config"]
    names = [b for b in gearbox.get("bearings", {}) if "dynamic_" + b + "_n" in table]
    if not names:
        return None
    figure, ax = plt.subplots(figsize=(10.5, 4.5), layout="constrained")
    values = [v for b in names for v in table["dynamic_" + b + "_n"]]
    floor = log_floor(values) or 1e-12
    for b in names:
        ax.semilogy(speeds, [max(v, floor) for v in table["dynamic_" + b + "_n"]], lw=1.2, label=b)
    operating = abs(summary["results"]["kinematics"]["input_speed_rpm"])
    if operating:
        ax.axvline(operating, color="tab:red", lw=0.8, ls=":", label="operating speed")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    ax.set_xlabel("input speed [rpm]")
    ax.set_ylabel("dynamic bearing force [N]")
    ax.set_title(f"{title}: forced response of the bearings to the unbalances, runouts and "
                 "bearing excitations (frequency domain)", fontsize=9)
    return figure


def _train_title(summary):
    return summary["config"].get("gearbox", {}).get("name") or \
        summary["config"].get("gearbox_description", {}).get("gearbox", {}).get("name") or "gear train"


def plot_train(result_dir, save=False):
    """{file name: Figure}: modes.png, campbell.png, forced_response.png (and forced_tones.png
    on the torus, plot_train_tones.py; housing_response.png with a flexible housing's response
    points, plot_train_housing.py), time_history.png,
    runup.png and waterfall.png (plot_train_runup.py), mesh_statistics.png
    (plot_train_stats.py), mesh_misalignment.png, mesh_contact.png and whine_orders.png
    (plot_train_contact.py), and nonlinear_response.png (common period) or nonlinear_tones.png (torus,
    plot_train_nonlinear_tones.py) of the analyses run; written into the folder when `save`."""
    folder = pathlib.Path(result_dir)
    summary = _read_summary(folder)
    title = _train_title(summary)
    figures = {}
    results = summary["results"]
    if "modal" in results and (folder / "mode_shapes.csv").exists():
        figures["modes.png"] = _mode_shapes(folder, summary, title)
    if "campbell" in results:
        figures["campbell.png"] = _campbell(folder, summary, title)
    if "static" in results and (folder / "mesh_misalignment.csv").exists():
        figures["mesh_misalignment.png"] = mesh_misalignment_figure(folder, title)
    if "contact" in results:
        figures["mesh_contact.png"] = mesh_contact_figure(folder, summary, title)
    if "forced" in results:
        # A train without meshes (a rotor with an unbalance) has bearing forces to draw instead.
        figure = (_forced(folder, summary, title) if results["forced"].get("meshes")
                  else _bearing_forced(folder, summary, title))
        if figure is not None:
            figures["forced_response.png"] = figure
        if (folder / "forced_mesh_orders.csv").exists():
            figure = whine_orders_figure(folder, summary, title)
            if figure is not None:
                figures["whine_orders.png"] = figure
        if (folder / "forced_tones.csv").exists():
            figures["forced_tones.png"] = train_tones_figure(folder, summary, title)
        if (folder / "housing_response.csv").exists():
            figures["housing_response.png"] = train_housing_figure(folder, summary, title)
    if "time" in results and (folder / "time_history.csv").exists():
        figure = train_time_figure(folder, summary, title)
        if figure is not None:
            figures["time_history.png"] = figure
    if "runup" in results and (folder / "runup.csv").exists():
        figures["runup.png"] = train_runup_figure(folder, title)
        figures["waterfall.png"] = train_waterfall_figure(folder, title)
    if "stats" in results and (folder / "mesh_statistics.csv").exists():
        figures["mesh_statistics.png"] = train_stats_figure(folder, title)
    if "nonlinear" in results:
        # On the torus (nonlinear_torus.csv, no per-sweep tables): the orders and tones along
        # the continuation; the common-period sweeps: the response curves.
        if results["nonlinear"].get("method") == "torus":
            figures["nonlinear_tones.png"] = train_nonlinear_tones_figure(folder, summary, title)
        else:
            figures["nonlinear_response.png"] = train_nonlinear_figure(folder, title=title)
    return finish(figures, folder, save)
