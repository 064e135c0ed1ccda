"""Figures of geardyn result folders (matplotlib).

Every ``plot_<command>(result_dir, save=False)`` returns ``{file name: Figure}``; with
``save=True`` it also writes each figure as PNG into the folder, atomically (temporary name in
the same folder, then rename). The ``*_figure(result_dir, ax=None)`` functions draw one figure,
on the caller's axes when given, and return it. The command line calls
``python3 -m geardyn.plot COMMAND RESULT_DIR`` after writing a command's CSV tables: the same
functions with ``save=True``; it prints the names of the files written, one per line.
"""

import csv
import json
import math
import pathlib
import sys

from ._plot_common import _read_columns, finish, plt
from .plot_fe_rotor import (campbell_figure, fe_modes_figure, plot_campbell, plot_rotor_fe,  # noqa: F401
                            runup_figure)
from .plot_hbm import details_figure, forced_response_figure, plot_hbm  # noqa: F401  (re-exported)
from .plot_face_load import face_load_figure
from .plot_rotor import (full_spectrum_figure, orbits_figure, plot_rotor, plot_spectrum,  # noqa: F401
                         study_figure)
from .plot_sweep import plot_histograms, plot_sweep  # noqa: F401  (re-exported)
from .plot_train import plot_train, train_campbell_figure, train_forced_response_figure  # noqa: F401
from .plot_train_nonlinear import train_nonlinear_figure  # noqa: F401
from .plot_train_runup import train_runup_figure, train_waterfall_figure  # noqa: F401


def _read_profiles(path):
    """tooth_profiles.csv -> {member: (xs, ys)} of the right half of one tooth [m]."""
    profiles = {}
    with open(path, newline="") as handle:
        for row in csv.DictReader(handle):
            xs, ys = profiles.setdefault(row["member"], ([], []))
            xs.append(float(row["x_m"]))
            ys.append(float(row["y_m"]))
    return profiles


def _whole_tooth(xs, ys):
    """One tooth from the middle of the space on its left to the middle of the space on its
    right: the mirrored half (up the left flank) then the half itself reversed (down the right)."""
    left_x = [-x for x in xs]
    return left_x + list(reversed(xs))[1:], ys + list(reversed(ys))[1:]


def _gear_outline(xs, ys, teeth, centre, rotation):
    """The whole gear: the tooth rotated `teeth` times, turned by `rotation`, moved to `centre`."""
    tooth_x, tooth_y = _whole_tooth(xs, ys)
    out_x, out_y = [], []
    for k in range(teeth):
        angle = rotation + 2.0 * math.pi * k / teeth
        c, s = math.cos(angle), math.sin(angle)
        # angle measured clockwise from +y, like the profile's own angles
        out_x += [centre[0] + c * x + s * y for x, y in zip(tooth_x, tooth_y)]
        out_y += [centre[1] - s * x + c * y for x, y in zip(tooth_x, tooth_y)]
    return out_x + out_x[:1], out_y + out_y[:1]


def plot_geometry(result_dir, save=False):
    """mesh.png: the pair in mesh (whole gears and a close-up of the contact zone with the line
    of action, path of contact and pitch point). Needs summary.json results and
    tooth_profiles.csv. Returns {"mesh.png": Figure}."""
    folder = pathlib.Path(result_dir)
    results = json.loads((folder / "summary.json").read_text())["results"]
    profiles = _read_profiles(folder / "tooth_profiles.csv")
    pinion, gear = results["pinion"], results["gear"]
    z1, z2 = pinion["teeth"], gear["teeth"]
    a = results["centre_distance"]
    alpha = results["operating_pressure_angle"]
    mm = 1e3

    # Pinion at the origin, a tooth centred on +y; gear above, a space centred on -y.
    p_x, p_y = _gear_outline(*profiles["pinion"], z1, (0.0, 0.0), 0.0)
    g_x, g_y = _gear_outline(*profiles["gear"], z2, (0.0, a), math.pi + math.pi / z2)
    # Line of action through the pitch point P, tangent to both base circles.
    r_w1 = pinion["operating_pitch_radius"]
    d = (math.cos(alpha), math.sin(alpha))
    t1 = (-r_w1 * math.sin(alpha) * d[0], r_w1 - r_w1 * math.sin(alpha) * d[1])
    length = results["line_of_action_length"]
    t2 = (t1[0] + length * d[0], t1[1] + length * d[1])
    s0, s1 = results["path_of_contact_start"], results["path_of_contact_end"]
    along = lambda s: (t1[0] + s * d[0], t1[1] + s * d[1])  # noqa: E731

    figure, axes = plt.subplots(1, 2, figsize=(12, 6))
    for ax, zoom in zip(axes, (False, True)):
        ax.plot([v * mm for v in p_x], [v * mm for v in p_y], color="tab:blue", lw=0.8,
                label=f"pinion, {z1} teeth")
        ax.plot([v * mm for v in g_x], [v * mm for v in g_y], color="tab:red", lw=0.8,
                label=f"gear, {z2} teeth")
        for centre, member, colour in (((0.0, 0.0), pinion, "tab:blue"), ((0.0, a), gear, "tab:red")):
            for key, style in (("base_radius", ":"), ("operating_pitch_radius", "-.")):
                ax.add_patch(plt.Circle((centre[0] * mm, centre[1] * mm), member[key] * mm, fill=False,
                                        ls=style, lw=0.6, color=colour))
        ax.plot([t1[0] * mm, t2[0] * mm], [t1[1] * mm, t2[1] * mm], color="0.4", lw=0.7,
                label="line of action T1T2")
        start, end = along(min(s0, s1)), along(max(s0, s1))
        ax.plot([start[0] * mm, end[0] * mm], [start[1] * mm, end[1] * mm], color="black", lw=2.5,
                label=f"path of contact, eps_alpha = {results['contact_ratio_transverse']:.4f}")
        ax.plot([0.0], [r_w1 * mm], "ko", ms=3)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        if zoom:
            half = 1.6 * max(length, 4 * pinion["tip_radius"] - 4 * pinion["root_radius"]) * mm / 2
            ax.set_xlim(-half, half)
            ax.set_ylim(r_w1 * mm - half, r_w1 * mm + half)
            ax.annotate("P", (0.0, r_w1 * mm), xytext=(4, -10), textcoords="offset points")
            ax.set_title("contact zone")
        else:
            ax.set_title(f"{z1}/{z2} teeth, a = {a * mm:.4f} mm, alpha_wt = "
                         f"{results['operating_pressure_angle_deg']:.3f} deg")
            ax.legend(loc="upper right", fontsize=7)
    figure.tight_layout()
    return finish({"mesh.png": figure}, folder, save)


def plot_stiffness(result_dir, save=False):
    """mesh_stiffness.png: k over two mesh periods for every model (as Visnadi 2021, Fig. 1),
    with the pairs of the primary model; and the static transmission error when computed."""
    folder = pathlib.Path(result_dir)
    summary = json.loads((folder / "summary.json").read_text())
    results = summary["results"]
    table = _read_columns(folder / "mesh_stiffness.csv")
    phase = table["mesh_fraction"]
    primary = results["mesh_stiffness"]["model"]
    two = [p for p in phase] + [p + 1.0 for p in phase]

    def twice(values):
        return list(values) + list(values)

    has_ste = "ste_transverse_m" in table
    figure, axes = plt.subplots(2 if has_ste else 1, 1, figsize=(9, 7 if has_ste else 4.8), squeeze=False)
    ax = axes[0][0]
    ax.plot(two, [k / 1e8 for k in twice(table["k_total_transverse_n_per_m"])], lw=1.6, label=primary)
    for name in [c for c in table if c.startswith("k_pair_")]:
        ax.plot(two, [k / 1e8 for k in twice(table[name])], lw=0.7, ls="--",
                label=f"{primary}, pair {name.split('_')[2]}")
    for name in [c for c in table if c.startswith("k_") and c != "k_total_transverse_n_per_m" and not c.startswith("k_pair_")]:
        ax.plot(two, [k / 1e8 for k in twice(table[name])], lw=1.1, label=name[2:].replace("_transverse_n_per_m", ""))
    ax.set_xlabel("mesh phase [mesh periods]")
    ax.set_ylabel("mesh stiffness [1e8 N/m]")
    ax.set_xlim(0, 2)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    title = summary.get("config", {}).get("title") or "mesh stiffness"
    ax.set_title(f"{title}\ncontact ratio {results['mesh_stiffness']['contact_ratio']:.4f}", fontsize=9)
    if has_ste:
        ax = axes[1][0]
        ax.plot(two, [d * 1e6 for d in twice(table["ste_transverse_m"])], color="black", lw=1.2)
        ax.set_xlabel("mesh phase [mesh periods]")
        ax.set_ylabel("loaded STE [µm]")
        ax.set_xlim(0, 2)
        ax.grid(alpha=0.3)
        force = results["static_transmission_error"]["force"]
        ax.set_title(f"static transmission error at F = {force:g} N ({primary})", fontsize=9)
    figure.tight_layout()
    return finish({"mesh_stiffness.png": figure}, folder, save)


def plot_simulate(result_dir, save=False):
    """time_response.png: relative deflection y = x - e and the mesh force over the steady
    periods written out, with the mean force for reference."""
    folder = pathlib.Path(result_dir)
    summary = json.loads((folder / "summary.json").read_text())
    table = _read_columns(folder / "time_response.csv")
    results = summary["results"]
    si = results["model"]["units"] == "SI"
    t = table["t_s" if si else "t_nondim"]
    figure, axes = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
    axes[0].plot(t, [y * (1e6 if si else 1.0) for y in table["y_transverse_" + ("m" if si else "nondim")]], lw=1.0)
    axes[0].set_ylabel("y = x - e [µm]" if si else "y = x - e [-]")
    axes[1].plot(t, table["mesh_force_transverse_" + ("n" if si else "nondim")], lw=1.0, color="tab:red",
                 label="mesh force")
    axes[1].axhline(results["model"]["mean_force"], color="0.4", lw=0.8, ls="--", label="mean load F")
    axes[1].set_ylabel("transverse mesh force [N]" if si else "mesh force [-]")
    axes[1].set_xlabel("t [s]" if si else "t1 = omega_n t [-]")
    axes[1].legend(fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
    title = summary.get("config", {}).get("title") or "gear-pair time response"
    axes[0].set_title(f"{title}\n{results['status']}: {results['message']}", fontsize=9)
    figure.tight_layout()
    return finish({"time_response.png": figure}, folder, save)


def plot_stats(result_dir, save=False):
    """mean_excitation_ratio.png: histogram of the Monte Carlo mean excitation ratio R with its
    5/50/95 % quantiles and the deterministic R."""
    folder = pathlib.Path(result_dir)
    results = json.loads((folder / "summary.json").read_text())["results"]
    table = _read_columns(folder / "histogram.csv")
    low, high, count = table["ratio_low"], table["ratio_high"], table["count"]
    figure, ax = plt.subplots(figsize=(8, 4.5))
    ax.bar(low, count, width=[h - l for l, h in zip(low, high)], align="edge", color="tab:blue", alpha=0.7)
    mc = results["monte_carlo"]["ratio"]
    for key, style in (("q05", ":"), ("q50", "--"), ("q95", ":")):
        ax.axvline(mc[key], color="black", ls=style, lw=1, label=f"{key[1:]} %: {mc[key]:.5g}")
    ax.axvline(results["mean_excitation"]["ratio"], color="tab:red", lw=1.5,
               label=f"without random errors: {results['mean_excitation']['ratio']:.5g}")
    ax.set_xlabel("mean excitation ratio R")
    ax.set_ylabel("samples")
    ax.legend(fontsize=8)
    ax.set_title(f"Monte Carlo, {results['monte_carlo']['samples']} samples (seed {results['monte_carlo']['seed']})", fontsize=9)
    figure.tight_layout()
    return finish({"mean_excitation_ratio.png": figure}, folder, save)


def plot_identify(result_dir, save=False):
    """identify.png: measured against re-simulated whirl peaks of each shaft and speed, forward
    right and backward left (as Rao 2023, Figs. 5.12 and 5.14)."""
    folder = pathlib.Path(result_dir)
    summary = json.loads((folder / "summary.json").read_text())
    table = _read_columns(folder / "resimulated_peaks.csv")
    speeds = list(dict.fromkeys(table["speed_rpm"]))
    figure, axes = plt.subplots(len(speeds), 2, figsize=(12, 3.6 * len(speeds)), squeeze=False)
    for row, speed in zip(axes, speeds):
        for ax, shaft in zip(row, ("pinion", "gear")):
            keep = [i for i in range(len(table["shaft"])) if table["shaft"][i] == shaft and table["speed_rpm"][i] == speed]
            f = [table["frequency_hz"][i] for i in keep]
            measured = [table["measured_amplitude_m"][i] * 1e6 for i in keep]
            model = [table["model_amplitude_m"][i] * 1e6 for i in keep]
            ax.vlines(f, 0, measured, color="0.6", lw=4, label="measured")
            ax.plot(f, model, "o", color="tab:red", ms=4, mfc="none", label="re-simulated (identified)")
            ax.set_title(f"{shaft} shaft, {speed:g} rpm", fontsize=9)
            ax.set_ylabel("0-peak whirl radius [µm]")
            ax.set_xlabel("frequency [Hz] (probe frame)")
            ax.grid(alpha=0.3)
        row[0].legend(fontsize=8)
    fit = summary["results"]["fit"]
    title = summary["config"].get("title") or "identification"
    figure.suptitle(f"{title}: {fit['method']}, re-simulated within {100 * fit['resimulated_relative_difference']:.2g} % "
                    f"of the largest peak", fontsize=9)
    figure.tight_layout()
    return finish({"identify.png": figure}, folder, save)


def plot_ltca(result_dir, save=False):
    """ltca.png: loaded STE over the mesh period and the load share of each tooth pair;
    harris.png: peak-to-peak STE against load (a Harris map); statistics.png: Gelman's r_ke and
    R against the normalised load."""
    folder = pathlib.Path(result_dir)
    summary = json.loads((folder / "summary.json").read_text())
    title = summary["config"].get("title") or "loaded tooth contact"
    gearbox = summary["config"].get("gearbox", {})
    if gearbox.get("mesh"):  # a mesh of a gearbox file
        title = f"{title}, mesh {gearbox['mesh']} of {gearbox.get('file', 'the gearbox')}"
    table = _read_columns(folder / "ltca.csv")
    figures = {}
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    top.plot(table["mesh_fraction"], [v * 1e6 for v in table["ste_transverse_m"]], label="loaded STE")
    top.plot(table["mesh_fraction"], [v * 1e6 for v in table["no_load_te_transverse_m"]], "--", label="no-load TE")
    top.set_ylabel("along the transverse line of action [µm]")
    top.legend(fontsize=8)
    top.grid(alpha=0.3)
    for name in [c for c in table if c.startswith("share_pair_")]:
        bottom.plot(table["mesh_fraction"], table[name], label=name.replace("share_", ""))
    bottom.set_ylabel("load share [-]")
    bottom.set_xlabel("mesh phase [periods]")
    bottom.legend(fontsize=8)
    bottom.grid(alpha=0.3)
    figure.suptitle(f"{title}: {summary['results']['ltca']['force']:.6g} N", fontsize=9)
    figure.tight_layout()
    figures["ltca.png"] = figure
    face = face_load_figure(folder, f"{title}: across the face", summary["results"]["ltca"].get("face_load_factor"))
    if face is not None:
        figures["face_load.png"] = face
    if (folder / "harris.csv").exists():
        harris = _read_columns(folder / "harris.csv")
        figure, ax = plt.subplots(figsize=(7, 4.5))
        ax.plot(harris["force_transverse_n"], [v * 1e6 for v in harris["peak_to_peak_m"]], "o-", label="peak to peak")
        for name in [c for c in harris if c.startswith("harmonic_")]:
            ax.plot(harris["force_transverse_n"], [v * 1e6 for v in harris[name]], lw=0.8, label=name.replace("_m", ""))
        if (folder / "harris_designs.csv").exists():
            others = _read_columns(folder / "harris_designs.csv")
            for name in dict.fromkeys(others["design"]):
                keep = [i for i, d in enumerate(others["design"]) if d == name]
                ax.plot([others["force_transverse_n"][i] for i in keep], [others["peak_to_peak_m"][i] * 1e6 for i in keep],
                        "--", lw=1.0, label=f"peak to peak, design {name}")
        design = summary["config"]["modifications"].get("design_load")
        if design:
            ax.axvline(design, color="0.5", ls=":", label="design load")
        ax.set_xlabel("transmitted force [N]")
        ax.set_ylabel("loaded STE [µm]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        ax.set_title(f"{title}: Harris map", fontsize=9)
        figure.tight_layout()
        figures["harris.png"] = figure
    if (folder / "load_statistics.csv").exists():
        stats = _read_columns(folder / "load_statistics.csv")
        figure, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
        left.plot(stats["a"], stats["r_ke"], "o-")
        left.axhline(0.0, color="0.5", lw=0.8)
        left.set_xlabel("a = F / F0")
        left.set_ylabel("r_ke")
        right.plot(stats["a"], stats["ratio_eq11"], "o-", label="R (eq. 11)")
        right.plot(stats["a"], stats["ratio_eq7"], "s--", label="R (eq. 7)")
        right.axhline(1.0, color="0.5", lw=0.8)
        right.set_xlabel("a = F / F0")
        right.legend(fontsize=8)
        for ax in (left, right):
            ax.grid(alpha=0.3)
        figure.suptitle(f"{title}: Gelman statistics against load", fontsize=9)
        figure.tight_layout()
        figures["statistics.png"] = figure
    return finish(figures, folder, save)


PLOTTERS = {"geometry": plot_geometry, "stiffness": plot_stiffness, "simulate": plot_simulate,
            "stats": plot_stats, "hbm": plot_hbm, "rotor": plot_rotor, "spectrum": plot_spectrum,
            "identify": plot_identify, "ltca": plot_ltca, "rotor_fe": plot_rotor_fe,
            "sweep": plot_sweep, "train": plot_train}


def main(argv=None):
    """The command line's PNGs: draws the command's figures, writes them into the folder and
    prints their file names, one per line."""
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 2 or argv[0] not in PLOTTERS:
        print(f"usage: python3 -m geardyn.plot {{{','.join(PLOTTERS)}}} RESULT_DIR", file=sys.stderr)
        return 2
    for name, figure in PLOTTERS[argv[0]](argv[1], save=True).items():
        plt.close(figure)
        print(name)
    return 0


if __name__ == "__main__":
    sys.exit(main())
